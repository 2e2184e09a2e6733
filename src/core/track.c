/* Peaks and time histories of a run.
 *
 * Peaks of U and theta are taken at step ends and, inside a step, at the
 * roots of U' and theta' on the dense output, so a peak between two steps
 * is found to the integrator's accuracy rather than to the step size. Forces
 * and reactions come from the equations at the points visited. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/aci17.h"
#include "bolt.h"
#include "root.h"
#include "solver.h"

static void note_displacements(rb_solver *sv, const double *y)
{
    rb_result *r = sv->res;
    r->max_u_m = fmax(r->max_u_m, fabs(y[RB_Y_U]));
    r->max_theta_rad = fmax(r->max_theta_rad, fabs(y[RB_Y_TH]));
}

/* Shift (t, v) into the window and return the larger of v and, when the
 * middle sample is a local maximum, the vertex of the parabola through the
 * three: the samples are check points of a step (a few per period of the
 * fastest mode), and the vertex takes the peak between them to third order
 * in their spacing instead of first. */
static double peak_push(rb_peak_window *w, double t, double v)
{
    if (w->n == 3) {
        w->t[0] = w->t[1]; w->v[0] = w->v[1];
        w->t[1] = w->t[2]; w->v[1] = w->v[2];
        w->n = 2;
    }
    w->t[w->n] = t;
    w->v[w->n] = v;
    w->n++;
    if (w->n < 3 || !(w->v[1] >= w->v[0] && w->v[1] >= w->v[2]))
        return v;
    /* a flat window (the floor's reaction on the floor) has no vertex:
     * what the slopes below would give, without their three divisions */
    if (w->v[0] == w->v[1] && w->v[1] == w->v[2])
        return fmax(v, w->v[1]);
    double h0 = w->t[1] - w->t[0], h1 = w->t[2] - w->t[1];
    if (!(h0 > 0 && h1 > 0))
        return v;
    double d0 = (w->v[1] - w->v[0]) / h0, d1 = (w->v[2] - w->v[1]) / h1;
    double curv = (d1 - d0) / (h0 + h1); /* half the second derivative */
    if (!(curv < 0))
        return fmax(v, w->v[1]);
    /* slope at t1 from the parabola, then the vertex */
    double slope = d0 + curv * h0;
    double dt = -slope / (2 * curv);
    if (!(dt >= -h0 && dt <= h1))
        return fmax(v, w->v[1]);
    return fmax(v, w->v[1] + slope * dt + curv * dt * dt);
}

/* Time with the floor's reaction at or below zero, linear between the
 * points visited; a point at the time of the one before (the two sides of
 * a transition) only replaces it. */
static void note_liftoff(rb_solver *sv, double t, double v)
{
    rb_result *r = sv->res;
    if (sv->lift_have && t > sv->lift_t) {
        double t0 = sv->lift_t, v0 = sv->lift_v, dt = t - t0;
        if (v0 <= 0 && v <= 0)
            r->liftoff_time_s += dt;
        else if (v0 <= 0 || v <= 0) {
            /* one end is at or below zero: the crossing, linearly */
            double tc = t0 + dt * v0 / (v0 - v);
            if (v0 <= 0)
                r->liftoff_time_s += tc - t0;
            else {
                r->liftoff_time_s += t - tc;
                if (r->liftoff_first_s < 0)
                    r->liftoff_first_s = tc;
            }
        }
    }
    if (v <= 0 && r->liftoff_first_s < 0)
        r->liftoff_first_s = t;
    sv->lift_have = 1;
    sv->lift_t = t;
    sv->lift_v = v;
}

void rb_track_reset(rb_solver *sv)
{
    sv->win_shear.n = sv->win_friction.n = sv->win_bolt.n = sv->win_vertical.n = 0;
    sv->fric_have = 0;
}

/* The friction demand |H| / V where V > floor. Near the floor it is large
 * and steep, so its largest value is often where V crosses the floor: that
 * point is found between two points (both linear there), or the largest
 * value would be whichever point happened to fall just past the crossing. */
static void note_friction(rb_solver *sv, double t, double H, double v, double floor)
{
    rb_result *r = sv->res;
    if (sv->fric_have && t > sv->fric_t && (sv->fric_v > floor) != (v > floor)) {
        double f = (floor - sv->fric_v) / (v - sv->fric_v);
        double h = fabs(sv->fric_h + f * (H - sv->fric_h));
        r->max_friction_demand = fmax(r->max_friction_demand, h / floor);
    }
    sv->fric_have = 1;
    sv->fric_t = t;
    sv->fric_h = H;
    sv->fric_v = v;
    if (v > floor)
        r->max_friction_demand = fmax(r->max_friction_demand,
                                      peak_push(&sv->win_friction, t, fabs(H) / v));
    else
        sv->win_friction.n = 0;
}

/* The anchorage's demand: tension and shear at the same instant, in the
 * interaction of 17.8, not the largest of each taken apart. */
static void note_anchor(rb_solver *sv, double t, double tension, double shear)
{
    rb_result *r = sv->res;
    int which;
    double u = rb_aci17_interaction(tension, sv->opts.anchor_phi_nn_n, shear,
                                    sv->opts.anchor_phi_vn_n, &which);
    r->anchor_checked = 1;
    if (u > r->anchor_max_ratio) {
        r->anchor_max_ratio = u;
        r->anchor_max_s = t;
        r->anchor_tension_n = tension;
        r->anchor_shear_n = shear;
        r->anchor_clause = which;
    }
}

