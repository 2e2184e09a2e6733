/* Taylor-series steps for stages 1, 2 and 4 (see taylor.h).
 *
 * Work is done in the mirrored frame of dynamics.c (rocking about the left
 * edge), with the same equations as rb_dyn_rhs, and the series are stored
 * in the physical frame, so that the mirror of a run is exact. */
#include <math.h>
#include "bolt.h"
#include "minmax.h"
#include "pair.h"
#include "simd.h"
#include "taylor.h"

enum { NT = RB_TAYLOR_MAX + 2 };

/* 1 / k: a multiplication in the recurrences instead of a division, which
 * costs several times as much and was the largest single item of a step */
#define INV4(k) 1.0 / (k), 1.0 / ((k) + 1), 1.0 / ((k) + 2), 1.0 / ((k) + 3)
static const double inv[NT + 2] = {
    0, INV4(1), INV4(5), INV4(9), INV4(13), INV4(17), INV4(21), INV4(25), INV4(29),
    1.0 / 33, 1.0 / 34, 1.0 / 35,
};

int rb_taylor_applies(const rb_sys *S, const rb_disc *D)
{
    if (S->form == RB_FORM_CONSISTENT || S->motion->kind == RB_MOTION_CRITICAL)
        return 0;
    /* a row in stage 4 is a rigid stop or a spring in its chord */
    if (D->stage == RB_STAGE_HELD)
        return S->bolt->rigid_stop || S->bolt->spring_npm;
    /* a yielding row pulls with Fy, a spring's or a rigid row's alike. A
     * usage grows by the stretch, a small difference of two angles, and
     * Dormand-Prince at the case's tolerance put an error on the angle's
     * scale into it (docs/solver.md, "Stage 5") */
    if (D->stage == RB_STAGE_YIELD)
        return 1;
    return D->stage == RB_STAGE_FIXED || D->stage == RB_STAGE_UPLIFT;
}

typedef struct {
    double Ns, Ks, Cs, Ms, Fs, Io, inv_det, inv_Io, inv_Ms, W, R, alpha, g, M, b, h;
    int rigid, small;
    int vert; /* a vertical floor acceleration: gravity is the series G */
} consts;

RB_INLINE void load_consts(const rb_sys *S, consts *k)
{
    const rb_derived *d = &S->d;
    k->Ns = d->Nstar; k->Ks = d->Kstar; k->Cs = d->Cstar; k->Ms = d->Mstar;
    k->Fs = d->Fstar; k->Io = d->Io; k->W = d->W; k->R = d->R; k->alpha = d->alpha;
    k->g = d->g; k->M = S->M; k->b = S->b; k->h = S->h;
    k->inv_det = 1 / (d->Mstar * d->Io - d->Fstar * d->Fstar);
    k->inv_Io = 1 / d->Io;
    k->inv_Ms = 1 / d->Mstar;
    k->rigid = S->model->rigid;
    k->small = S->form == RB_FORM_SMALL;
    k->vert = S->motion->vertical != NULL;
}

/* The mirrored series: U, T = theta, the floor acceleration X (polynomial
 * of degree xd), Q = theta'^2, and per order one row of what the order's
 * products read, so that every product of an order is a lane of one pass
 * over j (rb_taylor_step's order loop). A row is read from both ends of
 * the pass: as the later factor b (fg, cs, ov side by side, so that two
 * overlapping quads are (fg, cs) and (cs, ov)), and as the earlier factor
 * a, whose lanes ta are laid out to match: theta' three times and U' (a
 * quad against (cs, ov)), then U' and the floor three times (against (fg,
 * cs)). */
