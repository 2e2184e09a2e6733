/* The run loop of the restrained-rocking solver.
 *
 * Steps never straddle a kink or jump of the excitation (sample times, pulse
 * and ramp ends), so each Runge-Kutta step sees a smooth right-hand side.
 * After each accepted step the active guards are checked at four points of
 * the dense output; the earliest crossing is refined by the Illinois method
 * to ~1e-13 s and the transition applied there. A run has a bounded cost: a
 * step budget, a minimum step, and a bound on events per simulated second
 * (the rest criterion in transitions.c keeps impact series finite). */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "bolt.h"
#include "exact.h"
#include "minmax.h"
#include "root.h"
#include "stepper.h"

void rb_solve_opts_init(rb_solve_opts *o)
{
    memset(o, 0, sizeof *o);
    o->formulation = RB_FORM_LARGE;
    o->rtol = 1e-7;
    o->event_tol = 1e-3;
    o->rest_fraction = 1e-6;
    o->max_events_per_s = 20000;
    o->max_steps = 50000000;
    o->exact_floor = 1;
    o->min_checks = RB_MIN_CHECKS;
}

void rb_result_free(rb_result *r)
{
    if (!r)
        return;
    rb_history_free(r->history);
    r->history = NULL;
}

static rb_status fail(rb_solver *sv, rb_diag *diag, rb_status st, const char *what)
{
    return rb_diag_set(diag, st, NULL, 0, 0, "solver", "%s at t = %.6f s in stage %d",
                       what, sv->t, sv->disc.stage);
}

#define OPT_REQUIRE(cond, k, fmt, v) do { if (!(cond)) { if (diag) { \
        rb_diag_set_key(diag, "%s", k); \
        rb_diag_set_msg(diag, fmt, v); } \
        return RB_ERR_INVALID; } } while (0)

/* Options that would make a run unbounded or its tolerance unattainable
 * are refused up front, naming the limit. */
static rb_status check_opts(const rb_solve_opts *o, rb_diag *diag)
{
    OPT_REQUIRE(o->integrator == RB_INTEGRATOR_AUTO || o->integrator == RB_INTEGRATOR_RK45,
                "integrator", "must be auto or rk45 (got %d)", (int)o->integrator);
    OPT_REQUIRE(isfinite(o->rtol) && o->rtol >= RB_RTOL_MIN && o->rtol <= RB_RTOL_MAX,
                "rtol", "must be between 1e-13 (what double precision can meet) and 0.01 "
                "(got %g)", o->rtol);
    OPT_REQUIRE(o->max_events_per_s >= 1, "max_events_per_s", "must be at least 1 (got %g)",
                (double)o->max_events_per_s);
    OPT_REQUIRE(o->max_steps >= 1, "max_steps", "must be at least 1 (got %g)",
                (double)o->max_steps);
    OPT_REQUIRE(isfinite(o->rest_fraction) && o->rest_fraction >= 0 && o->rest_fraction < 1,
                "rest_fraction", "must be in [0, 1) (got %g)", o->rest_fraction);
    OPT_REQUIRE(isfinite(o->max_step_s), "max_step_s", "must be finite (got %g s)",
                o->max_step_s);
    OPT_REQUIRE(isfinite(o->history_dt_s) && o->history_dt_s >= 0, "history_dt_s",
                "must be finite and >= 0 (got %g s)", o->history_dt_s);
    OPT_REQUIRE(isfinite(o->theta_init_rad), "theta_init_rad", "must be finite (got %g)",
                o->theta_init_rad);
    return RB_OK;
}

static void fill_constants(rb_solver *sv, const rb_motion *motion)
{
    const rb_sys *S = &sv->sys;
    rb_result *r = sv->res;
    r->a_star_mps2 = S->d.a_star_mps2;
    r->a_uplift_mps2 = S->d.a_uplift_mps2;
    r->peak_floor_mps2 = rb_motion_peak(motion);
    r->min_vertical_reaction_n = HUGE_VAL; /* the first point sets it */
    r->liftoff_first_s = -1;
    r->u_static_m = S->model->rigid ? 0
                    : M_PI * M_PI * r->peak_floor_mps2 / (8 * S->d.omega * S->d.omega);
    r->alpha_rad = S->d.alpha;
    r->theta0_rad = S->d.theta0_rad;
    r->fy_row_n = S->d.fy_row_n;
    r->rigid_bolts = S->bolt->rows && S->bolt->rigid_stop;
    r->capacity_j = S->d.capacity_j;
    r->weight_n = S->d.W;
    r->delta = S->d.delta;
}

