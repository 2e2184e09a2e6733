/* The design factor of thesis sec. 6.6: A* over the largest peak floor
 * acceleration of a motion's shape that the anchorage withstands. The
 * response is not monotonic in the level, so the search scans upward on a
 * grid, stops at the first failing level and bisects below it. Threads
 * evaluate scan levels and bisection midpoints ahead of need; the decisions
 * read them in the order a single thread would, so the result is the
 * single-threaded one whatever the thread count.
 *
 * The scan and the bisection judge their runs without confirming a
 * marginal pass (docs/report-format.md, Confirmation): a confirmation can
 * only turn a pass into a fail, so only the pass the search ends on needs
 * one. When it does not hold, that level becomes the failing end and the
 * search bisects again below it, down from the pass before it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "design_internal.h"
#include "util/grow.h"

/* Largest scan grid accepted: a guard against a step of 1e-12. */
#define RB_SCAN_MAX_POINTS 100000
/* Most halvings of the bracket: one scan step halved 200 times is far
 * below the spacing of doubles, so a resolution finer than doubles can
 * resolve ends here (or sooner, where a midpoint equals an end) instead of
 * looping for ever. The case loader refuses such resolutions up front. */
#define RB_BISECT_MAX_HALVINGS 200

typedef struct {
    const rb_design_ctx *ctx;
    const double *levels_astar;
    rb_design_run *runs;
} factor_batch;

typedef struct {
    const rb_design_ctx *ctx;
    rb_design_factor_result *out;
    double *levels;        /* nt slots */
    rb_design_run *runs;   /* nt slots */
    size_t nt;
    int n_threads;
    double lo, hi;         /* current bracket in A*; hi = HUGE_VAL before a failure */
    double scan_end;
    double *passes;        /* every lo taken, increasing: where to go back to */
    size_t n_passes, cap_passes;
    double bound_pass;     /* a pass the caller's bound decides, not a run
                              (narrow_near); 0: none */
} factor_search;

/* Take level as the bracket's passing end, remembering the one before. */
static rb_status take_pass(factor_search *s, double level, const rb_design_run *run)
{
    if (s->n_passes == s->cap_passes) {
        double *p = rb_grow(s->passes, &s->cap_passes, sizeof *p, 32);
        if (!p)
            return RB_ERR_NOMEM;
        s->passes = p;
    }
    s->passes[s->n_passes++] = level;
    s->lo = level;
    memcpy(s->out->pass_reason, run->reason, sizeof s->out->pass_reason);
    return RB_OK;
}

static rb_status batch_job(void *v, size_t i)
{
    factor_batch *b = v;
    rb_motion m, vertical;
    rb_design_motion_at(b->ctx, b->levels_astar[i] * b->ctx->a_star_mps2, &m, &vertical);
    rb_design_run_one(b->ctx, b->ctx->model, &m, &b->runs[i]);
    return b->runs[i].status;
}

static rb_status eval_levels(factor_search *s, size_t n)
{
    factor_batch b = {s->ctx, s->levels, s->runs};
    return rb_pool_map(n, s->n_threads, batch_job, &b, NULL);
}

/* A run the search needs must have worked: there is no verdict otherwise. */
static rb_status check_run(const rb_design_run *run, double level, rb_diag *diag)
{
    char msg[200];
    if (run->status == RB_OK)
        return RB_OK;
    snprintf(msg, sizeof msg, "the solver run at %.6g A* failed: %s", level,
             rb_status_str(run->status));
    return rb_design_fail(diag, run->status, "motion", msg);
}