void rb_track_aux(rb_solver *sv, double t, const double *y, const rb_aux *a)
{
    const rb_sys *S = &sv->sys;
    rb_result *r = sv->res;
    double H, V;
    note_displacements(sv, y);
    if (sv->disc.side != 0 && a->bolt_force > 0) {
        int row = rb_row_of_side(sv->disc.side);
        r->max_bolt_force_n[row] = fmax(r->max_bolt_force_n[row],
                                        peak_push(&sv->win_bolt, t, a->bolt_force));
    }
    rb_dyn_reactions(S, &sv->disc, y, a, &H, &V);
    if (sv->opts.check_reactions) {
        double Hp, Vp;
        rb_dyn_reactions_points(S, &sv->disc, y, a, &Hp, &Vp);
        r->reaction_mismatch_n = fmax(r->reaction_mismatch_n,
                                      fmax(fabs(Hp - H), fabs(Vp - V)));
    }
    r->max_shear_total_n = fmax(r->max_shear_total_n, peak_push(&sv->win_shear, t, fabs(H)));
    /* V is what floor and bolt give together; the floor presses on the
     * plate with that plus the tension of a loaded bolt, which pulls the
     * plate onto it, and friction works with the floor's share alone. */
    double floor_v = V + (a->bolt_force > 0 ? a->bolt_force : 0);
    /* a least value is the peak of its negative */
    r->min_vertical_reaction_n = fmin(r->min_vertical_reaction_n,
                                      -peak_push(&sv->win_vertical, t, -floor_v));
    note_liftoff(sv, t, floor_v);
    note_friction(sv, t, H, floor_v, RB_FRICTION_FLOOR * S->d.W);
    if (sv->opts.anchor_phi_nn_n > 0 && sv->opts.anchor_phi_vn_n > 0)
        note_anchor(sv, t, a->bolt_force > 0 ? a->bolt_force : 0, fabs(H));
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
            double bound = fmax(fabs(prev[pc]), fabs(cur[pc]))
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
            rb_taylor_aux(&sv->sys, &sv->disc, &st->ts, v, &a);
            rb_track_aux(sv, t1, cur, &a);
        } else if (j < n && sv->disc.stage == RB_STAGE_HELD)
            rb_track_point(sv, t1, cur);
        memcpy(prev, cur, sizeof prev);
    }
}

static rb_status history_grow(rb_history *h)
{
    size_t cap = h->cap ? 2 * h->cap : 1024;
    double **cols[] = {&h->t, &h->accel, &h->theta, &h->u, &h->bolt_force_left,
                       &h->bolt_force_right, &h->shear_elastic, &h->shear_total,
                       &h->energy_left, &h->energy_right, &h->kinetic, &h->potential,
                       &h->strain};
    for (size_t i = 0; i < sizeof cols / sizeof cols[0]; i++) {
        double *p = realloc(*cols[i], cap * sizeof **cols[i]);
        if (!p)
            return RB_ERR_NOMEM;
        *cols[i] = p;
    }
    int *s = realloc(h->stage, cap * sizeof *s);
    if (!s)
        return RB_ERR_NOMEM;
    h->stage = s;
    h->cap = cap;
    return RB_OK;
}

rb_status rb_history_push(rb_solver *sv, double t, const double *y)
{
    rb_history *h = sv->res->history;
    const rb_sys *S = &sv->sys;
    rb_aux a;
    double H, V;
    if (!h)
        return RB_OK;
    if (h->n == h->cap && history_grow(h) != RB_OK)
        return RB_ERR_NOMEM;
    rb_dyn_rhs(S, &sv->disc, t, y, NULL, &a);
    rb_dyn_reactions(S, &sv->disc, y, &a, &H, &V);
    size_t i = h->n++;
    int row = sv->disc.side ? rb_row_of_side(sv->disc.side) : -1;
    h->t[i] = t;
    h->accel[i] = a.x;
    h->theta[i] = y[RB_Y_TH];
    h->u[i] = y[RB_Y_U];
    h->bolt_force_left[i] = row == RB_LEFT ? a.bolt_force : 0;
    h->bolt_force_right[i] = row == RB_RIGHT ? a.bolt_force : 0;
    h->shear_elastic[i] = S->d.Nstar * S->d.omega * S->d.omega * y[RB_Y_U];
    h->shear_total[i] = H;
    h->energy_left[i] = rb_absorbed_now(sv, RB_LEFT);
    h->energy_right[i] = rb_absorbed_now(sv, RB_RIGHT);
    h->kinetic[i] = rb_dyn_kinetic(S, &sv->disc, y);
    h->potential[i] = rb_dyn_potential(S, &sv->disc, y);
    h->strain[i] = rb_dyn_strain(S, &sv->disc, y);
    h->stage[i] = sv->disc.stage;
    return RB_OK;
}

/* The time of the next history row: k dt rather than a running sum, so
 * long runs do not drift. */
static double history_next(const rb_solver *sv)
{
    return (double)sv->hist_k * sv->opts.history_dt_s;
}

int rb_history_due(const rb_solver *sv, double tb)
{
    double next = history_next(sv);
    return sv->res->history && next <= tb && next <= sv->t_end;
}

rb_status rb_history_sample(rb_solver *sv, const rb_rk_step *st, double ta, double tb)
{
    double y[RB_NY];
    while (rb_history_due(sv, tb)) {
        double next = history_next(sv);
        rb_rk_dense_eval(st, next < ta ? ta : next, y);
        if (rb_history_push(sv, next, y) != RB_OK)
            return RB_ERR_NOMEM;
        sv->hist_k++;
    }
    return RB_OK;
}

void rb_history_free(rb_history *h)
{
    if (!h)
        return;
    free(h->t); free(h->accel); free(h->theta); free(h->u);
    free(h->bolt_force_left); free(h->bolt_force_right);
    free(h->shear_elastic); free(h->shear_total);
    free(h->energy_left); free(h->energy_right);
    free(h->kinetic); free(h->potential); free(h->strain);
    free(h->stage);
    free(h);
}