rb_status rb_solver_setup(rb_solver *sv, const rb_model *model, const rb_motion *motion,
                          const rb_solve_opts *opts, rb_result *out, rb_diag *diag)
{
    rb_sys *S = &sv->sys;
    memset(sv, 0, sizeof *sv);
    memset(out, 0, sizeof *out);
    sv->res = out;
    rb_track_span_none(sv);
    if (opts)
        sv->opts = *opts;
    else
        rb_solve_opts_init(&sv->opts);
    rb_status st = rb_model_derive(model, &S->d, diag);
    if (st != RB_OK)
        return st;
    if ((st = check_opts(&sv->opts, diag)) != RB_OK)
        return st;
    if ((st = rb_motion_vertical_check(motion, S->d.g, diag)) != RB_OK)
        return st;
    S->model = model;
    S->motion = motion;
    sv->memo.t = sv->memo.th = NAN;
    S->memo = &sv->memo;
    S->form = sv->opts.formulation;
    S->bolt = rb_bolt_ops_of(model->bolt_model);
    S->l = model->lever_arm_m;
    S->b = model->half_width_m;
    S->h = model->cm_height_m;
    S->M = model->mass_kg;
    sv->disc.gap[0] = sv->disc.gap[1] = model->gap_m;
    sv->disc.contact[0] = sv->disc.contact[1] = rb_dyn_contact_angle(S, model->gap_m);
    rb_disc_yield_angles(S, &sv->disc);
    sv->disc.stage = RB_STAGE_FIXED;
    fill_constants(sv, motion);
    if (!isfinite(out->peak_floor_mps2)) {
        memset(out, 0, sizeof *out);
        return fail(sv, diag, RB_ERR_INVALID, "the floor motion's amplitude or scale is not "
                    "finite");
    }
    sv->t_end = motion->duration_s;
    sv->friction_floor = RB_FRICTION_FLOOR * S->d.W;
    if (motion->vertical)
        sv->friction_floor = RB_FRICTION_FLOOR * S->M
                             * (S->d.g + rb_motion_least(motion->vertical, sv->t_end));
    if (!(isfinite(sv->t_end) && sv->t_end > 0))
        return fail(sv, diag, RB_ERR_INVALID, "the run needs a finite duration > 0");
    rb_control_init(sv);
    double th0 = S->bolt->rows ? rb_dyn_contact_angle(S, model->gap_m) : HUGE_VAL;
    sv->rest_theta = sv->opts.rest_fraction * rb_fmin(S->d.alpha, th0 > 0 ? th0 : S->d.alpha);
    if (sv->opts.theta_init_rad != 0) {
        double a0 = fabs(sv->opts.theta_init_rad);
        if (!(a0 < S->d.alpha && a0 < th0))
            return fail(sv, diag, RB_ERR_INVALID,
                        "initial rotation must be below alpha and the bolt contact angle");
        sv->y[RB_Y_TH] = sv->opts.theta_init_rad;
        sv->disc.side = sv->opts.theta_init_rad > 0 ? 1 : -1;
        sv->disc.stage = RB_STAGE_UPLIFT;
    }
    rb_exact_setup(sv);
    if (sv->opts.history_dt_s > 0) {
        out->history = calloc(1, sizeof *out->history);
        if (!out->history)
            return RB_ERR_NOMEM;
    }
    return RB_OK;
}

