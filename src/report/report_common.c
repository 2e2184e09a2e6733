/* Shared pieces of the reports: the overall verdict, the normalised forms
 * of a result (thesis sec. 6: ratios to W, V0 = M a, Fy, l, A*, g) and the
 * side names (the names of enum values are in rockbolt/names.h). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "rockbolt/names.h"
#include "report_internal.h"

double rb_report_ratio(double a, double b)
{
    if (!isfinite(a) || !isfinite(b) || b <= 0)
        return (double)NAN;
    return a / b;
}

void rb_report_norms_compute(const rb_report *r, const rb_report_motion *m,
                             rb_report_norms *n)
{
    const rb_result *res = m->result;
    double a = res->peak_floor_mps2, w = res->weight_n;
    double l = r->kase->model.lever_arm_m;
    int s;
    n->v0_n = r->kase->model.mass_kg * a;
    n->peak_g = rb_report_ratio(a, r->derived.g);
    n->peak_over_a_star = rb_report_ratio(a, res->a_star_mps2);
    n->shear_elastic_over_w = rb_report_ratio(res->max_shear_elastic_n, w);
    n->shear_elastic_over_v0 = rb_report_ratio(res->max_shear_elastic_n, n->v0_n);
    n->shear_total_over_w = rb_report_ratio(res->max_shear_total_n, w);
    n->shear_total_over_v0 = rb_report_ratio(res->max_shear_total_n, n->v0_n);
    n->min_vertical_over_w = rb_report_ratio(res->min_vertical_reaction_n, w);
    for (s = 0; s < 2; s++) {
        /* NaN without rows, as the judge's ratio (rb_result_governing) */
        n->force_over_fy[s] = rb_report_ratio(res->max_bolt_force_n[s], res->fy_row_n);
        n->final_gap_ratio[s] = rb_report_ratio(res->final_gap_m[s], l);
    }
}

void rb_report_headline(int pass, unsigned warnings, char *buf, size_t n)
{
    char w[80];
    rb_warnings_str(warnings, w, sizeof w);
    snprintf(buf, n, "%s%s%s%s", pass ? "PASS" : "FAIL", w[0] ? " (" : "", w,
             w[0] ? ")" : "");
}

void rb_report_conclude(rb_report *r)
{
    size_t i, failed = 0;
    const rb_report_motion *first = NULL;
    r->warnings = 0;
    for (i = 0; i < r->n_motions; i++) {
        r->warnings |= r->motions[i].verdict.warnings;
        if (!r->motions[i].verdict.pass) {
            if (!first)
                first = &r->motions[i];
            failed++;
        }
    }
    r->pass = failed == 0;
    rb_report_headline(r->pass, r->warnings, r->headline, sizeof r->headline);
    if (!first) {
        /* a pass on rigid stops says what the worst of them hid */
        const rb_report_motion *hid = NULL;
        for (i = 0; i < r->n_motions; i++)
            if (rb_bolt_impact_over_fy(r->motions[i].result)
                > (hid ? rb_bolt_impact_over_fy(hid->result) : 0))
                hid = &r->motions[i];
        char note[96] = "";
        if (hid)
            rb_bolt_impact_note(hid->result, note, sizeof note);
        snprintf(r->reason, sizeof r->reason, "%s%zu motion%s meet%s the %s criterion%s%s%s%s",
                 r->n_motions > 1 ? "all " : "", r->n_motions,
                 r->n_motions == 1 ? "" : "s", r->n_motions == 1 ? "s" : "",
                 rb_enum_str(rb_criterion_names, (int)r->kase->criteria.kind),
                 hid ? "; " : "", note, hid ? " (motion '" : "",
                 hid ? (hid->motion->name ? hid->motion->name : "?") : "");
        if (hid) {
            size_t len = strlen(r->reason);
            if (len < sizeof r->reason)
                snprintf(r->reason + len, sizeof r->reason - len, "')");
        }
    } else if (failed == 1) {
        snprintf(r->reason, sizeof r->reason, "motion '%.100s': %.250s",
                 first->motion->name ? first->motion->name : "?", first->verdict.reason);
    } else {
        snprintf(r->reason, sizeof r->reason,
                 "motion '%.100s': %.200s (and %zu more motions fail)",
                 first->motion->name ? first->motion->name : "?", first->verdict.reason,
                 failed - 1);
    }
}

const char *rb_report_side_str(int side)
{
    return side == RB_LEFT ? "left" : side == RB_RIGHT ? "right" : "unknown";
}
