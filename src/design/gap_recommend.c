/* The recommended gap ratio (thesis sec. 6.6): the smallest gap on a grid
 * from which every larger grid gap keeps the anchorage within the criteria
 * under the case's own motion. Because the response is not monotonic in
 * the gap, a gap that passes between failing ones is not recommended: the
 * recommendation is the start of the passing run that reaches the range's
 * end, found by walking down from the largest gap to the first failure. The thesis read the gap off the final gaps of yielding runs; that
 * run is made too and reported beside the search. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "design_internal.h"

#define RB_GAP_MAX_POINTS 100000

typedef struct {
    const rb_design_ctx *ctx;
    const double *ratios;
    const double *own;          /* the case's own point of the grid */
    rb_design_run *runs;
} gap_batch;

/* The model at a point of the grid; at the case's own point, the case's
 * model itself, whose gap over the lever arm and back can be an ulp off:
 * the run `check` made, which the design hands to the search
 * (rb_design_memo_keep), and whose verdict the own gap's must be. */
static void model_at(const rb_design_ctx *ctx, const double *ratio, const double *own,
                     rb_model *m)
{
    *m = *ctx->model;
    if (ratio != own)
        m->gap_m = *ratio * m->lever_arm_m;
}

static rb_status gap_job(void *v, size_t i)
{
    gap_batch *b = v;
    rb_model m;
    model_at(b->ctx, &b->ratios[i], b->own, &m);
    rb_design_run_one(b->ctx, &m, b->ctx->motion, &b->runs[i]);
    return b->runs[i].status;
}

static rb_status check_grid(const rb_design_opts *d, const rb_model *m, rb_diag *diag)
{
    if (m->bolt_model == RB_BOLT_NONE)
        return rb_design_fail(diag, RB_ERR_INVALID, "anchorage",
                              "a model without bolts has no gap to recommend");
    if (!(d->gap_ratio_min >= 0) || !(d->gap_ratio_step > 0)
        || !isfinite(d->gap_ratio_max) || !isfinite(d->gap_ratio_step)
        || !(d->gap_ratio_max >= d->gap_ratio_min))
        return rb_design_fail(diag, RB_ERR_INVALID, "design",
                              "the gap grid needs 0 <= min <= max and step > 0");
    if ((d->gap_ratio_max - d->gap_ratio_min) / d->gap_ratio_step + 1 > RB_GAP_MAX_POINTS)
        return rb_design_fail(diag, RB_ERR_INVALID, "design.gap_ratio_step",
                              "the gap grid has more than 100000 points");
    return RB_OK;
}

static void keep_point(rb_gap_point *p, double ratio, const rb_design_run *run)
{
    const rb_result *r = &run->r;
    p->gap_ratio = ratio;
    p->evaluated = 1;
    p->meets = run->meets == 1;
    p->max_force_over_fy = r->fy_row_n > 0
        ? rb_design_max2(r->max_bolt_force_n[0], r->max_bolt_force_n[1]) / r->fy_row_n : 0;
    p->max_u_over_ustatic = r->max_u_over_ustatic;
    p->max_theta_over_alpha = r->max_theta_over_alpha;
    p->usage_max = rb_design_max2(r->usage[0], r->usage[1]);
    memcpy(p->reason, run->reason, sizeof p->reason);
}

/* The thesis's yielding run: the case's gap, bolts that yield, and bolts
 * that keep stretching past their capacity, so the final gaps show how far
 * the motion would open them. */
static rb_status yield_run(const rb_design_ctx *ctx, rb_gap_result *out, rb_diag *diag)
{
    rb_design_ctx yc = *ctx;
    rb_model m = *ctx->model;
    rb_design_run run;
    if (m.bolt_model == RB_BOLT_NONYIELDING)
        m.bolt_model = RB_BOLT_RIGID_PLASTIC;
    yc.opts.stretch_past_failure = 1;
    rb_design_run_one(&yc, &m, ctx->motion, &run);
    out->runs++;
    if (run.status != RB_OK) {
        char msg[200];
        snprintf(msg, sizeof msg, "the yielding run at the case's gap failed: %s",
                 rb_status_str(run.status));
        return rb_design_fail(diag, run.status, "motion", msg);
    }
    out->yield_run = 1;
    out->yield_initial_gap_ratio = m.gap_m / m.lever_arm_m;
    for (int s = 0; s < 2; s++) {
        out->yield_final_gap_ratio[s] = run.r.final_gap_m[s] / m.lever_arm_m;
        out->yield_usage[s] = run.r.usage[s];
    }
    out->yield_final_gap_ratio_max = rb_design_max2(out->yield_final_gap_ratio[0],
                                                    out->yield_final_gap_ratio[1]);
    return RB_OK;
}

