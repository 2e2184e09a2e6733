/* The option loop of every command, on glibc's getopt_long: options and
 * operands in any order, "--opt VALUE" or "--opt=VALUE", "-j4", "--" ends
 * the options, "-" is an operand. Unlike plain getopt_long, a long option
 * must be spelled out (an abbreviation is an unknown option with a "did
 * you mean"), and no message is printed by getopt itself. */
#include <getopt.h>
#include <stdio.h>
#include <string.h>
#include "cli.h"

void rb_cli_getopt_init(rb_cli_getopt *g, const char *cmd, int argc, char **argv,
                        const char *shorts, const struct option *longs)
{
    memset(g, 0, sizeof *g);
    g->cmd = cmd;
    g->argc = argc;
    g->argv = argv;
    /* '-': operands come back in order as 1; ':' a missing value as ':' */
    snprintf(g->optstring, sizeof g->optstring, "-:%s", shorts);
    g->longs = longs;
    optind = 0;   /* glibc: start afresh */
    opterr = 0;
}

/* The option as written: "--json", "-j". */
static void name_of(rb_cli_getopt *g, int c, int idx)
{
    if (idx >= 0)
        snprintf(g->name, sizeof g->name, "--%s", g->longs[idx].name);
    else
        snprintf(g->name, sizeof g->name, "-%c", c);
}

int rb_cli_getopt_next(rb_cli_getopt *g)
{
    int idx = -1, c;
    g->arg = NULL;
    if (g->rest) {
        if (optind < g->argc) {
            g->arg = g->argv[optind++];
            return 1;
        }
        return -1;
    }
    c = getopt_long(g->argc, g->argv, g->optstring, g->longs, &idx);
    if (c == -1) {
        /* "--" or the end: what is left is operands */
        g->rest = 1;
        return rb_cli_getopt_next(g);
    }
    if (c == 1) {
        g->arg = optarg;
        return 1;
    }
    if (c == '?') {
        const char *tok = g->argv[optind - 1];
        char buf[8];
        if (optopt && !(tok[0] == '-' && tok[1] == '-')) {
            snprintf(buf, sizeof buf, "-%c", optopt);
            tok = buf;
        }
        rb_cli_unknown_option(g->cmd, tok);
        return '?';
    }
    if (c == ':') {
        const char *tok = g->argv[optind - 1];
        if (tok[0] == '-' && tok[1] == '-')
            snprintf(g->name, sizeof g->name, "%.*s", (int)strcspn(tok, "="), tok);
        else
            snprintf(g->name, sizeof g->name, "-%c", optopt);
        return ':';
    }
    name_of(g, c, idx);
    if (idx >= 0) {
        /* the token getopt matched: refuse "--jso" for "--json" */
        int sep = g->longs[idx].has_arg != no_argument && optarg
                  && optarg == g->argv[optind - 1] && optind >= 2;
        const char *tok = g->argv[optind - 1 - sep];
        size_t n = strlen(g->name);
        if (strncmp(tok, g->name, n) != 0 || (tok[n] != '\0' && tok[n] != '=')) {
            rb_cli_unknown_option(g->cmd, tok);
            return '?';
        }
    }
    g->arg = optarg;
    return c;
}
