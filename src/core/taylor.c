/* Taylor-series steps for stages 1, 2 and 4 (see taylor.h).
 *
 * Work is done in the mirrored frame of dynamics.c (rocking about the left
 * edge), with the same equations as rb_dyn_rhs, and the series are stored
 * in the physical frame, so that the mirror of a run is exact. */
#include <math.h>
#include <string.h>
#include "bolt.h"
#include "minmax.h"
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

static void load_consts(const rb_sys *S, consts *k)
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

/* The mirrored series: U, V = U', T = theta, the floor acceleration X
 * (polynomial of degree xd), Q = theta'^2, and cos theta, sin theta and
 * theta' side by side (CSO[k] = {C, S, O, 0}): the three convolutions with
 * theta' that each order needs are then one pass of independent lanes. */
enum { LC, LS, LO, LANES };
typedef struct {
    double U[NT], V[NT], T[NT], X[NT], Q[NT];
    double CSO[NT][LANES + 1];
    /* cos and sin of half the angle, for a row's lever arm l cos(theta/2)
     * (stages 4 and 5 of the large formulation) */
    double C2[NT], S2[NT];
    int xd;
    /* under a vertical: z'' (Z) and the apparent gravity g + z'' (G), of
     * degree gd, zeros past it */
    double Z[NT], G[NT];
    int gd;
} series;

#define C_(s, k) ((s)->CSO[k][LC])
#define S_(s, k) ((s)->CSO[k][LS])
#define O_(s, k) ((s)->CSO[k][LO])

/* sum_j a[j] X[k - j], a read with a stride of 'stride' doubles: X has
 * nothing past degree xd (1 for a record) */
static inline double times_x(const double *a, int stride, const series *s, int k)
{
    if (s->xd <= 1)
        return a[k * stride] * s->X[0] + (k > 0 ? a[(k - 1) * stride] * s->X[1] : 0);
    double sum = 0;
    for (int j = k > s->xd ? k - s->xd : 0; j <= k; j++)
        sum += a[j * stride] * s->X[k - j];
    return sum;
}

/* sum_j G[j] a[k - j], as times_x: the apparent gravity's product */
static inline double times_g(const double *a, int stride, const series *s, int k)
{
    double sum = 0;
    for (int j = k > s->gd ? k - s->gd : 0; j <= k; j++)
        sum += a[j * stride] * s->G[k - j];
    return sum;
}

/* times_x of cos and sin at once: the two sums in one pass, each in the
 * order times_x adds it, so that their additions overlap instead of each
 * waiting on the last (the floor through a building has a full series) */
static inline void times_x_cs(const series *s, int k, double *xc, double *xs)
{
    if (s->xd <= 1) {
        *xc = times_x(&s->CSO[0][LC], LANES + 1, s, k);
        *xs = times_x(&s->CSO[0][LS], LANES + 1, s, k);
        return;
    }
    double c = 0, sn = 0;
    for (int j = k > s->xd ? k - s->xd : 0; j <= k; j++) {
        c += s->CSO[j][LC] * s->X[k - j];
        sn += s->CSO[j][LS] * s->X[k - j];
    }
    *xc = c;
    *xs = sn;
}

/* Order k of the right-hand side while rocking, the bolt's moment at that
 * order being m_bolt (0 in stage 2), after
 * theta'^2 at order k and cos, sin at order k + 1, which need theta' only up
 * to order k: one pass over theta' gives all three. The floor's products
 * with cos and sin (and the vertical's, under one) are sums over the same
 * j in the same pass, each in the order times_x and times_g add it, so
 * that no number moves. gs is the vertical's G sin (G theta when small),
 * which the coupling work reads too. */
