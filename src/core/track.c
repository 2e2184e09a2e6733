/* Peaks of a run, and the dense output of the step whose points are
 * being tracked (solver.h, rb_span), which a peak between two of its
 * points is located on.
 *
 * Peaks of U and theta are taken at step ends and, inside a step, at the
 * roots of U' and theta' on the dense output, so a peak between two steps
 * is found to the integrator's accuracy rather than to the step size. Forces
 * and reactions come from the equations at the points visited, and their
 * peaks between those points are located on the same dense output. */
#include <math.h>
#include <string.h>
#include "rockbolt/interaction.h"
#include "bolt.h"
#include "minmax.h"
#include "root.h"
#include "solver.h"

/* out of line: the rare branch of a path that runs at every point */
#if defined(__GNUC__) || defined(__clang__)
#define RB_COLD __attribute__((noinline, cold))
#else
#define RB_COLD
#endif

static void note_displacements(rb_solver *sv, const double *y)
{
    rb_result *r = sv->res;
    r->max_u_m = rb_fmax(r->max_u_m, fabs(y[RB_Y_U]));
    r->max_theta_rad = rb_fmax(r->max_theta_rad, fabs(y[RB_Y_TH]));
}

/* The state and what the equations give besides it at t on the span's
 * dense output; 0 where there is none. An exact step's series is built on
 * first use, so that a step whose peaks stay below the running ones costs
 * nothing more. */
static int span_state(rb_solver *sv, double t, double *y, rb_aux *a)
{
    rb_span *sp = &sv->span;
    const rb_rk_step *st = sp->st;
    if (!st && sp->exact_tab >= 0 && rb_exact_span_state(sv, t, y, a))
        return 1;
    if (!st && sp->lazy == 1) {
        rb_rk_step *s = &sp->series;
        double h = rb_exact_dense(sv, sp->t0, sp->y0, sp->h, &s->ts);
        s->is_taylor = 1;
        s->t0 = sp->t0;
        s->h = h;
        /* a series that the order bound cut short does not reach the end */
        sp->lazy = h >= sp->h ? 2 : -1;
    }
    if (sp->lazy == 2)
        st = &sp->series;
    if (!st)
        return 0;
    if (st->is_taylor) {
        double v[RB_TS_CHECK];
        rb_taylor_check(&st->ts, t - st->t0, v);
        memcpy(y, v, 4 * sizeof *y);
        rb_taylor_aux_point(&sv->sys, &sv->disc, &st->ts, v, a);
    } else {
        rb_rk_dense_state(st, t, y);
        rb_dyn_rhs(&sv->sys, &sv->disc, t, y, NULL, a);
    }
    return 1;
}

/* The span: the step whose points are being tracked. */
static void set_span(rb_solver *sv, const rb_rk_step *st, double t0, double t1)
{
    sv->span.st = st;
    sv->span.lazy = 0;
    sv->span.exact_tab = -1;
    sv->span.t0 = t0;
    sv->span.t1 = t1;
}

/* A pulse that ends with a jump of the floor's acceleration makes every
 * tracked quantity jump with it, between the last step's end and this
 * step's start: the start is tracked as a point of its own, with windows
 * that start afresh, as at a transition. */
void rb_track_span(rb_solver *sv, const rb_rk_step *st, double t0, double t1)
{
    set_span(sv, st, t0, t1);
    if (sv->sys.motion->kind != RB_MOTION_PULSE || !sv->track_have || sv->track_t != t0)
        return;
    double y[RB_NY] = {0};
    rb_aux a;
    /* a step within the pulse starts where the last one ended, to
     * rounding */
    if (span_state(sv, t0, y, &a)
        && fabs(a.x - sv->track_x) > 1e-9 * rb_fmax(fabs(a.x), fabs(sv->track_x))) {
        rb_track_reset(sv);
        rb_track_aux(sv, t0, y, &a);
    }
}

void rb_track_span_series(rb_solver *sv, double t0, const double *y0, double h, double t1)
{
    set_span(sv, NULL, t0, t1);
    sv->span.lazy = 1;
    sv->span.h = h;
    memcpy(sv->span.y0, y0, sizeof sv->span.y0);
}

void rb_track_span_exact(rb_solver *sv, double t0, const double *y0, double h, double t1,
                         int tab, const double *z0)
{
    rb_track_span_series(sv, t0, y0, h, t1);
    sv->span.exact_tab = tab;
    sv->span.exact_formed = 0;
    memcpy(sv->span.exact_z0, z0, sizeof sv->span.exact_z0);
}

void rb_track_span_none(rb_solver *sv)
{
    set_span(sv, NULL, 0, 0);
}

/* At the case's tolerance the series put the total shear's located peaks
 * of runs on the floor through a 30 Hz building 1.4e-8 from Taylor steps
 * at 1e-13, no closer than Taylor steps at the case's tolerance; at a
 * tenth, 6.6e-10. */
