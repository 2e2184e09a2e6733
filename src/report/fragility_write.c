/* A case's fragility as text (the terminal), JSON (everything, SI) and CSV
 * (one row per motion and limit state). Intensities are peak floor
 * accelerations, shown in g and in A*. */
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

static const char *motion_name(const rb_case *c, size_t m)
{
    return c->motions[m].name ? c->motions[m].name : "?";
}

void rb_fragility_intensity_describe(const rb_case_fragility *f, char *buf, size_t n)
{
    if (f->intensity == RB_IM_SA)
        snprintf(buf, n, "%g %% spectral acceleration at %.3g Hz", 100 * f->im_damping,
                 f->im_freq_hz);
    else
        snprintf(buf, n, "peak floor acceleration");
}

/* Which limit state governs and by what rule (rb_fragility_governing). */
static void governing_line(rb_strbuf *b, const rb_case_fragility *f)
{
    char judged[96];
    rb_limit_states_str(f->judged, judged, sizeof judged);
    if (f->governing >= 0)
        rb_strbuf_printf(b, "governing limit state: %s, median %.4f g (the lowest median of "
                         "those the case's criteria fail on: %s; ties to the first "
                         "listed)\n", rb_enum_str(rb_limit_state_names, f->governing),
                         f->fit[f->governing].median / f->g_mps2, judged);
    else
        rb_strbuf_printf(b, "governing limit state: none (of those the case's criteria fail "
                         "on, %s, none is reached by two motions)\n", judged);
}

/* Which limit states' capacities were confirmed at tighter tolerances
 * and why the others were not (docs/fragility.md, "Fewer runs"). */
static void confirmed_line(rb_strbuf *b, const rb_case_fragility *f)
{
    char yes[96], no[96];
    rb_limit_states_str(f->confirmed & f->present, yes, sizeof yes);
    rb_limit_states_str(~f->confirmed & f->present, no, sizeof no);
    rb_strbuf_printf(b, "confirmed at tighter tolerances: %s (%s); not confirmed: %s (points "
                     "of fitted curves, each within the resolution at the runs' own "
                     "tolerance)\n", yes, f->confirmed ? "the governing state's, which signs "
                     "the verdict" : "no state governs", no);
}

/* The limit states some of whose capacities are the model's limit, not
 * the bolts' (rb_motion_fragility.model_limited), in one line. */
static void model_limited_line(rb_strbuf *b, const rb_case_fragility *f)
{
    int first = 1;
    for (int k = 0; k < RB_N_LIMITS; k++) {
        size_t n = rb_case_fragility_model_limited(f, k);
        if (!n)
            continue;
        rb_strbuf_printf(b, "%s%s %zu of %zu", first ? "limited by the model: " : ", ",
                         rb_enum_str(rb_limit_state_names, k), n, f->n_motions);
        first = 0;
    }
    if (!first)
        rb_strbuf_puts(b, " capacities are the level where the vertical floor acceleration "
                       "reaches -g (the base would be thrown off the floor, which the model "
                       "does not follow), not the bolts': counted as reached there, so those "
                       "fits are limited by the model and their medians are lower bounds\n");
}

static int any_model_limited(const rb_case_fragility *f)
{
    for (int k = 0; k < RB_N_LIMITS; k++)
        if (rb_case_fragility_model_limited(f, k))
            return 1;
    return 0;
}

