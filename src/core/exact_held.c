/* Quiet exact steps of a plate held by a rigid row (stage 4; see exact.h).
 *
 * Held at the angle th on side s, the plate is still and the frame obeys
 * (dynamics.c's solve_still, physical U)
 *     M* U'' = N* c x + s N* g sn - K* U - C* U'
 * with c = cos th and sn = sin th (c = 1 and sn = th in the small form).
 * V = (U - U_s) / c, with K* U_s = s N* g sn, obeys the floor stage's own
 * system (exact.c) with V in U's place, M* V'' = N* x - K* V - C* V', so
 * z = (V, V', u_b, v_b, g, s) steps by the floor's tables, and what the
 * held stage reads is affine in z, with a = V'' the floor stage's U''
 * form, G = M h x - F* a its uplift moment (M R x - F* a small) and H_1 =
 * -M x + N* a its total shear:
 *     U = c V + U_s, U'' = c a;
 *     the row's force F = f0 + s (c G + M b sn x) / l (small: f0 + s G / l),
 *         l the lever arm at th;
 *     the shear H = h0 + H_1 + (cos th c - 1) N* a (c^2 - 1 large);
 *     the floor's reaction fv0 - s sn c N* a + (F - f0).
 * The floor's tables bound V, H_1, G, x and a over a step (exact.c,
 * "Bounds over a step"), and so F, H, U and the reaction. A step whose
 * bounds keep F inside (0, Fy) and at or below its running peak, U, H and
 * the friction and anchor demands at or below theirs, and the reaction
 * above zero, the friction floor and its least, has nothing to find
 * between its ends: it is taken as the floor's quiet steps are, the state
 * and works advanced, its end read once the run of them is over
 * (rb_exact_held_settle). Any other step is a Taylor step.
 *
 * The forms are checked against the functions the Taylor steps read the
 * held stage with (rb_aux_of_values, rb_dyn_reactions) at the unit states,
 * once per hold; where they disagree beyond rounding, no step of that
 * hold is exact. */
#include <math.h>
#include <string.h>
#include "bolt.h"
#include "exact.h"
#include "minmax.h"
#include "stepper.h"
#include "taylor.h"

/* a hundredth of a per mille over the bounds, as exact.c's QUIET_MARGIN */
#define HELD_MARGIN (1 + 1e-6)

/* The state y and what the equations give (a) at z. */
static void held_point(const rb_solver *sv, const rb_exact_held *f, const double *z, double *y,
                       rb_aux *a)
{
    rb_exact_point p;
    rb_exact_point_at(sv, z, &p);
    double v[RB_TS_N] = {0};
    v[RB_TS_U] = f->c * z[ZU] + f->us;
    v[RB_TS_UD] = f->c * z[ZV];
    v[RB_TS_TH] = sv->y[RB_Y_TH];
    v[RB_TS_X] = p.x;
    v[RB_TS_UDD] = f->c * p.udd;
    /* the Taylor steps' cosine and sine of the held angle */
    v[RB_TS_COS] = f->th == 0 ? 1 : cos(f->th);
    v[RB_TS_SIN] = f->sn;
    rb_aux_of_values(&sv->sys, &sv->disc, 0, f->lever, v, a);
    memcpy(y, sv->y, RB_NY * sizeof *y);
    y[RB_Y_U] = v[RB_TS_U];
    y[RB_Y_UD] = v[RB_TS_UD];
}

/* F, H and the vertical reaction plus F (the floor's share where F > 0)
 * at z. */
static void held_quantities(const rb_solver *sv, const rb_exact_held *f, const double *z,
                            double *F, double *H, double *fv)
{
    double y[RB_NY], V;
    rb_aux a;
    held_point(sv, f, z, y, &a);
    rb_dyn_reactions(&sv->sys, &sv->disc, y, &a, H, &V);
    *F = a.bolt_force;
    *fv = V + a.bolt_force;
}

