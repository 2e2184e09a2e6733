/* Taylor-series steps for stages 1, 2 and 4 (see taylor.h).
 *
 * Work is done in the mirrored frame of dynamics.c (rocking about the left
 * edge), with the same equations as rb_dyn_rhs, and the series are stored
 * in the physical frame, so that the mirror of a run is exact. */
#include <math.h>
#include <string.h>
#include "taylor.h"

enum { NT = RB_TAYLOR_MAX + 2 };

int rb_taylor_applies(const rb_sys *S, const rb_disc *D)
{
    if (S->form == RB_FORM_CONSISTENT || S->elastic_bolts
        || S->motion->kind == RB_MOTION_CRITICAL)
        return 0;
    return D->stage == RB_STAGE_FIXED || D->stage == RB_STAGE_UPLIFT
           || D->stage == RB_STAGE_HELD;
}

typedef struct {
    double Ns, Ks, Cs, Ms, Fs, Io, det, W, R, alpha, g, M, b, h;
    int rigid, small;
} consts;

static void load_consts(const rb_sys *S, consts *k)
{
    const rb_derived *d = &S->d;
    k->Ns = d->Nstar; k->Ks = d->Kstar; k->Cs = d->Cstar; k->Ms = d->Mstar;
    k->Fs = d->Fstar; k->Io = d->Io; k->W = d->W; k->R = d->R; k->alpha = d->alpha;
    k->g = d->g; k->M = S->M; k->b = S->b; k->h = S->h;
    k->det = d->Mstar * d->Io - d->Fstar * d->Fstar;
    k->rigid = S->model->rigid;
    k->small = S->form == RB_FORM_SMALL;
}

/* The mirrored series: U, V = U', T = theta, O = theta', the floor
 * acceleration X (polynomial of degree xd), C = cos theta, S = sin theta,
 * Q = theta'^2. */
typedef struct {
    double U[NT], V[NT], T[NT], O[NT], X[NT], C[NT], S[NT], Q[NT];
    int xd;
} series;

/* sum_j a[j] X[k - j]: X has nothing past degree xd (1 for a record) */
static inline double times_x(const double *a, const series *s, int k)
{
    if (s->xd <= 1)
        return a[k] * s->X[0] + (k > 0 ? a[k - 1] * s->X[1] : 0);
    double sum = 0;
    for (int j = k > s->xd ? k - s->xd : 0; j <= k; j++)
        sum += a[j] * s->X[k - j];
    return sum;
}

/* Order k of the right-hand side while rocking (stage 2: no bolt), after
 * theta'^2 at order k and cos, sin at order k + 1, which need theta' only up
 * to order k: one pass over theta' gives all three. */
static void rocking_order(const consts *K, series *s, int k, double *udd, double *thdd)
{
    double q0 = 0, q1 = 0, sc = 0, ss = 0;
    int j = 0;
    for (; j + 1 <= k; j += 2) {
        q0 += s->O[j] * s->O[k - j];
        q1 += s->O[j + 1] * s->O[k - j - 1];
        sc += s->O[j] * s->C[k - j] + s->O[j + 1] * s->C[k - j - 1];
        ss += s->O[j] * s->S[k - j] + s->O[j + 1] * s->S[k - j - 1];
    }
    if (j == k) {
        q0 += s->O[k] * s->O[0];
        sc += s->O[k] * s->C[0];
        ss += s->O[k] * s->S[0];
    }
    s->Q[k] = q0 + q1;
    s->S[k + 1] = sc / (k + 1);
    s->C[k + 1] = -ss / (k + 1);
    double RU, Rth;
    if (K->small) {
        RU = K->Ns * (s->X[k] + K->g * s->T[k]) - K->Ks * s->U[k] - K->Cs * s->V[k]
             - K->Ns * K->b * s->Q[k];
        Rth = K->M * K->R * s->X[k] + K->W * K->R * (s->T[k] - (k == 0 ? K->alpha : 0));
    } else {
        double XC = times_x(s->C, s, k), XS = times_x(s->S, s, k);
        RU = K->Ns * (XC + K->g * s->S[k]) - K->Ks * s->U[k] - K->Cs * s->V[k]
             - K->Ns * K->b * s->Q[k];
        Rth = K->M * (K->h * XC + K->b * XS) - K->W * (K->b * s->C[k] - K->h * s->S[k]);
    }
    if (K->rigid) {
        *udd = 0;
        *thdd = Rth / K->Io;
    } else {
        *udd = (K->Io * RU - K->Fs * Rth) / K->det;
        *thdd = (K->Ms * Rth - K->Fs * RU) / K->det;
    }
}