/* Illinois (modified regula falsi) on a guard along the dense output. */
static double locate(rb_solver *sv, const rb_rk_step *st, int guard, double a, double b,
                     double ga, double gb)
{
    double y[RB_NY] = {0}, level;
    if (st->is_taylor && rb_guard_angle(sv, guard, &level)) {
        /* Newton on the angle's series lands on the root to rounding;
         * the time returned must read as crossed, so step over it if the
         * root itself rounds to the near side */
        double tol = 1e-13 * (1 + fabs(b)), side = sv->disc.side;
        /* an angle guard is theta - level in the mirrored frame */
        double x = st->t0 + rb_taylor_angle_root(&st->ts, a - st->t0, b - st->t0, level,
                                                 side * ga, side * gb, 0.125 * tol);
        for (int k = 0; k < 8 && x < b; k++) {
            rb_rk_dense_state(st, x, y);
            double gx = rb_guard_one(sv, guard, x, y);
            /* rb_guard_crossed, not gx == 0: a root at a nudged start (the
             * contact angle right after a release) is not a crossing */
            if (rb_guard_crossed(guard, ga, gx))
                return x;
            if (!(x > a)) /* an end that does not read as crossed */
                break;
            /* a guard reading exactly 0 here has not left its nudged
             * start; ga keeps the start's side */
            a = x;
            if (gx != 0)
                ga = gx;
            x = rb_fmin(b, x + 0.125 * tol * (1 << k));
        }
        if (x >= b)
            return b;
    }
    /* a start nudged off the boundary (rb_guard_nudge) that reads exactly
     * 0 again has not moved: the crossing lies further on. Taken for one,
     * a plate released from the bolt heads, which the floor then pressed
     * back onto them, met them again at the release itself, and the state
     * went back and forth between stages 2 and 4, 1e-12 s a cycle, until
     * the work bound stopped the run (Dormand-Prince, 20 491 events) */
    int from_nudge = fabs(ga) == DBL_MIN;
    int last = 0, hugged = 1;
    for (int i = 0; i < 200 && b - a > 1e-13 * (1 + fabs(b)); i++) {
        double m = (a * gb - b * ga) / (gb - ga);
        /* fall back to bisection when the secant hugs an end twice in a
         * row (a guard nudged off zero at a has a near-zero ga); a single
         * hug is superlinear convergence, which bisection would slow */
        int hug = !(m > a + 1e-3 * (b - a) && m < b - 1e-3 * (b - a));
        if (!(m > a && m < b) || (hug && hugged))
            m = 0.5 * (a + b);
        hugged = hug;
        rb_rk_dense_state(st, m, y);
        double gm = rb_guard_one(sv, guard, m, y);
        if (gm == 0 ? !from_nudge : rb_guard_crossed(guard, ga, gm)) {
            b = m;
            gb = gm;
            if (last == -1) ga *= 0.5;
            last = -1;
        } else {
            a = m;
            if (gm != 0) {
                ga = gm;
                from_nudge = 0;
            }
            if (last == 1) gb *= 0.5;
            last = 1;
        }
    }
    return b;
}

/* The earliest guard that crosses over [ta, tb], where the guards read ga
 * and gb, with its time; -1 if none does. */
static int first_crossing(rb_solver *sv, const rb_rk_step *st, unsigned mask, double ta,
                          double tb, const double *ga, const double *gb, double *t_event)
{
    int best = -1;
    double tbest = HUGE_VAL;
    for (unsigned m = mask; m;) {
        int k = rb_guard_next(&m);
        if (!rb_guard_crossed(k, ga[k], gb[k]))
            continue;
        double tk = locate(sv, st, k, ta, tb, ga[k], gb[k]);
        if (tk < tbest) {
            tbest = tk;
            best = k;
        }
    }
    *t_event = tbest;
    return best;
}

/* Whether the guards are also read where theta' turns inside a check
 * interval. Against a taut spring the tension is a monotone function of
 * the angle, and a swing can reach Fy or go slack and come back within
 * one check interval (a contact lasts about half a period of the spring).
 * A free plate can likewise graze a level and turn back between two check
 * points: the angle then passes a bolt head (or the floor) and returns
 * with both ends on the near side, and only its turning point shows the
 * crossing (a 0.3 % pass through the bolt heads of fig-5.17, gap ratio
 * 1e-4, went unseen). */
static int reads_turns(const rb_solver *sv, const rb_rk_step *st)
{
    return st->is_taylor && rb_dyn_rocking(&sv->sys, &sv->disc);
}

/* Whether the guards are also read where the moment that holds the plate
 * down turns: held at its angle by a rigid row, the row's force follows
 * the floor and the frame, and a peak between two check points passed Fy
 * by 0.1 % with the yield unseen (a random 11 Hz cabinet under Taft;
 * Dormand-Prince yielded there). On the floor (stage 1) the uplift guards
 * are the same moment at theta = 0, and an uplift that peaks between two
 * check points went unseen the same way. */
static int reads_force_turns(const rb_solver *sv, const rb_rk_step *st)
{
    return st->is_taylor && (sv->disc.stage == RB_STAGE_FIXED
                             || (sv->disc.stage == RB_STAGE_HELD && sv->sys.bolt->rigid_stop));
}

/* The guards at tm inside [*ta, tb]: the crossing over [*ta, tm] if any;
 * else the interval goes on from tm. */
static int guards_at(rb_solver *sv, const rb_rk_step *st, unsigned mask, double *ta,
                     double tm, double *ga, double *t_event)
{
    double ym[RB_NY] = {0}, gm[G_COUNT];
    rb_rk_dense_state(st, tm, ym);
    rb_guard_eval(sv, tm, ym, gm);
    int ev = first_crossing(sv, st, mask, *ta, tm, ga, gm, t_event);
    if (ev < 0) {
        memcpy(ga, gm, sizeof gm);
        *ta = tm;
    }
    return ev;
}

static int any_crossed(unsigned mask, const double *ga, const double *gb)
{
    for (unsigned m = mask; m;) {
        int k = rb_guard_next(&m);
        if (rb_guard_crossed(k, ga[k], gb[k]))
            return 1;
    }
    return 0;
}