static void rocking_order(const consts *K, series *s, int k, double m_bolt, double *udd,
                          double *thdd, double *gs)
{
    /* two sets of accumulators halve the chain of dependent additions */
    double a0[LANES + 1] = {0}, a1[LANES + 1] = {0};
    /* the floor's and the vertical's products with cos and sin, where
     * their series reach order k (times_x_cs and times_g then start at 0) */
    int fuse_x = !K->small && s->xd > 1 && k <= s->xd;
    int fuse_g = K->vert && !K->small && k <= s->gd;
    double xc = 0, xs = 0, gc = 0, gsn = 0;
    int j = 0;
    for (; j + 1 <= k; j += 2) {
        double o0 = O_(s, j), o1 = O_(s, j + 1);
        const double *p0 = s->CSO[k - j], *p1 = s->CSO[k - j - 1];
        for (int i = 0; i <= LANES; i++) {
            a0[i] += o0 * p0[i];
            a1[i] += o1 * p1[i];
        }
        if (fuse_x) {
            xc += s->CSO[j][LC] * s->X[k - j];
            xs += s->CSO[j][LS] * s->X[k - j];
            xc += s->CSO[j + 1][LC] * s->X[k - j - 1];
            xs += s->CSO[j + 1][LS] * s->X[k - j - 1];
        }
        if (fuse_g) {
            gsn += s->CSO[j][LS] * s->G[k - j];
            gc += s->CSO[j][LC] * s->G[k - j];
            gsn += s->CSO[j + 1][LS] * s->G[k - j - 1];
            gc += s->CSO[j + 1][LC] * s->G[k - j - 1];
        }
    }
    if (j == k) {
        for (int i = 0; i <= LANES; i++)
            a0[i] += O_(s, k) * s->CSO[0][i];
        if (fuse_x) {
            xc += s->CSO[k][LC] * s->X[0];
            xs += s->CSO[k][LS] * s->X[0];
        }
        if (fuse_g) {
            gsn += s->CSO[k][LS] * s->G[0];
            gc += s->CSO[k][LC] * s->G[0];
        }
    }
    s->Q[k] = a0[LO] + a1[LO];
    S_(s, k + 1) = (a0[LC] + a1[LC]) * inv[k + 1];
    C_(s, k + 1) = -(a0[LS] + a1[LS]) * inv[k + 1];
    double RU, Rth;
    *gs = 0;
    if (K->vert) {
        /* W = M G: every gravity term a product with G's series */
        double XC, XS, GS, GC;
        if (K->small) {
            XC = s->X[k];
            XS = 0;
            GS = times_g(s->T, 1, s, k);
            GC = GS - K->alpha * s->G[k]; /* G (T - alpha) */
        } else {
            if (fuse_x) {
                XC = xc;
                XS = xs;
            } else
                times_x_cs(s, k, &XC, &XS);
            GS = fuse_g ? gsn : times_g(&s->CSO[0][LS], LANES + 1, s, k);
            GC = fuse_g ? gc : times_g(&s->CSO[0][LC], LANES + 1, s, k);
        }
        *gs = GS;
        RU = K->Ns * (XC + GS) - K->Ks * s->U[k] - K->Cs * s->V[k] - K->Ns * K->b * s->Q[k];
        Rth = K->small ? K->M * K->R * (XC + GC)
                       : K->M * (K->h * XC + K->b * XS) - K->M * (K->b * GC - K->h * GS);
    } else if (K->small) {
        RU = K->Ns * (s->X[k] + K->g * s->T[k]) - K->Ks * s->U[k] - K->Cs * s->V[k]
             - K->Ns * K->b * s->Q[k];
        Rth = K->M * K->R * s->X[k] + K->W * K->R * (s->T[k] - (k == 0 ? K->alpha : 0));
    } else {
        double XC, XS;
        if (fuse_x) {
            XC = xc;
            XS = xs;
        } else
            times_x_cs(s, k, &XC, &XS);
        RU = K->Ns * (XC + K->g * S_(s, k)) - K->Ks * s->U[k] - K->Cs * s->V[k]
             - K->Ns * K->b * s->Q[k];
        Rth = K->M * (K->h * XC + K->b * XS) - K->W * (K->b * C_(s, k) - K->h * S_(s, k));
    }
    Rth -= m_bolt;
    if (K->rigid) {
        *udd = 0;
        *thdd = Rth * K->inv_Io;
    } else {
        *udd = (K->Io * RU - K->Fs * Rth) * K->inv_det;
        *thdd = (K->Ms * Rth - K->Fs * RU) * K->inv_det;
    }
}

/* What a row holds the plate with, for the order-k moment about the pivot. */
typedef struct {
    int kind;          /* BOLT_SLACK, BOLT_SPRING (stage 4), BOLT_YIELD (stage 5) */
    double k_row, gap, fy, l;
} bolt_law;
enum { BOLT_SLACK, BOLT_SPRING, BOLT_YIELD };

/* Order k of the bolt's moment: the tension times the lever l cos(theta/2)
 * (l when small). A spring's k (2 l sin(theta/2) - gap) l cos(theta/2) is
 * k l (l sin theta - gap cos(theta/2)). cos and sin of the half angle at
 * order k + 1 are formed here, from theta' up to order k. */