char *rb_fragility_render_text(const rb_case *c, const rb_case_fragility *f)
{
    rb_strbuf b = {0};
    char name[128];
    double g = f->g_mps2, as = f->a_star_mps2;
    char im[96];
    rb_fragility_intensity_describe(f, im, sizeof im);
    rb_strbuf_printf(&b, "fragility of %s: %zu motions, %s as the intensity (A* = %.3f g), "
                     "at the case's level %.4f g = %.4f A*\n",
                     rb_text_escape_buf(c->name ? c->name : "case", name, sizeof name),
                     f->n_motions, im, as / g, f->level_mps2 / g, f->level_mps2 / as);
    rb_strbuf_printf(&b, "%-12s %9s %7s %21s %9s %9s %8s %8s\n", "limit state",
                     "median g", "beta", "median 90% interval", "10% at g", "P(level)",
                     "reached", "censored");
    for (int k = 0; k < RB_N_LIMITS; k++) {
        size_t cens = 0;
        if (!rb_case_fragility_has(f, k))
            continue;
        for (size_t m = 0; m < f->n_motions; m++)
            cens += (size_t)f->motions[m].censored[k];
        rb_strbuf_printf(&b, "%-12s ", rb_enum_str(rb_limit_state_names, k));
        if (f->fitted[k]) {
            rb_strbuf_printf(&b, "%9.4f %7.3f ", f->fit[k].median / g, f->fit[k].beta);
            /* too few motions to resample (two equal draws fit no spread):
             * the interval is unknown, said so rather than printed as nan */
            if (isfinite(f->median_lo[k]) && isfinite(f->median_hi[k]))
                rb_strbuf_printf(&b, "%9.4f to %8.4f", f->median_lo[k] / g,
                                 f->median_hi[k] / g);
            else
                rb_strbuf_printf(&b, "%21s", "n/a (too few)");
            rb_strbuf_printf(&b, " %9.4f %9.4f", f->im10[k] / g, f->p_at_level[k]);
        }
        else
            rb_strbuf_printf(&b, "%9s %7s %21s %9s %9s", "n/a", "n/a",
                             "(fewer than 2 reach it)", "n/a", "n/a");
        rb_strbuf_printf(&b, " %8zu %8zu\n", f->n_motions - cens, cens);
    }
    governing_line(&b, f);
    confirmed_line(&b, f);
    model_limited_line(&b, f);
    rb_strbuf_printf(&b, "capacities (g; > : not reached up to the scan's end%s)\n",
                     any_model_limited(f) ? "; ^ : the model's limit, the bolts' capacity "
                     "lies above" : "");
    rb_strbuf_printf(&b, "%-28s", "motion");
    for (int k = 0; k < RB_N_LIMITS; k++)
        if (rb_case_fragility_has(f, k))
            rb_strbuf_printf(&b, " %12s", rb_enum_str(rb_limit_state_names, k));
    rb_strbuf_puts(&b, "\n");
    for (size_t m = 0; m < f->n_motions; m++) {
        rb_strbuf_printf(&b, "%-28.28s", rb_text_escape_buf(motion_name(c, m), name,
                                                           sizeof name));
        for (int k = 0; k < RB_N_LIMITS; k++)
            if (rb_case_fragility_has(f, k))
                rb_strbuf_printf(&b, " %s%11.4f", f->motions[m].censored[k] ? ">"
                                 : f->motions[m].model_limited[k] ? "^" : " ",
                                 f->motions[m].capacity_mps2[k] / g);
        rb_strbuf_puts(&b, "\n");
    }
    rb_strbuf_printf(&b, "%ld solver runs; median interval: percentile bootstrap of %u "
                     "resamples, seed %llu\n", f->runs, f->n_boot,
                     (unsigned long long)f->seed);
    return rb_strbuf_take(&b);
}

void rb_report_fragility_limit_json(rb_jctx *cx, cJSON *arr, const rb_case_fragility *f,
                                    int k)
{
    cJSON *o = rb_j_item(cx, arr);
    rb_j_str(cx, o, "limit_state", rb_enum_str(rb_limit_state_names, k));
    rb_j_bool(cx, o, "fitted", f->fitted[k]);
    if (f->fitted[k]) {
        rb_j_num_or_null(cx, o, "median_mps2", f->fit[k].median);
        rb_j_num_or_null(cx, o, "beta", f->fit[k].beta);
        rb_j_num_or_null(cx, o, "median_lo_mps2", f->median_lo[k]);
        rb_j_num_or_null(cx, o, "median_hi_mps2", f->median_hi[k]);
        rb_j_num_or_null(cx, o, "p_at_level", f->p_at_level[k]);
        rb_j_num_or_null(cx, o, "level_p10_mps2", f->im10[k]);
        rb_j_num_or_null(cx, o, "level_p50_mps2", f->im50[k]);
        rb_j_num_or_null(cx, o, "loglik", f->fit[k].loglik);
    }
    rb_j_bool(cx, o, "confirmed", (f->confirmed >> k) & 1u);
    rb_j_int(cx, o, "model_limited", (long)rb_case_fragility_model_limited(f, k));
}

