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
#include "pair.h"
#include "stepper.h"
#include "taylor.h"

/* the quantities bounded over a step ("Bounds over a step") */
enum { Q_U = RB_XQ_U, Q_SHEAR = RB_XQ_SHEAR, Q_UP_POS = RB_XQ_UP_POS, Q_UP_NEG = RB_XQ_UP_NEG };

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

static void table_bounds(rb_solver *sv, const rows *r, double h, rb_exact_table *t);

/* Peaks on the step's own polynomial. A table of one panel keeps the rows
 * of U, U', u_b, v_b and of the total shear (its form lin[Q_SHEAR], the
 * line's g and s rows included) of E(f h) as polynomials in f, unscaled:
 * a step's quantities between its check points are then these rows times
 * its z0, a polynomial in f with one coefficient a term, and a peak of the
 * shear is a root of that polynomial's derivative (rb_exact_span_shear_turns).
 * Terms past the last one above 1e-17 of the scaled series' order-one
 * entries are left out (the series of a short step falls off fast). A
 * table of several panels keeps none (nterm 0): its peaks are located on
 * the step's Taylor series as before. */
static void table_poly(const rb_solver *sv, const rows *r, rb_exact_table *t)
{
    const rb_exact_cache *c = &sv->exact;
    t->nterm = 0;
    if (r->m != 1)
        return;
    int nt = 1;
    for (int k = 0; k < NTERM; k++) {
        double l[ZN] = {0};
        for (int i = 0; i < NROW; i++)
            for (int j = 0; j < ZN; j++) {
                double e = r->d[row_of[i]] * r->pw[i][k][j] / r->d[j];
                if (i < 4)
                    t->poly[k][i][j] = e;
                l[j] += c->lin[Q_SHEAR][row_of[i]] * e;
                if (fabs(r->pw[i][k][j]) > 1e-17)
                    nt = k + 1;
            }
        /* the line's slope s is constant: its row of E is e_s */
        if (k == 0)
            l[ZS] += c->lin[Q_SHEAR][ZS];
        memcpy(t->poly[k][4], l, sizeof l);
    }
    t->nterm = nt;
}

/* panels of at most 1.5 rad of the fastest oscillation, whose squares
 * the 8 points integrate to rounding (a stiff building under a coarse
 * record turns several times in one step) */
static int panels_of(const rb_solver *sv, double h)
{
    int panels = (int)ceil(rb_fmax(sv->sys.d.omega, sv->exact.wb) * h / 1.5);
    return panels < 1 ? 1 : panels;
}