static rb_status check_grid(const rb_design_opts *d, rb_diag *diag)
{
    if (!(d->scan_start > 0) || !(d->scan_step > 0) || !(d->resolution > 0)
        || !isfinite(d->scan_start) || !isfinite(d->scan_step) || !isfinite(d->scan_end)
        || !isfinite(d->resolution) || !(d->scan_end >= d->scan_start))
        return rb_design_fail(diag, RB_ERR_INVALID, "design",
                              "the scan needs 0 < start <= end, step > 0, resolution > 0");
    if ((d->scan_end - d->scan_start) / d->scan_step + 1 > RB_SCAN_MAX_POINTS)
        return rb_design_fail(diag, RB_ERR_INVALID, "design.scan_step",
                              "the scan grid has more than 100000 levels");
    return RB_OK;
}

/* Scan the grid in rounds of nt levels; stop at the first failing one. */
static rb_status scan(factor_search *s, const rb_design_opts *d, rb_diag *diag)
{
    rb_design_factor_result *out = s->out;
    /* levels are start + k step, never accumulated, so that every thread
     * count sees the same doubles */
    size_t n_grid = (size_t)floor((d->scan_end - d->scan_start) / d->scan_step + 1e-9) + 1;
    for (size_t k = 0; k < n_grid;) {
        size_t n = n_grid - k < s->nt ? n_grid - k : s->nt;
        for (size_t j = 0; j < n; j++)
            s->levels[j] = rb_design_grid_point(d->scan_start + (double)(k + j) * d->scan_step);
        rb_status st = eval_levels(s, n);
        if (st != RB_OK)
            return st;
        for (size_t j = 0; j < n; j++) {
            const rb_design_run *run = &s->runs[j];
            out->scan_runs++;
            if ((st = check_run(run, s->levels[j], diag)) != RB_OK)
                return st;
            if (run->meets) {
                if ((st = take_pass(s, s->levels[j], run)) != RB_OK)
                    return st;
                continue;
            }
            s->hi = out->first_fail_astar = s->levels[j];
            memcpy(out->fail_reason, run->reason, sizeof out->fail_reason);
            out->fails_at_start = k + j == 0;
            out->runs_speculative += (long)(n - j - 1);
            return RB_OK;
        }
        k += n;
    }
    out->no_failure = 1;
    return RB_OK;
}

/* Bisect [lo, hi] to the resolution. Each round evaluates the first nt
 * nodes (breadth first) of the bisection tree below the bracket and then
 * walks down it as sequential bisection would. */
static rb_status bisect(factor_search *s, double res, rb_diag *diag)
{
    rb_design_factor_result *out = s->out;
    long halvings = 0;
    /* the bracket can be split while its midpoint lies strictly inside */
#define RB_SPLITTABLE(lo, hi) ((hi) - (lo) > res && 0.5 * ((lo) + (hi)) > (lo) \
                               && 0.5 * ((lo) + (hi)) < (hi))
    while (RB_SPLITTABLE(s->lo, s->hi) && halvings < RB_BISECT_MAX_HALVINGS) {
        double lo_k[64], hi_k[64];
        size_t m = s->nt < 63 ? s->nt : 63, depth = 0;
        /* no deeper than the halvings still needed: deeper nodes are waste */
        for (double w = s->hi - s->lo; w > res && depth < 6; w *= 0.5)
            depth++;
        if (m > ((size_t)1 << depth) - 1)
            m = ((size_t)1 << depth) - 1;
        lo_k[0] = s->lo;
        hi_k[0] = s->hi;
        for (size_t k = 0; k < m; k++) {
            double mid = 0.5 * (lo_k[k] + hi_k[k]);
            s->levels[k] = mid;
            if (2 * k + 2 < 64) {
                lo_k[2 * k + 1] = lo_k[k], hi_k[2 * k + 1] = mid;
                lo_k[2 * k + 2] = mid, hi_k[2 * k + 2] = hi_k[k];
            }
        }
        rb_status st = eval_levels(s, m);
        if (st != RB_OK)
            return st;
        size_t used = 0;
        for (size_t k = 0; k < m && RB_SPLITTABLE(s->lo, s->hi)
                           && halvings < RB_BISECT_MAX_HALVINGS; used++, halvings++) {
            const rb_design_run *run = &s->runs[k];
            out->bisect_runs++;
            if ((st = check_run(run, s->levels[k], diag)) != RB_OK)
                return st;
            if (run->meets) {
                if ((st = take_pass(s, s->levels[k], run)) != RB_OK)
                    return st;
                k = 2 * k + 2;
            } else {
                s->hi = s->levels[k];
                memcpy(out->fail_reason, run->reason, sizeof out->fail_reason);
                k = 2 * k + 1;
            }
        }
        out->runs_speculative += (long)(m - used);
    }