void rb_report_fragility_governing_json(rb_jctx *cx, cJSON *o, const rb_case_fragility *f)
{
    cJSON *judged = rb_j_arr(cx, o, "judged_limit_states");
    for (int k = 0; k < RB_N_LIMITS; k++)
        if ((f->judged >> k) & 1u)
            rb_j_append(cx, judged, cJSON_CreateString(rb_enum_str(rb_limit_state_names, k)));
    if (f->governing >= 0)
        rb_j_str(cx, o, "governing_limit_state",
                 rb_enum_str(rb_limit_state_names, f->governing));
    else
        rb_j_null(cx, o, "governing_limit_state");
}

cJSON *rb_report_file_json(rb_jctx *cx, const char *format, const rb_case *c)
{
    cJSON *root = cJSON_CreateObject();
    rb_j_oom(cx, root);
    rb_j_str(cx, root, "format", format);
    rb_j_int(cx, root, "format_version", 1);
    rb_j_text(cx, root, "case", c->name);
    return root;
}

char *rb_report_file_print(rb_jctx *cx, cJSON *root, const rb_json_layout *layout)
{
    char *text = cx->st == RB_OK ? rb_json_print_layout(root, layout) : NULL;
    cJSON_Delete(root);
    return text;
}

cJSON *rb_report_fragility_head_json(rb_jctx *cx, const char *format, const rb_case *c,
                                     const rb_case_fragility *f0)
{
    rb_fragility_intensity im = f0 ? f0->intensity : RB_IM_PFA;
    cJSON *root = rb_report_file_json(cx, format, c);
    rb_j_str(cx, root, "intensity", rb_enum_str(rb_intensity_report_names, (int)im));
    if (im == RB_IM_SA) {
        rb_j_num_or_null(cx, root, "intensity_freq_hz", f0->im_freq_hz);
        rb_j_num_or_null(cx, root, "intensity_damping", f0->im_damping);
    }
    rb_j_num_or_null(cx, root, "g_mps2", f0 ? f0->g_mps2 : (double)NAN);
    rb_j_num_or_null(cx, root, "a_star_mps2", f0 ? f0->a_star_mps2 : (double)NAN);
    rb_j_num_or_null(cx, root, "level_mps2", f0 ? f0->level_mps2 : (double)NAN);
    return root;
}

void rb_report_fragility_bootstrap_json(rb_jctx *cx, cJSON *root,
                                        const rb_case_fragility *f0)
{
    cJSON *boot = rb_j_obj(cx, root, "bootstrap");
    rb_j_uint(cx, boot, "resamples", f0 ? f0->n_boot : 0);
    rb_j_uint(cx, boot, "seed", f0 ? (unsigned long long)f0->seed : 0ull);
    rb_j_num(cx, boot, "interval", 0.9);
}

/* Where the fragility's lines break: the head in three lines, then each
 * limit state and each motion on a line of its own. */
static const rb_json_break fragility_breaks[] = {
    {0, "case", ",\n  ", NULL, NULL},
    {0, "intensity", ",\n  ", NULL, NULL},
    {0, "judged_limit_states", ",\n  ", NULL, NULL},
    {0, "confirmed_limit_states", ",\n  ", NULL, NULL},
    {0, "limit_states", ",\n  ", "\n    ", "\n  "},
    {0, "motions", ",\n  ", "\n    ", "\n  "},
};
static const rb_json_layout fragility_layout = {
    "\n  ", "\n", fragility_breaks, sizeof fragility_breaks / sizeof fragility_breaks[0]};