typedef struct {
    /* the coupling power per unit U' and the input power per unit floor
     * acceleration (order k's formed late, from order k's sums) */
    double fg[2];
    double cs[2]; /* cos theta, sin theta */
    double ov[2]; /* theta', U' */
    double h[2];  /* cos and sin of half the angle (a row's lever) */
    double ta[8]; /* theta' theta' theta' U' X X X, and one spare */
} orow;
typedef struct {
    double U[NT], T[NT], X[NT], Q[NT];
    orow R[NT];
    int xd;
    /* under a vertical: z'' (Z) and the apparent gravity g + z'' (G), of
     * degree gd, zeros past it */
    double Z[NT], G[NT];
    int gd;
    /* the vertical floor's power -z'' dH/dt (dynamics.c's vertical_power):
     * dH/dt is M (b cos + h sin)' rocking (large), M R (alpha - theta)
     * theta' (small), 0 with the plate still */
    double DH[NT];
} series;

#define C_(s, k) ((s)->R[k].cs[0])
#define S_(s, k) ((s)->R[k].cs[1])
#define O_(s, k) ((s)->R[k].ov[0])
#define V_(s, k) ((s)->R[k].ov[1])

/* What a row holds the plate with, for the order-k moment about the pivot. */
typedef struct {
    int kind;          /* BOLT_SLACK, BOLT_SPRING (stage 4), BOLT_YIELD (stage 5) */
    double k_row, gap, fy, l;
} bolt_law;
enum { BOLT_SLACK, BOLT_SPRING, BOLT_YIELD };

/* Order k of the bolt's moment: the tension times the lever l cos(theta/2)
 * (l when small). A spring's k (2 l sin(theta/2) - gap) l cos(theta/2) is
 * k l (l sin theta - gap cos(theta/2)). */
RB_INLINE double bolt_moment(const consts *K, const bolt_law *B, const series *s, int k)
{
    if (B->kind == BOLT_SLACK)
        return 0;
    if (K->small) {
        if (B->kind == BOLT_YIELD)
            return k == 0 ? B->fy * B->l : 0;
        return B->k_row * B->l * (B->l * s->T[k] - (k == 0 ? B->gap : 0));
    }
    if (B->kind == BOLT_YIELD)
        return B->fy * B->l * s->R[k].h[0];
    return B->k_row * B->l * (B->l * S_(s, k) - B->gap * s->R[k].h[0]);
}

RB_INLINE void bolt_law_of(const rb_sys *S, const rb_disc *D, double th0, bolt_law *B,
                        series *s)
{
    B->kind = D->stage == RB_STAGE_YIELD ? BOLT_YIELD
              : D->stage == RB_STAGE_HELD && !S->bolt->rigid_stop ? BOLT_SPRING
                                                                  : BOLT_SLACK;
    B->l = S->l;
    B->fy = S->d.fy_row_n;
    B->k_row = B->kind == BOLT_SPRING ? S->bolt->spring_npm(S) : 0;
    B->gap = D->gap[rb_row_of_side(D->side)];
    s->R[0].h[0] = B->kind != BOLT_SLACK ? cos(0.5 * th0) : 1;
    s->R[0].h[1] = B->kind != BOLT_SLACK ? sin(0.5 * th0) : 0;
}

/* The sums of order k, each sum_j a[j] b[k - j] over one pass of j. The
 * lanes of order k that are formed from this order's own sums (fg: the
 * coupling factor and the input power) are still 0 in row k, and their
 * j = 0 terms are added by the caller. */
typedef struct {
    double oc, os;     /* theta' cos, theta' sin: sin' and -cos' */
    double oo, vv;     /* theta'^2, U'^2 (damping power) */
    double xc, xs;     /* the floor's products with cos, sin */
    double vc;         /* U' cos (input power) */
    double vf, xg;     /* U' times the coupling factor, the floor times GI */
    double gc, gs;     /* the apparent gravity's products with cos, sin */
    double hc, hs;     /* theta' cos, sin of the half angle */
} order_sums;

/* Each j is two quads and a scalar (the lanes' products laid out as
 * orow's ta against the row's fg, cs, ov), and a pair each for the
 * vertical and the half angle: a lane's sum is added in the order of j
 * as a scalar sum is, so it has the same bits. */