static int agrees(double got, double want, double scale)
{
    return fabs(got - want) <= 1e-9 * scale;
}

/* The frame of the current hold, its forms checked at the unit states. */
static int held_frame(const rb_solver *sv, rb_exact_held *f)
{
    const rb_sys *S = &sv->sys;
    const rb_derived *d = &S->d;
    const rb_exact_cache *c = &sv->exact;
    int small = S->form == RB_FORM_SMALL;
    f->ok = 0;
    f->th = sv->disc.theta_hold;
    f->side = sv->disc.side;
    f->s = f->side < 0 ? -1.0 : 1.0;
    f->sn = f->th == 0 ? 0 : sin(f->th);
    f->c = small || f->th == 0 ? 1 : cos(f->th);
    double sn_g = small ? f->th : f->sn;
    f->us = f->s * d->Nstar * d->g * sn_g / d->Kstar;
    f->lever = rb_dyn_lever(S, f->th);
    f->kg = f->c;
    f->kx = small ? 0 : S->M * S->b * f->sn;
    f->cpl = f->s * d->Nstar * d->g * sn_g;
    /* the shear reads U'' = c a through the angle's own cosine */
    f->kh = ((f->th == 0 ? 1 : cos(f->th)) * f->c - 1) * d->Nstar;
    if (!c->lin_ready || !(f->lever > 0) || !isfinite(f->us))
        return 0;
    double z[ZN] = {0}, F[ZN], H[ZN], fv[ZN], sF = 0, sH = 0, sV = 0;
    held_quantities(sv, f, z, &f->f0, &f->h0, &f->fv0);
    for (int j = 0; j < ZN; j++) {
        z[j] = 1;
        held_quantities(sv, f, z, &F[j], &H[j], &fv[j]);
        z[j] = 0;
        sF = rb_fmax(sF, fabs(F[j] - f->f0));
        sH = rb_fmax(sH, fabs(H[j] - f->h0));
        sV = rb_fmax(sV, fabs(fv[j] - f->fv0));
    }
    double nsa = f->s * f->sn * f->c * d->Nstar;
    for (int j = 0; j < ZN; j++) {
        double dF = f->s * (f->kg * c->lin[RB_XQ_UP_POS][j] + f->kx * c->lin_x[j]) / f->lever;
        double dH = c->lin[RB_XQ_SHEAR][j] + f->kh * c->lin_a[j];
        double dV = -nsa * c->lin_a[j] + dF;
        if (!agrees(F[j] - f->f0, dF, sF + fabs(f->f0))
            || !agrees(H[j] - f->h0, dH, sH + fabs(f->h0))
            || !agrees(fv[j] - f->fv0, dV, sV + fabs(f->fv0)))
            return 0;
    }
    f->ok = 1;
    return 1;
}

/* The current hold's frame, formed once per hold. */
static const rb_exact_held *frame_of_hold(rb_solver *sv)
{
    rb_exact_held *f = &sv->exact.held;
    if (f->side != sv->disc.side || f->th != sv->disc.theta_hold)
        held_frame(sv, f);
    return f->ok ? f : NULL;
}

static double dot(const double *a, const double *b)
{
    double v = 0;
    for (int j = 0; j < ZN; j++)
        v += a[j] * b[j];
    return v;
}

/* What the step from z over table tab can reach (see the top): each
 * quantity's value at the start, from the forms, and how far it can move
 * over the step (the table's vary), widened by HELD_MARGIN and by a
 * billionth of its size for the forms' rounding against the equations':
 * the row force's least and largest, the largest |shear|, the floor's
 * least reaction and the largest |U| (r[RB_HELD_*]). */
