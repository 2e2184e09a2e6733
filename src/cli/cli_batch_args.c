/* "rockbolt batch" options. Like check's: "--opt VALUE" or "--opt=VALUE",
 * "--" ends the options, every mistake is a usage error (exit 2) found
 * before anything is read or written. */
#include <stdlib.h>
#include <string.h>
#include "cli_batch.h"

static int opt_is(const char *arg, const char *name, const char **inline_val)
{
    size_t n = strlen(name);
    if (strncmp(arg, name, n) != 0)
        return 0;
    if (arg[n] == '\0' || arg[n] == '=') {
        *inline_val = arg[n] == '=' ? arg + n + 1 : NULL;
        return 1;
    }
    return 0;
}

static rb_exit take(int argc, char **argv, int *i, const char *name,
                    const char *inline_val, const char **dst)
{
    const char *v = inline_val;
    if (!v) {
        if (*i + 1 >= argc) {
            rb_cli_error(NULL, NULL, "option '%s' needs a value", name);
            return RB_EXIT_USAGE;
        }
        v = argv[++*i];
    }
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

/* Options shared by batch and merge are the output files and --quiet. */
rb_exit rb_cli_batch_parse(int argc, char **argv, int is_merge, rb_batch_cli *o)
{
    int only_inputs = 0;
    memset(o, 0, sizeof *o);
    rb_outplan_init(&o->plan);
    o->inputs = calloc((size_t)argc + 1, sizeof *o->inputs);
    if (!o->inputs) {
        rb_cli_error(NULL, NULL, "out of memory");
        return RB_EXIT_INTERNAL;
    }
    for (int i = 0; i < argc; i++) {
        const char *a = argv[i], *v = NULL, *jv = NULL, *sv = NULL;
        rb_exit e = RB_EXIT_PASS;
        if (only_inputs || a[0] != '-' || !a[1]) {
            o->inputs[o->n_inputs++] = a;
            continue;
        }
        if (strcmp(a, "--") == 0)
            only_inputs = 1;
        else if (opt_is(a, "--json", &v))
            e = take(argc, argv, &i, "--json", v, &o->json_path);
        else if (opt_is(a, "--csv", &v))
            e = take(argc, argv, &i, "--csv", v, &o->csv_path);
        else if (opt_is(a, "--junit", &v))
            e = take(argc, argv, &i, "--junit", v, &o->junit_path);
        else if (strcmp(a, "-q") == 0 || strcmp(a, "--quiet") == 0)
            o->quiet = 1;
        else if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0)
            o->help = 1;
        else if (!is_merge && opt_is(a, "--reports", &v))
            e = take(argc, argv, &i, "--reports", v, &o->reports_dir);
        else if (!is_merge && opt_is(a, "--base", &v))
            e = take(argc, argv, &i, "--base", v, &o->base);
        else if (!is_merge && opt_is(a, "--sandbox", &v))
            e = take(argc, argv, &i, "--sandbox", v, &o->sandbox);
        else if (!is_merge && strcmp(a, "--design") == 0)
            o->design = 1;
        else if (!is_merge && opt_is(a, "--shard", &v)) {
            e = take(argc, argv, &i, "--shard", v, &sv);
            if (e == RB_EXIT_PASS)
                e = parse_shard(sv, o);
        } else if (!is_merge && (strncmp(a, "-j", 2) == 0 || opt_is(a, "--threads", &v))) {
            long n;
            if (a[1] == 'j' && a[2])
                v = a + 2;   /* -j4 */
            e = take(argc, argv, &i, "-j", v, &jv);
            if (e == RB_EXIT_PASS && !whole(jv, 1, 1024, &n)) {
                rb_cli_error(NULL, "-j", "expected a whole number of threads from 1 "
                             "to 1024, found '%s'", jv);
                e = RB_EXIT_USAGE;
            }
            if (e == RB_EXIT_PASS)
                o->threads = (int)n;
        } else {
            rb_cli_error(NULL, NULL, "unknown option '%s' (see 'rockbolt --help')", a);
            e = RB_EXIT_USAGE;
        }
        if (e != RB_EXIT_PASS)
            return e;
    }
    if (!o->help && o->n_inputs == 0) {
        rb_cli_error(NULL, NULL, is_merge ? "merge needs the JSON summaries of the "
                     "shards" : "batch needs case files, directories or equipment "
                     "lists (see 'rockbolt --help')");
        return RB_EXIT_USAGE;
    }
    return rb_cli_sandbox(o->sandbox);
}

void rb_cli_batch_cli_free(rb_batch_cli *o)
{
    free(o->inputs);
    o->inputs = NULL;
    rb_outplan_free(&o->plan);
}