RB_INLINE void fused_pass(const series *s, int k, int half, int vert, order_sums *p)
{
    rb_quad q1 = rb_quad_splat(0), q2 = q1; /* (oc, os, oo, vv), (vf, xg, xc, xs) */
    double vc = 0;
    rb_pair gcs = rb_pair_splat(0), h2 = gcs;
    for (int j = 0; j <= k; j++) {
        const orow *a = &s->R[j], *b = &s->R[k - j];
        q1 = rb_quad_horner(rb_quad_load(a->ta), rb_quad_load(b->cs), q1);
        q2 = rb_quad_horner(rb_quad_load(a->ta + 3), rb_quad_load(b->fg), q2);
        vc += a->ta[3] * b->cs[0];
        if (vert)
            gcs = rb_pair_madd(gcs, rb_pair_splat(s->G[j]), rb_pair_load(b->cs));
        if (half)
            h2 = rb_pair_madd(h2, rb_pair_splat(a->ov[0]), rb_pair_load(b->h));
    }
    double l1[4], l2[4];
    rb_quad_store(l1, q1);
    rb_quad_store(l2, q2);
    *p = (order_sums){l1[0], l1[1], l1[2], l1[3], l2[2], l2[3], vc, l2[0], l2[1],
                      rb_pair_lane(gcs, 0), rb_pair_lane(gcs, 1), rb_pair_lane(h2, 0),
                      rb_pair_lane(h2, 1)};
}

/* Row k's lanes of fused_pass: theta' and U' (set_rates) as the order
 * before forms them, the floor (set_floor) as the order reads it. */
RB_INLINE void set_rates(orow *r, double o, double v)
{
    r->ov[0] = o;
    r->ov[1] = v;
    r->ta[0] = r->ta[1] = r->ta[2] = o;
    r->ta[3] = v;
}

RB_INLINE void set_floor(orow *r, double x)
{
    r->ta[4] = r->ta[5] = r->ta[6] = x;
}

/* fused_pass with the plate still (stage 1, stage 4 against a rigid row):
 * theta' is 0 and cos and sin are constants, so only U''s and the floor's
 * products with the work rows are sums; the others are single terms,
 * the values fused_pass adds up (its other terms are exact zeros). */
RB_INLINE void still_pass(const series *s, int k, int vert, order_sums *p)
{
    double vv = 0;
    rb_pair fg = rb_pair_splat(0);
    for (int j = 0; j <= k; j++) {
        const orow *a = &s->R[j], *b = &s->R[k - j];
        vv += a->ov[1] * b->ov[1];
        fg = rb_pair_madd(fg, rb_pair_make(a->ov[1], s->X[j]), rb_pair_load(b->fg));
    }
    double c = C_(s, 0), sn = S_(s, 0), x = s->X[k], g = vert ? s->G[k] : 0;
    *p = (order_sums){0, 0, 0, vv, x * c, x * sn, V_(s, k) * c, rb_pair_lane(fg, 0),
                      rb_pair_lane(fg, 1), g * c, g * sn, 0, 0};
}

/* What the branches of an order read that a step holds constant: the
 * plate rocks, the motion has a vertical, the small formulation, the
 * half angle's series (a row that holds the rocking plate, large). The
 * usual shapes are compiled as order loops of their own (taylor_step),
 * with these branches out of them. */
typedef struct {
    int rocking, vert, small, half;
} shape;

/* Order k of the motion and of the work integrals (damping, input,
 * coupling: w, row k + 1's); they read the motion only up to order k and do not
 * feed back. The cos and sin of theta (and of its half) at order k + 1
 * come from s' = c theta', c' = -s theta' with theta' up to order k. With
 * the plate still (stages 1 and 4) theta' is 0, so the same sums hold
 * with only U'' left to the equation of motion. */