/* Whether the angle at the turn r could have passed one of the guards
 * since ta: a guard that is not an angle, or an angle level between the
 * two. The guards themselves are read only then: two Horner passes in
 * place of the state, the equations and every guard. */
static int turn_may_cross(const rb_solver *sv, const rb_rk_step *st, unsigned mask, double ta,
                          double r)
{
    double th_a = rb_taylor_one(&st->ts, ta - st->t0, RB_Y_TH);
    double th_r = rb_taylor_one(&st->ts, r - st->t0, RB_Y_TH), level;
    for (int k = 0; k < G_COUNT; k++)
        if ((mask & 1u << k)
            && (!rb_guard_angle(sv, k, &level) || (th_a - level) * (th_r - level) <= 0))
            return 1;
    return 0;
}

/* Turns of theta' inside [a, b], whose ends have the same sign (fa, fb):
 * two turns there let the angle pass a level and come back with both ends
 * on one side (after a floor impact at 1e-3 rad/s, a hop of 1.3 ms, and
 * the floor lifting the plate on the far side). theta' can only vanish
 * inside where |fa| + |fb| is at most the bound of |theta''| over the
 * step (thdd_max) times the interval; there the interval is halved, down
 * to a sign change, whose two turns are read, or to halves that cannot
 * hold one. Crossing levels twice takes a turn on the far side in
 * between, so the guards are read at the turns alone, in time order
 * (guards_at from *ta, which moves on). The crossing's index, or -1. */
static int hidden_turns(rb_solver *sv, const rb_rk_step *st, unsigned mask, double a,
                        double b, double fa, double fb, double thdd_max, double *ta,
                        double *ga, double *t_event, int depth)
{
    if (fabs(fa) + fabs(fb) > thdd_max * (b - a) || depth == 0)
        return -1;
    double tm = 0.5 * (a + b), fm = rb_taylor_one(&st->ts, tm - st->t0, RB_Y_THD);
    if (fm != 0 && (fm < 0) != (fa < 0)) {
        double tol = 1e-14 * (1 + fabs(b));
        double r[2] = {st->t0 + rb_taylor_rate_root(&st->ts, RB_Y_THD, a - st->t0,
                                                    tm - st->t0, fa, fm, tol),
                       st->t0 + rb_taylor_rate_root(&st->ts, RB_Y_THD, tm - st->t0,
                                                    b - st->t0, fm, fb, tol)};
        int ev = r[0] > *ta && r[0] < b && turn_may_cross(sv, st, mask, *ta, r[0])
                     ? guards_at(sv, st, mask, ta, r[0], ga, t_event) : -1;
        /* where theta' is itself a guard (a yielding row stops at its
         * zero), the turns are where it reads zero, on its boundary, so
         * it is read between them, past it */
        if (ev < 0 && (mask & 1u << G_UNLOAD) && tm > *ta)
            ev = guards_at(sv, st, mask, ta, tm, ga, t_event);
        if (ev < 0 && r[1] > *ta && r[1] < b && turn_may_cross(sv, st, mask, *ta, r[1]))
            ev = guards_at(sv, st, mask, ta, r[1], ga, t_event);
        return ev;
    }
    int ev = hidden_turns(sv, st, mask, a, tm, fa, fm, thdd_max, ta, ga, t_event, depth - 1);
    return ev >= 0 ? ev
                   : hidden_turns(sv, st, mask, tm, b, fm, fb, thdd_max, ta, ga, t_event,
                                  depth - 1);
}

typedef struct {
    rb_solver *sv;
    const rb_rk_step *st;
    int guard;
} graze_ctx;

/* The guard read toward its boundary: crossed where it turns positive. */
static double toward(const void *ctx, double t)
{
    const graze_ctx *c = ctx;
    double y[RB_NY] = {0};
    rb_rk_dense_state(c->st, t, y);
    return rb_guard_direction(c->guard) * rb_guard_one(c->sv, c->guard, t, y);
}

/* A Dormand-Prince step has no series whose turns could be read (see
 * reads_turns), so a guard that rises toward its boundary, passes it and
 * turns back inside one check interval shows the same side at both ends:
 * a rigid body through a 16.7 Hz building lifted for 3 ms by 0.14 % over
 * its uplift level, and the hop went unseen at every tolerance. The guards
 * are also read at the interval's midpoint (tm); a guard whose parabola
 * through its three readings peaks inside, within the parabola's own
 * curvature of its boundary, is followed to its peak (Brent on the dense
 * output), where all guards are read (guards_at, which moves *ta on). An
 * interval an eighth of the fastest period long holds one turn of a guard
 * at most, near enough a parabola. The crossing's index, or -1. */