static void held_ranges(const rb_solver *sv, const rb_exact_held *f, const rb_exact_table *tab,
                        const double *z, double *r)
{
    const rb_derived *d = &sv->sys.d;
    const rb_exact_cache *c = &sv->exact;
    rb_pair v01 = rb_pair_splat(0), v23 = v01, v4 = v01;
    for (int j = 0; j < ZN; j++) {
        rb_pair az = rb_pair_splat(fabs(z[j]));
        v01 = rb_pair_madd(v01, tab->vary[j][0], az);
        v23 = rb_pair_madd(v23, tab->vary[j][1], az);
        v4 = rb_pair_madd(v4, tab->vary[j][2], az);
    }
    double vU = rb_pair_lane(v01, 0), vH = rb_pair_lane(v01, 1), vG = rb_pair_lane(v23, 0);
    double vx = rb_pair_lane(v23, 1), va = rb_pair_lane(v4, 0);
    double G = dot(c->lin[RB_XQ_UP_POS], z), x = dot(c->lin_x, z), a = dot(c->lin_a, z);
    double nc2 = f->kh, nsa = f->s * f->sn * f->c * d->Nstar;
    double dF0 = f->s * (f->kg * G + f->kx * x) / f->lever;
    double F = f->f0 + dF0;
    double H = f->h0 + dot(c->lin[RB_XQ_SHEAR], z) + nc2 * a;
    double fv = f->fv0 - nsa * a + dF0;
    double U = f->c * z[ZU] + f->us;
    double dF = HELD_MARGIN * (f->kg * vG + fabs(f->kx) * vx) / f->lever
                + 1e-9 * (fabs(f->f0) + fabs(dF0));
    r[RB_HELD_F_LO] = F - dF;
    r[RB_HELD_F_HI] = F + dF;
    r[RB_HELD_SHEAR_HI]
        = fabs(H) + HELD_MARGIN * (vH + fabs(nc2) * va) + 1e-9 * (fabs(f->h0) + fabs(H));
    r[RB_HELD_FLOOR_LO]
        = fv - HELD_MARGIN * (fabs(nsa) * va) - dF - 1e-9 * (fabs(f->fv0) + fabs(fv));
    r[RB_HELD_U_HI] = fabs(U) + HELD_MARGIN * f->c * vU + 1e-9 * (fabs(f->us) + fabs(U));
}

/* Whether the step from z over table tab is quiet. */
static int held_quiet(const rb_solver *sv, const rb_exact_held *f, const rb_exact_table *tab,
                      const double *z)
{
    double r[RB_HELD_N];
    if (tab->held_bounded <= 0 || sv->opts.check_reactions)
        return 0;
    held_ranges(sv, f, tab, z, r);
    if (!(r[RB_HELD_F_LO] > 0) || !(r[RB_HELD_U_HI] <= sv->res->max_u_m))
        return 0;
    if (sv->sys.bolt->yields && !(r[RB_HELD_F_HI] < sv->sys.d.fy_row_n))
        return 0;
    return rb_track_held_quiet(sv, r[RB_HELD_F_HI], r[RB_HELD_SHEAR_HI], r[RB_HELD_FLOOR_LO]);
}

