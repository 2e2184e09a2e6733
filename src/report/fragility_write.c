/* A case's fragility as text (the terminal), JSON (everything, SI) and CSV
 * (one row per motion and limit state). Intensities are peak floor
 * accelerations, shown in g and in A*. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <cjson/cJSON.h>
#include "rockbolt/jsonnum.h"
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
        if (f->fitted[k])
            rb_strbuf_printf(&b, "%9.4f %7.3f %9.4f to %8.4f %9.4f %9.4f", f->fit[k].median / g,
                             f->fit[k].beta, f->median_lo[k] / g, f->median_hi[k] / g,
                             f->im10[k] / g, f->p_at_level[k]);
        else
            rb_strbuf_printf(&b, "%9s %7s %21s %9s %9s", "n/a", "n/a",
                             "(fewer than 2 reach it)", "n/a", "n/a");
        rb_strbuf_printf(&b, " %8zu %8zu\n", f->n_motions - cens, cens);
    }
    governing_line(&b, f);
    rb_strbuf_puts(&b, "capacities (g; > : not reached up to the scan's end)\n");
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
                rb_strbuf_printf(&b, " %s%11.4f", f->motions[m].censored[k] ? ">" : " ",
                                 f->motions[m].capacity_mps2[k] / g);
        rb_strbuf_puts(&b, "\n");
    }
    rb_strbuf_printf(&b, "%ld solver runs; median interval: percentile bootstrap of %u "
                     "resamples, seed %llu\n", f->runs, f->n_boot,
                     (unsigned long long)f->seed);
    return rb_strbuf_take(&b);
}

void rb_report_json_num(rb_strbuf *b, const char *key, double v, int comma)
{
    char buf[RB_JSONNUM_MAX];
    rb_json_number_or_null(v, buf);
    rb_strbuf_printf(b, "\"%s\": %s%s", key, buf, comma ? ", " : "");
}

/* A JSON string of text from the case: bytes that are not UTF-8 shown as
 * \xHH first (rockbolt/textsafe.h), as the other JSON outputs show them,
 * then JSON's own escapes (rockbolt/jsonprint.h): the text reads back as
 * it was. */
void rb_report_json_str(rb_strbuf *b, const char *s)
{
    char *fixed = rb_utf8_fix(s);
    cJSON *j = fixed ? cJSON_CreateString(fixed) : NULL;
    char *e = j ? rb_json_print(j, 0) : NULL;
    cJSON_Delete(j);
    free(fixed);
    if (!e) {
        b->oom = 1;
        return;
    }
    rb_strbuf_puts(b, e);
    free(e);
}

void rb_report_fragility_limit_json(rb_strbuf *b, const rb_case_fragility *f, int k)
{
    rb_strbuf_printf(b, "{\"limit_state\": \"%s\", \"fitted\": %s",
                     rb_enum_str(rb_limit_state_names, k), f->fitted[k] ? "true" : "false");
    if (f->fitted[k]) {
        rb_strbuf_puts(b, ", ");
        rb_report_json_num(b, "median_mps2", f->fit[k].median, 1);
        rb_report_json_num(b, "beta", f->fit[k].beta, 1);
        rb_report_json_num(b, "median_lo_mps2", f->median_lo[k], 1);
        rb_report_json_num(b, "median_hi_mps2", f->median_hi[k], 1);
        rb_report_json_num(b, "p_at_level", f->p_at_level[k], 1);
        rb_report_json_num(b, "level_p10_mps2", f->im10[k], 1);
        rb_report_json_num(b, "level_p50_mps2", f->im50[k], 1);
        rb_report_json_num(b, "loglik", f->fit[k].loglik, 0);
    }
    rb_strbuf_puts(b, "}");
}

void rb_report_fragility_governing_json(rb_strbuf *b, const rb_case_fragility *f)
{
    rb_strbuf_puts(b, "\"judged_limit_states\": [");
    for (int k = 0, first = 1; k < RB_N_LIMITS; k++)
        if ((f->judged >> k) & 1u) {
            rb_strbuf_printf(b, "%s\"%s\"", first ? "" : ", ",
                             rb_enum_str(rb_limit_state_names, k));
            first = 0;
        }
    rb_strbuf_puts(b, "], \"governing_limit_state\": ");
    if (f->governing >= 0)
        rb_strbuf_printf(b, "\"%s\"", rb_enum_str(rb_limit_state_names, f->governing));
    else
        rb_strbuf_puts(b, "null");
}

