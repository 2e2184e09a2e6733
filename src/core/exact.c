/* Exact steps of the fixed base (see exact.h).
 *
 * z = (U, U', u_b, v_b, g, s): the frame's top displacement and rate, the
 * building's relative displacement and velocity, and the line g + s tau
 * that drives it (the ground through a building, else the floor itself).
 * On the floor (5.3c, as still_order in taylor.c)
 *     M* U'' = N* x - K* U - C* U',  x = -(2 xi_b w_b v_b + w_b^2 u_b)
 * through a building, x = g without one; the building obeys
 *     u_b'' + 2 xi_b w_b u_b' + w_b^2 u_b = -g.
 * The transition to tau is E(tau) = exp(A tau). */
#include <float.h>
#include <math.h>
#include <string.h>
#include "../motion/matexp.h"
#include "exact.h"
#include "minmax.h"
#include "stepper.h"
#include "taylor.h"

enum { ZU, ZV, ZUB, ZVB, ZG, ZS, ZN = RB_EXACT_DIM };

/* Gauss-Legendre, 8 points on [-1, 1]: exact for polynomials of degree
 * 15; the integrands (products of the frame's and the building's
 * oscillations) are integrated to rounding over panels of up to 1.5 rad
 * of the fastest of them. */
static const double gl_x[8] = {
    -0.9602898564975363, -0.7966664774136267, -0.5255324099163290, -0.1834346424956498,
    0.1834346424956498,  0.5255324099163290,  0.7966664774136267,  0.9602898564975363};