double rb_exact_dense(const rb_solver *sv, double t0, const double *y0, double h,
                      rb_taylor *ts)
{
    /* never past what double precision can meet, where the series would
     * run to its longest and stop short of the step */
    double f = rb_fmax(RB_DENSE_TOL_FACTOR, rb_fmin(1, RB_RTOL_MIN / sv->opts.rtol)), atol[RB_NY];
    for (int i = 0; i < RB_NY; i++)
        atol[i] = f * sv->atol[i];
    return rb_taylor_step(&sv->sys, &sv->disc, t0, y0, h, atol, f * sv->atol_x,
                          f * sv->opts.rtol, ts);
}

/* The quantities tracked between points, each with its window. */
enum { Q_SHEAR, Q_BOLT, Q_VERTICAL, Q_FRICTION, Q_ANCHOR };

/* What the tracked quantities read at one point: the floor's reactions,
 * the floor's share of the vertical one, a loaded row's force. */
typedef struct {
    double H, V, floor_v, tension, bolt;
} sample;

static void sample_of(const rb_solver *sv, const double *y, const rb_aux *a, sample *s)
{
    rb_dyn_reactions(&sv->sys, &sv->disc, y, a, &s->H, &s->V);
    s->tension = a->bolt_force > 0 ? a->bolt_force : 0;
    /* V is what floor and bolt give together; the floor presses on the
     * plate with that plus the tension of a loaded bolt, which pulls the
     * plate onto it, and friction works with the floor's share alone. */
    s->floor_v = s->V + s->tension;
    s->bolt = sv->disc.side != 0 ? s->tension : 0;
}

static double anchor_ratio(const rb_solver *sv, const sample *s, int *which)
{
    return rb_aci17_interaction_by((rb_aci17_interaction_rule)sv->opts.anchor_interaction,
                                   s->tension, sv->opts.anchor_phi_nn_n, fabs(s->H),
                                   sv->opts.anchor_phi_vn_n, which);
}

/* Each quantity as the larger the worse: the least floor reaction as the
 * peak of its negative. */
static double quantity(const rb_solver *sv, int q, const sample *s)
{
    double floor = sv->friction_floor;
    int which;
    switch (q) {
    case Q_SHEAR:
        return fabs(s->H);
    case Q_BOLT:
        return s->bolt;
    case Q_VERTICAL:
        return -s->floor_v;
    case Q_FRICTION:
        return s->floor_v > floor ? fabs(s->H) / s->floor_v : 0;
    default:
        return anchor_ratio(sv, s, &which);
    }
}

static int span_sample(rb_solver *sv, double t, sample *s)
{
    double y[RB_NY] = {0};
    rb_aux a;
    if (!span_state(sv, t, y, &a))
        return 0;
    sample_of(sv, y, &a, s);
    return 1;
}

/* The vertex (tv, vv) of the parabola through three points, where it is a
 * maximum between the outer two; 0 where it is not. */
static int parabola_vertex(const double *t, const double *v, double *tv, double *vv)
{
    double h0 = t[1] - t[0], h1 = t[2] - t[1];
    if (!(h0 > 0 && h1 > 0))
        return 0;
    double d0 = (v[1] - v[0]) / h0, d1 = (v[2] - v[1]) / h1;
    double curv = (d1 - d0) / (h0 + h1); /* half the second derivative */
    if (!(curv < 0))
        return 0;
    /* slope at t1 from the parabola, then the vertex */
    double slope = d0 + curv * h0;
    double dt = -slope / (2 * curv);
    if (!(dt >= -h0 && dt <= h1))
        return 0;
    *tv = t[1] + dt;
    *vv = v[1] + slope * dt + curv * dt * dt;
    return 1;
}

/* Quantity q less a level (0 for a peak), on the span's dense output. */
typedef struct {
    rb_solver *sv;
    int q;
    double level;
} refine_ctx;

static double refine_at(const void *ctx, double t)
{
    const refine_ctx *c = ctx;
    sample s;
    return span_sample(c->sv, t, &s) ? quantity(c->sv, c->q, &s) - c->level : -HUGE_VAL;
}

/* The largest value of c's quantity in [ts[0], ts[1]], an interval known
 * at its ends only, where the quantity is most often monotone: its
 * middle, a probe 1e-8 of the interval inside the higher end (a peak a few
 * microseconds into a step is seen by no other point), and the vertex of
 * the parabola through the three where that lies above both ends tell
 * whether a peak lies inside, and bracket it for the search. ts and vs
 * have room for four points. */