static double bolt_order(const consts *K, const bolt_law *B, series *s, int k)
{
    if (B->kind == BOLT_SLACK)
        return 0;
    if (K->small) {
        if (B->kind == BOLT_YIELD)
            return k == 0 ? B->fy * B->l : 0;
        return B->k_row * B->l * (B->l * s->T[k] - (k == 0 ? B->gap : 0));
    }
    double ac = 0, as = 0;
    for (int j = 0; j <= k; j++) {
        ac += O_(s, j) * s->C2[k - j];
        as += O_(s, j) * s->S2[k - j];
    }
    s->S2[k + 1] = 0.5 * ac * inv[k + 1];
    s->C2[k + 1] = -0.5 * as * inv[k + 1];
    if (B->kind == BOLT_YIELD)
        return B->fy * B->l * s->C2[k];
    return B->k_row * B->l * (B->l * S_(s, k) - B->gap * s->C2[k]);
}

static void bolt_law_of(const rb_sys *S, const rb_disc *D, double th0, bolt_law *B,
                        series *s)
{
    B->kind = D->stage == RB_STAGE_YIELD ? BOLT_YIELD
              : D->stage == RB_STAGE_HELD && !S->bolt->rigid_stop ? BOLT_SPRING
                                                                  : BOLT_SLACK;
    B->l = S->l;
    B->fy = S->d.fy_row_n;
    B->k_row = B->kind == BOLT_SPRING ? S->bolt->spring_npm(S) : 0;
    B->gap = D->gap[rb_row_of_side(D->side)];
    if (B->kind != BOLT_SLACK) {
        s->C2[0] = cos(0.5 * th0);
        s->S2[0] = sin(0.5 * th0);
    }
}

/* Order k of U'' with the plate still at an angle whose cos and sin are
 * C[0], S[0] (stages 1 and 4). */
static double still_order(const consts *K, const series *s, int k)
{
    if (K->rigid)
        return 0;
    if (K->vert) {
        double QU = K->Ns * (K->small ? s->X[k] + s->G[k] * s->T[0]
                                      : s->X[k] * C_(s, 0) + s->G[k] * S_(s, 0));
        return (QU - K->Ks * s->U[k] - K->Cs * s->V[k]) * K->inv_Ms;
    }
    double QU = K->small ? K->Ns * (s->X[k] + (k == 0 ? K->g * s->T[0] : 0))
                         : K->Ns * (s->X[k] * C_(s, 0) + (k == 0 ? K->g * S_(s, 0) : 0));
    return (QU - K->Ks * s->U[k] - K->Cs * s->V[k]) * K->inv_Ms;
}

/* The work integrals' series, one order at a time: these do not feed back
 * into the motion, so order k + 1 is formed as soon as the motion's order
 * k is (inside the order loop, one pass per order). w[k][0..2] = damping,
 * input, coupling. */
enum { WV, WC, WF, WL };
typedef struct {
    /* U' side by side with what it multiplies: itself (damping), cos theta
     * (input) and the coupling factor N* (g sin - b theta'^2) per unit U',
     * so one pass of independent lanes forms the three products */
    double P[NT][WL + 1], G[NT];
    /* the vertical floor's power -z'' dH/dt (dynamics.c's vertical_power):
     * dH/dt is M (b cos + h sin)' rocking (large), M R (alpha - theta)
     * theta' (small), 0 with the plate still */
    double DH[NT];
} work_rows;