RB_INLINE void series_order(const consts *K, const bolt_law *B, shape f, series *s, int k,
                             double *w)
{
    int rocking = f.rocking, half = f.half;
    order_sums p;
    set_floor(&s->R[k], s->X[k]);
    if (!rocking)
        still_pass(s, k, f.vert, &p);
    else if (f.vert)
        fused_pass(s, k, half, 1, &p);
    else if (half)
        fused_pass(s, k, 1, 0, &p);
    else
        fused_pass(s, k, 0, 0, &p);
    double ik = inv[k + 1];
    orow *r = &s->R[k], *n = &s->R[k + 1];
    s->Q[k] = p.oo;
    n->cs[1] = p.oc * ik;
    n->cs[0] = -p.os * ik;
    if (half) {
        n->h[1] = 0.5 * p.hc * ik;
        n->h[0] = -0.5 * p.hs * ik;
    }
    /* the floor's and gravity's terms: X cos and X sin, G sin and G cos (G
     * theta and G (theta - alpha) when small) */
    double XC, XS, GS, GC;
    if (f.small) {
        XC = s->X[k];
        XS = 0;
        if (f.vert) {
            double tg = 0;
            for (int j = 0; j <= k; j++)
                tg += s->T[j] * s->G[k - j];
            GS = tg;
            GC = GS - K->alpha * s->G[k];
        } else {
            GS = K->g * s->T[k];
            GC = 0; /* the moment's gravity term is W R (theta - alpha) */
        }
    } else {
        XC = p.xc;
        XS = p.xs;
        GS = f.vert ? p.gs : K->g * S_(s, k);
        GC = p.gc; /* read under a vertical only */
    }
    double RU = K->Ns * (XC + GS) - K->Ks * s->U[k] - K->Cs * r->ov[1] - K->Ns * K->b * p.oo;
    double udd, thdd = 0;
    if (rocking) {
        double Rth;
        if (f.vert) /* W = M G: every gravity term a product with G's series */
            Rth = f.small ? K->M * K->R * (XC + GC)
                           : K->M * (K->h * XC + K->b * XS) - K->M * (K->b * GC - K->h * GS);
        else if (f.small)
            Rth = K->M * K->R * XC + K->W * K->R * (s->T[k] - (k == 0 ? K->alpha : 0));
        else
            Rth = K->M * (K->h * XC + K->b * XS) - K->W * (K->b * C_(s, k) - K->h * S_(s, k));
        Rth -= bolt_moment(K, B, s, k);
        if (K->rigid) {
            udd = 0;
            thdd = Rth * K->inv_Io;
        } else {
            udd = (K->Io * RU - K->Fs * Rth) * K->inv_det;
            thdd = (K->Ms * Rth - K->Fs * RU) * K->inv_det;
        }
    } else
        udd = K->rigid ? 0 : RU * K->inv_Ms;
    s->U[k + 1] = r->ov[1] * ik;
    s->T[k + 1] = r->ov[0] * ik;
    set_rates(n, thdd * ik, udd * ik);
    n->fg[0] = n->fg[1] = 0;

    /* the work integrals: the coupling factor N* (G sin - b theta'^2) and
     * the input power per unit floor acceleration, N* cos U' + M (h cos +
     * b sin) theta' (the second the derivative of M (h sin - b cos)), at
     * order k, then their j = 0 terms */
    r->fg[0] = K->Ns * (GS - K->b * p.oo);
    r->fg[1] = f.small ? K->Ns * r->ov[1] + K->M * K->R * r->ov[0]
                     : K->Ns * p.vc + K->M * (k + 1) * (K->h * n->cs[1] - K->b * n->cs[0]);
    double vf = p.vf + V_(s, 0) * r->fg[0], xg = p.xg + s->X[0] * r->fg[1];
    w[0] = K->Cs * p.vv * ik;
    w[2] = vf * ik;
    if (f.vert) {
        if (!rocking)
            s->DH[k] = 0;
        else if (f.small) {
            double to = 0;
            for (int j = 0; j <= k; j++)
                to += s->T[j] * O_(s, k - j);
            s->DH[k] = K->M * K->R * (K->alpha * r->ov[0] - to);
        } else
            s->DH[k] = K->M * (k + 1) * (K->b * n->cs[1] + K->h * n->cs[0]);
        double pv = 0;
        for (int j = 0; j <= k; j++)
            pv += s->Z[j] * s->DH[k - j];
        xg -= pv;
    }
    w[1] = xg * ik;
}

