/* Confirming a pass by solving again at tighter tolerances
 * (include/rockbolt/criteria.h, docs/report-format.md, "Confirmation"). The
 * judge itself is criteria.c's; this only makes the runs it folds. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/criteria.h"

static rb_status solve_plain(void *ctx, const rb_model *model, const rb_motion *motion,
                             const rb_solve_opts *opts, rb_result *out)
{
    (void)ctx;
    return rb_solve_run(model, motion, opts, out, NULL);
}

/* x to 12 significant digits: a hundredth of 1e-7 is reported, and
 * solved, as 1e-09, not 9.999999999999999e-10 */
static double decimal(double x)
{
    char buf[32];
    snprintf(buf, sizeof buf, "%.12g", x);
    return strtod(buf, NULL);
}

static void confirm_one(const rb_criteria *c, const rb_model *model, const rb_motion *motion,
                        const rb_solve_opts *opts, int k, rb_solve_fn solve, void *ctx,
                        rb_confirm_run *out)
{
    rb_solve_opts so = *opts;
    rb_result r;
    memset(&r, 0, sizeof r);
    memset(out, 0, sizeof *out);
    so.history_dt_s = 0;
    so.rtol = fmax(decimal(opts->rtol / (k == 0 ? 10.0 : 100.0)), RB_CONFIRM_RTOL_MIN);
    if (k == RB_CONFIRM_RUNS - 1)
        so.rest_fraction = decimal(opts->rest_fraction / 100.0);
    out->integrator = (int)so.integrator;
    out->rtol = so.rtol;
    out->rest_fraction = so.rest_fraction;
    rb_status st = solve(ctx, model, motion, &so, &r);
    out->status = (int)st;
    out->solved = st == RB_OK;
    if (out->solved) {
        rb_governing g = rb_result_governing(&r);
        rb_judge(c, &r, &out->verdict);
        out->usage = g.usage;
        out->max_bolt_force_over_fy = g.force_over_fy;
        out->max_theta_over_alpha = r.max_theta_over_alpha;
        out->margin = rb_verdict_margin(c, &r);
        rb_verdict_margins(c, &r, out->limit_margins);
    }
    rb_result_free(&r);
}

/* The confirming runs in order; with decide_only, none after the first
 * that fails: the verdict is then a fail whatever the next says, and the
 * first failing run is the one whose reason it gives. */
static void judge_run(const rb_criteria *c, const rb_model *model, const rb_motion *motion,
                      const rb_solve_opts *opts, const rb_result *r, rb_solve_fn solve,
                      void *ctx, int decide_only, rb_verdict *v, rb_confirm_run *runs,
                      size_t *n_runs)
{
    double band = rb_confirm_band(c, motion);
    *n_runs = 0;
    rb_judge(c, r, v);
    if (!rb_verdict_wants_confirm(c, band, r, v))
        return;
    for (int k = 0; k < RB_CONFIRM_RUNS; k++) {
        confirm_one(c, model, motion, opts, k, solve ? solve : solve_plain, ctx, &runs[k]);
        ++*n_runs;
        if (decide_only && !(runs[k].solved && runs[k].verdict.pass))
            break;
    }
    double each[RB_N_GOVERNS];
    rb_verdict_margins(c, r, each);
    rb_verdict_confirm(v, rb_verdict_margin(c, r), each, band, opts->rtol, runs, *n_runs);
}

void rb_judge_run(const rb_criteria *c, const rb_model *model, const rb_motion *motion,
                  const rb_solve_opts *opts, const rb_result *r, rb_solve_fn solve,
                  void *ctx, rb_verdict *v, rb_confirm_run *runs, size_t *n_runs)
{
    judge_run(c, model, motion, opts, r, solve, ctx, 0, v, runs, n_runs);
}

void rb_judge_decide(const rb_criteria *c, const rb_model *model, const rb_motion *motion,
                     const rb_solve_opts *opts, const rb_result *r, rb_solve_fn solve,
                     void *ctx, rb_verdict *v)
{
    rb_confirm_run runs[RB_CONFIRM_RUNS];
    size_t n_runs;
    judge_run(c, model, motion, opts, r, solve, ctx, 1, v, runs, &n_runs);
}