static double edge_peak(const refine_ctx *c, double *ts, double *vs, double *at)
{
    double tm = 0.5 * (ts[0] + ts[1]), vm = refine_at(c, tm), hi = rb_fmax(vs[0], vs[1]);
    ts[2] = ts[1];
    vs[2] = vs[1];
    ts[1] = tm;
    vs[1] = vm;
    double tol = 3e-5 * (ts[2] - ts[0]);
    if (vm > hi)
        return rb_max_brent(refine_at, c, ts, vs, 3, tol, at);
    int left = vs[0] >= vs[2];
    double tp = left ? ts[0] + 1e-8 * (ts[2] - ts[0]) : ts[2] - 1e-8 * (ts[2] - ts[0]);
    double vp = refine_at(c, tp);
    /* the probe is compared with its end on the same dense output: a
     * step's first point is the last step's end, whose series leaves it
     * within the tolerance (1e-7) of this one's, far more than the rise
     * over 1e-8 of the interval */
    double ve = left ? vs[0] : vs[2];
    if (left && ts[0] == c->sv->span.t0 && vp <= hi)
        ve = refine_at(c, ts[0]);
    if (vp > hi || (vp > ve && vp >= vm)) {
        double tb[3] = {left ? ts[0] : tm, tp, left ? tm : ts[2]};
        double vb[3] = {left ? ve : vm, vp, left ? vm : ve};
        return rb_max_brent(refine_at, c, tb, vb, 3, tol, at);
    }
    double tv, vv;
    if (!parabola_vertex(ts, vs, &tv, &vv) || !(vv > hi) || !(tv > ts[0] && tv < ts[2])
        || tv == tm) {
        *at = tm;
        return vm;
    }
    double fv = refine_at(c, tv);
    if (!(fv > hi)) {
        *at = fv > vm ? tv : tm;
        return rb_fmax(fv, vm);
    }
    /* the vertex above both ends and the middle: it and its two
     * neighbours bracket the peak */
    int k = tv < tm ? 1 : 2;
    for (int i = 3; i > k; i--) {
        ts[i] = ts[i - 1];
        vs[i] = vs[i - 1];
    }
    ts[k] = tv;
    vs[k] = fv;
    return rb_max_brent(refine_at, c, ts + k - 1, vs + k - 1, 3, tol, at);
}

/* On an exact step of the floor (a one-panel table) the shear, the
 * friction demand |H| / W and the anchors' interaction at no tension all
 * peak where the total shear turns: the largest of the quantity at those
 * turns (rb_exact_span_shear_turns, Newton on the step's own polynomial)
 * and at the m points (t, v) given, and where it is; -HUGE_VAL where the
 * span has no polynomial. */
static double exact_turns_peak(const refine_ctx *c, const double *ts, const double *vs, int m,
                               double *at)
{
    double tr[8];
    int k = rb_exact_span_shear_turns(c->sv, ts[0], ts[m - 1], tr, 8);
    if (k < 0)
        return -HUGE_VAL;
    double best = vs[0];
    *at = ts[0];
    for (int i = 1; i < m; i++)
        if (vs[i] > best) {
            best = vs[i];
            *at = ts[i];
        }
    for (int i = 0; i < k; i++) {
        double v = refine_at(c, tr[i]);
        if (v > best) {
            best = v;
            *at = tr[i];
        }
    }
    return best;
}

/* The largest value of quantity q between the first and the last of the
 * n points (t, v) on the span's dense output, and where it is; -HUGE_VAL
 * where there is none. A tenth of a per mille of the interval puts the
 * value within about 1e-9 of the peak's height relative to its
 * curvature. */
static double refine(rb_solver *sv, int q, const double *t, const double *v, int n,
                     double *at)
{
    const rb_span *sp = &sv->span;
    double ts[4], vs[4];
    int m = 0;
    /* a window reaches back into the last step at most by its first point,
     * whose part of the peak that step's rising end took */
    for (int i = 0; i < n; i++)
        if (t[i] >= sp->t0 && t[i] <= sp->t1) {
            ts[m] = t[i];
            vs[m++] = v[i];
        }
    if (m < 2 || !(ts[m - 1] > ts[0]) || (!sp->st && sp->lazy <= 0))
        return -HUGE_VAL;
    refine_ctx c = {sv, q, 0};
    if (q == Q_SHEAR || q == Q_FRICTION || q == Q_ANCHOR) {
        double ve = exact_turns_peak(&c, ts, vs, m, at);
        if (ve > -HUGE_VAL)
            return ve;
    }
    if (m == 2)
        return edge_peak(&c, ts, vs, at);
    return rb_max_brent(refine_at, &c, ts, vs, m, 3e-5 * (ts[m - 1] - ts[0]), at);
}

/* The two searches of peak_push, out of line: most points push and
 * return (a point is the window's crest about once a half period, and a
 * step's end or a transition's first interval once a step), and the
 * push then costs less than a call's saved registers. */
static int span_covers(const rb_solver *sv, double t0, double t);