static void work_order(const consts *K, const series *s, int rocking, int k, double gs,
                       work_rows *r, double (*w)[3])
{
    double *P = r->P[k];
    P[WV] = s->V[k];
    P[WC] = C_(s, k);
    if (K->vert) /* the still stages' angle is constant, G is not; rocking,
                  * the product is rocking_order's */
        P[WF] = K->Ns * ((rocking ? gs
                          : K->small ? times_g(s->T, 1, s, k)
                                     : times_g(&s->CSO[0][LS], LANES + 1, s, k))
                         - (rocking ? K->b * s->Q[k] : 0));
    else
        P[WF] = K->Ns * (K->g * (K->small ? s->T[k] : S_(s, k))
                         - (rocking ? K->b * s->Q[k] : 0));
    P[WL] = 0;
    if (K->vert && rocking) {
        if (K->small) {
            double to = 0;
            for (int j = 0; j <= k; j++)
                to += s->T[j] * O_(s, k - j);
            r->DH[k] = K->M * K->R * (K->alpha * O_(s, k) - to);
        } else
            r->DH[k] = K->M * (k + 1) * (K->b * S_(s, k + 1) + K->h * C_(s, k + 1));
    } else
        r->DH[k] = 0;
    double acc[WL + 1] = {0};
    /* the input power's product with the floor, where its series reaches
     * order k: its terms up to k - 1 in the same pass, in times_x's order,
     * the last once G[k] is formed */
    int fuse_x = rocking && s->xd > 1 && k <= s->xd;
    double gx = 0;
    if (rocking) {
        for (int j = 0; j <= k; j++) {
            for (int i = 0; i <= WL; i++)
                acc[i] += s->V[j] * r->P[k - j][i];
            if (fuse_x && j < k)
                gx += r->G[j] * s->X[k - j];
        }
    } else {
        /* the still stages' angle and its factors are constants */
        double vv = 0;
        for (int j = 0; j <= k; j++)
            vv += s->V[j] * s->V[k - j];
        acc[WV] = vv;
        acc[WC] = s->V[k] * r->P[0][WC];
        if (K->vert) {
            double f = 0;
            for (int j = 0; j <= k; j++)
                f += s->V[j] * r->P[k - j][WF];
            acc[WF] = f;
        } else
            acc[WF] = s->V[k] * r->P[0][WF];
    }
    /* input power per unit floor acceleration: N* cos U' + M (h cos +
     * b sin) theta'; the second is the derivative of M (h sin - b cos) */
    if (K->small)
        r->G[k] = K->Ns * s->V[k] + (rocking ? K->M * K->R * O_(s, k) : 0);
    else
        r->G[k] = K->Ns * acc[WC]
                  + (rocking ? K->M * (k + 1) * (K->h * S_(s, k + 1) - K->b * C_(s, k + 1))
                             : 0);
    w[k + 1][0] = K->Cs * acc[WV] * inv[k + 1];
    double win = fuse_x ? gx + r->G[k] * s->X[0] : times_x(r->G, 1, s, k);
    if (K->vert) {
        double pv = 0;
        for (int j = 0; j <= k; j++)
            pv += s->Z[j] * r->DH[k - j];
        w[k + 1][1] = (win - pv) * inv[k + 1];
    } else
        w[k + 1][1] = win * inv[k + 1];
    w[k + 1][2] = acc[WF] * inv[k + 1];
}

/* Largest scaled size of the order-k coefficients over a step of hk = h^k.
 * Plain comparisons make branch-free maxima, which drop a NaN; the product
 * 0 * sum keeps a NaN or an infinity, so a non-finite series is caught. */
