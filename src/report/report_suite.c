/* A case with several floor motions (a suite, say the seven records a code
 * asks for): which motion governs, and the mean and maximum of each key
 * result over the motions. Shared by the JSON and text reports so they
 * name the same governing motion.
 *
 * The governing motion is the one with the largest demand on the case's
 * criterion: bolt force / Fy for "no yield", toughness usage for "no
 * break"; an overturn outranks any demand, and ties go to the first
 * motion, so the choice is stable. */
#include <math.h>
#include <string.h>
#include "report_internal.h"

const char *const rb_suite_names[RB_SUITE_N] = {
    "usage", "bolt_force_over_fy", "shear_elastic_over_w", "shear_total_over_w",
    "u_over_ustatic", "theta_over_alpha"
};

static double max2(double a, double b)
{
    return a > b ? a : b;
}

/* The values of one motion; NAN where there is no denominator (no bolts),
 * which the mean and maximum then skip. */
static void motion_values(const rb_report *r, const rb_report_motion *m,
                          double v[RB_SUITE_N])
{
    rb_report_norms n;
    const rb_result *res = m->result;
    rb_report_norms_compute(r, m, &n);
    v[0] = r->kase->model.bolt_model == RB_BOLT_NONE ? (double)NAN
                                                     : max2(res->usage[0], res->usage[1]);
    v[1] = isnan(n.force_over_fy[0]) ? (double)NAN
                                     : max2(n.force_over_fy[0], n.force_over_fy[1]);
    v[2] = n.shear_elastic_over_w;
    v[3] = n.shear_total_over_w;
    v[4] = res->max_u_over_ustatic;
    v[5] = res->max_theta_over_alpha;
}

static double demand(const rb_report *r, const rb_report_motion *m,
                     const double v[RB_SUITE_N])
{
    double d = r->kase->criteria.kind == RB_CRIT_NO_YIELD ? v[1] : v[0];
    if (m->result->overturned)
        return HUGE_VAL;
    return isnan(d) ? v[5] : d;   /* free-standing: rotation / alpha */
}

void rb_report_suite_compute(const rb_report *r, rb_report_suite *s)
{
    size_t i, k, count[RB_SUITE_N] = {0};
    double best = -HUGE_VAL;
    memset(s, 0, sizeof *s);
    for (k = 0; k < RB_SUITE_N; k++) {
        s->mean[k] = 0;
        s->max[k] = (double)NAN;
    }
    for (i = 0; i < r->n_motions; i++) {
        double v[RB_SUITE_N], d;
        motion_values(r, &r->motions[i], v);
        d = demand(r, &r->motions[i], v);
        if (d > best) {
            best = d;
            s->governing = i;
        }
        for (k = 0; k < RB_SUITE_N; k++) {
            if (isnan(v[k]))
                continue;
            s->mean[k] += v[k];
            s->max[k] = count[k] ? max2(s->max[k], v[k]) : v[k];
            count[k]++;
        }
    }
    for (k = 0; k < RB_SUITE_N; k++)
        s->mean[k] = count[k] ? s->mean[k] / (double)count[k] : (double)NAN;
}