#undef RB_SPLITTABLE
    return RB_OK;
}

/* Narrow the bracket to the resolution above a level below which the
 * caller has shown that no level fails (a fragility's lift-off: the uplift
 * level, below which the base never leaves the floor), before bisecting:
 * half a resolution below it is a pass without a run, then levels above
 * it at 1, 2, 4, ... resolutions are run until one fails. Where the first
 * failing level is that near, one or two runs replace the bisection's
 * dozen; where it is not, what was run is a bracket the bisection goes on
 * from. A level outside the bracket is ignored. */
static rb_status narrow_near(factor_search *s, double near, double res, rb_diag *diag)
{
    rb_design_factor_result *out = s->out;
    double below = near - 0.5 * res;
    for (double step = 0; ; step = step > 0 ? 2 * step : res) {
        double level = below + step;
        if (!(level > s->lo && level < s->hi))
            return RB_OK;
        rb_motion m, vertical;
        rb_design_run run;
        rb_status st;
        if (step == 0) {
            memset(&run, 0, sizeof run);
            run.meets = 1;
            snprintf(run.reason, sizeof run.reason, "below %.6g A*, where no level fails",
                     near);
            if ((st = take_pass(s, level, &run)) != RB_OK)
                return st;
            s->bound_pass = level;
            continue;
        }
        rb_design_motion_at(s->ctx, level * s->ctx->a_star_mps2, &m, &vertical);
        rb_design_run_one(s->ctx, s->ctx->model, &m, &run);
        out->bisect_runs++;
        st = check_run(&run, level, diag);
        if (st != RB_OK)
            return st;
        if (!run.meets) {
            s->hi = level;
            memcpy(out->fail_reason, run.reason, sizeof out->fail_reason);
            return RB_OK;
        }
        if ((st = take_pass(s, level, &run)) != RB_OK)
            return st;
    }
}

/* How far a run is from failing, continuous in the level where the
 * criteria allow it: the usage over its limit less 1 (no-break, the bolts
 * stretching on, so that it goes on growing past the limit), the largest
 * row force over Fy less 1 before a row yields (no-yield; a run that
 * yielded, stopped there, says no more). NAN where there is none. */
static double run_margin(const rb_design_ctx *ctx, const rb_design_run *run)
{
    const rb_criteria *cr = ctx->criteria;
    const rb_result *r = &run->r;
    if (!cr || run->status != RB_OK)
        return NAN;
    if (cr->kind == RB_CRIT_NO_BREAK && isfinite(cr->usage_limit) && cr->usage_limit > 0
        && ctx->opts.stretch_past_failure && !r->overturned)
        return rb_design_max2(r->usage[0], r->usage[1]) / cr->usage_limit - 1;
    if (cr->kind == RB_CRIT_NO_YIELD && !r->yielded[0] && !r->yielded[1]
        && r->fy_row_n > 0)
        return rb_design_max2(r->max_bolt_force_n[0], r->max_bolt_force_n[1])
               / r->fy_row_n - 1;
    return NAN;
}

/* Where the margin crosses 0 between the bracket's ends, by the secant of
 * the two runs nearest it on either side (or of the two highest passes,
 * where the failing end has no margin); NAN where they give none inside
 * the bracket. A line through two passes that crosses 0 at or above a
 * failing end without a margin (a run stopped at its first yield: the
 * row force, near linear below Fy, ends there) says the crossing lies just
 * below that end, so the guess is half a resolution under it (half: the
 * caller's own half resolution below the guess): one run there that
 * passes closes the bracket, where halving it from a guess outside the
 * bracket took four or five runs. */
