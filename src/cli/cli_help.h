/* The help texts, generated at build time from src/cli/help.txt by
 * tools/helpgen.c (which also writes the man page from it). */
#ifndef RB_CLI_HELP_H
#define RB_CLI_HELP_H

typedef struct {
    const char *name;                 /* "check" */
    const char *const *lines;         /* its --help, one line each, NULL-ended */
    const char *const *options;       /* the options it documents ("--json",
                                         "-q", "--quiet"), NULL-ended */
} rb_help_command;

/* Every command, ended by a NULL name. */
extern const rb_help_command rb_help_commands[];

/* `rockbolt --help`, one line each, NULL-ended. */
extern const char *const rb_help_overview[];

#endif