/* Walk the grid down from the largest gap in rounds of nt runs, and stop at
 * the first failing gap: the gaps below it cannot change the answer. Runs
 * made past that point in the last round are discarded, so the points kept
 * are those a single thread would have run. */
static rb_status run_grid(const rb_design_ctx *ctx, const double *ratios, const double *own,
                          int n_threads, rb_gap_result *out, rb_diag *diag)
{
    size_t n = out->n_points;
    size_t nt = (size_t)(n_threads > 0 ? n_threads : rb_pool_threads_default());
    rb_design_run *runs = malloc(nt * sizeof *runs);
    if (!runs)
        return RB_ERR_NOMEM;
    rb_status st = RB_OK;
    out->fail_index = -1;
    for (size_t k = n; st == RB_OK && k > 0 && out->fail_index < 0;) {
        size_t m = k < nt ? k : nt;
        gap_batch b = {ctx, ratios + (k - m), own, runs};
        if ((st = rb_pool_map(m, n_threads, gap_job, &b, NULL)) != RB_OK)
            break;
        /* slot j holds grid point k - m + j; read them from the top down */
        for (size_t j = m; j-- > 0;) {
            size_t i = k - m + j;
            out->runs++;
            if (runs[j].status != RB_OK) {
                char msg[200];
                snprintf(msg, sizeof msg, "the solver run at gap ratio %.6g failed: %s",
                         ratios[i], rb_status_str(runs[j].status));
                st = rb_design_fail(diag, runs[j].status, "gap_ratio", msg);
                break;
            }
            keep_point(&out->points[i], ratios[i], &runs[j]);
            if (!runs[j].meets) {
                out->fail_index = (long)i;
                out->runs_speculative += (long)j;
                break;
            }
        }
        k -= m;
    }
    free(runs);
    return st;
}

rb_status rb_gap_recommend(const rb_model *model, const rb_motion *motion,
                           const rb_solve_opts *opts, const rb_criteria *criteria,
                           const rb_design_opts *design, int n_threads,
                           rb_gap_result *out, rb_diag *diag)
{
    return rb_gap_recommend_memo(model, motion, opts, criteria, design, n_threads, NULL,
                                 out, diag);
}

