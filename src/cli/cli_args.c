/* Command-line parsing: "rockbolt COMMAND [ARGS] [OPTIONS]", with
 * getopt_long (cli_getopt.c).
 *
 * Options may come before or after the case file, as "--json FILE" or
 * "--json=FILE"; "--" ends the options. Every mistake is a usage error
 * (exit 2) with one line naming the offending argument, and is found
 * before anything is read or written. The options are documented in
 * src/cli/help.txt, which --help and the man page are made from. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "rockbolt/plot.h"
#include "rockbolt/run.h"
#include "rockbolt/sandbox.h"

/* Store the value of a FILE option, once, not empty. */
static rb_exit take_value(const char *name, const char *v, const char **dst)
{
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

rb_exit rb_cli_take_seed(const char *v, unsigned long long *out)
{
    char *end;
    errno = 0;
    unsigned long long n = strtoull(v, &end, 10);
    if (end == v || *end || errno || v[0] == '-') {
        rb_cli_error(NULL, NULL, "option '--seed' needs a whole number from 0 to "
                     "18446744073709551615 (got '%s')", v);
        return RB_EXIT_USAGE;
    }
    *out = n;
    return RB_EXIT_PASS;
}

rb_exit rb_cli_take_intensity(const char *v, rb_fragility_intensity *out, int *given)
{
    int im;
    if (*given) {
        rb_cli_error(NULL, NULL, "option '--intensity' given twice");
        return RB_EXIT_USAGE;
    }
    if (!rb_enum_parse(rb_intensity_names, v, &im)) {
        rb_cli_error(NULL, NULL, "option '--intensity' needs pfa or sa (got '%s')", v);
        return RB_EXIT_USAGE;
    }
    *out = (rb_fragility_intensity)im;
    *given = 1;
    return RB_EXIT_PASS;
}

/* A finite number making up the whole of s. */
static int number(const char *s, double *out)
{
    char *end;
    errno = 0;
    *out = strtod(s, &end);
    return end != s && !*end && !errno && isfinite(*out);
}

/* --sweep-gap FROM:TO:STEP: the gap ratios FROM, FROM + STEP, ... up to TO
 * (included when it is on the grid, as design's gap grid). Each is
 * rounded to 12 significant digits, so that 0.002 + 28 x 0.001 is the
 * 0.03 a case file would give, not 0.030000000000000002. */
static rb_exit take_sweep_gap(const char *v, rb_cli_opts *o)
{
    char buf[128];
    const char *c1 = strchr(v, ':'), *c2 = c1 ? strchr(c1 + 1, ':') : NULL;
    double from = 0, to = 0, step = 0;
    int ok = c1 && c2 && strlen(v) < sizeof buf;
    if (o->sweep_gap) {
        rb_cli_error(NULL, NULL, "option '--sweep-gap' given twice");
        return RB_EXIT_USAGE;
    }
    if (ok) {
        memcpy(buf, v, strlen(v) + 1);
        buf[c1 - v] = buf[c2 - v] = '\0';
        ok = number(buf, &from) && number(buf + (c1 - v) + 1, &to)
             && number(buf + (c2 - v) + 1, &step)
             && from >= 0 && to > from && to <= 1 && step > 0;
    }
    if (!ok) {
        rb_cli_error(NULL, NULL, "option '--sweep-gap' needs FROM:TO:STEP, gap ratios of "
                     "the lever arm with 0 <= FROM < TO <= 1 and STEP > 0, e.g. "
                     "0.002:0.03:0.002 (got '%s')", v);
        return RB_EXIT_USAGE;
    }
    double n = floor((to - from) / step + 1e-9) + 1;
    if (n < 2 || n > RB_FRAGILITY_SWEEP_MAX_POINTS) {
        rb_cli_error(NULL, NULL, "option '--sweep-gap' gives %.0f gap ratio%s from %g to %g "
                     "in steps of %g; it takes 2 to %d (each is a whole fragility)", n,
                     n == 1 ? "" : "s", from, to, step, RB_FRAGILITY_SWEEP_MAX_POINTS);
        return RB_EXIT_USAGE;
    }
    o->sweep_gap = v;
    o->n_gap_ratios = (size_t)n;
    for (size_t i = 0; i < o->n_gap_ratios; i++) {
        char r[32];
        snprintf(r, sizeof r, "%.12g", from + (double)i * step);
        o->gap_ratios[i] = strtod(r, NULL);
    }
    return RB_EXIT_PASS;
}

/* -j N / --threads N: a whole number from 1 to 1024. */
static rb_exit take_threads(const char *v, rb_cli_opts *o)
{
    char *end;
    long n = strtol(v, &end, 10);
    if (end == v || *end || n < 1 || n > 1024) {
        rb_cli_error(NULL, NULL, "option '-j' needs a whole number of threads from 1 "
                     "to 1024 (got '%s')", v);
        return RB_EXIT_USAGE;
    }
    o->threads = (int)n;
    return RB_EXIT_PASS;
}

enum { OPT_JSON = 256, OPT_TEXT, OPT_HISTORY, OPT_SVG, OPT_HTML, OPT_SANDBOX,
       OPT_SWEEP_CSV, OPT_CSV, OPT_SEED, OPT_DAMPING, OPT_FROM, OPT_TO, OPT_PER_OCTAVE,
       OPT_AC156, OPT_X_SCALE, OPT_SWEEP_GAP, OPT_INTENSITY, OPT_P58, OPT_PDF, OPT_DIR };

/* Every long option once, with the commands that take it: each command's
 * table is drawn from this one, so an option means the same everywhere. */
#define CHECK (1u << RB_CMD_CHECK)
#define DESIGN (1u << RB_CMD_DESIGN)
#define FRAGILITY (1u << RB_CMD_FRAGILITY)
#define INIT (1u << RB_CMD_INIT)
#define SPECTRUM (1u << RB_CMD_SPECTRUM)
#define MOTION (1u << RB_CMD_MOTION)
static const struct {
    struct option o;
    unsigned commands;
} all_longs[] = {
    {{"json", required_argument, NULL, OPT_JSON},
     CHECK | DESIGN | FRAGILITY | SPECTRUM | MOTION},
    {{"text", required_argument, NULL, OPT_TEXT}, CHECK | DESIGN},
    {{"history", required_argument, NULL, OPT_HISTORY}, CHECK | DESIGN},
    {{"svg", required_argument, NULL, OPT_SVG},
     CHECK | DESIGN | FRAGILITY | SPECTRUM | MOTION},
    {{"html", required_argument, NULL, OPT_HTML},
     CHECK | DESIGN | FRAGILITY | SPECTRUM | MOTION},
    {{"pdf", required_argument, NULL, OPT_PDF}, CHECK | DESIGN | FRAGILITY},
    {{"csv", required_argument, NULL, OPT_CSV}, FRAGILITY | SPECTRUM},
    {{"p58", required_argument, NULL, OPT_P58}, FRAGILITY},
    {{"dir", required_argument, NULL, OPT_DIR}, MOTION},
    {{"sandbox", required_argument, NULL, OPT_SANDBOX},
     CHECK | DESIGN | FRAGILITY | SPECTRUM | MOTION},
    {{"sweep-csv", required_argument, NULL, OPT_SWEEP_CSV}, DESIGN},
    {{"seed", required_argument, NULL, OPT_SEED}, FRAGILITY},
    {{"damping", required_argument, NULL, OPT_DAMPING}, SPECTRUM},
    {{"from", required_argument, NULL, OPT_FROM}, SPECTRUM},
    {{"to", required_argument, NULL, OPT_TO}, SPECTRUM},
    {{"per-octave", required_argument, NULL, OPT_PER_OCTAVE}, SPECTRUM},
    {{"ac156", no_argument, NULL, OPT_AC156}, INIT},
    {{"x-scale", required_argument, NULL, OPT_X_SCALE}, FRAGILITY},
    {{"sweep-gap", required_argument, NULL, OPT_SWEEP_GAP}, FRAGILITY},
    {{"intensity", required_argument, NULL, OPT_INTENSITY}, FRAGILITY},
    {{"threads", required_argument, NULL, 'j'}, DESIGN | FRAGILITY},
    {{"quiet", no_argument, NULL, 'q'}, CHECK | DESIGN | FRAGILITY | SPECTRUM | MOTION},
    {{"help", no_argument, NULL, 'h'},
     CHECK | DESIGN | FRAGILITY | INIT | SPECTRUM | MOTION},
};
#define N_LONGS (sizeof all_longs / sizeof all_longs[0])

/* The long options of a command into longs (ended by a zero entry) and
 * the short ones (-q, -j N, -h) it takes into shorts. */
static void options_of(rb_cli_command cmd, struct option longs[N_LONGS + 1],
                       char shorts[8])
{
    size_t n = 0, k = 0;
    for (size_t i = 0; i < N_LONGS; i++) {
        if (!(all_longs[i].commands & (1u << cmd)))
            continue;
        longs[n++] = all_longs[i].o;
        if (all_longs[i].o.val == 'q' || all_longs[i].o.val == 'h')
            shorts[k++] = (char)all_longs[i].o.val;
        else if (all_longs[i].o.val == 'j')
            shorts[k++] = 'j', shorts[k++] = ':';
    }
    longs[n] = (struct option){NULL, 0, NULL, 0};
    shorts[k] = '\0';
}

/* A quantity option of spectrum: a number with or without its unit
 * ("5 %", "0.05"; "0.5 Hz", "0.5"), within [lo, hi]. */
static rb_exit take_quantity(const char *name, const char *v, rb_dim dim, double lo,
                             double hi, const char *expected, double *out)
{
    rb_quantity q;
    char msg[200], *end;
    double x;
    if (rb_unit_parse(v, dim, &q, msg, sizeof msg) == RB_OK && !q.relative_a_star)
        x = q.value;
    else if ((x = strtod(v, &end)), end == v || *end)
        x = NAN;
    if (!(x >= lo && x <= hi)) {
        rb_cli_error(NULL, NULL, "option '%s' needs %s (got '%s')", name, expected, v);
        return RB_EXIT_USAGE;
    }
    *out = x;
    return RB_EXIT_PASS;
}

/* One option of check, design or init (already known to the table). */
static rb_exit take_option(int c, const rb_cli_getopt *g, rb_cli_opts *o)
{
    switch (c) {
    case OPT_JSON:
        return take_value(g->name, g->arg, &o->json_path);
    case OPT_TEXT:
        return take_value(g->name, g->arg, &o->text_path);
    case OPT_HISTORY:
        return take_value(g->name, g->arg, &o->history_path);
    case OPT_SVG:
        return take_value(g->name, g->arg, &o->svg_path);
    case OPT_HTML:
        return take_value(g->name, g->arg, &o->html_path);
    case OPT_SANDBOX:
        return take_value(g->name, g->arg, &o->sandbox_dir);
    case OPT_SWEEP_CSV:
        return take_value(g->name, g->arg, &o->sweep_csv_path);
    case OPT_CSV:
        return take_value(g->name, g->arg, &o->csv_path);
    case OPT_P58:
        return take_value(g->name, g->arg, &o->p58_path);
    case OPT_PDF:
        return take_value(g->name, g->arg, &o->pdf_path);
    case OPT_DIR:
        return take_value(g->name, g->arg, &o->dir_path);
    case OPT_SEED:
        return rb_cli_take_seed(g->arg, &o->seed);
    case OPT_SWEEP_GAP:
        return take_sweep_gap(g->arg, o);
    case OPT_INTENSITY:
        return rb_cli_take_intensity(g->arg, &o->intensity, &o->intensity_given);
    case OPT_X_SCALE: {
        int v;
        if (o->x_scale_given) {
            rb_cli_error(NULL, NULL, "option '--x-scale' given twice");
            return RB_EXIT_USAGE;
        }
        if (!rb_enum_parse(rb_plot_scale_names, g->arg, &v)) {
            rb_cli_error(NULL, NULL, "option '--x-scale' needs log or linear (got '%s')",
                         g->arg);
            return RB_EXIT_USAGE;
        }
        o->x_scale = (rb_plot_scale)v;
        o->x_scale_given = 1;
        return RB_EXIT_PASS;
    }
    case OPT_DAMPING:
        return take_quantity(g->name, g->arg, RB_DIM_RATIO, 0, 0.99,
                             "a damping ratio from 0 to 99 %, e.g. '5 %' or 0.05",
                             &o->spectrum.damping);
    case OPT_FROM:
        return take_quantity(g->name, g->arg, RB_DIM_FREQUENCY, RB_SPECTRUM_MIN_HZ,
                             RB_SPECTRUM_MAX_HZ,
                             "a frequency from 0.001 to 10000 Hz, e.g. '0.5 Hz'",
                             &o->spectrum.f_min_hz);
    case OPT_TO:
        return take_quantity(g->name, g->arg, RB_DIM_FREQUENCY, RB_SPECTRUM_MIN_HZ,
                             RB_SPECTRUM_MAX_HZ,
                             "a frequency from 0.001 to 10000 Hz, e.g. '50 Hz'",
                             &o->spectrum.f_max_hz);
    case OPT_PER_OCTAVE:
        return take_quantity(g->name, g->arg, RB_DIM_RATIO, 1, 96,
                             "a number of points per octave from 1 to 96",
                             &o->spectrum.per_octave);
    case OPT_AC156:
        o->init_ac156 = 1;
        return RB_EXIT_PASS;
    case 'j':
        return take_threads(g->arg, o);
    case 'q':
        o->quiet = 1;
        return RB_EXIT_PASS;
    default:
        rb_cli_error(NULL, NULL, "option '%s' is not handled (a bug)", g->name);
        return RB_EXIT_INTERNAL;
    }
}

/* Two outputs, or an output and the case, must not be the same file. */
static rb_exit check_distinct(const rb_cli_opts *o)
{
    const char *p[10] = { o->json_path, o->text_path, o->history_path,
                          o->sweep_csv_path, o->svg_path, o->html_path, o->csv_path,
                          o->p58_path, o->pdf_path, o->case_path };
    static const char *const what[10] = { "--json", "--text", "--history",
                                          "--sweep-csv", "--svg", "--html", "--csv",
                                          "--p58", "--pdf", "the case" };
    int a, b;
    for (a = 0; a < 9; a++)
        for (b = a + 1; b < 10; b++)
            if (p[a] && p[b] && strcmp(p[a], p[b]) == 0) {
                rb_cli_error(p[a], what[a], "same file as %s", what[b]);
                return RB_EXIT_USAGE;
            }
    return RB_EXIT_PASS;
}

/* Operands and options after the command name. */
static rb_exit parse_rest(int argc, char **argv, rb_cli_opts *o)
{
    int takes_case = o->command == RB_CMD_CHECK || o->command == RB_CMD_DESIGN
                     || o->command == RB_CMD_FRAGILITY || o->command == RB_CMD_SPECTRUM
                     || o->command == RB_CMD_MOTION;
    const char **positional = takes_case ? &o->case_path : &o->init_path;
    const char *cmd = argv[1];
    rb_cli_getopt g;
    int c;
    struct option longs[N_LONGS + 1];
    char shorts[8];
    options_of(o->command, longs, shorts);
    rb_cli_getopt_init(&g, cmd, argc - 1, argv + 1, shorts, longs);
    while ((c = rb_cli_getopt_next(&g)) != -1) {
        rb_exit e = RB_EXIT_PASS;
        if (c == '?')
            return RB_EXIT_USAGE;
        if (c == ':') {
            rb_cli_error(NULL, NULL, "option '%s' needs %s", g.name,
                         strcmp(g.name, "-j") == 0 || strcmp(g.name, "--threads") == 0
                         ? "a number of threads"
                         : strcmp(g.name, "--seed") == 0 ? "a whole number"
                         : strcmp(g.name, "--x-scale") == 0 ? "log or linear"
                         : strcmp(g.name, "--intensity") == 0 ? "pfa or sa"
                         : strcmp(g.name, "--sweep-gap") == 0 ? "FROM:TO:STEP"
                         : strcmp(g.name, "--dir") == 0 ? "a directory"
                         : o->command == RB_CMD_SPECTRUM && strcmp(g.name, "--json")
                           && strcmp(g.name, "--csv") && strcmp(g.name, "--svg")
                           && strcmp(g.name, "--html") && strcmp(g.name, "--sandbox")
                         ? "a value" : "a file name");
            return RB_EXIT_USAGE;
        }
        if (c == 'h') {
            o->command = RB_CMD_HELP;
            o->help_command = cmd;
            return RB_EXIT_PASS;
        }
        if (c != 1) {
            e = take_option(c, &g, o);
        } else if (*positional) {
            rb_cli_error(NULL, NULL, "unexpected argument '%s' (see 'rockbolt help %s')",
                         g.arg, cmd);
            return RB_EXIT_USAGE;
        } else {
            *positional = g.arg;
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
    rb_spectrum_opts_init(&o->spectrum);
    static const char *const commands[] = {"check", "design", "batch", "merge",
                                           "init", "fragility", "spectrum", "motion", "help",
                                           "version",
                                           NULL};
    if (!cmd) {
        rb_cli_error(NULL, NULL, "no command given (see rockbolt --help)");
        return RB_EXIT_USAGE;
    }
    if (!strcmp(cmd, "--help") || !strcmp(cmd, "-h")) {
        o->command = RB_CMD_HELP;
        return RB_EXIT_PASS;
    }
    if (!strcmp(cmd, "help")) {
        /* "rockbolt help [COMMAND]" */
        if (argc > 3) {
            rb_cli_error(NULL, NULL, "unexpected argument '%s' (see 'rockbolt help')",
                         argv[3]);
            return RB_EXIT_USAGE;
        }
        o->command = RB_CMD_HELP;
        o->help_command = argc > 2 ? argv[2] : NULL;
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
    else if (!strcmp(cmd, "fragility"))
        o->command = RB_CMD_FRAGILITY;
    else if (!strcmp(cmd, "spectrum"))
        o->command = RB_CMD_SPECTRUM;
    else if (!strcmp(cmd, "motion"))
        o->command = RB_CMD_MOTION;
    else {
        rb_cli_unknown_word("command", cmd, commands, NULL);
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
        const char *c = o->command == RB_CMD_DESIGN ? "design"
                        : o->command == RB_CMD_FRAGILITY ? "fragility"
                        : o->command == RB_CMD_SPECTRUM ? "spectrum"
                        : o->command == RB_CMD_MOTION ? "motion" : "check";
        rb_cli_error(NULL, NULL, "'%s' needs a case file: rockbolt %s CASE.yaml", c, c);
        return RB_EXIT_USAGE;
    }
    if (o->sweep_gap && o->x_scale_given) {
        rb_cli_error(NULL, NULL, "option '--x-scale' sets the intensity axis of the "
                     "fragility figure; the figure of --sweep-gap has the gap ratio along "
                     "x");
        return RB_EXIT_USAGE;
    }
    /* a loss tool's row is one fragility in peak floor acceleration */
    if (o->p58_path && (o->sweep_gap || o->intensity == RB_IM_SA)) {
        rb_cli_error(NULL, "--p58", "FEMA P-58's fragilities are in the peak floor "
                     "acceleration, one a component: not with %s",
                     o->sweep_gap ? "--sweep-gap" : "--intensity sa");
        return RB_EXIT_USAGE;
    }
    if ((e = check_distinct(o)) != RB_EXIT_PASS)
        return e;
    return rb_cli_sandbox(o->sandbox_dir, &o->sandbox);
}

rb_exit rb_cli_sandbox(const char *dir, rb_sandbox *sb)
{
    rb_diag d;
    if (rb_sandbox_open(sb, dir, &d) != RB_OK) {
        rb_cli_diag_print(&d);
        return RB_EXIT_USAGE;
    }
    return RB_EXIT_PASS;
}