static RB_COLD double peak_edge(rb_solver *sv, rb_peak_window *w, int q, double v,
                                double best, double *at)
{
    int k = w->n - 2;
    double vk = w->v[k], tr, vr;
    double hi = v > vk ? v : vk, reach = v > vk ? v - vk : vk - v;
    /* two ends alike say nothing of a crest between them: the
     * window's other interval bounds the slope there */
    if (w->n == 3)
        reach = rb_fmax(reach, fabs(w->v[1] - w->v[0]));
    else if (!(hi + 0.5 * reach > best) && span_covers(sv, w->t[0], w->t[1])) {
        /* a window's first interval: the quantity jumped at the
         * transition before it and can turn inside, where the one
         * difference bounds nothing (a floor reaction 0.8 ms below zero
         * 1.4 ms after a floor impact, between two points 2.9 ms apart
         * well above it); its middle halves the interval */
        refine_ctx c = {sv, q, 0};
        double vm = refine_at(&c, 0.5 * (w->t[0] + w->t[1]));
        reach = rb_fmax(fabs(vm - vk), fabs(v - vm));
        hi = rb_fmax(hi, vm);
    }
    if (hi + 0.5 * reach > best && (vr = refine(sv, q, w->t + k, w->v + k, 2, &tr)) > v) {
        *at = tr;
        return vr;
    }
    return v;
}

static RB_COLD double peak_crest(rb_solver *sv, rb_peak_window *w, int q, double t, double v,
                                 double best, double *at)
{
    double tr, vr;
    double up = w->v[1] - w->v[0], down = w->v[1] - w->v[2], reach = up > down ? up : down;
    if (!(reach > 0) || !(w->v[1] + 0.5 * reach > best))
        return w->v[1];
    if ((vr = refine(sv, q, w->t, w->v, 3, &tr)) > -HUGE_VAL) {
        *at = vr > v ? tr : t;
        return rb_fmax(v, vr);
    }
    double tv, vv;
    return parabola_vertex(w->t, w->v, &tv, &vv) ? rb_fmax(v, vv) : rb_fmax(v, w->v[1]);
}

/* Shift (t, v) into the window and return the largest value of the
 * quantity since the window's last point, and where it is (*at). The
 * points are check points of a step (a few per period of the fastest
 * mode) and step ends; between them a peak that could pass the running
 * one (best) is located on the step's dense output: where the middle of
 * the three points is the largest, over the three; where a step ends
 * rising, over its last interval (the next step's window cannot reach
 * back into it); and where a window's first interval falls from a
 * transition, over that interval. Between points a third of a period apart a sinusoid
 * exceeds the larger by at most a third of their difference (a fifth at a
 * quarter period; the points are an eighth of the fastest mode's period
 * apart, a quarter of the period of its square), so a peak is located
 * where the larger point and half the difference pass the running peak. Where
 * the span has no dense output, the vertex of the parabola through the
 * three points takes the peak to third order in their spacing. */
static inline double peak_push(rb_solver *sv, rb_peak_window *w, int q, double t, double v,
                               double best, double *at)
{
    if (w->n == 3) {
        w->t[0] = w->t[1]; w->v[0] = w->v[1];
        w->t[1] = w->t[2]; w->v[1] = w->v[2];
        w->n = 2;
    }
    w->t[w->n] = t;
    w->v[w->n] = v;
    w->n++;
    *at = t;
    if (w->n < 3 || !(w->v[1] >= w->v[0] && w->v[1] >= w->v[2])) {
        if (w->n < 2)
            return v;
        double vk = w->v[w->n - 2];
        /* a window's first interval, after a transition, falling; or a
         * step's last, rising */
        if (!((w->n == 2 && v < vk) || (v > vk && t == sv->span.t1)))
            return v;
        return peak_edge(sv, w, q, v, best, at);
    }
    return peak_crest(sv, w, q, t, v, best, at);
}

/* Whether the span's dense output covers [t0, t]. */
static int span_covers(const rb_solver *sv, double t0, double t)
{
    const rb_span *sp = &sv->span;
    return t0 >= sp->t0 && t <= sp->t1 && (sp->st || sp->lazy > 0);
}

/* Where the floor's reaction passes the level between the last point
 * (t0, v0) and (t, v), on the span's dense output; the straight line
 * between them where the span has none. */
static double floor_crossing(rb_solver *sv, double t0, double v0, double t, double v,
                             double level)
{
    if (span_covers(sv, t0, t) && (v0 - level) * (v - level) < 0) {
        /* the least reaction's quantity is the reaction's negative */
        refine_ctx c = {sv, Q_VERTICAL, -level};
        return rb_root_illinois(refine_at, &c, t0, t, level - v0, level - v, 1e-14);
    }
    return t0 + (t - t0) * (v0 - level) / (v0 - v);
}