/* Largest scaled size of the order-k coefficients over a step of hk = h^k.
 * Plain comparisons make branch-free maxima, which drop a NaN; the product
 * 0 * sum keeps a NaN or an infinity, so a non-finite series is caught. */
RB_INLINE double scaled(const series *s, int k, double hk, const double *tol, double tol_x)
{
    double a = fabs(s->U[k]) * tol[RB_Y_U], b = fabs(V_(s, k)) * tol[RB_Y_UD];
    double c = fabs(s->T[k]) * tol[RB_Y_TH], d = fabs(O_(s, k)) * tol[RB_Y_THD];
    double x = fabs(s->X[k]) * tol_x;
    double ab = a > b ? a : b, cd = c > d ? c : d, abcd = ab > cd ? ab : cd;
    return (abcd > x ? abcd : x) * hk + 0.0 * (a + b + c + d + x);
}

/* The floor's series is formed to a first guess of the order a step
 * needs, and again to the largest only when a step goes past it: its terms
 * do not depend on how many are asked for, and through a building (two
 * divisions a term) the whole RB_TAYLOR_MAX + 2 were a sixth of a step. */
#define RB_X_FIRST 16

/* The mirrored floor's series to order n into s->X, zeros past a
 * polynomial's degree; returns the order up to which s->X holds the
 * motion (all of it for a polynomial). */
RB_INLINE int floor_series(const rb_motion *m, double t0, double sgn, int n, series *s)
{
    s->xd = rb_motion_taylor(m, t0, n, s->X);
    /* the mirror's sign: X (-1) is -X, and X 1 is X */
    if (sgn < 0)
        for (int k = 0; k <= s->xd; k++)
            s->X[k] = -s->X[k];
    /* a polynomial's series is its terms and zeros to the last order; a
     * series of n terms is formed again before an order reads past them */
    if (s->xd < n) {
        for (int k = n + 1; k < NT; k++)
            s->X[k] = 0;
        return NT;
    }
    return n;
}

/* The vertical's series z'' and g + z'' to the largest order at once: a
 * sine or a line, no building. */
RB_INLINE void gravity_series(const rb_motion *v, double g, double t0, series *s)
{
    s->gd = rb_motion_taylor(v, t0, RB_TAYLOR_MAX + 1, s->Z);
    for (int k = RB_TAYLOR_MAX + 2; k < NT; k++)
        s->Z[k] = 0;
    for (int k = 0; k < NT; k++)
        s->G[k] = s->Z[k];
    s->G[0] += g;
}

/* The physical frame's series as the orders form them: row k + 1's state,
 * cos and sin, and row k's floor and accelerations (the derivatives of
 * the rates' series, row k + 1's). The still stages keep theta as it
 * was: their angle's rows past the first are zeros. */
RB_INLINE void physical_rows(double (*p)[RB_TS_N], const series *s, int k, double sgn,
                             int rocking, int vert)
{
    double *q = p[k], *r = p[k + 1];
    q[RB_TS_X] = sgn * s->X[k];
    q[RB_TS_UDD] = sgn * (k + 1) * V_(s, k + 1);
    q[RB_TS_Z] = vert ? s->Z[k] : 0;
    r[RB_TS_U] = sgn * s->U[k + 1];
    r[RB_TS_UD] = sgn * V_(s, k + 1);
    if (rocking) {
        q[RB_TS_THDD] = sgn * (k + 1) * O_(s, k + 1);
        r[RB_TS_TH] = sgn * s->T[k + 1];
        r[RB_TS_THD] = sgn * O_(s, k + 1);
        r[RB_TS_COS] = C_(s, k + 1);
        r[RB_TS_SIN] = S_(s, k + 1);
    } else {
        q[RB_TS_THDD] = 0;
        r[RB_TS_TH] = r[RB_TS_THD] = r[RB_TS_COS] = r[RB_TS_SIN] = 0;
    }
}

