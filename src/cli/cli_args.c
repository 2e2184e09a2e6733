/* Command-line parsing: "rockbolt COMMAND [ARGS] [OPTIONS]".
 *
 * Options may come before or after the case file, as "--json FILE" or
 * "--json=FILE"; "--" ends the options. Every mistake is a usage error
 * (exit 2) with one line naming the offending argument, and is found
 * before anything is read or written. */
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "rockbolt/sandbox.h"

/* Is arg the option name, as "--name" alone or "--name=VALUE"? Sets
 * *inline_val to the text after '=' if any. */
static int opt_is(const char *arg, const char *name, const char **inline_val)
{
    size_t n = strlen(name);
    if (strncmp(arg, name, n) != 0)
        return 0;
    if (arg[n] == '\0') {
        *inline_val = NULL;
        return 1;
    }
    if (arg[n] == '=') {
        *inline_val = arg + n + 1;
        return 1;
    }
    return 0;
}

/* Take the value of a FILE option from "=VALUE" or the next argument. */
static rb_exit take_value(int argc, char **argv, int *i, const char *name,
                          const char *inline_val, const char **dst)
{
    const char *v = inline_val;
    if (!v) {
        if (*i + 1 >= argc) {
            rb_cli_error(NULL, NULL, "option '%s' needs a file name", name);
            return RB_EXIT_USAGE;
        }
        v = argv[++*i];
    }
    if (!v[0]) {
        rb_cli_error(NULL, NULL, "option '%s' needs a non-empty file name", name);
        return RB_EXIT_USAGE;
    }
    if (*dst) {
        rb_cli_error(NULL, NULL, "option '%s' given twice", name);
        return RB_EXIT_USAGE;
    }
    *dst = v;
    return RB_EXIT_PASS;
}

/* -j N / --threads N: a whole number from 1 to 1024. */
static rb_exit take_threads(int argc, char **argv, int *i, const char *inline_val,
                            rb_cli_opts *o)
{
    const char *v = inline_val;
    char *end;
    long n;
    if (!v) {
        if (*i + 1 >= argc) {
            rb_cli_error(NULL, NULL, "option '-j' needs a number of threads");
            return RB_EXIT_USAGE;
        }
        v = argv[++*i];
    }
    n = strtol(v, &end, 10);
    if (end == v || *end || n < 1 || n > 1024) {
        rb_cli_error(NULL, NULL, "option '-j' needs a whole number of threads from 1 "
                     "to 1024 (got '%s')", v);
        return RB_EXIT_USAGE;
    }
    o->threads = (int)n;
    return RB_EXIT_PASS;
}

/* Options only `design` takes; RB_EXIT_INTERNAL when arg is not one. */
static rb_exit design_option(int argc, char **argv, int *i, rb_cli_opts *o)
{
    const char *arg = argv[*i], *val = NULL;
    if (opt_is(arg, "--sweep-csv", &val))
        return take_value(argc, argv, i, "--sweep-csv", val, &o->sweep_csv_path);
    if (opt_is(arg, "--threads", &val) || opt_is(arg, "-j", &val))
        return take_threads(argc, argv, i, val, o);
    if (strncmp(arg, "-j", 2) == 0 && arg[2])
        return take_threads(argc, argv, i, arg + 2, o);
    return RB_EXIT_INTERNAL;
}

/* One option of "check" or "design"; RB_EXIT_USAGE if arg is not one. */
static rb_exit check_option(int argc, char **argv, int *i, rb_cli_opts *o)
{
    const char *arg = argv[*i], *val = NULL;
    const char *cmd = o->command == RB_CMD_DESIGN ? "design" : "check";
    if (o->command == RB_CMD_DESIGN) {
        rb_exit e = design_option(argc, argv, i, o);
        if (e != RB_EXIT_INTERNAL)
            return e;
    }
    if (opt_is(arg, "--json", &val))
        return take_value(argc, argv, i, "--json", val, &o->json_path);
    if (opt_is(arg, "--text", &val))
        return take_value(argc, argv, i, "--text", val, &o->text_path);
    if (opt_is(arg, "--history", &val))
        return take_value(argc, argv, i, "--history", val, &o->history_path);
    if (opt_is(arg, "--svg", &val))
        return take_value(argc, argv, i, "--svg", val, &o->svg_path);
    if (opt_is(arg, "--html", &val))
        return take_value(argc, argv, i, "--html", val, &o->html_path);
    if (opt_is(arg, "--sandbox", &val))
        return take_value(argc, argv, i, "--sandbox", val, &o->sandbox_dir);
    if (strcmp(arg, "--quiet") == 0 || strcmp(arg, "-q") == 0) {
        o->quiet = 1;
        return RB_EXIT_PASS;
    }
    rb_cli_error(NULL, NULL, "unknown option '%s' for '%s' (see rockbolt --help)",
                 arg, cmd);
    return RB_EXIT_USAGE;
}