/* Order k of U'' with the plate still at an angle whose cos and sin are
 * C[0], S[0] (stages 1 and 4). */
static double still_order(const consts *K, const series *s, int k)
{
    if (K->rigid)
        return 0;
    double QU = K->small ? K->Ns * (s->X[k] + (k == 0 ? K->g * s->T[0] : 0))
                         : K->Ns * (s->X[k] * s->C[0] + (k == 0 ? K->g * s->S[0] : 0));
    return (QU - K->Ks * s->U[k] - K->Cs * s->V[k]) / K->Ms;
}

/* The work integrals' series to order n: these do not feed back into the
 * motion, so they are formed once the state is known. w[k][0..2] = damping,
 * input, coupling. */
static void work_series(const consts *K, const series *s, int rocking, int n,
                        double (*w)[3])
{
    double F[NT], G[NT];
    /* coupling factor N* (g sin - b theta'^2), per unit U'; the still
     * stages' is a constant */
    for (int k = 0; k < n; k++)
        F[k] = K->Ns * (K->g * (K->small ? s->T[k] : s->S[k])
                        - (rocking ? K->b * s->Q[k] : 0));
    for (int k = 0; k < n; k++) {
        double vv = 0, vc, vf;
        /* U'^2 is symmetric: half the products */
        for (int j = 0; 2 * j < k; j++)
            vv += s->V[j] * s->V[k - j];
        vv = 2 * vv + (k % 2 == 0 ? s->V[k / 2] * s->V[k / 2] : 0);
        if (rocking) {
            vc = vf = 0;
            for (int j = 0; j <= k; j++) {
                vc += s->V[j] * s->C[k - j];
                vf += s->V[j] * F[k - j];
            }
        } else {
            /* the still stages' angle and its factors are constants */
            vc = s->V[k] * s->C[0];
            vf = s->V[k] * F[0];
        }
        /* input power per unit floor acceleration: N* cos U' + M (h cos +
         * b sin) theta'; the second is the derivative of M (h sin - b cos) */
        if (K->small)
            G[k] = K->Ns * s->V[k] + (rocking ? K->M * K->R * s->O[k] : 0);
        else
            G[k] = K->Ns * (rocking ? vc : s->V[k] * s->C[0])
                   + (rocking ? K->M * (k + 1) * (K->h * s->S[k + 1] - K->b * s->C[k + 1])
                              : 0);
        w[k + 1][0] = K->Cs * vv / (k + 1);
        w[k + 1][1] = times_x(G, s, k) / (k + 1);
        w[k + 1][2] = vf / (k + 1);
    }
}

/* a NaN wins, so that a non-finite series is caught */
static inline double max2(double a, double b) { return a > b || a != a ? a : b; }

/* Largest scaled size of the order-k coefficients over a step of hk = h^k. */
static double scaled(const series *s, int k, double hk, const double *tol)
{
    double e = max2(max2(fabs(s->U[k]) * tol[RB_Y_U], fabs(s->V[k]) * tol[RB_Y_UD]),
                    max2(fabs(s->T[k]) * tol[RB_Y_TH], fabs(s->O[k]) * tol[RB_Y_THD]));
    return e * hk;
}

