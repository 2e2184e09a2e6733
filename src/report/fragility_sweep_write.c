/* A fragility sweep over gap ratios as text, JSON and CSV. Every point has
 * the case's motions and level, so the head gives them once. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <cjson/cJSON.h>
#include "rockbolt/jsonbuild.h"
#include "rockbolt/jsonprint.h"
#include "rockbolt/names.h"
#include "rockbolt/report.h"
#include "rockbolt/textsafe.h"
#include "report_internal.h"
#include "util/strbuf.h"

char *rb_fragility_sweep_render_text(const rb_case *c, const rb_fragility_sweep *s)
{
    rb_strbuf b = {0};
    char name[128];
    if (s->n_points == 0)
        return rb_strbuf_take(&b);
    const rb_case_fragility *f0 = &s->points[0];
    double g = f0->g_mps2;
    char im[96];
    rb_fragility_intensity_describe(f0, im, sizeof im);
    rb_strbuf_printf(&b, "fragility of %s against the gap ratio: %zu motions, %s as the "
                     "intensity, at the case's level %.4f g",
                     rb_text_escape_buf(c->name ? c->name : "case", name, sizeof name),
                     f0->n_motions, im, f0->level_mps2 / g);
    /* A* is a peak floor acceleration: a spectral level is not a fraction of it */
    if (f0->intensity == RB_IM_PFA)
        rb_strbuf_printf(&b, " = %.4f A*", f0->level_mps2 / f0->a_star_mps2);
    rb_strbuf_puts(&b, "\n");
    rb_strbuf_printf(&b, "%-9s", "");
    for (int k = 0; k < RB_N_LIMITS; k++)
        if (rb_case_fragility_has(f0, k))
            rb_strbuf_printf(&b, " %28s", rb_enum_str(rb_limit_state_names, k));
    rb_strbuf_printf(&b, " %s\n%-9s", "governing", "gap ratio");
    for (int k = 0; k < RB_N_LIMITS; k++)
        if (rb_case_fragility_has(f0, k))
            rb_strbuf_printf(&b, " %11s %7s %8s", "median g", "beta", "P(level)");
    rb_strbuf_puts(&b, "\n");
    long runs = 0;
    for (size_t i = 0; i < s->n_points; i++) {
        const rb_case_fragility *f = &s->points[i];
        rb_strbuf_printf(&b, "%-9.4g", s->gap_ratios[i]);
        for (int k = 0; k < RB_N_LIMITS; k++) {
            if (!rb_case_fragility_has(f, k))
                continue;
            if (f->fitted[k])
                rb_strbuf_printf(&b, " %11.4g %7.3f %8.4f", f->fit[k].median / g,
                                 f->fit[k].beta, f->p_at_level[k]);
            else
                rb_strbuf_printf(&b, " %28s", "not fitted");
        }
        rb_strbuf_printf(&b, " %s\n", f->governing >= 0
                         ? rb_enum_str(rb_limit_state_names, f->governing) : "none");
        runs += f->runs;
    }
    char judged[96];
    rb_limit_states_str(f0->judged, judged, sizeof judged);
    rb_strbuf_printf(&b, "%ld solver runs; P: probability at the case's level; governing: "
                     "the lowest median of %s (ties to the first listed)\n", runs, judged);
    return rb_strbuf_take(&b);
}

/* Where the sweep's lines break: the head in three lines, then each point
 * on a line of its own with its limit states below it. */
static const rb_json_break sweep_breaks[] = {
    {0, "case", ",\n  ", NULL, NULL},
    {0, "intensity", ",\n  ", NULL, NULL},
    {0, "points", ",\n  ", "\n    ", "\n  "},
    {1, "limit_states", NULL, "\n      ", "\n    "},
};
static const rb_json_layout sweep_layout = {
    "\n  ", "\n", sweep_breaks, sizeof sweep_breaks / sizeof sweep_breaks[0]};

char *rb_fragility_sweep_render_json(const rb_case *c, const rb_fragility_sweep *s)
{
    rb_jctx cx = {.st = RB_OK, .where = "fragility sweep"};
    const rb_case_fragility *f0 = s->n_points ? &s->points[0] : NULL;
    long runs = 0;
    for (size_t i = 0; i < s->n_points; i++)
        runs += s->points[i].runs;
    cJSON *root = rb_report_fragility_head_json(&cx, "rockbolt-fragility-gap-sweep", c, f0);
    rb_j_uint(&cx, root, "motions", f0 ? f0->n_motions : 0);
    rb_report_fragility_bootstrap_json(&cx, root, f0);
    rb_j_int(&cx, root, "runs", runs);
    cJSON *points = rb_j_arr(&cx, root, "points");
    for (size_t i = 0; i < s->n_points; i++) {
        const rb_case_fragility *f = &s->points[i];
        cJSON *o = rb_j_item(&cx, points);
        rb_j_num_or_null(&cx, o, "gap_ratio", s->gap_ratios[i]);
        rb_j_int(&cx, o, "runs", f->runs);
        rb_report_fragility_governing_json(&cx, o, f);
        cJSON *limits = rb_j_arr(&cx, o, "limit_states");
        for (int k = 0; k < RB_N_LIMITS; k++)
            if (rb_case_fragility_has(f, k))
                rb_report_fragility_limit_json(&cx, limits, f, k);
    }
    return rb_report_file_print(&cx, root, &sweep_layout);
}

/* A number of 6 significant digits, or nothing when there is none. */
static void field(rb_strbuf *b, double v)
{
    if (isfinite(v))
        rb_strbuf_printf(b, ",%.6g", v);
    else
        rb_strbuf_puts(b, ",");
}

char *rb_fragility_sweep_render_csv(const rb_fragility_sweep *s)
{
    rb_strbuf b = {0};
    rb_strbuf_puts(&b, "gap_ratio,limit_state,fitted,median_g,beta,median_lo_g,median_hi_g,"
                       "p_at_level,reached,governing\n");
    for (size_t i = 0; i < s->n_points; i++) {
        const rb_case_fragility *f = &s->points[i];
        double g = f->g_mps2;
        for (int k = 0; k < RB_N_LIMITS; k++) {
            size_t reached = 0;
            if (!rb_case_fragility_has(f, k))
                continue;
            for (size_t m = 0; m < f->n_motions; m++)
                reached += f->motions[m].censored[k] == 0;
            rb_strbuf_printf(&b, "%.6g,%s,%d", s->gap_ratios[i],
                             rb_enum_str(rb_limit_state_names, k), f->fitted[k]);
            if (f->fitted[k]) {
                field(&b, f->fit[k].median / g);
                field(&b, f->fit[k].beta);
                field(&b, f->median_lo[k] / g);
                field(&b, f->median_hi[k] / g);
                field(&b, f->p_at_level[k]);
            } else {
                rb_strbuf_puts(&b, ",,,,,");
            }
            rb_strbuf_printf(&b, ",%zu,%d\n", reached, k == f->governing);
        }
    }
    return rb_strbuf_take(&b);
}