/* Where the floor's reaction crosses zero between (t0, v0) and (t, v):
 * regula falsi (Illinois) on the span's dense output from the straight
 * line's crossing, until a step moves it by at most 1e-4 of the interval
 * (the straight line alone where the span has none). The total time off
 * the floor adds some two thousand crossings a run, too many for a root
 * to rounding each; one falsi step, as before, was 1.3e-2 off the time
 * with two check points a step (docs/solver.md, "Peaks between check
 * points"). */
static double falsi_crossing(rb_solver *sv, double t0, double v0, double t, double v)
{
    double a = t0, fa = v0, b = t, fb = v, x = t0 + (t - t0) * v0 / (v0 - v);
    if (!span_covers(sv, t0, t))
        return x;
    refine_ctx c = {sv, Q_VERTICAL, 0};
    double tol = 1e-4 * (t - t0);
    int last = 0;
    for (int k = 0; k < 20; k++) {
        double fx = -refine_at(&c, x);
        if (!isfinite(fx) || fx == 0)
            return x;
        rb_illinois_narrow(&a, &fa, &b, &fb, &last, x, fx);
        double next = a + (b - a) * fa / (fa - fb);
        if (!(fabs(next - x) > tol))
            return next;
        x = next;
    }
    return x;
}

/* Time with the floor's reaction at or below zero, each crossing of zero
 * between the points visited taken by falsi_crossing; a point at the
 * time of the one before (the two sides of a transition) only replaces
 * it. */
static void note_liftoff(rb_solver *sv, double t, double v)
{
    rb_result *r = sv->res;
    if (sv->lift_have && t > sv->lift_t) {
        double t0 = sv->lift_t, v0 = sv->lift_v, dt = t - t0;
        if (v0 <= 0 && v <= 0)
            r->liftoff_time_s += dt;
        else if (v0 <= 0 || v <= 0) {
            double tc = falsi_crossing(sv, t0, v0, t, v);
            if (v0 <= 0)
                r->liftoff_time_s += tc - t0;
            else {
                r->liftoff_time_s += t - tc;
                /* the first is located: one root a run */
                if (r->liftoff_first_s < 0)
                    r->liftoff_first_s = floor_crossing(sv, t0, v0, t, v, 0);
            }
        }
    }
    if (v <= 0 && r->liftoff_first_s < 0)
        r->liftoff_first_s = t;
    sv->lift_have = 1;
    sv->lift_t = t;
    sv->lift_v = v;
}

/* The two points of the least reaction's window on either side of a dip
 * it located at `at`, where both hold a reaction above level: (t0, v0) and
 * (t1, v1), the reactions themselves (the window holds their negatives).
 * 0 where the dip is not of that kind. */
static int dip_bracket(const rb_peak_window *w, double at, double level, double *t0,
                       double *v0, double *t1, double *v1)
{
    int k = -1;
    for (int i = 0; i < w->n && w->t[i] < at; i++)
        k = i;
    if (k < 0 || k + 1 >= w->n || !(-w->v[k] > level && -w->v[k + 1] > level))
        return 0;
    *t0 = w->t[k];
    *v0 = -w->v[k];
    *t1 = w->t[k + 1];
    *v1 = -w->v[k + 1];
    return 1;
}

/* Whether the points a window keeps when the next one is pushed all hold
 * a reaction above level (the window holds their negatives). */
static int window_above(const rb_peak_window *w, double level)
{
    for (int i = w->n == 3 ? 1 : 0; i < w->n; i++)
        if (!(-w->v[i] > level))
            return 0;
    return 1;
}

/* A dip of the floor's reaction to zero or below at `at`, between two
 * points above zero: the points alone never show it, so its time off the
 * floor (between the crossings on either side, as note_liftoff takes
 * them) and, where it is the first, the first lift-off are taken here. */
static void note_dip(rb_solver *sv, double at, double least)
{
    rb_result *r = sv->res;
    double t0, v0, t1, v1;
    if (!dip_bracket(&sv->win_vertical, at, 0, &t0, &v0, &t1, &v1))
        return;
    if (r->liftoff_first_s < 0)
        r->liftoff_first_s = floor_crossing(sv, t0, v0, at, least, 0);
    if (least < 0)
        r->liftoff_time_s += falsi_crossing(sv, at, least, t1, v1)
                             - falsi_crossing(sv, t0, v0, at, least);
}

/* A dip of the floor's reaction below the friction floor between two
 * points above it: the friction demand is largest at the floor's
 * crossings on either side (note_friction), which the points alone never
 * show. A cabinet under Taft lost its demand that way, 3.64 against
 * 4.036 (the reaction dipped 13 N below a floor of 423 N for 0.8 ms). */