static double scaled(const series *s, int k, double hk, const double *tol, double tol_x)
{
    double a = fabs(s->U[k]) * tol[RB_Y_U], b = fabs(s->V[k]) * tol[RB_Y_UD];
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
static int floor_series(const rb_motion *m, double t0, double sgn, int n, series *s)
{
    s->xd = rb_motion_taylor(m, t0, n, s->X);
    for (int k = 0; k <= s->xd; k++)
        s->X[k] *= sgn;
    for (int k = n + 1; k < NT; k++)
        s->X[k] = 0;
    return s->xd < n ? NT : n;
}

/* The vertical's series z'' and g + z'' to the largest order at once: a
 * sine or a line, no building. */
static void gravity_series(const rb_motion *v, double g, double t0, series *s)
{
    s->gd = rb_motion_taylor(v, t0, RB_TAYLOR_MAX + 1, s->Z);
    for (int k = RB_TAYLOR_MAX + 2; k < NT; k++)
        s->Z[k] = 0;
    for (int k = 0; k < NT; k++)
        s->G[k] = s->Z[k];
    s->G[0] += g;
}

double rb_taylor_step(const rb_sys *S, const rb_disc *D, double t0, const double *y0,
                      double h_want, const double *atol, double atol_x, double rtol,
                      rb_taylor *ts)
{
    consts K;
    series s;
    bolt_law B;
    /* the vertical's series are read only where there is one, but a
     * vectorised pass over a row may load them: keep them defined */
    memset(s.Z, 0, sizeof s.Z);
    memset(s.G, 0, sizeof s.G);
    s.gd = 0;
    double sgn = D->side < 0 ? -1.0 : 1.0, tol[RB_NY];
    int rocking = rb_dyn_rocking(S, D);
    load_consts(S, &K);
    int xn = floor_series(S->motion, t0, sgn, RB_X_FIRST, &s);
    if (K.vert)
        gravity_series(S->motion->vertical, K.g, t0, &s);
    s.U[0] = sgn * y0[RB_Y_U];
    s.V[0] = sgn * y0[RB_Y_UD];
    s.T[0] = rocking ? sgn * y0[RB_Y_TH] : D->stage == RB_STAGE_HELD ? D->theta_hold : 0;
    O_(&s, 0) = rocking ? sgn * y0[RB_Y_THD] : 0;
    C_(&s, 0) = s.T[0] == 0 ? 1 : cos(s.T[0]);
    S_(&s, 0) = s.T[0] == 0 ? 0 : sin(s.T[0]);
    s.CSO[0][LANES] = 0;
    bolt_law_of(S, D, s.T[0], &B, &s);
    /* reciprocals: the test runs once per order */
    for (int i = RB_Y_U; i <= RB_Y_THD; i++)
        tol[i] = 1 / (atol[i] + rtol * fabs(y0[i]));
    /* the floor's own series too: the reactions and the uplift guards read
     * it between check points, and through a building stiffer than the
     * frame (or under a rigid body, which has no frame) it converges more
     * slowly than the state's */
    double tol_x = 1 / (atol_x + rtol * fabs(s.X[0]));

    double h = h_want, hk = 1, e_prev = HUGE_VAL;
    double w[NT][3];
    work_rows wr;
    int n = 0;
    for (int k = 0;; k++) {
        double udd, thdd = 0, gs = 0;
        /* order k reads the floor to order k, and the step's end to n */
        if (k + 1 > xn)
            xn = floor_series(S->motion, t0, sgn, RB_TAYLOR_MAX + 1, &s);
        if (rocking)
            rocking_order(&K, &s, k, bolt_order(&K, &B, &s, k), &udd, &thdd, &gs);
        else {
            udd = still_order(&K, &s, k);
            C_(&s, k + 1) = S_(&s, k + 1) = s.Q[k] = 0;
        }
        s.U[k + 1] = s.V[k] * inv[k + 1];
        s.V[k + 1] = udd * inv[k + 1];
        s.T[k + 1] = rocking ? O_(&s, k) * inv[k + 1] : 0;
        O_(&s, k + 1) = thdd * inv[k + 1];
        s.CSO[k + 1][LANES] = 0;
        work_order(&K, &s, rocking, k, gs, &wr, w);
        n = k + 1;
        hk *= h;
        double e = scaled(&s, n, hk, tol, tol_x);
        if (K.vert) /* the vertical's own series, on the floor's scale */
            e = rb_fmax(e, fabs(s.Z[n]) * tol_x * hk + 0.0 * s.Z[n]);
        if (!isfinite(e))
            return 0;
        /* two terms in a row, since a series can have a vanishing term */
        if (n >= 3 && e <= 1 && e_prev <= 1)
            break;
        if (n == RB_TAYLOR_MAX) {
            double f = rb_fmin(pow(0.5 / e, 1.0 / n), pow(0.5 / e_prev, 1.0 / (n - 1)));
            h *= rb_fmin(f, 1.0);
            break;
        }
        e_prev = e;
    }
    w[0][0] = y0[RB_Y_WDAMP];
    w[0][1] = y0[RB_Y_WIN];
    w[0][2] = y0[RB_Y_WCPL];
    /* back to the physical frame, every component of every order written
     * (the still stages keep theta as it was); the accelerations are the
     * derivatives of the rates' series */
    for (int k = 0; k <= n; k++) {
        double *p = ts->p[k];
        p[RB_TS_U] = sgn * s.U[k];
        p[RB_TS_UD] = sgn * s.V[k];
        p[RB_TS_X] = sgn * s.X[k];
        p[RB_TS_UDD] = k < n ? sgn * (k + 1) * s.V[k + 1] : 0;
        p[RB_TS_WDAMP] = w[k][0];
        p[RB_TS_WIN] = w[k][1];
        p[RB_TS_WCPL] = w[k][2];
        p[RB_TS_Z] = K.vert ? s.Z[k] : 0;
        if (rocking) {
            p[RB_TS_TH] = sgn * s.T[k];
            p[RB_TS_THD] = sgn * O_(&s, k);
            p[RB_TS_COS] = C_(&s, k);
            p[RB_TS_SIN] = S_(&s, k);
            p[RB_TS_THDD] = k < n ? sgn * (k + 1) * O_(&s, k + 1) : 0;
        } else if (k == 0) {
            p[RB_TS_TH] = y0[RB_Y_TH];
            p[RB_TS_THD] = y0[RB_Y_THD];
            p[RB_TS_COS] = C_(&s, 0);
            p[RB_TS_SIN] = S_(&s, 0);
            p[RB_TS_THDD] = 0;
        } else
            p[RB_TS_TH] = p[RB_TS_THD] = p[RB_TS_COS] = p[RB_TS_SIN] = p[RB_TS_THDD] = 0;
    }
    ts->rocking = rocking;
    ts->vertical = K.vert;
    ts->order = n;
    ts->lever_hold = D->stage == RB_STAGE_HELD ? rb_dyn_lever(S, D->theta_hold) : 0;
    return h;
}