int rb_exact_held_step(rb_solver *sv, double target, double *g, rb_status *status)
{
    rb_exact_cache *c = &sv->exact;
    const rb_exact_held *f;
    const rb_exact_table *tab;
    rb_floor_line fl;
    int landing;
    double t0 = sv->t, h = rb_step_length(sv, target, &landing);
    if (!(h > 0) || !rb_motion_floor_line(sv->sys.motion, t0, &fl)
        || !(tab = rb_exact_table_of_length(sv, h))
        || !rb_exact_table_held(sv, &sv->exact.tab[tab - sv->exact.tab])
        || !(f = frame_of_hold(sv)))
        return 0;
    double z[ZN] = {(sv->y[RB_Y_U] - f->us) / f->c, sv->y[RB_Y_UD] / f->c, fl.u, fl.v, fl.g0,
                    fl.slope};
    if (!held_quiet(sv, f, tab, z))
        return 0;
    double v1, vd1, t1 = landing ? target : t0 + h;
    rb_exact_end_state(tab, z, &v1, &vd1);
    double u1 = f->c * v1 + f->us, ud1 = f->c * vd1;
    if (!isfinite(u1) || !isfinite(ud1))
        return 0;
    /* a quiet step before this one leaves nothing to read: this one's end
     * takes its place */
    if ((*status = rb_exact_history(sv, t0, sv->y, tab->h, t1)) != RB_OK)
        return 1;
    rb_exact_count_step(sv, t1);
    /* the works of V scaled by c^2 (U' = c V', and the floor's power on
     * the frame N* c x U'); gravity's on the held frame N* g sn U' */
    double wd = 0, wi = 0, c2 = f->c * f->c;
    rb_exact_work_forms(tab, z, &wd, &wi);
    sv->y[RB_Y_WDAMP] += c2 * wd;
    sv->y[RB_Y_WIN] += c2 * wi;
    sv->y[RB_Y_WCPL] += f->cpl * (u1 - sv->y[RB_Y_U]);
    sv->t = t1;
    sv->y[RB_Y_U] = u1;
    sv->y[RB_Y_UD] = ud1;
    c->pending = 1;
    c->pend_settle = rb_exact_held_settle;
    c->pend_tab = tab;
    memcpy(c->pend_z0, z, sizeof c->pend_z0);
    c->pend_t0 = t0;
    c->pend_g0 = fl.g0;
    c->pend_slope = fl.slope;
    if (sv->res->history)
        rb_exact_settle(sv, g);
    return 1;
}

/* The end of the last quiet held step: its last two points tracked (as
 * rb_exact_settle's on the floor), the rates and the guards at its end. */
void rb_exact_held_settle(rb_solver *sv, double *g)
{
    const rb_exact_cache *c = &sv->exact;
    const rb_exact_held *f = &c->held;
    const rb_exact_table *tab = c->pend_tab;
    const rb_floor_line fl = {.g0 = c->pend_g0, .slope = c->pend_slope};
    int n = tab->n;
    double z[ZN], y[2][RB_NY], t0 = c->pend_t0, t1 = sv->t;
    double tt[2] = {t0 + (t1 - t0) / n * (n - 1), t1};
    rb_aux a[2];
    for (int k = 0; k < 2; k++) {
        rb_exact_check_state(tab, &fl, c->pend_z0, n - 1 + k, z);
        held_point(sv, f, z, y[k], &a[k]);
    }
    /* the end's U and U' as the step advanced them (the check point's are
     * the same rows' sums, rounded alike or within a rounding) */
    rb_dyn_deriv(&sv->sys, &sv->disc, sv->y, &a[1], sv->f);
    if (g)
        rb_guard_eval_aux(sv, t1, sv->y, &a[1], g);
    rb_track_held_points(sv, tt, (const double (*)[RB_NY])y, a);
}

int rb_exact_held_probe(rb_solver *sv, double h, const double *floor_z, double *range)
{
    const rb_exact_held *f;
    rb_exact_table *tab = &sv->exact.tab[0];
    rb_exact_table_build(sv, h, rb_step_checks(sv, h), tab);
    if (!rb_exact_table_held(sv, tab) || !(f = frame_of_hold(sv)))
        return 0;
    double z[ZN] = {(sv->y[RB_Y_U] - f->us) / f->c, sv->y[RB_Y_UD] / f->c, floor_z[0],
                    floor_z[1], floor_z[2], floor_z[3]};
    held_ranges(sv, f, tab, z, range);
    return 1;
}

/* The held plate's stepper: a quiet step, or the step handed on. */
static rb_step_outcome held_apply(rb_solver *sv, double target, double h, rb_rk_step *st,
                                  double *g, rb_status *status)
{
    (void)h;
    (void)st;
    return rb_exact_outcome(sv, rb_exact_held_step(sv, target, g, status), g);
}

const rb_stepper rb_stepper_exact_held = {"exact-held", held_apply, NULL};
