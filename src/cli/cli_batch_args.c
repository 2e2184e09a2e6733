/* "rockbolt batch" and "rockbolt merge" options, with getopt_long
 * (cli_getopt.c). Like check's: "--opt VALUE" or "--opt=VALUE", "--" ends
 * the options, every mistake is a usage error (exit 2) found before
 * anything is read or written. Documented in src/cli/help.txt. */
#include <iconv.h>
#include <stdlib.h>
#include <string.h>
#include "cli_batch.h"

static rb_exit take(const char *name, const char *v, const char **dst)
{
    if (!v[0]) {
        rb_cli_error(NULL, NULL, "option '%s' needs a non-empty value", name);
        return RB_EXIT_USAGE;
    }
    if (*dst) {
        rb_cli_error(NULL, NULL, "option '%s' given twice", name);
        return RB_EXIT_USAGE;
    }
    *dst = v;
    return RB_EXIT_PASS;
}

/* A whole number in [lo, hi] from the whole of s. */
static int whole(const char *s, long lo, long hi, long *out)
{
    char *end;
    if (!s[0] || s[0] == '+' || s[0] == '-' || s[0] == ' ')
        return 0;
    long v = strtol(s, &end, 10);
    if (*end || v < lo || v > hi)
        return 0;
    *out = v;
    return 1;
}

static rb_exit parse_shard(const char *v, rb_batch_cli *o)
{
    char buf[64];
    long i, n;
    const char *slash = strchr(v, '/');
    if (slash && (size_t)(slash - v) < sizeof buf) {
        memcpy(buf, v, (size_t)(slash - v));
        buf[slash - v] = '\0';
        if (whole(buf, 1, 1000000, &i) && whole(slash + 1, 1, 1000000, &n) && i <= n) {
            o->shard = (size_t)i;
            o->n_shards = (size_t)n;
            return RB_EXIT_PASS;
        }
    }
    rb_cli_error(NULL, "--shard", "expected I/N with 1 <= I <= N (e.g. 3/8), "
                 "found '%s'", v);
    return RB_EXIT_USAGE;
}

enum { OPT_JSON = 256, OPT_CSV, OPT_JUNIT, OPT_REPORTS, OPT_BASE, OPT_SANDBOX,
       OPT_DESIGN, OPT_SHARD, OPT_ENCODING, OPT_FRAGILITY, OPT_SEED, OPT_INTENSITY,
       OPT_P58, OPT_PDF };

/* Options shared by batch and merge are the output files and --quiet. */
static const struct option merge_longs[] = {
    {"json", required_argument, NULL, OPT_JSON},
    {"csv", required_argument, NULL, OPT_CSV},
    {"junit", required_argument, NULL, OPT_JUNIT},
    {"quiet", no_argument, NULL, 'q'},
    {"help", no_argument, NULL, 'h'},
    {NULL, 0, NULL, 0}
};
static const struct option batch_longs[] = {
    {"json", required_argument, NULL, OPT_JSON},
    {"csv", required_argument, NULL, OPT_CSV},
    {"junit", required_argument, NULL, OPT_JUNIT},
    {"reports", required_argument, NULL, OPT_REPORTS},
    {"base", required_argument, NULL, OPT_BASE},
    {"sandbox", required_argument, NULL, OPT_SANDBOX},
    {"encoding", required_argument, NULL, OPT_ENCODING},
    {"design", no_argument, NULL, OPT_DESIGN},
    {"fragility", no_argument, NULL, OPT_FRAGILITY},
    {"p58", required_argument, NULL, OPT_P58},
    {"pdf", required_argument, NULL, OPT_PDF},
    {"seed", required_argument, NULL, OPT_SEED},
    {"intensity", required_argument, NULL, OPT_INTENSITY},
    {"shard", required_argument, NULL, OPT_SHARD},
    {"threads", required_argument, NULL, 'j'},
    {"quiet", no_argument, NULL, 'q'},
    {"help", no_argument, NULL, 'h'},
    {NULL, 0, NULL, 0}
};