static double secant_guess(double lo, double m_lo, double lo2, double m_lo2, double hi,
                           double m_hi, double half)
{
    double x = NAN;
    if (isfinite(m_lo) && isfinite(m_hi) && m_hi > m_lo)
        x = lo + (hi - lo) * -m_lo / (m_hi - m_lo);
    else if (isfinite(m_lo) && isfinite(m_lo2) && m_lo > m_lo2 && lo > lo2) {
        x = lo + (lo - lo2) * -m_lo / (m_lo - m_lo2);
        if (!isfinite(m_hi) && x >= hi)
            x = hi - half;
    }
    return x > lo && x < hi ? x : (double)NAN;
}

/* The margins the secant reads: of the bracket's ends and of the pass
 * below lo. */
typedef struct {
    double m_lo, lo2, m_lo2, m_hi;
} margins;

/* Run level inside the bracket and make it the end it gives. */
static rb_status probe(factor_search *s, double level, margins *g, rb_diag *diag)
{
    rb_design_run run;
    rb_motion m, vertical;
    rb_design_motion_at(s->ctx, level * s->ctx->a_star_mps2, &m, &vertical);
    rb_design_run_one(s->ctx, s->ctx->model, &m, &run);
    s->out->bisect_runs++;
    rb_status st = check_run(&run, level, diag);
    if (st != RB_OK)
        return st;
    double margin = run_margin(s->ctx, &run);
    if (!run.meets) {
        s->hi = level;
        g->m_hi = margin;
        memcpy(s->out->fail_reason, run.reason, sizeof s->out->fail_reason);
        return RB_OK;
    }
    g->lo2 = s->lo;
    g->m_lo2 = g->m_lo;
    g->m_lo = margin;
    return take_pass(s, level, &run);
}

/* The margin of a run the search has made (from the memo). */
static double margin_at(const factor_search *s, double level)
{
    rb_design_run run;
    rb_motion m, vertical;
    rb_design_motion_at(s->ctx, level * s->ctx->a_star_mps2, &m, &vertical);
    rb_design_run_one(s->ctx, s->ctx->model, &m, &run);
    return run_margin(s->ctx, &run);
}

/* Narrow the bracket by the margin's secant (run_margin) before the
 * bisection: a run a little under half a resolution below where the
 * margin's line crosses 0 and, if it passes, one as far above it; where
 * the line is right they are the bracket, under one resolution wide, in
 * two runs instead of the bisection's six from a 0.05 A* scan step. A
 * round that does not halve the bracket is followed by a bisection step,
 * as where the line gives no crossing inside the bracket. Each run is an
 * end of the bracket whatever it gives, so the result is a failing level
 * within the resolution above a pass, as the bisection's; no monotonicity
 * is assumed: a bracket holds a crossing because its ends pass and fail. */
static rb_status straddle(factor_search *s, double res, rb_diag *diag)
{
    margins g = {NAN, NAN, NAN, NAN};
    if (s->lo > 0)
        g.m_lo = margin_at(s, s->lo);
    g.m_hi = margin_at(s, s->hi);
    if (!isfinite(g.m_lo) && !isfinite(g.m_hi))
        return RB_OK;    /* no margin: the bisection's, threads and all */
    if (s->n_passes >= 2) {
        g.lo2 = s->passes[s->n_passes - 2];
        g.m_lo2 = margin_at(s, g.lo2);
    }
    const double half = 0.45 * res;
    int halve = 0;
    rb_status st = RB_OK;
    for (int round = 0; s->hi - s->lo > res && round < 8 && st == RB_OK; round++) {
        double width = s->hi - s->lo;
        double x = halve ? (double)NAN
                         : secant_guess(s->lo, g.m_lo, g.lo2, g.m_lo2, s->hi, g.m_hi, half);
        if (!isfinite(x) || !(x - half > s->lo || x + half < s->hi)) {
            st = probe(s, 0.5 * (s->lo + s->hi), &g, diag);
            halve = 0;
            continue;
        }
        if (x - half > s->lo)
            st = probe(s, x - half, &g, diag);
        /* a pass below x: the level above it closes the bracket */
        if (st == RB_OK && s->lo >= x - half && x + half < s->hi)
            st = probe(s, x + half, &g, diag);
        halve = s->hi - s->lo > 0.5 * width;
    }
    return st;
}