/* Two outputs, or an output and the case, must not be the same file. */
static rb_exit check_distinct(const rb_cli_opts *o)
{
    const char *p[7] = { o->json_path, o->text_path, o->history_path,
                         o->sweep_csv_path, o->svg_path, o->html_path, o->case_path };
    static const char *const what[7] = { "--json", "--text", "--history",
                                         "--sweep-csv", "--svg", "--html", "the case" };
    int a, b;
    for (a = 0; a < 6; a++)
        for (b = a + 1; b < 7; b++)
            if (p[a] && p[b] && strcmp(p[a], p[b]) == 0) {
                rb_cli_error(p[a], what[a], "same file as %s", what[b]);
                return RB_EXIT_USAGE;
            }
    return RB_EXIT_PASS;
}

/* Positional arguments and options after the command name. */
static rb_exit parse_rest(int argc, char **argv, rb_cli_opts *o)
{
    int takes_case = o->command == RB_CMD_CHECK || o->command == RB_CMD_DESIGN;
    const char **positional = takes_case ? &o->case_path : &o->init_path;
    int i, options_done = 0;
    for (i = 2; i < argc; i++) {
        const char *arg = argv[i];
        rb_exit e = RB_EXIT_PASS;
        if (!options_done && (strcmp(arg, "--help") == 0 || strcmp(arg, "-h") == 0)) {
            o->command = RB_CMD_HELP;
            return RB_EXIT_PASS;
        }
        if (!options_done && strcmp(arg, "--") == 0) {
            options_done = 1;
            continue;
        }
        if (!options_done && arg[0] == '-' && arg[1] != '\0') {
            if (!takes_case) {
                rb_cli_error(NULL, NULL, "unknown option '%s' for 'init' "
                             "(see rockbolt --help)", arg);
                return RB_EXIT_USAGE;
            }
            e = check_option(argc, argv, &i, o);
        } else if (*positional) {
            rb_cli_error(NULL, NULL, "unexpected argument '%s' (see rockbolt --help)",
                         arg);
            return RB_EXIT_USAGE;
        } else {
            *positional = arg;
        }
        if (e != RB_EXIT_PASS)
            return e;
    }
    return RB_EXIT_PASS;
}

rb_exit rb_cli_args_parse(int argc, char **argv, rb_cli_opts *o)
{
    const char *cmd = argc > 1 ? argv[1] : NULL;
    rb_exit e;
    memset(o, 0, sizeof *o);
    if (!cmd) {
        rb_cli_error(NULL, NULL, "no command given (see rockbolt --help)");
        return RB_EXIT_USAGE;
    }
    if (!strcmp(cmd, "--help") || !strcmp(cmd, "-h") || !strcmp(cmd, "help")) {
        o->command = RB_CMD_HELP;
        return RB_EXIT_PASS;
    }
    if (!strcmp(cmd, "--version") || !strcmp(cmd, "-V") || !strcmp(cmd, "version")) {
        o->command = RB_CMD_VERSION;
        return RB_EXIT_PASS;
    }
    if (!strcmp(cmd, "check"))
        o->command = RB_CMD_CHECK;
    else if (!strcmp(cmd, "design"))
        o->command = RB_CMD_DESIGN;
    else if (!strcmp(cmd, "init"))
        o->command = RB_CMD_INIT;
    else {
        rb_cli_error(NULL, NULL, "unknown command '%s' (see rockbolt --help)", cmd);
        return RB_EXIT_USAGE;
    }
    if ((e = parse_rest(argc, argv, o)) != RB_EXIT_PASS || o->command == RB_CMD_HELP)
        return e;
    if (o->command == RB_CMD_INIT) {
        if (!o->init_path)
            o->init_path = "case.yaml";
        return RB_EXIT_PASS;
    }
    if (!o->case_path) {
        const char *c = o->command == RB_CMD_DESIGN ? "design" : "check";
        rb_cli_error(NULL, NULL, "'%s' needs a case file: rockbolt %s CASE.yaml", c, c);
        return RB_EXIT_USAGE;
    }
    if ((e = check_distinct(o)) != RB_EXIT_PASS)
        return e;
    return rb_cli_sandbox(o->sandbox_dir);
}

rb_exit rb_cli_sandbox(const char *dir)
{
    rb_diag d;
    if (!dir)
        return RB_EXIT_PASS;
    if (rb_sandbox_set(dir, &d) != RB_OK) {
        rb_cli_diag_print(&d);
        return RB_EXIT_USAGE;
    }
    return RB_EXIT_PASS;
}