static const double gl_w[8] = {
    0.1012285362903763, 0.2223810344533745, 0.3137066458778873, 0.3626837833783620,
    0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

/* The floor as a row over z. */
static void floor_row(const rb_exact_cache *c, double *r)
{
    memset(r, 0, ZN * sizeof *r);
    if (c->wb > 0) {
        r[ZUB] = -c->wb * c->wb;
        r[ZVB] = -2 * c->xib * c->wb;
    } else
        r[ZG] = 1;
}

static void system_matrix(const rb_solver *sv, double a[ZN][ZN])
{
    const rb_derived *d = &sv->sys.d;
    const rb_exact_cache *c = &sv->exact;
    double x[ZN];
    memset(a, 0, ZN * ZN * sizeof a[0][0]);
    floor_row(c, x);
    a[ZU][ZV] = 1;
    a[ZV][ZU] = -d->Kstar / d->Mstar;
    a[ZV][ZV] = -d->Cstar / d->Mstar;
    for (int j = 0; j < ZN; j++)
        a[ZV][j] += d->Nstar / d->Mstar * x[j];
    if (c->wb > 0) {
        a[ZUB][ZVB] = 1;
        a[ZVB][ZUB] = -c->wb * c->wb;
        a[ZVB][ZVB] = -2 * c->xib * c->wb;
        a[ZVB][ZG] = -1;
    }
    a[ZG][ZS] = 1;
}

/* The rows of E(F h) a table reads (U, U', u_b, v_b and the line g), for
 * 0 <= F <= 1. The system is scaled so that its entries are of order one:
 * time in units of h, and each component in its natural size for the
 * fastest frequency w, D = diag(1/w^2, 1/w, 1/w^2, 1/w, 1, w) in units of
 * the line's value. The step is cut into m panels of at most 1.5 rad of
 * the fastest oscillation; inside a panel a row is the Taylor series of
 * the scaled exponential, e_i^T exp(S f) = sum_k e_i^T S^k f^k / k!, whose
 * terms are below rounding by the 30th (|S| is about 2 at most), and the
 * panels before it are the panel's transition (rb_matexp) applied once
 * each. A table costs a few hundred dot products; an exponential for each
 * of its points cost 60 us, 1.5 % of a 4 ms run. */
enum { NROW = 5, NTERM = 30 };
static const int row_of[NROW] = {ZU, ZV, ZUB, ZVB, ZG};

typedef struct {
    double pw[NROW][NTERM][ZN]; /* e_i^T S^k / k! */
    double ep[ZN][ZN];          /* exp(S), the panel's transition */
    double d[ZN];
    int m;
} rows;

static void rows_init(const rb_solver *sv, double h, int m, rows *r)
{
    double a[ZN][ZN], s[ZN][ZN];
    const rb_exact_cache *c = &sv->exact;
    system_matrix(sv, a);
    double w = rb_fmax(rb_fmax(sv->sys.d.omega, c->wb), 1 / h);
    const double d[ZN] = {1 / (w * w), 1 / w, 1 / (w * w), 1 / w, 1, w};
    memcpy(r->d, d, sizeof d);
    r->m = m;
    for (int i = 0; i < ZN; i++)
        for (int j = 0; j < ZN; j++)
            s[i][j] = h / m * a[i][j] * d[j] / d[i];
    for (int i = 0; i < NROW; i++) {
        memset(r->pw[i][0], 0, sizeof r->pw[i][0]);
        r->pw[i][0][row_of[i]] = 1;
        for (int k = 1; k < NTERM; k++)
            for (int j = 0; j < ZN; j++) {
                double v = 0;
                for (int l = 0; l < ZN; l++)
                    v += r->pw[i][k - 1][l] * s[l][j];
                r->pw[i][k][j] = v / k;
            }
    }
    if (m > 1)
        rb_matexp(ZN, &s[0][0], &r->ep[0][0]);
}

/* out[i] = row row_of[i] of E(F h), unscaled. */
static void rows_at(const rows *r, double F, double out[NROW][ZN])
{
    int p = (int)(F * r->m);
    if (p > r->m - 1)
        p = r->m - 1;
    double f = F * r->m - p;
    for (int i = 0; i < NROW; i++) {
        double v[ZN];
        memcpy(v, r->pw[i][NTERM - 1], sizeof v);
        for (int k = NTERM - 2; k >= 0; k--)
            for (int j = 0; j < ZN; j++)
                v[j] = v[j] * f + r->pw[i][k][j];
        for (int q = 0; q < p; q++) {
            double u[ZN];
            for (int j = 0; j < ZN; j++) {
                u[j] = 0;
                for (int l = 0; l < ZN; l++)
                    u[j] += v[l] * r->ep[l][j];
            }
            memcpy(v, u, sizeof v);
        }
        for (int j = 0; j < ZN; j++)
            out[i][j] = r->d[row_of[i]] * v[j] / r->d[j];
    }
}

static void build_table(const rb_solver *sv, double h, int n, rb_exact_table *t)
{
    const rb_exact_cache *c = &sv->exact;
    double e[NROW][ZN], x[ZN];
    rows r;
    floor_row(c, x);
    /* panels of at most 1.5 rad of the fastest oscillation, whose squares
     * the 8 points integrate to rounding (a stiff building under a coarse
     * record turns several times in one step) */
    int panels = (int)ceil(rb_fmax(sv->sys.d.omega, c->wb) * h / 1.5);
    if (panels < 1)
        panels = 1;
    rows_init(sv, h, panels, &r);
    t->h = h;
    t->n = n;
    for (int j = 1; j <= n; j++) {
        rows_at(&r, (double)j / n, e);
        memcpy(t->row[j - 1], e, sizeof t->row[0]);
    }
    memset(t->gvv, 0, sizeof t->gvv);
    memset(t->gxv, 0, sizeof t->gxv);
    for (int q = 0; q < 8 * panels; q++) {
        double rx[ZN] = {0}, wq = 0.5 * h / panels * gl_w[q % 8];
        rows_at(&r, (q / 8 + 0.5 * (1 + gl_x[q % 8])) / panels, e);
        for (int i = 0; i < NROW; i++)
            for (int j = 0; j < ZN; j++)
                rx[j] += x[row_of[i]] * e[i][j];
        for (int i = 0; i < ZN; i++)
            for (int j = 0; j < ZN; j++) {
                t->gvv[i][j] += wq * e[1][i] * e[1][j];
                t->gxv[i][j] += wq * rx[i] * e[1][j];
            }
    }
}

/* Step lengths repeat (a sample interval, or its share of steps capped at
 * a tenth of the frame's period); those after an event do not, and a
 * table is only formed for a length met before. Lengths equal to 1e-12
 * and to a few roundings of the time share a table: a sample interval's
 * length, or what is left of it after a capped step, rounds differently
 * from one sample to the next (a shift of 1e-12 s in a 40 s run). A run
 * keeps RB_EXACT_TABLES tables; a length met after they are taken (a
 * record of uneven steps) is stepped by Taylor series, as before. */
static int same_length(double a, double b, double t)
{
    return fabs(a - b) <= 1e-12 * a + 8 * DBL_EPSILON * t;
}

static const rb_exact_table *table_for(rb_solver *sv, double h, int n)
{
    rb_exact_cache *c = &sv->exact;
    double t = fabs(sv->t) + h;
    for (int i = 0; i < c->n_tab; i++)
        if (c->tab[i].n == n && same_length(c->tab[i].h, h, t))
            return &c->tab[i];
    if (c->n_tab == RB_EXACT_TABLES)
        return NULL;
    int seen = 0;
    for (int i = 0; i < c->n_seen && !seen; i++)
        seen = same_length(c->seen[i], h, t);
    if (!seen) {
        c->seen[c->n_seen % RB_EXACT_TABLES] = h;
        c->n_seen++;
        if (c->n_seen > RB_EXACT_TABLES)
            c->n_seen = RB_EXACT_TABLES;
        return NULL;
    }
    build_table(sv, h, n, &c->tab[c->n_tab]);
    return &c->tab[c->n_tab++];
}

void rb_exact_setup(rb_solver *sv)
{
    const rb_motion *m = sv->sys.motion;
    const rb_derived *d = &sv->sys.d;
    rb_exact_cache *c = &sv->exact;
    /* the exact transition is the frame's under a constant g: under a
     * vertical, stage 1 takes Taylor steps */
    c->on = m->kind == RB_MOTION_SAMPLED && m->series && !sv->sys.model->rigid
            && !m->vertical
            && sv->opts.integrator == RB_INTEGRATOR_AUTO && sv->opts.exact_floor
            && sv->sys.form != RB_FORM_CONSISTENT;
    if (!c->on)
        return;
    if (m->series->bld.ground_mps2) {
        c->wb = m->series->bld.omega_rps;
        c->xib = m->series->bld.xi;
    }
    c->inv_ms = 1 / d->Mstar;
    c->in_th = sv->sys.form == RB_FORM_SMALL ? sv->sys.M * d->R : sv->sys.M * sv->sys.h;
}

/* One check point: the state, the floor, U'' and the rate of the uplift
 * moment M h x' - F* U''' (as rb_taylor_held_force_rate on the floor). */
typedef struct {
    double y[RB_NY], x, udd, rate;
} point;

static void point_at(const rb_solver *sv, const double *z, point *p)
{
    const rb_derived *d = &sv->sys.d;
    const rb_exact_cache *c = &sv->exact;
    double xd;
    if (c->wb > 0) {
        double w2 = c->wb * c->wb, cb = 2 * c->xib * c->wb;
        double vbd = -w2 * z[ZUB] - cb * z[ZVB] - z[ZG];
        p->x = -(cb * z[ZVB] + w2 * z[ZUB]);
        xd = -(cb * vbd + w2 * z[ZVB]);
    } else {
        p->x = z[ZG];
        xd = z[ZS];
    }
    p->udd = (d->Nstar * p->x - d->Kstar * z[ZU] - d->Cstar * z[ZV]) * c->inv_ms;
    double uddd = (d->Nstar * xd - d->Kstar * z[ZV] - d->Cstar * p->udd) * c->inv_ms;
    p->rate = c->in_th * xd - d->Fstar * uddd;
    /* the angle stays as the floor stage keeps it (as a Taylor step) */
    memcpy(p->y, sv->y, sizeof p->y);
    p->y[RB_Y_U] = z[ZU];
    p->y[RB_Y_UD] = z[ZV];
}

/* What rb_dyn_rhs gives besides the derivatives on the floor, from the
 * point laid out as a still Taylor step's series are. */
static void aux_of(const rb_solver *sv, const point *p, rb_aux *a)
{
    double v[RB_TS_N] = {0};
    v[RB_TS_U] = p->y[RB_Y_U];
    v[RB_TS_UD] = p->y[RB_Y_UD];
    v[RB_TS_X] = p->x;
    v[RB_TS_UDD] = p->udd;
    v[RB_TS_COS] = 1;
    rb_aux_of_values(&sv->sys, &sv->disc, 0, 0, v, a);
}

static double quad(const double q[ZN][ZN], const double *z)
{
    double s = 0;
    for (int i = 0; i < ZN; i++) {
        double r = 0;
        for (int j = 0; j < ZN; j++)
            r += q[i][j] * z[j];
        s += z[i] * r;
    }
    return s;
}

static int point_finite(const point *p)
{
    return isfinite(p->y[RB_Y_U]) && isfinite(p->y[RB_Y_UD]) && isfinite(p->x)
           && isfinite(p->udd) && isfinite(p->rate);
}

/* A time history reads the state between check points: the step's
 * Taylor series serves it there, so that asking for a history does not
 * change how the run is integrated. */
static rb_status history(rb_solver *sv, double t0, const double *y0, double h, double t1)
{
    if (!rb_history_due(sv, t1))
        return RB_OK;
    rb_rk_step st;
    st.is_taylor = 1;
    st.t0 = t0;
    st.h = h;
    st.t1 = t1;
    if (!(rb_exact_dense(sv, t0, y0, h, &st.ts) > 0))
        return RB_ERR_NONFINITE;
    return rb_history_sample(sv, &st, t0, t1);
}

/* An exact step of stage 1 towards target (the next break or the end):
 * 1 when taken, with the state, the guards g at its end and the tracked
 * quantities advanced as a Taylor step without an event would (*status
 * says whether the time history's rows could be stored); 0 when the step
 * must be a Taylor step instead (nothing changed). */
static int exact_step(rb_solver *sv, double target, double *g, rb_status *status)
{
    rb_floor_line fl;
    int landing;
    double t0 = sv->t, h = rb_step_length(sv, target, &landing);
    if (!(h > 0) || !rb_motion_floor_line(sv->sys.motion, t0, &fl))
        return 0;
    int n = rb_step_checks(sv, h);
    const rb_exact_table *tab = table_for(sv, h, n);
    if (!tab)
        return 0;
    double t1 = landing ? target : t0 + h;
    double z0[ZN] = {sv->y[RB_Y_U], sv->y[RB_Y_UD], fl.u, fl.v, fl.g0, fl.slope};
    point p[RB_SUB_MAX + 1];
    *status = RB_OK;
    double gs[RB_SUB_MAX + 1][G_COUNT];
    unsigned mask = rb_guard_mask(sv);
    double dt_guard = h / n, dt_track = (t1 - t0) / n;

    /* the start as the step before left it */
    point_at(sv, z0, &p[0]);
    memcpy(gs[0], g, sizeof gs[0]);
    rb_guard_nudge(gs[0]);
    for (int j = 1; j <= n; j++) {
        double z[ZN];
        for (int i = 0; i < 4; i++) {
            double r = 0;
            for (int k = 0; k < ZN; k++)
                r += tab->row[j - 1][i][k] * z0[k];
            z[i] = r;
        }
        z[ZG] = fl.g0 + fl.slope * tab->h * j / n;
        z[ZS] = fl.slope;
        point_at(sv, z, &p[j]);
        if (!point_finite(&p[j]))
            return 0;
        double tj = j == n ? t1 : t0 + dt_guard * j;
        rb_guard_eval_x(sv, tj, p[j].y, p[j].x, sv->sys.d.g, gs[j]);
        /* a root inside: the Taylor step finds it */
        for (unsigned m = mask; m;) {
            int k = rb_guard_next(&m);
            if (rb_guard_crossed(k, gs[j - 1][k], gs[j][k]))
                return 0;
        }
        double ra = p[j - 1].rate, rb = p[j].rate;
        if (ra != 0 && rb != 0 && (ra < 0) != (rb < 0)
            && !rb_force_turn_stays(mask, dt_guard, fabs(ra), fabs(rb), gs[j - 1], gs[j]))
            return 0;
        double va = p[j - 1].y[RB_Y_UD], vb = p[j].y[RB_Y_UD];
        if ((va < 0) != (vb < 0) && va != 0 && vb != 0) {
            double ua = p[j - 1].y[RB_Y_U], ub = p[j].y[RB_Y_U];
            double bound = rb_fmax(fabs(ua), fabs(ub)) + dt_track * (fabs(va) + fabs(vb));
            if (bound > sv->res->max_u_m)
                return 0;
        }
    }

    /* taken: what advance and rb_track_interval do with a step that has no
     * event and no peak to locate */
    rb_aux a;
    rb_track_span_series(sv, t0, sv->y, h, t1);
    for (int j = 1; j < n; j++) {
        aux_of(sv, &p[j], &a);
        rb_track_aux(sv, t0 + dt_track * j, p[j].y, &a);
    }
    if ((*status = history(sv, t0, sv->y, h, t1)) != RB_OK)
        return 1;
    sv->res->steps++;
    sv->res->exact_steps++;
    sv->res->stage_steps[sv->disc.stage]++;
    sv->res->stage_time_s[sv->disc.stage] += t1 - t0;
    double wd = sv->y[RB_Y_WDAMP] + sv->sys.d.Cstar * quad(tab->gvv, z0);
    double wi = sv->y[RB_Y_WIN] + sv->sys.d.Nstar * quad(tab->gxv, z0);
    sv->t = t1;
    sv->y[RB_Y_U] = p[n].y[RB_Y_U];
    sv->y[RB_Y_UD] = p[n].y[RB_Y_UD];
    sv->y[RB_Y_WDAMP] = wd;
    sv->y[RB_Y_WIN] = wi;
    aux_of(sv, &p[n], &a);
    sv->f[RB_Y_U] = p[n].y[RB_Y_UD];
    sv->f[RB_Y_UD] = p[n].udd;
    sv->f[RB_Y_TH] = sv->f[RB_Y_THD] = 0;
    sv->f[RB_Y_WDAMP] = sv->sys.d.Cstar * p[n].y[RB_Y_UD] * p[n].y[RB_Y_UD];
    sv->f[RB_Y_WIN] = a.p_input;
    sv->f[RB_Y_WCPL] = a.p_coupling;
    memcpy(g, gs[n], sizeof gs[n]);
    rb_track_aux(sv, t1, sv->y, &a);
    rb_track_span_none(sv);
    return 1;
}

static rb_step_outcome exact_apply(rb_solver *sv, double target, double h, rb_rk_step *st,
                                   double *g, rb_status *status)
{
    (void)h;
    (void)st;
    return exact_step(sv, target, g, status) ? RB_STEP_ADVANCED : RB_STEP_DECLINED;
}

const rb_stepper rb_stepper_exact = {"exact", exact_apply, NULL};