static void note_friction_dip(rb_solver *sv, double at, double least)
{
    rb_result *r = sv->res;
    double floor = sv->friction_floor, t0, v0, t1, v1;
    if (!dip_bracket(&sv->win_vertical, at, floor, &t0, &v0, &t1, &v1))
        return;
    double tc[2] = {floor_crossing(sv, t0, v0, at, least, floor),
                    floor_crossing(sv, at, least, t1, v1, floor)};
    for (int i = 0; i < 2; i++) {
        sample c;
        if (span_sample(sv, tc[i], &c))
            r->max_friction_demand = rb_fmax(r->max_friction_demand, fabs(c.H) / floor);
    }
}

void rb_track_reset(rb_solver *sv)
{
    sv->win_shear.n = sv->win_friction.n = sv->win_bolt.n = sv->win_vertical.n = 0;
    sv->win_anchor.n = 0;
    sv->fric_have = 0;
}

/* The friction demand |H| / V where V > floor. Near the floor it is large
 * and steep, so its largest value is often where V crosses the floor: that
 * point is found between two points (on the step's dense output where the
 * demand there could pass the running one, else both linear), or the
 * largest value would be whichever point happened to fall just past the
 * crossing. */
static void note_friction(rb_solver *sv, double t, const sample *s)
{
    rb_result *r = sv->res;
    double floor = sv->friction_floor, H = s->H, v = s->floor_v;
    if (sv->fric_have && t > sv->fric_t && (sv->fric_v > floor) != (v > floor)) {
        double f = (floor - sv->fric_v) / (v - sv->fric_v);
        double h = fabs(sv->fric_h + f * (H - sv->fric_h));
        if ((h + fabs(H - sv->fric_h)) / floor > r->max_friction_demand
            && span_covers(sv, sv->fric_t, t)) {
            double tc = floor_crossing(sv, sv->fric_t, sv->fric_v, t, v, floor);
            sample c;
            if (span_sample(sv, tc, &c))
                h = fabs(c.H);
        }
        r->max_friction_demand = rb_fmax(r->max_friction_demand, h / floor);
    }
    sv->fric_have = 1;
    sv->fric_t = t;
    sv->fric_h = H;
    sv->fric_v = v;
    double at;
    if (v > floor)
        r->max_friction_demand
            = rb_fmax(r->max_friction_demand,
                   peak_push(sv, &sv->win_friction, Q_FRICTION, t, fabs(H) / v,
                             r->max_friction_demand, &at));
    else
        sv->win_friction.n = 0;
}

static void anchor_record(rb_result *r, double t, double u, int which, const sample *s)
{
    r->anchor_max_ratio = u;
    r->anchor_max_s = t;
    r->anchor_tension_n = s->tension;
    r->anchor_shear_n = fabs(s->H);
    r->anchor_clause = which;
}

/* The anchorage's demand: tension and shear at the same instant, in the
 * interaction of 17.8, not the largest of each taken apart; a peak between
 * points is kept only where it was located, so that its components are
 * those of one instant. */
static void note_anchor(rb_solver *sv, double t, const sample *s)
{
    rb_result *r = sv->res;
    int which;
    double u = anchor_ratio(sv, s, &which), at;
    r->anchor_checked = 1;
    double best = r->anchor_max_ratio;
    if (u > best)
        anchor_record(r, t, u, which, s);
    double ur = peak_push(sv, &sv->win_anchor, Q_ANCHOR, t, u, best, &at);
    sample c;
    if (ur > r->anchor_max_ratio && at != t && span_sample(sv, at, &c)) {
        double uc = anchor_ratio(sv, &c, &which);
        if (uc > r->anchor_max_ratio)
            anchor_record(r, at, uc, which, &c);
    }
}

int rb_track_quiet_bound(const rb_solver *sv, double shear_bound)
{
    const rb_result *r = sv->res;
    double W = sv->sys.d.W;
    /* the friction demand is |H| / W there, the least reaction W */
    if (!(W > sv->friction_floor) || !(r->min_vertical_reaction_n <= W)
        || !(shear_bound <= r->max_shear_total_n) || !(shear_bound / W <= r->max_friction_demand))
        return 0;
    if (sv->opts.anchor_phi_nn_n > 0 && sv->opts.anchor_phi_vn_n > 0) {
        /* the interaction rises with the shear at a given tension (none) */
        sample s = {shear_bound, W, W, 0, 0};
        if (!(anchor_ratio(sv, &s, &(int){0}) <= r->anchor_max_ratio))
            return 0;
    }
    return 1;
}

int rb_track_held_quiet(const rb_solver *sv, double force_hi, double shear_hi, double floor_lo)
{
    const rb_result *r = sv->res;
    int row = rb_row_of_side(sv->disc.side);
    if (!(floor_lo > 0) || !(floor_lo > sv->friction_floor)
        || !(floor_lo >= r->min_vertical_reaction_n) || !(force_hi <= r->max_bolt_force_n[row])
        || !(shear_hi <= r->max_shear_total_n) || !(shear_hi / floor_lo <= r->max_friction_demand))
        return 0;
    if (sv->opts.anchor_phi_nn_n > 0 && sv->opts.anchor_phi_vn_n > 0) {
        /* the interaction rises with the tension and with the shear */
        sample s = {shear_hi, floor_lo - force_hi, floor_lo, force_hi, force_hi};
        if (!(anchor_ratio(sv, &s, &(int){0}) <= r->anchor_max_ratio))
            return 0;
    }
    return 1;
}

