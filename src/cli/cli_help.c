/* --help, `rockbolt help COMMAND`, --version, and the "did you mean" of an
 * unknown option. The texts are generated from src/cli/help.txt, which
 * also makes the man page; the exit codes listed there are the contract
 * scripts rely on (README.md and docs/exit-codes.md repeat them). */
#include <stdio.h>
#include <string.h>
#include "util/nearest.h"
#include "cli.h"
#include "cli_help.h"

static void print_lines(const char *const *lines)
{
    for (; *lines; lines++) {
        fputs(*lines, stdout);
        fputc('\n', stdout);
    }
}

void rb_cli_help_print(void)
{
    print_lines(rb_help_overview);
}

static const rb_help_command *find_command(const char *name)
{
    for (const rb_help_command *c = rb_help_commands; c->name; c++)
        if (strcmp(c->name, name) == 0)
            return c;
    return NULL;
}

rb_exit rb_cli_help_command_print(const char *name)
{
    const rb_help_command *c = find_command(name);
    if (!c) {
        const char *names[16];
        size_t n = 0;
        for (const rb_help_command *k = rb_help_commands; k->name && n < 15; k++)
            names[n++] = k->name;
        names[n] = NULL;
        rb_cli_unknown_word("command", name, names, NULL);
        return RB_EXIT_USAGE;
    }
    print_lines(c->lines);
    return RB_EXIT_PASS;
}

void rb_cli_version_print(void)
{
    printf("rockbolt %s (JSON report format %d)\n", RB_VERSION_STRING,
           RB_REPORT_FORMAT_VERSION);
}

const char *rb_cli_nearest(const char *word, const char *const *cands)
{
    char w[64];
    const char *best = NULL;
    int bestd = 9;
    size_t len;
    /* "--jsn=FILE": only the name counts */
    snprintf(w, sizeof w, "%.*s", (int)strcspn(word, "="), word);
    len = strlen(w);
    /* a short option is one letter: every other one is as near */
    if (len - strspn(w, "-") <= 1)
        return NULL;
    for (size_t i = 0; cands[i]; i++) {
        int d = rb_edit_distance(w, cands[i]);
        /* an abbreviation of one option, "--jso" */
        if (len > 3 && strncmp(cands[i], w, len) == 0)
            d = 1;
        if (d < bestd) {
            bestd = d;
            best = cands[i];
        }
    }
    return bestd <= rb_typo_limit(len - strspn(w, "-")) ? best : NULL;
}

void rb_cli_unknown_word(const char *what, const char *word, const char *const *cands,
                         const char *cmd)
{
    const char *near = rb_cli_nearest(word, cands);
    char see[64];
    snprintf(see, sizeof see, "see 'rockbolt help%s%s'", cmd ? " " : "", cmd ? cmd : "");
    if (near && cmd)
        rb_cli_error(NULL, NULL, "unknown %s '%s' for '%s'; did you mean '%s'? (%s)",
                     what, word, cmd, near, see);
    else if (near)
        rb_cli_error(NULL, NULL, "unknown %s '%s'; did you mean '%s'? (%s)", what,
                     word, near, see);
    else if (cmd)
        rb_cli_error(NULL, NULL, "unknown %s '%s' for '%s' (%s)", what, word, cmd, see);
    else
        rb_cli_error(NULL, NULL, "unknown %s '%s' (%s)", what, word, see);
}

void rb_cli_unknown_option(const char *cmd, const char *arg)
{
    const rb_help_command *c = find_command(cmd);
    static const char *const none[] = {NULL};
    char name[64];
    snprintf(name, sizeof name, "%.*s", (int)strcspn(arg, "="), arg);
    if (c && !rb_cli_nearest(arg, c->options)) {
        /* an option of another command: say whose */
        for (const rb_help_command *k = rb_help_commands; k->name; k++)
            for (const char *const *o = k->options; *o; o++)
                if (strcmp(*o, name) == 0) {
                    rb_cli_error(NULL, NULL, "unknown option '%s' for '%s' ('%s' is "
                                 "an option of '%s'; see 'rockbolt help %s')", arg,
                                 cmd, name, k->name, cmd);
                    return;
                }
    }
    rb_cli_unknown_word("option", arg, c ? c->options : none, cmd);
}