/* Row 0 in the physical frame, less what physical_rows writes. */
RB_INLINE void physical_start(double *q, const series *s, double sgn, int rocking,
                              const double *y0)
{
    q[RB_TS_U] = sgn * s->U[0];
    q[RB_TS_UD] = sgn * V_(s, 0);
    q[RB_TS_TH] = rocking ? sgn * s->T[0] : y0[RB_Y_TH];
    q[RB_TS_THD] = rocking ? sgn * O_(s, 0) : y0[RB_Y_THD];
    q[RB_TS_COS] = C_(s, 0);
    q[RB_TS_SIN] = S_(s, 0);
    q[RB_TS_WDAMP] = y0[RB_Y_WDAMP];
    q[RB_TS_WIN] = y0[RB_Y_WIN];
    q[RB_TS_WCPL] = y0[RB_Y_WCPL];
}

/* The orders of a step from its row 0, until two terms in a row are
 * within the tolerance (tol, tol_x) over h or the order bound is met,
 * which cuts h. Returns the order, 0 where the series is not finite. */
RB_INLINE int orders(const rb_motion *m, const consts *K, const bolt_law *B, shape f,
                     series *s, double t0, double sgn, int xn, const double *tol,
                     double tol_x, double *h_io, double (*p)[RB_TS_N])
{
    double h = *h_io, hk = 1, e_prev = HUGE_VAL;
    for (int k = 0;; k++) {
        /* order k reads the floor to order k, and the step's end to n */
        if (k + 1 > xn) {
            xn = floor_series(m, t0, sgn, RB_TAYLOR_MAX + 1, s);
            /* the rows' copies of the floor, so that they are these terms */
            for (int j = 0; j < k; j++)
                set_floor(&s->R[j], s->X[j]);
        }
        series_order(K, B, f, s, k, p[k + 1] + RB_TS_WDAMP);
        physical_rows(p, s, k, sgn, f.rocking, f.vert);
        int n = k + 1;
        hk *= h;
        double e = scaled(s, n, hk, tol, tol_x);
        if (f.vert) /* the vertical's own series, on the floor's scale */
            e = rb_fmax(e, fabs(s->Z[n]) * tol_x * hk + 0.0 * s->Z[n]);
        if (!isfinite(e))
            return 0;
        /* two terms in a row, since a series can have a vanishing term */
        if (n >= 3 && e <= 1 && e_prev <= 1)
            return n;
        if (n == RB_TAYLOR_MAX) {
            double g = rb_fmin(pow(0.5 / e, 1.0 / n), pow(0.5 / e_prev, 1.0 / (n - 1)));
            *h_io = h * rb_fmin(g, 1.0);
            return n;
        }
        e_prev = e;
    }
}

