/* What the JSON and text reports share: the normalised forms of a result
 * and the names of enum values, computed in one place so the two reports
 * cannot disagree. Private to src/io. */
#ifndef RB_REPORT_INTERNAL_H
#define RB_REPORT_INTERNAL_H

#include "rockbolt/report.h"

/* Normalised forms of one result. A ratio whose denominator is zero or not
 * positive (no motion, no bolts) is NAN here and "no value" in a report. */
typedef struct {
    double v0_n;                 /* V0 = M a, a = peak floor acceleration */
    double peak_g;               /* a / g */
    double peak_over_a_star;     /* a / A* */
    double shear_elastic_over_w, shear_elastic_over_v0;
    double shear_total_over_w, shear_total_over_v0;
    double force_over_fy[2];     /* max bolt force / Fy_row */
    double final_gap_ratio[2];   /* final gap / l */
} rb_report_norms;

void rb_report_norms_compute(const rb_report *r, const rb_report_motion *m,
                             rb_report_norms *n);

/* Ratio a / b, or NAN when b is not positive or either is not finite. */
double rb_report_ratio(double a, double b);

/* Fixed names of enum values, as written in the reports; never NULL. */
const char *rb_report_motion_kind_str(rb_motion_kind kind);
const char *rb_report_pulse_str(rb_pulse_shape shape);
const char *rb_report_bolt_model_str(rb_bolt_model model);
const char *rb_report_formulation_str(rb_formulation form);
const char *rb_report_criterion_str(rb_criterion_kind kind);
const char *rb_report_side_str(int side); /* RB_LEFT, RB_RIGHT */

#endif
