/* A case with several floor motions (a suite, say the seven records a code
 * asks for): which motion governs, and the mean and maximum of each key
 * result over the motions. Shared by the JSON and text reports so they
 * name the same governing motion.
 *
 * The governing motion and its limit are the judge's one rule
 * (rb_verdict_governing): the least margin over all the verdict's
 * criteria, the anchorage's utilization among them, ties to the first
 * motion, so that the choice is stable and is the motion a failing case's
 * verdict line names. */
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
    v[1] = rb_result_governing(res).force_over_fy;
    v[2] = n.shear_elastic_over_w;
    v[3] = n.shear_total_over_w;
    v[4] = res->max_u_over_ustatic;
    v[5] = res->max_theta_over_alpha;
}

size_t rb_report_governing(const rb_report *r, double *margin, int *limit)
{
    size_t g = 0;
    double best = 0;
    rb_governs_limit lim = RB_GOVERNS_OVERTURN, best_lim = RB_GOVERNS_OVERTURN;
    for (size_t i = 0; i < r->n_motions; i++) {
        const rb_report_motion *m = &r->motions[i];
        double x = rb_verdict_governing(&r->kase->criteria, m->result, &m->verdict, &lim);
        if (i == 0 || rb_margin_governs(x, best)) {
            g = i;
            best = x;
            best_lim = lim;
        }
    }
    if (margin)
        *margin = best;
    if (limit)
        *limit = (int)best_lim;
    return g;
}

void rb_report_suite_compute(const rb_report *r, rb_report_suite *s)
{
    size_t i, k, count[RB_SUITE_N] = {0};
    memset(s, 0, sizeof *s);
    s->governing = rb_report_governing(r, &s->margin, &s->limit);
    for (k = 0; k < RB_SUITE_N; k++) {
        s->mean[k] = 0;
        s->max[k] = (double)NAN;
    }
    for (i = 0; i < r->n_motions; i++) {
        double v[RB_SUITE_N];
        motion_values(r, &r->motions[i], v);
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
