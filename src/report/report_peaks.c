/* A run's peaks for the reports: one line each, with its JSON key and,
 * when the text templates show it, its template name, so that a new peak
 * of rb_result reaches the JSON report and the templates from this table
 * (docs/architecture.md, "A new report field"). The numbers of another
 * unit than the JSON's (the text's mm and kN, the case's units) stay with
 * the text report's own variables. */
#include <stddef.h>
#include "report_peaks.h"

typedef enum {
    PEAK_RESULT,      /* a double of rb_result */
    PEAK_NORM,        /* a double of rb_report_norms: null when undefined */
    PEAK_PAIR,        /* a double[2] of rb_result, per row */
    PEAK_PAIR_NORM    /* a double[2] of rb_report_norms */
} peak_kind;

typedef struct {
    const char *json;   /* key in "peaks" */
    const char *text;   /* template name; NULL: not one */
    peak_kind kind;
    size_t at;          /* offsetof in rb_result or rb_report_norms */
} peak;

#define R(f) PEAK_RESULT, offsetof(rb_result, f)
#define N(f) PEAK_NORM, offsetof(rb_report_norms, f)

static const peak peaks[] = {
    {"max_theta_rad", "max_theta_rad", R(max_theta_rad)},
    {"max_theta_over_alpha", "max_theta_over_alpha", R(max_theta_over_alpha)},
    {"max_u_m", NULL, R(max_u_m)},
    {"max_u_over_ustatic", "max_u_over_ustatic", R(max_u_over_ustatic)},
    {"max_shear_elastic_n", NULL, R(max_shear_elastic_n)},
    {"max_shear_elastic_over_w", "shear_elastic_over_w", N(shear_elastic_over_w)},
    {"max_shear_elastic_over_v0", "shear_elastic_over_v0", N(shear_elastic_over_v0)},
    {"max_shear_total_n", NULL, R(max_shear_total_n)},
    {"max_shear_total_over_w", "shear_total_over_w", N(shear_total_over_w)},
    {"max_shear_total_over_v0", "shear_total_over_v0", N(shear_total_over_v0)},
    {"max_friction_demand", "friction_demand", R(max_friction_demand)},
    {"min_vertical_reaction_n", NULL, R(min_vertical_reaction_n)},
    {"min_vertical_reaction_over_w", "min_vertical_over_w", N(min_vertical_over_w)},
    {"max_bolt_force_n", NULL, PEAK_PAIR, offsetof(rb_result, max_bolt_force_n)},
    {"max_bolt_force_over_fy", NULL, PEAK_PAIR_NORM, offsetof(rb_report_norms, force_over_fy)},
};

static const double *value_of(const peak *p, const rb_result *r, const rb_report_norms *n)
{
    const char *base = p->kind == PEAK_RESULT || p->kind == PEAK_PAIR
        ? (const char *)r : (const char *)n;
    return (const double *)(const void *)(base + p->at);
}

void rb_report_json_peaks(rb_jctx *cx, cJSON *o, const rb_result *r,
                          const rb_report_norms *n)
{
    for (size_t i = 0; i < sizeof peaks / sizeof peaks[0]; i++) {
        const peak *p = &peaks[i];
        const double *v = value_of(p, r, n);
        switch (p->kind) {
        case PEAK_RESULT: rb_j_num(cx, o, p->json, *v); break;
        case PEAK_NORM: rb_j_norm(cx, o, p->json, *v); break;
        case PEAK_PAIR: rb_j_pair(cx, o, p->json, v); break;
        case PEAK_PAIR_NORM: rb_j_pair_norm(cx, o, p->json, v); break;
        }
    }
}

void rb_report_text_peaks(rb_tvars *t, const rb_result *r, const rb_report_norms *n)
{
    for (size_t i = 0; i < sizeof peaks / sizeof peaks[0]; i++)
        if (peaks[i].text && (peaks[i].kind == PEAK_RESULT || peaks[i].kind == PEAK_NORM))
            rb_tv_num(t, peaks[i].text, *value_of(&peaks[i], r, n));
}