char *rb_fragility_render_json(const rb_case *c, const rb_case_fragility *f)
{
    rb_strbuf b = {0};
    rb_strbuf_puts(&b, "{\n  \"format\": \"rockbolt-fragility\", \"format_version\": 1,\n"
                       "  \"case\": ");
    rb_report_json_str(&b, c->name ? c->name : "");
    rb_strbuf_printf(&b, ",\n  \"intensity\": \"%s\", ",
                     rb_enum_str(rb_intensity_report_names, (int)f->intensity));
    if (f->intensity == RB_IM_SA) {
        rb_report_json_num(&b, "intensity_freq_hz", f->im_freq_hz, 1);
        rb_report_json_num(&b, "intensity_damping", f->im_damping, 1);
    }
    rb_report_json_num(&b, "g_mps2", f->g_mps2, 1);
    rb_report_json_num(&b, "a_star_mps2", f->a_star_mps2, 1);
    rb_report_json_num(&b, "level_mps2", f->level_mps2, 1);
    rb_strbuf_printf(&b, "\"bootstrap\": {\"resamples\": %u, \"seed\": %llu, "
                     "\"interval\": 0.9}, \"runs\": %ld,\n  ",
                     f->n_boot, (unsigned long long)f->seed, f->runs);
    rb_report_fragility_governing_json(&b, f);
    rb_strbuf_puts(&b, ",\n  \"limit_states\": [\n");
    const char *sep = "";
    for (int k = 0; k < RB_N_LIMITS; k++) {
        if (!rb_case_fragility_has(f, k))
            continue;
        rb_strbuf_printf(&b, "%s    ", sep);
        rb_report_fragility_limit_json(&b, f, k);
        sep = ",\n";
    }
    rb_strbuf_puts(&b, "\n");
    rb_strbuf_puts(&b, "  ],\n  \"motions\": [\n");
    for (size_t m = 0; m < f->n_motions; m++) {
        rb_strbuf_puts(&b, "    {\"name\": ");
        rb_report_json_str(&b, motion_name(c, m));
        if (f->intensity != RB_IM_PFA) {
            rb_strbuf_puts(&b, ", ");
            rb_report_json_num(&b, "im_per_pfa", f->motions[m].im_per_pfa, 0);
        }
        rb_strbuf_puts(&b, ", \"capacity_mps2\": {");
        for (int k = 0, first = 1; k < RB_N_LIMITS; k++) {
            if (!rb_case_fragility_has(f, k))
                continue;
            rb_strbuf_puts(&b, first ? "" : ", ");
            rb_report_json_num(&b, rb_enum_str(rb_limit_state_names, k),
                               f->motions[m].capacity_mps2[k], 0);
            first = 0;
        }
        rb_strbuf_puts(&b, "}, \"censored\": {");
        for (int k = 0, first = 1; k < RB_N_LIMITS; k++) {
            if (!rb_case_fragility_has(f, k))
                continue;
            rb_strbuf_printf(&b, "%s\"%s\": %s", first ? "" : ", ",
                             rb_enum_str(rb_limit_state_names, k),
                             f->motions[m].censored[k] ? "true" : "false");
            first = 0;
        }
        rb_strbuf_printf(&b, "}, \"runs\": %ld}%s\n", f->motions[m].runs,
                         m + 1 < f->n_motions ? "," : "");
    }
    rb_strbuf_puts(&b, "  ]\n}\n");
    return rb_strbuf_take(&b);
}

char *rb_fragility_render_csv(const rb_case *c, const rb_case_fragility *f)
{
    rb_strbuf b = {0};
    rb_strbuf_puts(&b, "motion,limit_state,capacity_g,capacity_astar,censored,governing\n");
    for (size_t m = 0; m < f->n_motions; m++)
        for (int k = 0; k < RB_N_LIMITS; k++) {
            if (!rb_case_fragility_has(f, k))
                continue;
            char *field = rb_csv_field(motion_name(c, m), 0);
            if (!field) {
                b.oom = 1;
                break;
            }
            rb_strbuf_printf(&b, "%s,%s,%.6g,%.6g,%d,%d\n", field,
                             rb_enum_str(rb_limit_state_names, k),
                             f->motions[m].capacity_mps2[k] / f->g_mps2,
                             f->motions[m].capacity_mps2[k] / f->a_star_mps2,
                             f->motions[m].censored[k], k == f->governing);
            free(field);
        }
    return rb_strbuf_take(&b);
}