/* Confirm the pass the search ended on; while it does not hold, make it
 * the failing end and bisect again from the pass before it (0 when there
 * is none, as when the scan fails at its first level). */
static rb_status confirm_pass(factor_search *s, double res, rb_diag *diag)
{
    rb_design_factor_result *out = s->out;
    rb_design_ctx full = *s->ctx;
    full.defer_confirm = 0;
    /* a pass the bound decides holds at any tolerance: it has no run */
    while (s->lo > 0 && s->lo != s->bound_pass) {
        rb_motion m, vertical;
        rb_design_run run;
        rb_design_motion_at(&full, s->lo * full.a_star_mps2, &m, &vertical);
        rb_design_run_one(&full, full.model, &m, &run);
        rb_status st = check_run(&run, s->lo, diag);
        if (st != RB_OK)
            return st;
        if (run.meets)
            return RB_OK;
        /* the pass is not confirmed: a fail at that level */
        s->hi = s->lo;
        memcpy(out->fail_reason, run.reason, sizeof out->fail_reason);
        if (out->no_failure) {
            out->no_failure = 0;
            out->first_fail_astar = s->hi;
        }
        s->n_passes--;
        s->lo = s->n_passes ? s->passes[s->n_passes - 1] : 0;
        out->pass_reason[0] = '\0';
        out->confirm_fails++;
        if ((st = bisect(s, res, diag)) != RB_OK)
            return st;
    }
    return RB_OK;
}

static void finish(factor_search *s, double a_star, double res)
{
    rb_design_factor_result *out = s->out;
    out->a_star_mps2 = a_star;
    out->resolution_astar = res;
    out->scan_end_astar = s->scan_end;
    out->level_astar = s->lo;
    out->level_mps2 = s->lo * a_star;
    out->factor = s->lo > 0 ? 1.0 / s->lo : HUGE_VAL;
    out->fail_astar = s->hi;
    out->fail_mps2 = out->no_failure ? HUGE_VAL : s->hi * a_star;
    out->bracket_astar = out->no_failure ? 0 : s->hi - s->lo;
    out->runs = out->scan_runs + out->bisect_runs;
}

rb_status rb_design_factor(const rb_model *model, const rb_motion *motion,
                           const rb_solve_opts *opts, const rb_criteria *criteria,
                           const rb_design_opts *design, int n_threads,
                           rb_design_memo *memo, rb_design_factor_result *out,
                           rb_diag *diag)
{
    return rb_design_factor_near(model, motion, opts, criteria, design, n_threads, memo,
                                 NULL, out, diag);
}