void rb_track_held_points(rb_solver *sv, const double *t, const double (*y)[RB_NY],
                          const rb_aux *a)
{
    rb_track_reset(sv);
    rb_track_aux(sv, t[0], y[0], &a[0]);
    rb_track_aux(sv, t[1], y[1], &a[1]);
}

static void window_of_two(rb_peak_window *w, const double *t, double v0, double v1)
{
    w->n = 2;
    w->t[0] = t[0];
    w->t[1] = t[1];
    w->v[0] = v0;
    w->v[1] = v1;
}

/* What rb_track_aux does at two points after rb_track_reset where the
 * floor's reaction is W, the bolts slack and no span is set: a window of
 * one point returns it, and one of two refines nothing without a dense
 * output; the lift-off and friction crossings need a reaction on both
 * sides of a level, which W is not. */
void rb_track_quiet_points(rb_solver *sv, const double *t, const double *u, const double *H,
                           double x_last)
{
    rb_result *r = sv->res;
    double W = sv->sys.d.W, hs[2] = {fabs(H[0]), fabs(H[1])};
    rb_track_reset(sv);
    sv->track_have = 1;
    sv->track_t = t[1];
    sv->track_x = x_last;
    r->max_u_m = rb_fmax(r->max_u_m, rb_fmax(fabs(u[0]), fabs(u[1])));
    r->max_shear_total_n = rb_fmax(r->max_shear_total_n, rb_fmax(hs[0], hs[1]));
    window_of_two(&sv->win_shear, t, hs[0], hs[1]);
    window_of_two(&sv->win_vertical, t, -W, -W);
    r->min_vertical_reaction_n = rb_fmin(r->min_vertical_reaction_n, W);
    sv->lift_have = 1;
    sv->lift_t = t[1];
    sv->lift_v = W;
    sv->fric_have = 1;
    sv->fric_t = t[1];
    sv->fric_h = H[1];
    sv->fric_v = W;
    window_of_two(&sv->win_friction, t, hs[0] / W, hs[1] / W);
    r->max_friction_demand = rb_fmax(r->max_friction_demand, rb_fmax(hs[0], hs[1]) / W);
    if (sv->opts.anchor_phi_nn_n > 0 && sv->opts.anchor_phi_vn_n > 0) {
        double uu[2];
        r->anchor_checked = 1;
        for (int k = 0; k < 2; k++) {
            sample s = {H[k], W, W, 0, 0};
            int which;
            uu[k] = anchor_ratio(sv, &s, &which);
            if (uu[k] > r->anchor_max_ratio)
                anchor_record(r, t[k], uu[k], which, &s);
        }
        window_of_two(&sv->win_anchor, t, uu[0], uu[1]);
    }
}

void rb_track_aux(rb_solver *sv, double t, const double *y, const rb_aux *a)
{
    const rb_sys *S = &sv->sys;
    rb_result *r = sv->res;
    sample s;
    double at;
    sv->track_have = 1;
    sv->track_t = t;
    sv->track_x = a->x;
    note_displacements(sv, y);
    sample_of(sv, y, a, &s);
    if (s.bolt > 0) {
        int row = rb_row_of_side(sv->disc.side);
        r->max_bolt_force_n[row]
            = rb_fmax(r->max_bolt_force_n[row], peak_push(sv, &sv->win_bolt, Q_BOLT, t, s.bolt,
                                                       r->max_bolt_force_n[row], &at));
    }
    if (sv->opts.check_reactions) {
        double Hp, Vp;
        rb_dyn_reactions_points(S, &sv->disc, y, a, &Hp, &Vp);
        r->reaction_mismatch_n = rb_fmax(r->reaction_mismatch_n,
                                      rb_fmax(fabs(Hp - s.H), fabs(Vp - s.V)));
    }
    r->max_shear_total_n = rb_fmax(r->max_shear_total_n,
                                peak_push(sv, &sv->win_shear, Q_SHEAR, t, fabs(s.H),
                                          r->max_shear_total_n, &at));
    /* a least value is the peak of its negative; where the window's
     * points all lie above the friction floor, or above zero, a dip is
     * also located where it could pass that level, for the friction
     * demand and the time off the floor, which the points never show */
    double floor = sv->friction_floor, least_v = r->min_vertical_reaction_n;
    double gate = -least_v;
    if (least_v < floor && s.floor_v > floor && window_above(&sv->win_vertical, floor))
        gate = -floor;
    else if (least_v < 0 && s.floor_v > 0 && window_above(&sv->win_vertical, 0))
        gate = 0;
    double least = -peak_push(sv, &sv->win_vertical, Q_VERTICAL, t, -s.floor_v, gate, &at);
    r->min_vertical_reaction_n = rb_fmin(r->min_vertical_reaction_n, least);
    if (least <= 0 && at < t)
        note_dip(sv, at, least);
    if (least < floor && at < t)
        note_friction_dip(sv, at, least);
    note_liftoff(sv, t, s.floor_v);
    note_friction(sv, t, &s);
    if (sv->opts.anchor_phi_nn_n > 0 && sv->opts.anchor_phi_vn_n > 0)
        note_anchor(sv, t, &s);
}