RB_INLINE double taylor_step(const rb_sys *S, const rb_disc *D, double t0, const double *y0,
                             double h_want, const double *atol, double atol_x, double rtol,
                             rb_taylor *ts)
{
    consts K;
    series s;
    bolt_law B;
    /* the vertical's series are read only where there is one
     * (gravity_series then writes all of them): not cleared here */
    s.gd = 0;
    double sgn = D->side < 0 ? -1.0 : 1.0, tol[RB_NY];
    int rocking = rb_dyn_rocking(S, D);
    load_consts(S, &K);
    int xn = floor_series(S->motion, t0, sgn, RB_X_FIRST, &s);
    if (K.vert)
        gravity_series(S->motion->vertical, K.g, t0, &s);
    s.U[0] = sgn * y0[RB_Y_U];
    s.T[0] = rocking ? sgn * y0[RB_Y_TH] : D->stage == RB_STAGE_HELD ? D->theta_hold : 0;
    set_rates(&s.R[0], rocking ? sgn * y0[RB_Y_THD] : 0, sgn * y0[RB_Y_UD]);
    C_(&s, 0) = s.T[0] == 0 ? 1 : cos(s.T[0]);
    S_(&s, 0) = s.T[0] == 0 ? 0 : sin(s.T[0]);
    s.R[0].fg[0] = s.R[0].fg[1] = 0;
    bolt_law_of(S, D, s.T[0], &B, &s);
    /* reciprocals: the test runs once per order */
    for (int i = RB_Y_U; i <= RB_Y_THD; i++)
        tol[i] = 1 / (atol[i] + rtol * fabs(y0[i]));
    /* the floor's own series too: the reactions and the uplift guards read
     * it between check points, and through a building stiffer than the
     * frame (or under a rigid body, which has no frame) it converges more
     * slowly than the state's */
    double tol_x = 1 / (atol_x + rtol * fabs(s.X[0]));

    double h = h_want;
    /* written as the orders are formed: a step that returns 0 leaves them
     * half written, and no one reads them */
    double (*p)[RB_TS_N] = ts->p;
    physical_start(p[0], &s, sgn, rocking, y0);
    shape f = {rocking, K.vert, K.small, rocking && !K.small && B.kind != BOLT_SLACK};
    int n;
    if (f.vert)
        n = orders(S->motion, &K, &B, f, &s, t0, sgn, xn, tol, tol_x, &h, p);
    else if (f.half)
        n = orders(S->motion, &K, &B, (shape){1, 0, 0, 1}, &s, t0, sgn, xn, tol, tol_x, &h,
                   p);
    else if (f.rocking)
        n = f.small ? orders(S->motion, &K, &B, (shape){1, 0, 1, 0}, &s, t0, sgn, xn, tol,
                             tol_x, &h, p)
                    : orders(S->motion, &K, &B, (shape){1, 0, 0, 0}, &s, t0, sgn, xn, tol,
                             tol_x, &h, p);
    else
        n = f.small ? orders(S->motion, &K, &B, (shape){0, 0, 1, 0}, &s, t0, sgn, xn, tol,
                             tol_x, &h, p)
                    : orders(S->motion, &K, &B, (shape){0, 0, 0, 0}, &s, t0, sgn, xn, tol,
                             tol_x, &h, p);
    if (n == 0)
        return 0;
    /* the last row's floor, and its accelerations past the series */
    p[n][RB_TS_X] = sgn * s.X[n];
    p[n][RB_TS_UDD] = p[n][RB_TS_THDD] = 0;
    p[n][RB_TS_Z] = K.vert ? s.Z[n] : 0;
    ts->rocking = rocking;
    ts->vertical = K.vert;
    ts->order = n;
    ts->lever_hold = D->stage == RB_STAGE_HELD ? rb_dyn_lever(S, D->theta_hold) : 0;
    return h;
}

double rb_taylor_step_plain(const rb_sys *S, const rb_disc *D, double t0, const double *y0,
                            double h_want, const double *atol, double atol_x, double rtol,
                            rb_taylor *ts)
{
    return taylor_step(S, D, t0, y0, h_want, atol, atol_x, rtol, ts);
}

RB_SIMD_AVX double rb_taylor_step_avx(const rb_sys *S, const rb_disc *D, double t0,
                                      const double *y0, double h_want, const double *atol,
                                      double atol_x, double rtol, rb_taylor *ts)
{
    return taylor_step(S, D, t0, y0, h_want, atol, atol_x, rtol, ts);
}

double rb_taylor_step(const rb_sys *S, const rb_disc *D, double t0, const double *y0,
                      double h_want, const double *atol, double atol_x, double rtol,
                      rb_taylor *ts)
{
    return rb_simd_avx() ? rb_taylor_step_avx(S, D, t0, y0, h_want, atol, atol_x, rtol, ts)
                         : rb_taylor_step_plain(S, D, t0, y0, h_want, atol, atol_x, rtol, ts);
}