rb_status rb_design_factor_near(const rb_model *model, const rb_motion *motion,
                                const rb_solve_opts *opts, const rb_criteria *criteria,
                                const rb_design_opts *design, int n_threads,
                                rb_design_memo *memo, const rb_design_hints *hints,
                                rb_design_factor_result *out, rb_diag *diag)
{
    double near_astar = hints ? hints->near_astar : 0;
    rb_design_ctx ctx;
    factor_search s;
    rb_status st;
    memset(out, 0, sizeof *out);
    out->first_fail_astar = out->fail_astar = out->fail_mps2 = HUGE_VAL;
    if (!model || !motion || !criteria || !design)
        return rb_design_fail(diag, RB_ERR_INVALID, "", "missing model, motion, criteria "
                              "or design options");
    if ((st = check_grid(design, diag)) != RB_OK
        || (st = rb_design_ctx_init(&ctx, model, motion, opts, criteria, diag)) != RB_OK)
        return st;
    ctx.memo = memo;
    ctx.defer_confirm = 1;
    memset(&s, 0, sizeof s);
    s.ctx = &ctx;
    s.out = out;
    s.n_threads = n_threads > 0 ? n_threads : rb_pool_threads_default();
    s.nt = (size_t)s.n_threads;
    s.hi = HUGE_VAL;
    s.scan_end = design->scan_end;
    s.levels = malloc(s.nt * sizeof *s.levels);
    s.runs = malloc(s.nt * sizeof *s.runs);
    if (!s.levels || !s.runs)
        st = RB_ERR_NOMEM;
    if (st == RB_OK)
        st = scan(&s, design, diag);
    if (st == RB_OK && !out->no_failure && near_astar > 0)
        st = narrow_near(&s, near_astar, design->resolution, diag);
    if (st == RB_OK && !out->no_failure && hints && hints->secant && !(near_astar > 0))
        st = straddle(&s, design->resolution, diag);
    /* Above a bound the levels run are below + k res, so a pass and the
     * failure next to it are one resolution apart in exact arithmetic;
     * the slack keeps a rounding of their difference from costing a run */
    double res = near_astar > 0 ? design->resolution * (1 + 1e-9) : design->resolution;
    if (st == RB_OK && !out->no_failure)
        st = bisect(&s, res, diag);
    if (st == RB_OK)
        st = confirm_pass(&s, res, diag);
    if (st == RB_OK)
        finish(&s, ctx.a_star_mps2, design->resolution);
    free(s.levels);
    free(s.runs);
    free(s.passes);
    return st;
}

void rb_design_factor_describe(const rb_design_factor_result *f, const rb_out_units *u,
                               double g_mps2, char *buf, size_t n)
{
    /* US customary reports show accelerations in g alone */
    int in_g = u && u->system == RB_UNITS_US && g_mps2 > 0;
    double k = in_g ? 1 / g_mps2 : 1;
    const char *unit = in_g ? "g" : "m/s^2";
    if (!buf || n == 0)
        return;
    if (f->no_failure)
        snprintf(buf, n, "no failing level up to scan_end (%.4g A*): the criteria are met "
                 "up to %.4f A* (%.4g %s) at least, so the design factor is at most "
                 "%.3g; %ld runs", f->scan_end_astar, f->level_astar, k * f->level_mps2,
                 unit, f->factor, f->runs);
    else if (!(f->level_astar > 0))
        snprintf(buf, n, "no level meets the criteria: fails at %.4f A* (%.4g %s) "
                 "already; resolution %.4g A*; %ld runs", f->fail_astar, k * f->fail_mps2,
                 unit, f->resolution_astar, f->runs);
    else
        snprintf(buf, n, "design factor %.3g: meets the criteria up to %.4f A* "
                 "(%.4g %s); fails at %.4f A* (first failing scan level %.4g A*); "
                 "resolution %.4g A*; %ld runs", f->factor, f->level_astar,
                 k * f->level_mps2, unit, f->fail_astar, f->first_fail_astar,
                 f->resolution_astar, f->runs);
    size_t len = strlen(buf);
    if (f->confirm_fails > 0 && len < n)
        len += (size_t)snprintf(buf + len, n - len, "; %ld higher pass%s not confirmed at "
                                "tighter tolerances", f->confirm_fails,
                                f->confirm_fails == 1 ? "" : "es");
    /* why the failing level fails, as its verdict line says it */
    if (!f->no_failure && f->fail_reason[0] && len < n)
        snprintf(buf + len, n - len, "; at %.4f A*: %s", f->fail_astar, f->fail_reason);
}