static int grazes(rb_solver *sv, const rb_rk_step *st, unsigned mask, double *ta, double tb,
                  double *ga, const double *gb, double *t_event)
{
    double a = *ta, tm = 0.5 * (a + tb), ym[RB_NY] = {0}, gm[G_COUNT];
    rb_rk_dense_state(st, tm, ym);
    rb_guard_eval(sv, tm, ym, gm);
    int ev = first_crossing(sv, st, mask, a, tm, ga, gm, t_event);
    if (ev >= 0)
        return ev;
    double peak_t[G_COUNT];
    int n = 0, order[G_COUNT];
    for (unsigned m = mask; m;) {
        int k = rb_guard_next(&m), dir = rb_guard_direction(k);
        /* a guard a transition left on its boundary (nudged, see
         * rb_guard_nudge) leaves it: what the dense output shows of it
         * turning back at once is its own error (a 4e-15 rad rise past
         * the bolt heads right after a release, read as an impact that
         * released again, without end) */
        if (dir == 0 || fabs(ga[k]) == DBL_MIN)
            continue;
        double qa = dir * ga[k], qm = dir * gm[k], qb = dir * gb[k];
        double c = qa - 2 * qm + qb; /* second difference over half intervals */
        if (!(c < 0))
            continue;
        double s = (qa - qb) / (2 * c), q_peak = qm - (qb - qa) * (qb - qa) / (8 * c);
        if (!(fabs(s) < 1) || !(q_peak > c))
            continue;
        double t3[3] = {a, tm, tb}, q3[3] = {qa, qm, qb}, at = tm;
        graze_ctx cx = {sv, st, k};
        rb_max_brent(toward, &cx, t3, q3, 3, 1e-9 * (tb - a), &at);
        /* in time order: reading one peak moves *ta past it */
        int i = n++;
        for (; i > 0 && peak_t[order[i - 1]] > at; i--)
            order[i] = order[i - 1];
        order[i] = k;
        peak_t[k] = at;
    }
    for (int i = 0; i < n; i++) {
        double at = peak_t[order[i]];
        if (at > *ta && at < tb && (ev = guards_at(sv, st, mask, ta, at, ga, t_event)) >= 0)
            return ev;
    }
    return -1;
}

/* Whether a rocking Taylor step keeps clear of every active guard over
 * the whole step: the guards of stage 2 and stage 5's overturning are
 * angle levels (floor, bolt heads, overturning), stage 5's end of
 * yielding is theta' at zero. Where the ranges of the step's series of
 * theta and theta' (rb_taylor_range) say none can be reached, no check
 * point, turn or graze can read a crossing, and the step reads its guards
 * at its end alone. The ranges are taken over the step's span in time as
 * well, since a turn's root is read at r - t0. */
static int angle_clear(const rb_solver *sv, const rb_rk_step *st, unsigned mask)
{
    if (!st->is_taylor || !st->ts.rocking || !mask)
        return 0;
    double h = rb_fmax(st->h, st->t1 - st->t0) * (1 + 1e-12), level, lo, hi;
    rb_taylor_range(&st->ts, RB_Y_TH, h, &lo, &hi);
    for (unsigned m = mask; m;) {
        int k = rb_guard_next(&m);
        if (k == G_UNLOAD) {
            double rlo, rhi;
            rb_taylor_range(&st->ts, RB_Y_THD, h, &rlo, &rhi);
            if (!(rlo > 0 || rhi < 0))
                return 0;
        } else if (!rb_guard_angle(sv, k, &level) || !(level < lo || level > hi))
            return 0;
    }
    return 1;
}

/* Earliest guard crossing inside the accepted step, or -1. ys[j] is the
 * state at the end of check interval j of n_sub (ys[n_sub - 1] = y1).
 * Without a crossing, g_end holds the guards at the step's end, which the
 * next step starts from. */