static rb_exit take_option(int c, const rb_cli_getopt *g, rb_batch_cli *o)
{
    const char *sv = NULL;
    long n;
    rb_exit e;
    switch (c) {
    case OPT_JSON:
        return take(g->name, g->arg, &o->json_path);
    case OPT_CSV:
        return take(g->name, g->arg, &o->csv_path);
    case OPT_JUNIT:
        return take(g->name, g->arg, &o->junit_path);
    case OPT_P58:
        return take(g->name, g->arg, &o->p58_path);
    case OPT_PDF:
        return take(g->name, g->arg, &o->pdf_path);
    case OPT_REPORTS:
        return take(g->name, g->arg, &o->reports_dir);
    case OPT_BASE:
        return take(g->name, g->arg, &o->base);
    case OPT_SANDBOX:
        return take(g->name, g->arg, &o->sandbox_dir);
    case OPT_ENCODING:
        e = take(g->name, g->arg, &o->encoding);
        if (e == RB_EXIT_PASS) {
            /* a name iconv does not know is a usage error, found now */
            iconv_t cd = iconv_open("UTF-8", o->encoding);
            if (cd == (iconv_t)-1) {
                rb_cli_error(NULL, "--encoding", "unknown encoding '%s' (give an "
                             "iconv name such as cp1252, latin1 or utf-16; "
                             "'iconv -l' lists them)", o->encoding);
                return RB_EXIT_USAGE;
            }
            iconv_close(cd);
        }
        return e;
    case OPT_DESIGN:
        o->design = 1;
        return RB_EXIT_PASS;
    case OPT_FRAGILITY:
        o->fragility = 1;
        return RB_EXIT_PASS;
    case OPT_SEED:
        if (o->seed_given) {
            rb_cli_error(NULL, NULL, "option '--seed' given twice");
            return RB_EXIT_USAGE;
        }
        o->seed_given = 1;
        return rb_cli_take_seed(g->arg, &o->seed);
    case OPT_INTENSITY:
        return rb_cli_take_intensity(g->arg, &o->intensity, &o->intensity_given);
    case OPT_SHARD:
        e = take(g->name, g->arg, &sv);
        return e == RB_EXIT_PASS ? parse_shard(sv, o) : e;
    case 'j':
        if (!g->arg[0]) {
            rb_cli_error(NULL, NULL, "option '-j' needs a non-empty value");
            return RB_EXIT_USAGE;
        }
        if (!whole(g->arg, 1, 1024, &n)) {
            rb_cli_error(NULL, "-j", "expected a whole number of threads from 1 "
                         "to 1024, found '%s'", g->arg);
            return RB_EXIT_USAGE;
        }
        o->threads = (int)n;
        return RB_EXIT_PASS;
    case 'q':
        o->quiet = 1;
        return RB_EXIT_PASS;
    case 'h':
        o->help = 1;
        return RB_EXIT_PASS;
    default:
        rb_cli_error(NULL, NULL, "option '%s' is not handled (a bug)", g->name);
        return RB_EXIT_INTERNAL;
    }
}

rb_exit rb_cli_batch_parse(int argc, char **argv, int is_merge, rb_batch_cli *o)
{
    const char *cmd = is_merge ? "merge" : "batch";
    rb_cli_getopt g;
    char **av;
    int c;
    rb_exit e = RB_EXIT_PASS;
    memset(o, 0, sizeof *o);
    rb_outplan_init(&o->plan);
    o->inputs = calloc((size_t)argc + 1, sizeof *o->inputs);
    /* getopt wants the program in argv[0]: the command word stands in */
    av = calloc((size_t)argc + 2, sizeof *av);
    if (!o->inputs || !av) {
        free(av);
        rb_cli_error(NULL, NULL, "out of memory");
        return RB_EXIT_INTERNAL;
    }
    av[0] = (char *)cmd;
    memcpy(av + 1, argv, (size_t)argc * sizeof *av);
    if (is_merge)
        rb_cli_getopt_init(&g, cmd, argc + 1, av, "qh", merge_longs);
    else
        rb_cli_getopt_init(&g, cmd, argc + 1, av, "qhj:", batch_longs);
    while (e == RB_EXIT_PASS && (c = rb_cli_getopt_next(&g)) != -1) {
        if (c == 1)
            o->inputs[o->n_inputs++] = g.arg;
        else if (c == '?')
            e = RB_EXIT_USAGE;
        else if (c == ':') {
            rb_cli_error(NULL, NULL, "option '%s' needs a value",
                         strcmp(g.name, "--threads") == 0 ? "-j" : g.name);
            e = RB_EXIT_USAGE;
        } else
            e = take_option(c, &g, o);
    }
    free(av);
    if (e != RB_EXIT_PASS)
        return e;
    if (!o->help && o->seed_given && !o->fragility) {
        rb_cli_error(NULL, "--seed", "the seed of the fragility's bootstrap needs "
                     "--fragility");
        return RB_EXIT_USAGE;
    }
    if (!o->help && o->intensity_given && !o->fragility) {
        rb_cli_error(NULL, "--intensity", "the intensity of the fragility needs "
                     "--fragility");
        return RB_EXIT_USAGE;
    }
    if (!o->help && o->p58_path && !o->fragility) {
        rb_cli_error(NULL, "--p58", "the FEMA P-58 rows are each case's fragility: "
                     "they need --fragility");
        return RB_EXIT_USAGE;
    }
    if (!o->help && o->p58_path && o->intensity == RB_IM_SA) {
        rb_cli_error(NULL, "--p58", "FEMA P-58's fragilities are in the peak floor "
                     "acceleration: not with --intensity sa");
        return RB_EXIT_USAGE;
    }
    if (!o->help && o->n_inputs == 0) {
        rb_cli_error(NULL, NULL, is_merge ? "merge needs the JSON summaries of the "
                     "shards (see 'rockbolt help merge')" : "batch needs case files, "
                     "directories or equipment lists (see 'rockbolt help batch')");
        return RB_EXIT_USAGE;
    }
    return rb_cli_sandbox(o->sandbox_dir, &o->sandbox);
}

void rb_cli_batch_cli_free(rb_batch_cli *o)
{
    free(o->inputs);
    o->inputs = NULL;
    rb_outplan_free(&o->plan);
    rb_cli_stream_close(o);
}
