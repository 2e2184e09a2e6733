/* Shared pieces of the reports: the overall verdict, the normalised forms
 * of a result (thesis sec. 6: ratios to W, V0 = M a, Fy, l, A*, g) and the
 * names of enum values. The switches have no default so that a new enum
 * value without a name is a compiler warning. */
#include <math.h>
#include <stdio.h>
#include <string.h>
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
        snprintf(r->reason, sizeof r->reason, "%s%zu motion%s meet%s the %s criterion",
                 r->n_motions > 1 ? "all " : "", r->n_motions,
                 r->n_motions == 1 ? "" : "s", r->n_motions == 1 ? "s" : "",
                 rb_report_criterion_str(r->kase->criteria.kind));
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

const char *rb_report_motion_kind_str(rb_motion_kind kind)
{
    switch (kind) {
    case RB_MOTION_HARMONIC: return "harmonic";
    case RB_MOTION_PULSE: return "pulse";
    case RB_MOTION_SAMPLED: return "sampled";
    case RB_MOTION_CRITICAL: return "critical";
    }
    return "unknown";
}

const char *rb_report_pulse_str(rb_pulse_shape shape)
{
    switch (shape) {
    case RB_PULSE_RECT: return "rectangular";
    case RB_PULSE_TRI_DEC: return "triangular-decreasing";
    case RB_PULSE_TRI_INC: return "triangular-increasing";
    case RB_PULSE_HALF_SINE: return "half-sine";
    }
    return "unknown";
}

const char *rb_report_bolt_model_str(rb_bolt_model model)
{
    switch (model) {
    case RB_BOLT_NONE: return "none";
    case RB_BOLT_RIGID_PLASTIC: return "rigid-plastic";
    case RB_BOLT_NONYIELDING: return "non-yielding";
    case RB_BOLT_ELASTIC_PLASTIC: return "elastic-plastic";
    }
    return "unknown";
}

const char *rb_report_formulation_str(rb_formulation form)
{
    switch (form) {
    case RB_FORM_LARGE: return "large";
    case RB_FORM_SMALL: return "small";
    case RB_FORM_CONSISTENT: return "consistent";
    }
    return "unknown";
}

const char *rb_report_integrator_str(rb_integrator integ)
{
    switch (integ) {
    case RB_INTEGRATOR_AUTO: return "auto";
    case RB_INTEGRATOR_RK45: return "rk45";
    }
    return "unknown";
}

const char *rb_report_criterion_str(rb_criterion_kind kind)
{
    switch (kind) {
    case RB_CRIT_NO_YIELD: return "no-yield";
    case RB_CRIT_NO_BREAK: return "no-break";
    }
    return "unknown";
}

const char *rb_report_validity_mode_str(rb_validity_mode mode)
{
    switch (mode) {
    case RB_VALIDITY_WARN: return "warn";
    case RB_VALIDITY_FAIL: return "fail";
    }
    return "unknown";
}

const char *rb_report_side_str(int side)
{
    return side == RB_LEFT ? "left" : side == RB_RIGHT ? "right" : "unknown";
}