static int find_event(rb_solver *sv, const rb_rk_step *st, const double *g0,
                      double (*ys)[RB_NY], double *t_event, double *g_end)
{
    unsigned mask = rb_guard_mask(sv);
    double ga[G_COUNT], gb[G_COUNT];
    if (angle_clear(sv, st, mask)) {
        rb_guard_eval_x(sv, st->t1, ys[st->n_sub - 1], st->aux1.x, st->aux1.gz, g_end);
        return -1;
    }
    memcpy(ga, g0, sizeof ga);
    rb_guard_nudge(ga);
    int n = st->n_sub, turns = reads_turns(sv, st), force_turns = reads_force_turns(sv, st);
    double dt = st->h / n, rate[2] = {0, 0};
    double scale = force_turns ? rb_taylor_held_force_scale(&st->ts) : 0;
    /* the side whose force is followed: the held row's, or on the floor
     * the edge nearer uplift (under a vertical the two uplift guards turn
     * apart, and only one can be near its boundary while g + z'' > 0) */
    int side = sv->disc.stage == RB_STAGE_HELD ? sv->disc.side
               : g0[G_UP_POS] >= g0[G_UP_NEG] ? 1 : -1;
    double thdd_max = -1; /* formed where an interval first needs it */
    const double *ya = st->y0;
    for (int j = 1; j <= n; j++) {
        double ta = st->t0 + dt * (j - 1);
        double tb = j == n ? st->t1 : st->t0 + dt * j;
        double fa = ya[RB_Y_THD], fb = ys[j - 1][RB_Y_THD];
        if (turns && fa != 0 && fb != 0 && (fa < 0) != (fb < 0)) {
            double tm = st->t0 + rb_taylor_rate_root(&st->ts, RB_Y_THD, ta - st->t0,
                                                     tb - st->t0, fa, fb,
                                                     1e-14 * (1 + fabs(tb)));
            int ev = tm > ta && tm < tb ? guards_at(sv, st, mask, &ta, tm, ga, t_event) : -1;
            if (ev >= 0)
                return ev;
        }
        /* a Taylor step knows the floor at its check points and end */
        double x = !st->is_taylor ? (double)NAN
                   : j < n ? st->vcheck[j - 1][RB_TS_X] : st->aux1.x;
        double ge = !st->is_taylor ? (double)NAN
                    : j < n ? sv->sys.d.g + st->vcheck[j - 1][RB_TS_Z] : st->aux1.gz;
        rb_guard_eval_x(sv, tb, ys[j - 1], x, ge, gb);
        /* two turns inside, where the ends show no crossing */
        if (turns && fa != 0 && fb != 0 && (fa < 0) == (fb < 0)) {
            if (thdd_max < 0)
                thdd_max = rb_taylor_rate_bound(&st->ts, RB_Y_THD, st->h);
            if (fabs(fa) + fabs(fb) <= thdd_max * (tb - ta) && !any_crossed(mask, ga, gb)) {
                int ev = hidden_turns(sv, st, mask, ta, tb, fa, fb, thdd_max, &ta, ga, t_event,
                                      4);
                if (ev >= 0)
                    return ev;
            }
        }
        if (force_turns) {
            /* the rate at a check point serves both intervals it bounds */
            rate[0] = j == 1 ? rb_taylor_held_force_rate(&sv->sys, &st->ts, side, 0) : rate[1];
            rate[1] = rb_taylor_held_force_rate(&sv->sys, &st->ts, side, tb - st->t0);
        }
        if (force_turns && rate[0] != 0 && rate[1] != 0 && (rate[0] < 0) != (rate[1] < 0)
            && !rb_force_turn_stays(mask, tb - ta, scale * fabs(rate[0]),
                                    scale * fabs(rate[1]), ga, gb)) {
            double tm = st->t0 + rb_taylor_held_force_turn(&sv->sys, &st->ts, side,
                                                           ta - st->t0, tb - st->t0, rate,
                                                           1e-14);
            int ev = tm > ta && tm < tb ? guards_at(sv, st, mask, &ta, tm, ga, t_event) : -1;
            if (ev >= 0)
                return ev;
        }
        if (!st->is_taylor && mask) {
            int ev = grazes(sv, st, mask, &ta, tb, ga, gb, t_event);
            if (ev >= 0)
                return ev;
        }
        int ev = first_crossing(sv, st, mask, ta, tb, ga, gb, t_event);
        if (ev >= 0)
            return ev;
        memcpy(ga, gb, sizeof ga);
        ya = ys[j - 1];
    }
    memcpy(g_end, gb, sizeof gb);
    return -1;
}

static rb_status check_work(rb_solver *sv, rb_diag *diag)
{
    rb_control_event_window(sv);
    if (sv->window_events > sv->opts.max_events_per_s)
        return fail(sv, diag, RB_ERR_WORK_LIMIT, "more transitions per simulated second "
                    "than the work bound allows (chattering)");
    if (sv->res->steps >= sv->opts.max_steps)
        return fail(sv, diag, RB_ERR_LIMIT, "step budget exhausted");
    return RB_OK;
}

static int state_finite(const double *y)
{
    for (int i = 0; i < RB_NY; i++)
        if (!isfinite(y[i]))
            return 0;
    return 1;
}

/* Name what went non-finite at (t, y): the excitation, the state, or the
 * equations (a model whose constants overflow in them). */
static rb_status nonfinite(rb_solver *sv, rb_diag *diag, double t, const double *y)
{
    rb_aux a;
    double dy[RB_NY];
    sv->t = t;
    if (!state_finite(y))
        return fail(sv, diag, RB_ERR_NONFINITE, "non-finite state");
    rb_dyn_rhs(&sv->sys, &sv->disc, t, y, dy, &a);
    if (!isfinite(a.x))
        return fail(sv, diag, RB_ERR_NONFINITE, "non-finite floor acceleration");
    return fail(sv, diag, RB_ERR_NONFINITE, "non-finite value in the equations of motion");
}