rb_status rb_gap_recommend_memo(const rb_model *model, const rb_motion *motion,
                                const rb_solve_opts *opts, const rb_criteria *criteria,
                                const rb_design_opts *design, int n_threads,
                                rb_design_memo *memo, rb_gap_result *out, rb_diag *diag)
{
    rb_design_ctx ctx;
    rb_status st;
    memset(out, 0, sizeof *out);
    if (!model || !motion || !criteria || !design)
        return rb_design_fail(diag, RB_ERR_INVALID, "", "missing model, motion, criteria "
                              "or design options");
    if ((st = check_grid(design, model, diag)) != RB_OK
        || (st = rb_design_ctx_init(&ctx, model, motion, opts, criteria, diag)) != RB_OK)
        return st;
    /* the case's own gap at the motion's own level is a run the design
     * factors' scan may have made (and the yielding run too, for bolts
     * that yield anyway) */
    ctx.memo = memo;
    /* the range: gap_ratio_max, or max_gap over the lever arm where that is
     * less, but never below gap_ratio_min */
    double top = design->gap_ratio_max;
    out->bound = RB_GAP_BOUND_RATIO;
    out->max_gap_m = design->max_gap_m > 0 ? design->max_gap_m : 0;
    if (out->max_gap_m > 0 && out->max_gap_m / model->lever_arm_m < top) {
        top = fmax(out->max_gap_m / model->lever_arm_m, design->gap_ratio_min);
        out->bound = RB_GAP_BOUND_MAX_GAP;
    }
    size_t n = (size_t)floor((top - design->gap_ratio_min) / design->gap_ratio_step + 1e-9)
               + 1;
    /* the case's own gap is always a point, so that a case that passes at
     * it can never read "no gap meets" */
    double own = model->gap_m / model->lever_arm_m;
    double *ratios = malloc((n + 1) * sizeof *ratios);
    out->points = calloc(n + 1, sizeof *out->points);
    if (!ratios || !out->points) {
        free(ratios);
        rb_gap_result_free(out);
        return RB_ERR_NOMEM;
    }
    size_t k = 0, own_i = 0;
    int own_placed = 0;
    for (size_t i = 0; i < n; i++) {
        double x = design->gap_ratio_min + (double)i * design->gap_ratio_step;
        if (!own_placed && own <= x * (1 + 1e-12) + 1e-15) {
            own_placed = 1;
            own_i = k;
            if (fabs(own - x) > 1e-12 * fmax(own, 1e-3))
                ratios[k++] = own;
        }
        ratios[k++] = x;
    }
    if (!own_placed) {
        own_i = k;
        ratios[k++] = own;
    }
    n = k;
    out->n_points = n;
    out->own_gap_ratio = ratios[own_i];
    out->range_max = ratios[n - 1];
    out->own_above = own_i == n - 1 && own > top * (1 + 1e-12);
    for (size_t i = 0; i < n; i++)
        out->points[i].gap_ratio = ratios[i];
    st = run_grid(&ctx, ratios, &ratios[own_i], n_threads, out, diag);
    if (st == RB_OK && !out->points[own_i].evaluated) {
        /* below the highest failing gap: the walk did not reach it */
        rb_design_run run;
        rb_model m;
        model_at(&ctx, &ratios[own_i], &ratios[own_i], &m);
        rb_design_run_one(&ctx, &m, ctx.motion, &run);
        out->runs++;
        if (run.status != RB_OK)
            st = rb_design_fail(diag, run.status, "gap_ratio",
                                "the solver run at the case's own gap failed");
        else
            keep_point(&out->points[own_i], ratios[own_i], &run);
    }
    if (st == RB_OK)
        st = yield_run(&ctx, out, diag);
    if (st != RB_OK) {
        free(ratios);
        rb_gap_result_free(out);
        return st;
    }
    out->own_meets = out->points[own_i].meets;
    /* the passing run that reaches the end of the range */
    size_t first = (size_t)(out->fail_index + 1);
    out->found = first < n;
    out->gap_ratio = out->found ? ratios[first] : 0;
    if (!out->found && out->own_meets) {
        /* a larger gap fails: the case's own gap, which passes, is the
         * largest the search can stand behind */
        out->found = out->own_only = 1;
        out->gap_ratio = ratios[own_i];
    }
    out->gap_m = out->found ? out->gap_ratio * model->lever_arm_m : 0;
    free(ratios);
    return RB_OK;
}

void rb_gap_result_free(rb_gap_result *r)
{
    if (!r)
        return;
    free(r->points);
    r->points = NULL;
    r->n_points = 0;
}

void rb_gap_describe(const rb_gap_result *g, const rb_out_units *u, char *buf, size_t n)
{
    double gap = u ? g->gap_m / u->small_length_f : 1e3 * g->gap_m;
    const char *unit = u ? u->small_length : "mm";
    if (!buf || n == 0)
        return;
    if (g->n_points == 0) {
        snprintf(buf, n, "no gap ratio was evaluated");
        return;
    }
    char range[240];
    double lo = g->points[0].gap_ratio;
    const char *own = g->own_above ? ", and the case's own gap ratio above it" : "";
    if (g->bound == RB_GAP_BOUND_MAX_GAP)
        snprintf(range, sizeof range, "searched [%.4g, %.4g], bounded by design.max_gap "
                 "%.4g %s (above 1/4 in ASCE 7 13.6.4 doubles the force on snubbed "
                 "equipment)%s", lo, g->range_max,
                 u ? g->max_gap_m / u->small_length_f : 1e3 * g->max_gap_m, unit, own);
    else
        snprintf(range, sizeof range, "searched [%.4g, %.4g], bounded by "
                 "design.gap_ratio_max%s", lo, g->range_max, own);
    if (!g->found)
        snprintf(buf, n, "no gap ratio meets the criteria, the case's own %.4g neither "
                 "(%s)", g->own_gap_ratio, range);
    else if (g->own_only)
        snprintf(buf, n, "recommended gap ratio %.4g (gap %.4g %s), the case's own: it "
                 "meets the criteria, and the larger gap ratio %.4g fails (%s)",
                 g->gap_ratio, gap, unit, g->points[g->fail_index].gap_ratio, range);
    else
        snprintf(buf, n, "recommended gap ratio %.4g (gap %.4g %s): every grid gap ratio "
                 "from there to %.4g meets the criteria (%s)", g->gap_ratio, gap, unit,
                 g->range_max, range);
}