static void build_table(rb_solver *sv, double h, int n, rb_exact_table *t)
{
    const rb_exact_cache *c = &sv->exact;
    double e[NROW][ZN], x[ZN];
    rows r;
    floor_row(c, x);
    int panels = panels_of(sv, h);
    rows_init(sv, h, panels, &r);
    t->h = h;
    t->n = n;
    for (int j = 1; j <= n; j++) {
        rows_at(&r, (double)j / n, e);
        memcpy(t->row[j - 1], e, sizeof t->row[0]);
    }
    for (int j = 0; j < ZN; j++)
        t->end_uv[j] = rb_pair_make(t->row[n - 1][ZU][j], t->row[n - 1][ZV][j]);
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
    table_bounds(sv, &r, h, t);
    table_poly(sv, &r, t);
    const double cw[2] = {sv->sys.d.Cstar, sv->sys.d.Nstar};
    double pk[ZN * (ZN + 1) / 2][2];
    for (int w = 0; w < 2; w++) {
        double(*q)[ZN] = w == 0 ? t->gvv : t->gxv;
        int k = 0;
        for (int i = 0; i < ZN; i++)
            for (int j = i; j < ZN; j++)
                pk[k++][w] = cw[w] * (i == j ? q[i][i] : q[i][j] + q[j][i]);
    }
    for (int k = 0; k < ZN * (ZN + 1) / 2; k++)
        t->work[k] = rb_pair_make(pk[k][0], pk[k][1]);
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

static void quantities_at(const rb_solver *sv, const double *z, double *q)
{
    rb_exact_point p;
    rb_aux a;
    double g[G_COUNT], V;
    rb_exact_point_at(sv, z, &p);
    rb_exact_aux_of(sv, &p, &a);
    rb_guard_eval_x(sv, sv->t, p.y, p.x, sv->sys.d.g, g);
    q[Q_U] = p.y[RB_Y_U];
    rb_dyn_reactions(&sv->sys, &sv->disc, p.y, &a, &q[Q_SHEAR], &V);
    q[Q_UP_POS] = g[G_UP_POS];
    q[Q_UP_NEG] = g[G_UP_NEG];
}

static int point_finite(const rb_exact_point *p)
{
    return isfinite(p->y[RB_Y_U]) && isfinite(p->y[RB_Y_UD]) && isfinite(p->x)
           && isfinite(p->udd) && isfinite(p->rate);
}

/* Bounds over a step.
 *
 * On the floor every quantity a step must watch is an affine function of
 * the state z at its instant, q(z) = l . z + l0: U, the total shear
 * (-M x + N* U'', x and U'' being linear in z), and the two uplift guards
 * (the moment M h x - F* U'' less W b, and its mirror). Over a step,
 * z(tau) = E(tau) z0, so q = r(tau) . z0 + l0 with the row
 * r(tau) = l^T E(tau), and
 *     |q(tau) - l0| <= sum_j B[j] |z0_j|,   B[j] = max over [0, h] of |r_j|.
 * A step whose bounds keep every guard below its boundary and every
 * tracked quantity below its running peak has nothing to find between its
 * ends: no uplift, no new peak. It then costs the bounds, the works and
 * the advance (exact_quiet), where a step with check points reads the
 * state, the guards and the tracked quantities at each of them.
 *
 * Why B is a bound (a missed uplift would be a wrong PASS). The row is
 * sampled at tau_k = k h / K, k = 0..K, to S[j] = max_k |r_j(tau_k)|.
 * Every tau lies within d = h / (2K) of a sample, and r' = r A (A the
 * system matrix, E' = E A), so with M[j] the true maximum of |r_j|
 *     M[j] <= S[j] + d sum_l |A_lj| M[l],   i.e.  M <= S + d |A|^T M.
 * Let B > 0 satisfy S + d |A|^T B <= B (checked after it is computed; S
 * is taken slightly above the samples' rounding and positive). Then the
 * nonnegative matrix P = d |A|^T has P B <= B - S < B, so its spectral
 * radius is below one (Collatz-Wielandt), and D = M - B satisfies
 * D <= P D, hence max(D, 0) <= P^k max(D, 0) -> 0: M <= B. The rows
 * themselves are the scaled exponential's series, exact to rounding
 * (build_table). test_exact_bounds holds B against dense sampling of the
 * quantities over random cabinets, buildings, states and step lengths. */
/* Sample intervals per panel of the table (a panel being at most 1.5 rad
 * of the fastest oscillation): d |A| is then about 0.02, which is what B
 * exceeds the samples by. */
enum { BOUND_SAMPLES = 32 };

/* The quantities' affine forms, read off the functions that evaluate them
 * at a check point (point_at, aux_of, rb_dyn_reactions,
 * rb_guard_eval_x), so that the bounds are of the same quantities. */
static void linear_forms(rb_solver *sv)
{
    rb_exact_cache *c = &sv->exact;
    double z[ZN] = {0}, q0[RB_EXACT_NQ], q[RB_EXACT_NQ];
    rb_exact_point p0, p;
    /* the floor stage's forms, whichever stage builds the first table (a
     * plate held by a row reads them too): its guards are the uplift
     * guards, with the side of a plate on the floor */
    rb_disc held = sv->disc;
    sv->disc.stage = RB_STAGE_FIXED;
    sv->disc.side = 0;
    quantities_at(sv, z, q0);
    rb_exact_point_at(sv, z, &p0);
    for (int j = 0; j < ZN; j++) {
        z[j] = 1;
        quantities_at(sv, z, q);
        rb_exact_point_at(sv, z, &p);
        z[j] = 0;
        for (int k = 0; k < RB_EXACT_NQ; k++)
            c->lin[k][j] = q[k] - q0[k];
        c->lin_x[j] = p.x - p0.x;
        c->lin_a[j] = p.udd - p0.udd;
    }
    memcpy(c->lin0, q0, sizeof q0);
    c->lin_ready = 1;
    c->lin_side = sv->disc.side;
    sv->disc = held;
}

/* B from S: (I - d |A|^T) B = S by elimination, then checked to satisfy
 * S + d |A|^T B <= B; 0 where it does not (no bound is used then). */
static int supersolution(double pa[ZN][ZN], const double *S, double *B)
{
    double m[ZN][ZN + 1];
    for (int i = 0; i < ZN; i++) {
        for (int j = 0; j < ZN; j++)
            m[i][j] = (i == j) - pa[j][i];
        m[i][ZN] = S[i];
    }
    for (int k = 0; k < ZN; k++) {
        int p = k;
        for (int i = k + 1; i < ZN; i++)
            if (fabs(m[i][k]) > fabs(m[p][k]))
                p = i;
        if (!(fabs(m[p][k]) > 0))
            return 0;
        for (int j = 0; j <= ZN; j++) {
            double tmp = m[k][j];
            m[k][j] = m[p][j];
            m[p][j] = tmp;
        }
        for (int i = k + 1; i < ZN; i++) {
            double f = m[i][k] / m[k][k];
            for (int j = k; j <= ZN; j++)
                m[i][j] -= f * m[k][j];
        }
    }
    for (int i = ZN - 1; i >= 0; i--) {
        double v = m[i][ZN];
        for (int j = i + 1; j < ZN; j++)
            v -= m[i][j] * B[j];
        B[i] = v / m[i][i];
    }
    for (int i = 0; i < ZN; i++)
        B[i] *= 1 + 1e-9;
    for (int i = 0; i < ZN; i++) {
        double v = S[i];
        for (int l = 0; l < ZN; l++)
            v += pa[l][i] * B[l];
        if (!(B[i] > 0) || !isfinite(B[i]) || !(v <= B[i]))
            return 0;
    }
    return 1;
}

/* B for one quantity from its samples' largest sizes S (taken above the
 * rows' rounding, and positive: the proof's B > 0); 0 where none. */
static int bound_of_samples(double pa[ZN][ZN], double *S, double *B)
{
    double smax = 0;
    for (int j = 0; j < ZN; j++)
        smax = rb_fmax(smax, S[j]);
    for (int j = 0; j < ZN; j++)
        S[j] = S[j] * (1 + 1e-12) + 1e-15 * smax + DBL_MIN;
    return supersolution(pa, S, B);
}

/* How far U, the total shear, the uplift moment, the floor acceleration
 * and U'' (lin_x, lin_a) can move from their start over a step, which the
 * held stage's force and reactions are formed from (exact_held.c): with
 * D(tau) = r(tau) - r(0) sampled to S_D, and r' = r A bounded through
 * the row's own bound B (above), |D_j| <= S_D[j] + d sum_l |A_lj| B[l]
 * between samples. */
enum { NV = 5 };
static void held_bounds(rb_solver *sv, const rows *r, double pa[ZN][ZN], int K,
                        rb_exact_table *t)
{
    double B4[RB_EXACT_NQ][ZN];
    for (int j = 0; j < ZN; j++)
        for (int q = 0; q < RB_EXACT_NQ; q++)
            B4[q][j] = rb_pair_lane(t->bound[j][q / 2], q % 2);
    const rb_exact_cache *c = &sv->exact;
    double S[2][ZN] = {{0}}, B[NV][ZN] = {{0}}, SD[NV][ZN] = {{0}}, r0[NV][ZN], e[NROW][ZN];
    const double *form[NV] = {c->lin[Q_U], c->lin[Q_SHEAR], c->lin[Q_UP_POS], c->lin_x,
                              c->lin_a};
    for (int k = 0; k <= K; k++) {
        rows_at(r, (double)k / K, e);
        for (int q = 0; q < NV; q++)
            for (int j = 0; j < ZN; j++) {
                double v = j == ZS ? form[q][ZS] : 0;
                for (int i = 0; i < NROW; i++)
                    v += form[q][row_of[i]] * e[i][j];
                if (k == 0)
                    r0[q][j] = v;
                if (q >= 3)
                    S[q - 3][j] = rb_fmax(S[q - 3][j], fabs(v));
                SD[q][j] = rb_fmax(SD[q][j], fabs(v - r0[q][j]));
            }
    }
    t->held_bounded = t->bounded && bound_of_samples(pa, S[0], B[3])
                      && bound_of_samples(pa, S[1], B[4]);
    memcpy(B[0], B4[Q_U], sizeof B[0]);
    memcpy(B[1], B4[Q_SHEAR], sizeof B[1]);
    memcpy(B[2], B4[Q_UP_POS], sizeof B[2]);
    double D[NV + 1][ZN] = {{0}};
    for (int q = 0; q < NV; q++) {
        double smax = 0;
        for (int j = 0; j < ZN; j++)
            smax = rb_fmax(smax, SD[q][j]);
        for (int j = 0; j < ZN; j++) {
            double v = SD[q][j] * (1 + 1e-12) + 1e-15 * smax + DBL_MIN;
            for (int l = 0; l < ZN; l++)
                v += pa[l][j] * B[q][l];
            D[q][j] = v * (1 + 1e-12);
        }
    }
    for (int j = 0; j < ZN; j++)
        for (int q = 0; q < 3; q++)
            t->vary[j][q] = rb_pair_make(D[2 * q][j], D[2 * q + 1][j]);
}

static void table_bounds(rb_solver *sv, const rows *r, double h, rb_exact_table *t)
{
    rb_exact_cache *c = &sv->exact;
    double a[ZN][ZN], pa[ZN][ZN], S[RB_EXACT_NQ][ZN] = {{0}}, e[NROW][ZN];
    if (!c->lin_ready)
        linear_forms(sv);
    int K = BOUND_SAMPLES * r->m;
    system_matrix(sv, a);
    for (int i = 0; i < ZN; i++)
        for (int j = 0; j < ZN; j++)
            pa[i][j] = h / (2.0 * K) * fabs(a[i][j]);
    for (int k = 0; k <= K; k++) {
        rows_at(r, (double)k / K, e);
        for (int q = 0; q < RB_EXACT_NQ; q++)
            for (int j = 0; j < ZN; j++) {
                /* the line's slope s is constant: its row of E is e_s */
                double v = j == ZS ? c->lin[q][ZS] : 0;
                for (int i = 0; i < NROW; i++)
                    v += c->lin[q][row_of[i]] * e[i][j];
                S[q][j] = rb_fmax(S[q][j], fabs(v));
            }
    }
    double B[RB_EXACT_NQ][ZN] = {{0}};
    t->bounded = 1;
    for (int q = 0; q < RB_EXACT_NQ && t->bounded; q++)
        t->bounded = bound_of_samples(pa, S[q], B[q]);
    for (int j = 0; j < ZN; j++)
        for (int q = 0; q < RB_EXACT_NQ; q += 2)
            t->bound[j][q / 2] = rb_pair_make(B[q][j], B[q + 1][j]);
    /* formed when a held plate first asks (rb_exact_table_held) */
    t->held_bounded = -1;
}

/* A time history reads the state between check points: the step's
 * Taylor series serves it there, so that asking for a history does not
 * change how the run is integrated. */
rb_status rb_exact_history(rb_solver *sv, double t0, const double *y0, double h, double t1)
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

/* Peaks a step's bounds must stay under to be quiet: a hundredth of a
 * per mille below, more than what the dense output a step with check
 * points locates its peaks on can add to them (a tenth of the tolerance,
 * not below 1e-13 relative), so that such a step would not have moved
 * them either. */
#define QUIET_MARGIN (1 + 1e-6)

/* What a step's bounds are held to (step_quiet), constant over a run of
 * quiet steps (they move no result): the guards' distance below zero and
 * U's peak; the shear is held to rb_track_quiet_bound, whose conditions
 * rise with it, so a bound at or below one it passed passes too. */
typedef struct {
    double up_pos, up_neg, u;
    double shear_passed; /* the largest shear bound passed, -1 before */
} quiet_limits;

void rb_exact_bounds_of(const rb_exact_table *tab, const double *z0, double *b)
{
    /* each quantity summed over j in order, two quantities a vector */
    _Static_assert(RB_EXACT_NQ == 4, "two pairs of quantities");
    rb_pair lo = rb_pair_splat(0), hi = lo;
    for (int j = 0; j < ZN; j++) {
        rb_pair az = rb_pair_splat(fabs(z0[j]));
        lo = rb_pair_madd(lo, tab->bound[j][0], az);
        hi = rb_pair_madd(hi, tab->bound[j][1], az);
    }
    b[0] = rb_pair_lane(lo, 0);
    b[1] = rb_pair_lane(lo, 1);
    b[2] = rb_pair_lane(hi, 0);
    b[3] = rb_pair_lane(hi, 1);
}

/* 0 where no step can be quiet (the forms of the other side, reactions
 * checked at every point). */
static int quiet_limits_of(const rb_solver *sv, quiet_limits *l)
{
    const rb_exact_cache *c = &sv->exact;
    if (c->lin_side != sv->disc.side || sv->opts.check_reactions)
        return 0;
    /* the guards are lin0 (-W b) plus their bounded part */
    l->up_pos = -c->lin0[Q_UP_POS];
    l->up_neg = -c->lin0[Q_UP_NEG];
    l->u = sv->res->max_u_m;
    l->shear_passed = -1;
    return 1;
}

/* Whether the step from z0 over table tab can be taken with no check
 * points: its bounds keep both uplift guards below zero and U and the
 * total shear (hence the friction demand, the floor's reaction being W)
 * and the anchors' demand at or below their running peaks, so that no
 * point or located peak inside it could move a result. */
static inline int bounds_quiet(const rb_solver *sv, const rb_exact_table *tab,
                               const double *z0, quiet_limits *l)
{
    if (!tab->bounded)
        return 0;
    double b[RB_EXACT_NQ];
    rb_exact_bounds_of(tab, z0, b);
    for (int q = 0; q < RB_EXACT_NQ; q++)
        b[q] *= QUIET_MARGIN;
    if (!(b[Q_UP_POS] < l->up_pos && b[Q_UP_NEG] < l->up_neg && b[Q_U] <= l->u))
        return 0;
    if (b[Q_SHEAR] <= l->shear_passed)
        return 1;
    if (!rb_track_quiet_bound(sv, b[Q_SHEAR]))
        return 0;
    l->shear_passed = b[Q_SHEAR];
    return 1;
}

static int step_quiet(const rb_solver *sv, const rb_exact_table *tab, const double *z0)
{
    quiet_limits l;
    return quiet_limits_of(sv, &l) && bounds_quiet(sv, tab, z0, &l);
}

/* The state at check point j (1..n) of the step from z0. */
void rb_exact_check_state(const rb_exact_table *tab, const rb_floor_line *fl, const double *z0,
                          int j, double *z)
{
    for (int i = 0; i < 4; i++) {
        double r = 0;
        for (int k = 0; k < ZN; k++)
            r += tab->row[j - 1][i][k] * z0[k];
        z[i] = r;
    }
    z[ZG] = fl->g0 + fl->slope * tab->h * j / tab->n;
    z[ZS] = fl->slope;
}

/* The works' quadratic forms of z added to *wd and *wi, written out
 * (the 21 pairs of a 6-state: a loop over the triangle is not unrolled,
 * and costs twice as many instructions), both sums a vector, and the
 * products z_i z_j two at a time (z_i times z_j and z_j+1). */
_Static_assert(ZN == 6, "work_forms writes out the pairs of a 6-state");
void rb_exact_work_forms(const rb_exact_table *tab, const double *z, double *wd, double *wi)
{
    const rb_pair *w = tab->work;
    rb_pair s = rb_pair_splat(0), p;
#define TWO(i, j, k)                                                    \
    (p = rb_pair_mul(rb_pair_splat(z[i]), rb_pair_load(z + (j))),       \
     s = rb_pair_madd(s, w[k], rb_pair_dup(p, 0)),                      \
     s = rb_pair_madd(s, w[(k) + 1], rb_pair_dup(p, 1)))
#define ONE(i, j, k) (s = rb_pair_madd(s, w[k], rb_pair_splat(z[i] * z[j])))
    TWO(0, 0, 0); TWO(0, 2, 2); TWO(0, 4, 4);
    TWO(1, 1, 6); TWO(1, 3, 8); ONE(1, 5, 10);
    TWO(2, 2, 11); TWO(2, 4, 13);
    TWO(3, 3, 15); ONE(3, 5, 17);
    TWO(4, 4, 18);
    ONE(5, 5, 20);
#undef TWO
#undef ONE
    *wd += rb_pair_lane(s, 0);
    *wi += rb_pair_lane(s, 1);
}

/* U and U' at the end of the step from z0, both sums a vector. */
void rb_exact_end_state(const rb_exact_table *tab, const double *z0, double *u, double *v)
{
    rb_pair s = rb_pair_splat(0);
    for (int j = 0; j < ZN; j++)
        s = rb_pair_madd(s, tab->end_uv[j], rb_pair_splat(z0[j]));
    *u = rb_pair_lane(s, 0);
    *v = rb_pair_lane(s, 1);
}

/* Advance the run's time, state and works over a step taken from z0,
 * whose end point carries U and U' (u_end, v_end). */
void rb_exact_count_step(rb_solver *sv, double t1)
{
    sv->res->steps++;
    sv->res->exact_steps++;
    sv->res->stage_steps[sv->disc.stage]++;
    sv->res->stage_time_s[sv->disc.stage] += t1 - sv->t;
}

static void advance_step(rb_solver *sv, const rb_exact_table *tab, const double *z0, double t1,
                         double u_end, double v_end)
{
    rb_exact_count_step(sv, t1);
    double wd = sv->y[RB_Y_WDAMP], wi = sv->y[RB_Y_WIN];
    rb_exact_work_forms(tab, z0, &wd, &wi);
    sv->t = t1;
    sv->y[RB_Y_U] = u_end;
    sv->y[RB_Y_UD] = v_end;
    sv->y[RB_Y_WDAMP] = wd;
    sv->y[RB_Y_WIN] = wi;
}

/* The rates at the end point p of the step just advanced over, and the
 * guards there (g_end, read by the caller) into g. */
static void end_rates(rb_solver *sv, const rb_exact_point *p, const double *g_end, double *g, rb_aux *a)
{
    rb_exact_aux_of(sv, p, a);
    sv->f[RB_Y_U] = p->y[RB_Y_UD];
    sv->f[RB_Y_UD] = p->udd;
    sv->f[RB_Y_TH] = sv->f[RB_Y_THD] = 0;
    sv->f[RB_Y_WDAMP] = sv->sys.d.Cstar * p->y[RB_Y_UD] * p->y[RB_Y_UD];
    sv->f[RB_Y_WIN] = a->p_input;
    sv->f[RB_Y_WCPL] = a->p_coupling;
    if (g)
        memcpy(g, g_end, G_COUNT * sizeof *g);
}

/* Advance the run over a step taken: the works from their Gramians, the
 * state, its rates and the guards at the end point p (tracked there by
 * the caller). */
static void finish_step(rb_solver *sv, const rb_exact_table *tab, const double *z0,
                        double t1, const rb_exact_point *p, const double *g_end, double *g, rb_aux *a)
{
    advance_step(sv, tab, z0, t1, p->y[RB_Y_U], p->y[RB_Y_UD]);
    end_rates(sv, p, g_end, g, a);
}

/* What a quiet step reads at its end, read once a run of them is over:
 * its last two points, which the peaks' windows keep for the next step,
 * with windows that start at them as after a transition (the next step's
 * windows then hold the points a step with check points would have left
 * in them); the guards and the rates at its end. The points of the quiet
 * steps before it move no result: their bounds kept U, the shear, the
 * friction and anchor demands at or below the running peaks and the
 * floor's reaction at W, at or above the least (step_quiet), and the
 * windows each of them would have left are overwritten by the next. */
void rb_exact_settle(rb_solver *sv, double *g)
{
    rb_exact_cache *c = &sv->exact;
    if (!c->pending)
        return;
    c->pending = 0;
    if (c->pend_settle) {
        c->pend_settle(sv, g);
        return;
    }
    const rb_exact_table *tab = c->pend_tab;
    const rb_floor_line fl = {.g0 = c->pend_g0, .slope = c->pend_slope};
    int n = tab->n;
    double z[ZN], gs[G_COUNT], u[2], H[2], t0 = c->pend_t0, t1 = sv->t;
    rb_exact_point p[2];
    for (int k = 0; k < 2; k++) {
        rb_exact_check_state(tab, &fl, c->pend_z0, n - 1 + k, z);
        rb_exact_point_at(sv, z, &p[k]);
        /* the shear's form is the reactions' own (linear_forms) */
        u[k] = p[k].y[RB_Y_U];
        H[k] = c->lin0[Q_SHEAR];
        for (int j = 0; j < ZN; j++)
            H[k] += c->lin[Q_SHEAR][j] * z[j];
    }
    rb_guard_eval_x(sv, t1, p[1].y, p[1].x, sv->sys.d.g, gs);
    rb_aux a;
    double tt[2] = {t0 + (t1 - t0) / n * (n - 1), t1};
    end_rates(sv, &p[1], gs, g, &a);
    rb_track_quiet_points(sv, tt, u, H, p[1].x);
}

/* A quiet step (step_quiet): it advances the state and the works alone,
 * and leaves what is read at its end to rb_exact_settle, at once where a
 * time history is kept (its rows read the rates), else when the run of
 * quiet steps is over. 0 where the end is not finite (nothing changed). */
static int exact_quiet(rb_solver *sv, const rb_exact_table *tab, const rb_floor_line *fl,
                       const double *z0, double t1, double *g, rb_status *status)
{
    rb_exact_cache *c = &sv->exact;
    double u, v, t0 = sv->t;
    rb_exact_end_state(tab, z0, &u, &v);
    if (!isfinite(u) || !isfinite(v))
        return 0;
    /* a quiet step before this one leaves nothing to read: this one's end
     * takes its place */
    if ((*status = rb_exact_history(sv, t0, sv->y, tab->h, t1)) != RB_OK)
        return 1;
    advance_step(sv, tab, z0, t1, u, v);
    c->pending = 1;
    c->pend_settle = NULL;
    c->pend_tab = tab;
    memcpy(c->pend_z0, z0, sizeof c->pend_z0);
    c->pend_t0 = t0;
    c->pend_g0 = fl->g0;
    c->pend_slope = fl->slope;
    if (sv->res->history)
        rb_exact_settle(sv, g);
    return 1;
}

/* The table for steps of length h: a run's steps are mostly of one
 * length, looked up once; NULL where the step is to be a Taylor step. */
const rb_exact_table *rb_exact_table_of_length(rb_solver *sv, double h)
{
    rb_exact_cache *c = &sv->exact;
    for (int k = 0; k < RB_EXACT_TABLES; k++)
        if (h == c->memo_h[k] && c->memo_tab[k])
            return c->memo_tab[k];
    /* a length found once keeps its table (table_for finds the first
     * that fits, and tables are only added after it) */
    const rb_exact_table *tab = table_for(sv, h, rb_step_checks(sv, h));
    if (tab) {
        c->memo_h[c->memo_next] = h;
        c->memo_tab[c->memo_next] = tab;
        c->memo_next = (c->memo_next + 1) % RB_EXACT_TABLES;
    }
    return tab;
}

/* The sample a step starts at: i where t is the sample's time to the
 * bit (t0_s + i dt_s, as rb_motion_next_break puts the breaks), else -1. */
static long sample_at(const rb_series *s, double t)
{
    double k = floor((t - s->t0_s) / s->dt_s + 0.5);
    if (!(k >= 0 && k < (double)s->n - 1) || s->t0_s + k * s->dt_s != t)
        return -1;
    return (long)k;
}

/* A run of quiet steps from a sample (the first one's bounds passed by
 * the caller), taken here as the run loop and exact_step would take them
 * one by one: the same target (the next sample), length, floor line,
 * table and bounds, the works added step by step in the same order, the
 * end read once (rb_exact_settle). Nothing is read between them but the
 * loop's own conditions (rb_run_goes_on); the first step that is not
 * quiet, or that is not from a sample to the next, is left to the loop,
 * nothing changed. Returns whether it took one. */
static int quiet_run(rb_solver *sv)
{
    rb_exact_cache *c = &sv->exact;
    const rb_motion *m = sv->sys.motion;
    const rb_series *s = m->series;
    quiet_limits lim;
    long last = -1, i = sample_at(s, sv->t);
    if (i < 0 || !quiet_limits_of(sv, &lim))
        return 0;
    double u0 = 0, v0 = 0, t0 = 0;
    const rb_exact_table *tab = NULL;
    /* the control's trial length short of any target (exact steps leave
     * it as it is) */
    double trial = rb_control_trial(sv, HUGE_VAL);
    for (; rb_run_goes_on(sv); i++) {
        /* the run loop's target: the next sample (a later end is the
         * loop's), its trial length and the step's */
        double brk = s->t0_s + (double)(i + 1) * s->dt_s;
        if (!(i + 1 <= (long)s->n - 1) || !(brk <= sv->t_end)
            || !(rb_fmin(trial, brk - sv->t) > 1e-14 * (1 + sv->t)))
            break;
        int landing;
        double h = rb_step_length(sv, brk, &landing);
        const rb_exact_table *t = h > 0 ? rb_exact_table_of_length(sv, h) : NULL;
        rb_floor_line f;
        if (!t || !rb_motion_floor_line_at(m, i, &f))
            break;
        double z[ZN] = {sv->y[RB_Y_U], sv->y[RB_Y_UD], f.u, f.v, f.g0, f.slope};
        if (!bounds_quiet(sv, t, z, &lim))
            break;
        double u, v, t1 = landing ? brk : sv->t + h;
        rb_exact_end_state(t, z, &u, &v);
        if (!isfinite(u) || !isfinite(v))
            break;
        t0 = sv->t;
        advance_step(sv, t, z, t1, u, v);
        /* the last step's start, for rb_exact_settle */
        last = i;
        u0 = z[ZU];
        v0 = z[ZV];
        tab = t;
        if (!landing)
            break;
    }
    if (last < 0)
        return 0;
    double z[ZN] = {u0, v0};
    rb_floor_line f;
    rb_motion_floor_line_at(m, last, &f);
    z[ZUB] = f.u;
    z[ZVB] = f.v;
    z[ZG] = f.g0;
    z[ZS] = f.slope;
    c->pending = 1;
    c->pend_settle = NULL;
    c->pend_tab = tab;
    memcpy(c->pend_z0, z, sizeof c->pend_z0);
    c->pend_t0 = t0;
    c->pend_g0 = f.g0;
    c->pend_slope = f.slope;
    return 1;
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
    const rb_exact_table *tab;
    if (!(h > 0) || !rb_motion_floor_line(sv->sys.motion, t0, &fl)
        || !(tab = rb_exact_table_of_length(sv, h)))
        return 0;
    int n = tab->n;
    double t1 = landing ? target : t0 + h;
    double z0[ZN] = {sv->y[RB_Y_U], sv->y[RB_Y_UD], fl.u, fl.v, fl.g0, fl.slope};
    rb_exact_point p[RB_SUB_MAX + 1];
    *status = RB_OK;
    double gs[RB_SUB_MAX + 1][G_COUNT];
    unsigned mask = rb_guard_mask(sv);
    double dt_guard = h / n, dt_track = (t1 - t0) / n;

    if (step_quiet(sv, tab, z0)
        && ((!sv->res->history && quiet_run(sv))
            || exact_quiet(sv, tab, &fl, z0, t1, g, status)))
        return 1;
    rb_exact_settle(sv, g);

    /* the start as the step before left it */
    rb_exact_point_at(sv, z0, &p[0]);
    memcpy(gs[0], g, sizeof gs[0]);
    rb_guard_nudge(gs[0]);
    for (int j = 1; j <= n; j++) {
        double z[ZN];
        rb_exact_check_state(tab, &fl, z0, j, z);
        rb_exact_point_at(sv, z, &p[j]);
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
    rb_track_span_exact(sv, t0, sv->y, h, t1, (int)(tab - sv->exact.tab), z0);
    for (int j = 1; j < n; j++) {
        rb_exact_aux_of(sv, &p[j], &a);
        rb_track_aux(sv, t0 + dt_track * j, p[j].y, &a);
    }
    if ((*status = rb_exact_history(sv, t0, sv->y, h, t1)) != RB_OK)
        return 1;
    finish_step(sv, tab, z0, t1, &p[n], gs[n], g, &a);
    rb_track_aux(sv, t1, sv->y, &a);
    rb_track_span_none(sv);
    return 1;
}

rb_step_outcome rb_exact_outcome(rb_solver *sv, int taken, double *g)
{
    if (taken)
        return RB_STEP_ADVANCED;
    /* the next stepper reads the guards, the rates and the tracking */
    rb_exact_settle(sv, g);
    return RB_STEP_DECLINED;
}

static rb_step_outcome exact_apply(rb_solver *sv, double target, double h, rb_rk_step *st,
                                   double *g, rb_status *status)
{
    (void)h;
    (void)st;
    return rb_exact_outcome(sv, exact_step(sv, target, g, status), g);
}

const rb_stepper rb_stepper_exact = {"exact", exact_apply, NULL};

void rb_exact_table_build(rb_solver *sv, double h, int n, rb_exact_table *t)
{
    build_table(sv, h, n, t);
}

void rb_exact_system(const rb_solver *sv, double a[RB_EXACT_DIM][RB_EXACT_DIM])
{
    system_matrix(sv, a);
}

/* A table's held bounds (held_bounds), formed on first use: most runs
 * never hold the plate, and the floor run's tables cost a tenth more
 * with them. The rows are formed again as build_table formed them. */
int rb_exact_table_held(rb_solver *sv, rb_exact_table *t)
{
    if (t->held_bounded < 0) {
        double a[ZN][ZN], pa[ZN][ZN];
        rows r;
        rows_init(sv, t->h, panels_of(sv, t->h), &r);
        int K = BOUND_SAMPLES * r.m;
        system_matrix(sv, a);
        for (int i = 0; i < ZN; i++)
            for (int j = 0; j < ZN; j++)
                pa[i][j] = t->h / (2.0 * K) * fabs(a[i][j]);
        t->held_bounded = 0;
        if (t->bounded)
            held_bounds(sv, &r, pa, K, t);
    }
    return t->held_bounded > 0;
}