/* Every trial step from the current point, down to the smallest, gave
 * non-finite values while the point itself is finite: what lies just
 * ahead is not computable. The excitation is the usual culprit (a bad
 * sample read by interpolation over the interval that leads to it). */
static rb_status nonfinite_ahead(rb_solver *sv, rb_diag *diag, double h)
{
    double t = sv->t + h;
    double thd = sv->y[RB_Y_THD] != 0 ? sv->y[RB_Y_THD] : -sv->y[RB_Y_TH];
    if (!isfinite(rb_motion_accel(sv->sys.motion, t, thd)))
        return fail(sv, diag, RB_ERR_NONFINITE, "non-finite floor acceleration just ahead");
    return fail(sv, diag, RB_ERR_NONFINITE, "non-finite values in every trial step down "
                "to the smallest step");
}

/* After a transition: settle immediate follow-ups, refresh f and guards. */
static rb_status restart(rb_solver *sv, double *g, rb_diag *diag)
{
    /* one evaluation of the equations at the restart serves the
     * derivative, the guards and the tracked point: the last test for an
     * immediate transition made it in the stage the run goes on in */
    rb_aux a;
    int have = 0;
    for (int n = 0; !sv->done; n++) {
        if (!rb_transition_immediate(sv, &a)) {
            have = 1;
            break;
        }
        if (n > 16)
            return fail(sv, diag, RB_ERR_WORK_LIMIT, "stage transitions do not settle");
    }
    if (!have)
        rb_dyn_rhs(&sv->sys, &sv->disc, sv->t, sv->y, NULL, &a);
    rb_dyn_deriv(&sv->sys, &sv->disc, sv->y, &a, sv->f);
    if (!state_finite(sv->y) || !state_finite(sv->f))
        return nonfinite(sv, diag, sv->t, sv->y);
    rb_guard_eval_aux(sv, sv->t, sv->y, &a, g);
    /* the stage's steppers, once for the stage */
    sv->n_steppers = rb_steppers_of_stage(sv, sv->steppers);
    rb_track_reset(sv);
    rb_track_span_none(sv);
    rb_track_aux(sv, sv->t, sv->y, &a);
    return RB_OK;
}

/* A jump of the excitation at a break a step landed on (a pulse that ends
 * at its peak) can carry a guard across its boundary: the uplift moment, a
 * held row's force. A Taylor step reads its guards before the jump and the
 * next step would start after it, so no interval holds the crossing, and
 * one that comes back within the next check interval would be missed. The
 * run restarts at the break as after a transition, which settles what the
 * jump set off and starts the peaks' windows afresh (no parabola through a
 * jump). A run that ends there ends before the jump. */
static rb_status after_landing(rb_solver *sv, double target, double *g, rb_diag *diag)
{
    if (sv->t != target || sv->done || !(target < sv->t_end)
        || !rb_motion_jumps_at(sv->sys.motion, target))
        return RB_OK;
    return restart(sv, g, diag);
}

static rb_status advance(rb_solver *sv, rb_rk_step *st, double *g, rb_diag *diag)
{
    double t_event, tb = st->t1;
    /* the check points serve the guards and the peaks alike */
    double ys[RB_SUB_MAX][RB_NY];
    int n = st->n_sub;
    double dt = st->h / n;
    for (int j = 1; j < n; j++) {
        if (st->is_taylor) {
            /* guards read the state, tracking the rest */
            rb_taylor_check(&st->ts, dt * j, st->vcheck[j - 1]);
            memcpy(ys[j - 1], st->vcheck[j - 1], 4 * sizeof ys[0][0]);
        } else
            rb_rk_dense_state(st, st->t0 + dt * j, ys[j - 1]);
    }
    memcpy(ys[n - 1], st->y1, sizeof ys[0]);
    /* the step end and its derivative (the next step's first stage) */
    if (!state_finite(st->y1) || !state_finite(st->k[6]))
        return nonfinite(sv, diag, st->t1, st->y1);
    double g_end[G_COUNT];
    int ev = find_event(sv, st, g, ys, &t_event, g_end);
    if (ev >= 0)
        tb = t_event;
    rb_track_span(sv, st, st->t0, tb);
    rb_track_interval(sv, st, st->t0, tb, ev < 0 ? (const double (*)[RB_NY])ys : NULL);
    if (rb_history_sample(sv, st, st->t0, tb) != RB_OK)
        return RB_ERR_NOMEM;
    sv->res->stage_time_s[sv->disc.stage] += tb - st->t0;
    sv->t = tb;
    if (ev < 0) {
        memcpy(sv->y, st->y1, sizeof sv->y);
        memcpy(sv->f, st->k[6], sizeof sv->f);
        memcpy(g, g_end, sizeof g_end);
        rb_track_aux(sv, sv->t, sv->y, &st->aux1);
        rb_track_span_none(sv);
        return RB_OK;
    }
    rb_rk_dense_eval(st, tb, sv->y);
    rb_track_point(sv, sv->t, sv->y);
    rb_track_span_none(sv);
    rb_transition(sv, ev);
    return restart(sv, g, diag);
}