void rb_track_point(rb_solver *sv, double t, const double *y)
{
    rb_aux a;
    rb_dyn_rhs(&sv->sys, &sv->disc, t, y, NULL, &a);
    rb_track_aux(sv, t, y, &a);
}

/* Component c of a Dormand-Prince step's dense output at t. */
typedef struct {
    const rb_rk_step *st;
    int c;
} dense_component;

static double dense_at(const void *ctx, double t)
{
    const dense_component *d = ctx;
    return rb_rk_dense_one(d->st, t, d->c);
}

/* Root of component c of the dense output in [a, b], where it changes sign
 * from fa to fb: Newton on a Taylor step's series, Illinois steps (which
 * converge superlinearly on these quartics) on Dormand-Prince's. */
static double dense_root(const rb_rk_step *st, int c, double a, double b, double fa,
                         double fb)
{
    if (st->is_taylor)
        return st->t0 + rb_taylor_rate_root(&st->ts, c, a - st->t0, b - st->t0, fa, fb,
                                            1e-14 * (1 + fabs(b)));
    dense_component d = {st, c};
    return rb_root_illinois(dense_at, &d, a, b, fa, fb, 1e-14);
}

void rb_track_interval(rb_solver *sv, const rb_rk_step *st, double ta, double tb,
                       const double (*ys)[RB_NY])
{
    double prev[RB_NY] = {0}, cur[RB_NY] = {0}, y[RB_NY] = {0};
    int n = st->n_sub;
    /* against a taut spring the bolt force peaks where theta' turns, which
     * is read there rather than by the parabola through the check points */
    int spring = st->is_taylor && sv->disc.stage == RB_STAGE_HELD
                 && !sv->sys.bolt->rigid_stop;
    if (ta == st->t0)
        memcpy(prev, st->y0, sizeof prev);
    else
        rb_rk_dense_state(st, ta, prev);
    /* one division per step: they are slow enough to show in a profile */
    double dt = (tb - ta) / n;
    for (int j = 1; j <= n; j++) {
        double t0 = ta + dt * (j - 1), t1 = j == n ? tb : ta + dt * j;
        if (ys)
            memcpy(cur, ys[j - 1], sizeof cur);
        else
            rb_rk_dense_state(st, t1, cur);
        static const int rates[2] = {RB_Y_UD, RB_Y_THD};
        for (int k = 0; k < 2; k++) {
            int c = rates[k], pc = c == RB_Y_UD ? RB_Y_U : RB_Y_TH;
            /* a rate that is zero at a check point (theta' at an uplift)
             * has its extremum there, where the state was noted */
            if ((prev[c] < 0) == (cur[c] < 0) || prev[c] == 0 || cur[c] == 0)
                continue;
            /* the root only matters for a new peak: over a check interval
             * (an eighth of the fastest period) the rate is monotone about
             * its zero, so the displacement there stays within this bound */
            double bound = rb_fmax(fabs(prev[pc]), fabs(cur[pc]))
                           + (t1 - t0) * (fabs(prev[c]) + fabs(cur[c]));
            int turn = spring && c == RB_Y_THD;
            if (turn || bound > (c == RB_Y_UD ? sv->res->max_u_m : sv->res->max_theta_rad)) {
                double tr = dense_root(st, c, t0, t1, prev[c], cur[c]);
                rb_rk_dense_state(st, tr, y);
                if (turn)
                    rb_track_point(sv, tr, y);
                else
                    note_displacements(sv, y);
            }
        }
        if (j < n && st->is_taylor) {
            /* a long step: forces and reactions at every check point, read
             * from the series */
            rb_aux a;
            double v[RB_TS_CHECK];
            if (ys)
                memcpy(v, st->vcheck[j - 1], sizeof v);
            else
                rb_taylor_check(&st->ts, t1 - st->t0, v);
            rb_taylor_aux_point(&sv->sys, &sv->disc, &st->ts, v, &a);
            rb_track_aux(sv, t1, cur, &a);
        } else if (j < n && sv->disc.stage == RB_STAGE_HELD)
            rb_track_point(sv, t1, cur);
        memcpy(prev, cur, sizeof prev);
    }
}