double rb_taylor_step(const rb_sys *S, const rb_disc *D, double t0, const double *y0,
                      double h_want, const double *atol, double rtol, rb_taylor *ts)
{
    consts K;
    series s;
    double sgn = D->side < 0 ? -1.0 : 1.0, tol[RB_NY];
    int rocking = D->stage == RB_STAGE_UPLIFT;
    load_consts(S, &K);
    s.xd = rb_motion_taylor(S->motion, t0, RB_TAYLOR_MAX + 1, s.X);
    for (int k = 0; k <= s.xd; k++) /* the rest are zeros */
        s.X[k] *= sgn;
    s.U[0] = sgn * y0[RB_Y_U];
    s.V[0] = sgn * y0[RB_Y_UD];
    s.T[0] = rocking ? sgn * y0[RB_Y_TH] : D->stage == RB_STAGE_HELD ? D->theta_hold : 0;
    s.O[0] = rocking ? sgn * y0[RB_Y_THD] : 0;
    s.C[0] = s.T[0] == 0 ? 1 : cos(s.T[0]);
    s.S[0] = s.T[0] == 0 ? 0 : sin(s.T[0]);
    /* reciprocals: the test runs once per order */
    for (int i = RB_Y_U; i <= RB_Y_THD; i++)
        tol[i] = 1 / (atol[i] + rtol * fabs(y0[i]));

    double h = h_want, hk = 1, e_prev = HUGE_VAL;
    int n = 0;
    for (int k = 0;; k++) {
        double udd, thdd = 0;
        if (rocking)
            rocking_order(&K, &s, k, &udd, &thdd);
        else {
            udd = still_order(&K, &s, k);
            s.C[k + 1] = s.S[k + 1] = s.Q[k] = 0;
        }
        s.U[k + 1] = s.V[k] / (k + 1);
        s.V[k + 1] = udd / (k + 1);
        s.T[k + 1] = rocking ? s.O[k] / (k + 1) : 0;
        s.O[k + 1] = thdd / (k + 1);
        n = k + 1;
        hk *= h;
        double e = scaled(&s, n, hk, tol);
        if (!isfinite(e))
            return 0;
        /* two terms in a row, since a series can have a vanishing term */
        if (n >= 3 && e <= 1 && e_prev <= 1)
            break;
        if (n == RB_TAYLOR_MAX) {
            double f = fmin(pow(0.5 / e, 1.0 / n), pow(0.5 / e_prev, 1.0 / (n - 1)));
            h *= fmin(f, 1.0);
            break;
        }
        e_prev = e;
    }
    double w[NT][3];
    work_series(&K, &s, rocking, n, w);
    w[0][0] = y0[RB_Y_WDAMP];
    w[0][1] = y0[RB_Y_WIN];
    w[0][2] = y0[RB_Y_WCPL];
    /* back to the physical frame; still stages keep theta as it was */
    memset(ts->p, 0, (size_t)(n + 1) * sizeof ts->p[0]);
    for (int k = 0; k <= n; k++) {
        double *p = ts->p[k];
        p[RB_TS_U] = sgn * s.U[k];
        p[RB_TS_UD] = sgn * s.V[k];
        p[RB_TS_X] = sgn * s.X[k];
        p[RB_TS_WDAMP] = w[k][0];
        p[RB_TS_WIN] = w[k][1];
        p[RB_TS_WCPL] = w[k][2];
    }
    /* the accelerations: derivatives of the rates' series */
    for (int k = 0; k < n; k++)
        ts->p[k][RB_TS_UDD] = sgn * (k + 1) * s.V[k + 1];
    if (rocking) {
        for (int k = 0; k <= n; k++) {
            double *p = ts->p[k];
            p[RB_TS_TH] = sgn * s.T[k];
            p[RB_TS_THD] = sgn * s.O[k];
            p[RB_TS_COS] = s.C[k];
            p[RB_TS_SIN] = s.S[k];
        }
        for (int k = 0; k < n; k++)
            ts->p[k][RB_TS_THDD] = sgn * (k + 1) * s.O[k + 1];
    } else {
        ts->p[0][RB_TS_TH] = y0[RB_Y_TH];
        ts->p[0][RB_TS_THD] = y0[RB_Y_THD];
        ts->p[0][RB_TS_COS] = s.C[0];
        ts->p[0][RB_TS_SIN] = s.S[0];
    }
    ts->rocking = rocking;
    ts->order = n;
    ts->lever_hold = D->stage == RB_STAGE_HELD ? rb_dyn_lever(S, D->theta_hold) : 0;
    return h;
}