static void motion_json(rb_jctx *cx, cJSON *arr, const rb_case *c,
                        const rb_case_fragility *f, size_t m)
{
    cJSON *o = rb_j_item(cx, arr);
    rb_j_text(cx, o, "name", motion_name(c, m));
    if (f->intensity != RB_IM_PFA)
        rb_j_num_or_null(cx, o, "im_per_pfa", f->motions[m].im_per_pfa);
    cJSON *cap = rb_j_obj(cx, o, "capacity_mps2");
    for (int k = 0; k < RB_N_LIMITS; k++)
        if (rb_case_fragility_has(f, k))
            rb_j_num_or_null(cx, cap, rb_enum_str(rb_limit_state_names, k),
                             f->motions[m].capacity_mps2[k]);
    cJSON *cens = rb_j_obj(cx, o, "censored");
    for (int k = 0; k < RB_N_LIMITS; k++)
        if (rb_case_fragility_has(f, k))
            rb_j_bool(cx, cens, rb_enum_str(rb_limit_state_names, k),
                      f->motions[m].censored[k]);
    cJSON *lim = rb_j_obj(cx, o, "model_limited");
    for (int k = 0; k < RB_N_LIMITS; k++)
        if (rb_case_fragility_has(f, k))
            rb_j_bool(cx, lim, rb_enum_str(rb_limit_state_names, k),
                      f->motions[m].model_limited[k]);
    rb_j_num_or_null(cx, o, "model_limit_mps2", f->motions[m].model_limit_mps2);
    rb_j_int(cx, o, "runs", f->motions[m].runs);
}

char *rb_fragility_render_json(const rb_case *c, const rb_case_fragility *f)
{
    rb_jctx cx = {.st = RB_OK, .where = "fragility"};
    cJSON *root = rb_report_fragility_head_json(&cx, "rockbolt-fragility", c, f);
    rb_report_fragility_bootstrap_json(&cx, root, f);
    rb_j_int(&cx, root, "runs", f->runs);
    rb_report_fragility_governing_json(&cx, root, f);
    cJSON *confirmed = rb_j_arr(&cx, root, "confirmed_limit_states");
    for (int k = 0; k < RB_N_LIMITS; k++)
        if (rb_case_fragility_has(f, k) && (f->confirmed >> k) & 1u)
            rb_j_append(&cx, confirmed,
                        cJSON_CreateString(rb_enum_str(rb_limit_state_names, k)));
    cJSON *limits = rb_j_arr(&cx, root, "limit_states");
    for (int k = 0; k < RB_N_LIMITS; k++)
        if (rb_case_fragility_has(f, k))
            rb_report_fragility_limit_json(&cx, limits, f, k);
    cJSON *motions = rb_j_arr(&cx, root, "motions");
    for (size_t m = 0; m < f->n_motions; m++)
        motion_json(&cx, motions, c, f, m);
    return rb_report_file_print(&cx, root, &fragility_layout);
}

char *rb_fragility_render_csv(const rb_case *c, const rb_case_fragility *f)
{
    rb_strbuf b = {0};
    rb_strbuf_puts(&b, "motion,limit_state,capacity_g,capacity_astar,censored,governing,"
                       "confirmed,model_limited\n");
    for (size_t m = 0; m < f->n_motions; m++)
        for (int k = 0; k < RB_N_LIMITS; k++) {
            if (!rb_case_fragility_has(f, k))
                continue;
            char *field = rb_csv_field(motion_name(c, m), 0);
            if (!field) {
                b.oom = 1;
                break;
            }
            rb_strbuf_printf(&b, "%s,%s,%.6g,%.6g,%d,%d,%d,%d\n", field,
                             rb_enum_str(rb_limit_state_names, k),
                             f->motions[m].capacity_mps2[k] / f->g_mps2,
                             f->motions[m].capacity_mps2[k] / f->a_star_mps2,
                             f->motions[m].censored[k], k == f->governing,
                             (int)((f->confirmed >> k) & 1u),
                             f->motions[m].model_limited[k] != 0);
            free(field);
        }
    return rb_strbuf_take(&b);
}