static rb_status run(rb_solver *sv, rb_diag *diag)
{
    rb_rk_step st;
    double g[G_COUNT];
    rb_status s = rb_history_push(sv, 0, sv->y);
    sv->hist_k = 1;
    if (s == RB_OK)
        s = restart(sv, g, diag);
    while (s == RB_OK && !sv->done && sv->t < sv->t_end && !rb_control_stop_reached(sv)) {
        if ((s = check_work(sv, diag)) != RB_OK)
            break;
        double brk = rb_motion_next_break(sv->sys.motion, sv->t);
        double target = rb_fmin(brk, sv->t_end), h = rb_control_trial(sv, target);
        if (!(h > 1e-14 * (1 + sv->t)))
            return sv->nonfinite_trial ? nonfinite_ahead(sv, diag, h)
                   : fail(sv, diag, RB_ERR_STEP_TOO_SMALL, "step size underflow: the "
                          "tolerance cannot be met");
        const rb_stepper *stepper = NULL;
        rb_step_outcome out = RB_STEP_DECLINED;
        for (int i = 0; i < sv->n_steppers && out == RB_STEP_DECLINED; i++) {
            stepper = sv->steppers[i];
            out = stepper->apply(sv, target, h, &st, g, &s);
        }
        if (out != RB_STEP_DENSE)
            continue;
        s = advance(sv, &st, g, diag);
        if (s == RB_OK && st.lands) {
            if (sv->t == target && !sv->done && stepper->landed)
                stepper->landed(sv);
            s = after_landing(sv, target, g, diag);
        }
    }
    return s;
}

static void finish(rb_solver *sv)
{
    rb_result *r = sv->res;
    const rb_sys *S = &sv->sys;
    r->t_end_s = sv->t;
    for (int row = 0; row < 2; row++) {
        r->absorbed_j[row] = rb_absorbed_now(sv, row);
        r->usage[row] = S->d.capacity_j > 0 ? r->absorbed_j[row] / S->d.capacity_j : 0;
        r->final_gap_m[row] = sv->disc.gap[row];
        if (sv->disc.stage == RB_STAGE_YIELD && rb_row_of_side(sv->disc.side) == row)
            r->final_gap_m[row] = rb_dyn_chord(S, sv->disc.side * sv->y[RB_Y_TH]);
    }
    r->max_theta_over_alpha = r->max_theta_rad / S->d.alpha;
    r->max_u_over_ustatic = r->u_static_m > 0 ? r->max_u_m / r->u_static_m : 0;
    r->max_shear_elastic_n = S->d.Nstar * S->d.omega * S->d.omega * r->max_u_m;
    r->e_input = sv->y[RB_Y_WIN];
    r->e_damping = sv->y[RB_Y_WDAMP];
    r->e_coupling = sv->y[RB_Y_WCPL];
    r->e_kinetic = rb_dyn_kinetic(S, &sv->disc, sv->y);
    r->e_potential = rb_dyn_potential(S, &sv->disc, sv->y);
    r->e_strain = rb_dyn_strain(S, &sv->disc, sv->y);
    r->e_impact = sv->e_impact;
    r->e_plastic = r->absorbed_j[0] + r->absorbed_j[1];
}

rb_status rb_solve_run(const rb_model *model, const rb_motion *motion,
                       const rb_solve_opts *opts, rb_result *out, rb_diag *diag)
{
    rb_solver sv;
    rb_status s = rb_solver_setup(&sv, model, motion, opts, out, diag);
    if (s == RB_OK)
        s = run(&sv, diag);
    /* what the last of a run of quiet exact steps leaves to be read */
    rb_exact_settle(&sv, NULL);
    if (s == RB_OK && sv.res->history && sv.res->history->n
        && sv.res->history->t[sv.res->history->n - 1] < sv.t)
        s = rb_history_push(&sv, sv.t, sv.y);
    if (s == RB_OK || s == RB_ERR_STEP_TOO_SMALL || s == RB_ERR_WORK_LIMIT
        || s == RB_ERR_LIMIT)
        finish(&sv);
    return s;
}
