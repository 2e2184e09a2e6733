/* "rockbolt fragility CASE.yaml": the case's fragility over its motions
 * (rb_run_fragility), or with --sweep-gap at each gap ratio of a sweep
 * (rb_run_fragility_gap_sweep), as a table on stdout and, when asked,
 * JSON, CSV, an SVG figure and a page, all planned and checked before the
 * searches and written all or none. Exit 0 when it is computed (a
 * fragility is not a verdict). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "cli_batch.h"
#include "rockbolt/outplan.h"
#include "rockbolt/plot.h"
#include "rockbolt/run.h"

typedef struct {
    const rb_case *c;
    const rb_case_fragility *f;      /* the fragility, or */
    const rb_fragility_sweep *sweep; /* the sweep over gap ratios */
    rb_plot_scale x_scale;
} outputs;

static char *text_of(const void *ctx)
{
    const outputs *o = ctx;
    return o->sweep ? rb_fragility_sweep_render_text(o->c, o->sweep)
                    : rb_fragility_render_text(o->c, o->f);
}

static char *json_of(const void *ctx)
{
    const outputs *o = ctx;
    return o->sweep ? rb_fragility_sweep_render_json(o->c, o->sweep)
                    : rb_fragility_render_json(o->c, o->f);
}

static char *csv_of(const void *ctx)
{
    const outputs *o = ctx;
    return o->sweep ? rb_fragility_sweep_render_csv(o->sweep)
                    : rb_fragility_render_csv(o->c, o->f);
}

static char *p58_of(const void *ctx)
{
    const outputs *o = ctx;
    return rb_fragility_render_p58(o->c, o->f);
}

static rb_status figure(const void *ctx, const char *title, char **out, rb_diag *d)
{
    const outputs *o = ctx;
    return o->sweep ? rb_plot_fragility_sweep_svg(o->sweep, title, out, d)
                    : rb_plot_fragility_svg(o->f, title, o->x_scale, out, d);
}

static rb_exit compute(const rb_cli_opts *o, const rb_case *c, rb_case_fragility *f,
                       rb_fragility_sweep *sweep)
{
    rb_cli_progress line;
    rb_diag d;
    rb_status st;
    rb_diag_clear(&d);
    rb_cli_progress_start(&line, o->quiet);
    /* an intensity the case cannot have is refused before the searches */
    st = rb_run_fragility_intensity_ok(c, o->intensity, &d);
    if (st == RB_OK && o->sweep_gap)
        st = rb_run_fragility_gap_sweep(c, o->gap_ratios, o->n_gap_ratios, o->threads,
                                        o->seed, RB_FRAGILITY_RESAMPLES, sweep, &d,
                                        line.enabled ? rb_cli_progress_design : NULL, &line);
    else if (st == RB_OK)
        st = rb_run_fragility(c, o->threads, o->seed, RB_FRAGILITY_RESAMPLES, f, &d,
                              line.enabled ? rb_cli_progress_design : NULL, &line);
    if (st == RB_OK)
        st = o->sweep_gap ? rb_run_fragility_sweep_intensity(c, o->intensity, sweep, &d)
                          : rb_run_fragility_intensity(c, o->intensity, f, &d);
    if (line.enabled && line.shown)
        fputs("\r\033[K", stderr);
    if (st == RB_OK)
        return RB_EXIT_PASS;
    /* a ratio of the sweep that the case cannot take is the option's fault */
    const char *key = o->sweep_gap && strcmp(d.key, "gap_ratio") == 0 ? "--sweep-gap"
                      : d.key[0] ? d.key : NULL;
    rb_cli_error(o->case_path, key, "%s%s%s", rb_status_str(st), d.msg[0] ? ": " : "",
                 d.msg);
    return st == RB_ERR_INVALID ? RB_EXIT_USAGE : RB_EXIT_INTERNAL;
}

rb_exit rb_cli_fragility_run(const rb_cli_opts *o)
{
    rb_outplan p;
    rb_case c;
    rb_case_fragility f;
    rb_fragility_sweep sweep;
    char title[256];
    memset(&c, 0, sizeof c);
    memset(&f, 0, sizeof f);
    memset(&sweep, 0, sizeof sweep);
    rb_outplan_init(&p);
    rb_exit e = rb_cli_plan_case_outputs(o, &p);
    if (e == RB_EXIT_PASS)
        e = rb_cli_load_case_planned(o, &c, &p);
    if (e == RB_EXIT_PASS)
        e = compute(o, &c, &f, &sweep);
    outputs out = {&c, o->sweep_gap ? NULL : &f, o->sweep_gap ? &sweep : NULL, o->x_scale};
    if (e == RB_EXIT_PASS) {
        snprintf(title, sizeof title, "Fragility of %.200s%s", c.name ? c.name : "the case",
                 o->sweep_gap ? " against the gap ratio" : "");
        rb_cli_renders r = {&out, title, "fragility", text_of, json_of, csv_of, figure,
                           p58_of, &c, NULL, NULL};
        e = rb_cli_emit_case_outputs(o, &p, &r);
    }
    rb_case_fragility_free(&f);
    rb_fragility_sweep_free(&sweep);
    rb_case_free(&c);
    rb_outplan_free(&p);
    return e;
}
