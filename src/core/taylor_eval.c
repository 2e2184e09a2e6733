/* Reading a Taylor step: its series at any instant of the step (the dense
 * output), what rb_dyn_rhs would give there, and roots of the rates and of
 * the angle by Newton's method on a series and its derivative series. */
#include <float.h>
#include <math.h>
#include "bolt.h"
#include "root.h"
#include "simd.h"
#include "taylor.h"
#include "unroll.h"

/* Horner on every component (RB_TS_N) side by side, four to a vector
 * (src/core/simd.h): each lane is the scalar chain v = v tau + p_k. */
_Static_assert(RB_TS_N == 13, "horner_all reads three quads and one scalar");
RB_INLINE void horner_all(const rb_taylor *ts, double tau, double *out)
{
    const double (*p)[RB_TS_N] = (const double (*)[RB_TS_N])ts->p;
    int n = ts->order;
    rb_quad t = rb_quad_splat(tau), a = rb_quad_load(p[n]), b = rb_quad_load(p[n] + 4),
            c = rb_quad_load(p[n] + 8);
    double d = p[n][12];
#define ALL_STEP(k)                                                              \
    do {                                                                         \
        a = rb_quad_horner(a, t, rb_quad_load(p[k]));                            \
        b = rb_quad_horner(b, t, rb_quad_load(p[k] + 4));                        \
        c = rb_quad_horner(c, t, rb_quad_load(p[k] + 8));                        \
        d = d * tau + p[k][12];                                                  \
    } while (0)
    RB_DOWN_FROM(n, ALL_STEP)
#undef ALL_STEP
    rb_quad_store(out, a);
    rb_quad_store(out + 4, b);
    rb_quad_store(out + 8, c);
    out[12] = d;
}

static const int state_series[RB_NY] = {
    RB_TS_U, RB_TS_UD, RB_TS_TH, RB_TS_THD, RB_TS_WDAMP, RB_TS_WIN, RB_TS_WCPL,
};

double rb_taylor_one(const rb_taylor *ts, double tau, int c)
{
    int i = state_series[c];
    double v = ts->p[ts->order][i];
#define ONE_STEP(k) (v = v * tau + ts->p[k][i])
    RB_DOWN_FROM(ts->order, ONE_STEP)
#undef ONE_STEP
    return v;
}

double rb_taylor_rate_bound(const rb_taylor *ts, int c, double h)
{
    int i = state_series[c];
    double b = 0;
#define BOUND_STEP(j) (b = b * h + ((j) + 1) * fabs(ts->p[(j) + 1][i]))
    RB_DOWN_FROM(ts->order, BOUND_STEP)
#undef BOUND_STEP
    return b;
}

double rb_taylor_reach(const rb_taylor *ts, int c, double h)
{
    int i = state_series[c];
    double b = 0;
    for (int k = ts->order; k >= 1; k--)
        b = (b + fabs(ts->p[k][i])) * h;
    return b;
}

void rb_taylor_range(const rb_taylor *ts, int c, double h, double *lo, double *hi)
{
    /* The series' first three terms, a parabola whose range over [0, h]
     * is its ends and its vertex, and the rest bounded by sum |p_k| h^k
     * (k >= 3). The reach alone (every term's full size added both ways)
     * would spread a step that moves one way over both sides of its
     * start: a step that leaves the floor or the bolt head would read its
     * own guard's level as reachable behind it, and read every check
     * point for a crossing that cannot be there. */
    int i = state_series[c], n = ts->order;
    double p0 = ts->p[0][i], p1 = n >= 1 ? ts->p[1][i] : 0, p2 = n >= 2 ? ts->p[2][i] : 0;
    double tail = 0;
    /* k = j + 1 from n down to 3 */
#define TAIL_STEP(j)                                                             \
    do {                                                                         \
        if ((j) >= 2)                                                            \
            tail = (tail + fabs(ts->p[(j) + 1][i])) * h;                         \
    } while (0)
    RB_DOWN_FROM(n, TAIL_STEP)
#undef TAIL_STEP
    tail *= h * h;
    double at_h = p1 * h + p2 * h * h, qlo = at_h < 0 ? at_h : 0, qhi = at_h > 0 ? at_h : 0;
    double tv = p2 != 0 ? -p1 / (2 * p2) : -1;
    if (tv > 0 && tv < h) {
        double qv = (p1 + p2 * tv) * tv;
        qlo = qv < qlo ? qv : qlo;
        qhi = qv > qhi ? qv : qhi;
    }
    /* Horner's rounding is within n eps of sum |p_k| tau^k (Higham,
     * Accuracy and Stability, 5.1); the parabola's ends and vertex, the
     * tail's sum and the additions below are within a few eps more of the
     * same sum: twice all of it. A NaN term gives NaN ends through the
     * sizes summed here. */
    double size = fabs(p0) + fabs(p1) * h + fabs(p2) * h * h + tail;
    double w = tail + (4.0 * n + 16.0) * DBL_EPSILON * size;
    *lo = p0 + qlo - w;
    *hi = p0 + qhi + w;
}

int rb_taylor_stays_off(const rb_taylor *ts, int c, double h, double level)
{
    double lo, hi;
    rb_taylor_range(ts, c, h, &lo, &hi);
    return level < lo || level > hi;
}

/* The still stages' angle, its rate and their trigonometry are constant,
 * and only four series need the Horner pass: U, U', theta and theta',
 * side by side in one quad. */
_Static_assert(RB_TS_U == 0 && RB_TS_UD == 1 && RB_TS_TH == 2 && RB_TS_THD == 3,
               "the four mechanical series are one quad of a row");
RB_INLINE void state_values(const rb_taylor *ts, double tau, double *y)
{
    const double (*p)[RB_TS_N] = (const double (*)[RB_TS_N])ts->p;
    int n = ts->order;
    rb_quad t = rb_quad_splat(tau), v = rb_quad_load(p[n]);
#define STATE_STEP(k) (v = rb_quad_horner(v, t, rb_quad_load(p[k])))
    RB_DOWN_FROM(n, STATE_STEP)
#undef STATE_STEP
    rb_quad_store(y, v);
}

static void state_plain(const rb_taylor *ts, double tau, double *y)
{
    state_values(ts, tau, y);
}

RB_SIMD_AVX static void state_avx(const rb_taylor *ts, double tau, double *y)
{
    state_values(ts, tau, y);
}

_Static_assert(RB_Y_U == 0 && RB_Y_UD == 1 && RB_Y_TH == 2 && RB_Y_THD == 3,
               "rb_taylor_state writes the four mechanical components as one quad");
void rb_taylor_state(const rb_taylor *ts, double tau, double *y)
{
    if (rb_simd_avx())
        state_avx(ts, tau, y);
    else
        state_plain(ts, tau, y);
}

/* The first eight components are two quads; theta'' and z'' are read
 * where they move. A still stage's angle, rate and trigonometry are its
 * start's, taken as they are (the chains would give them too, but a -0
 * start would come out +0). */
_Static_assert(RB_TS_U == 0 && RB_TS_UD == 1 && RB_TS_TH == 2 && RB_TS_THD == 3
                   && RB_TS_X == 4 && RB_TS_COS == 5 && RB_TS_SIN == 6 && RB_TS_UDD == 7,
               "rb_taylor_check reads the first eight components as two quads");
RB_INLINE void check_values(const rb_taylor *ts, double tau, double *v)
{
    const double (*p)[RB_TS_N] = (const double (*)[RB_TS_N])ts->p;
    int n = ts->order;
    rb_quad t = rb_quad_splat(tau), a = rb_quad_load(p[n]), b = rb_quad_load(p[n] + 4);
    if (ts->rocking) {
        /* theta'''s chain in the same pass: one loop a reading */
        double thdd = p[n][RB_TS_THDD];
#define ROCKING_STEP(k)                                                          \
    do {                                                                         \
        a = rb_quad_horner(a, t, rb_quad_load(p[k]));                            \
        b = rb_quad_horner(b, t, rb_quad_load(p[k] + 4));                        \
        thdd = thdd * tau + p[k][RB_TS_THDD];                                    \
    } while (0)
        RB_DOWN_FROM(n, ROCKING_STEP)
#undef ROCKING_STEP
        rb_quad_store(v, a);
        rb_quad_store(v + 4, b);
        v[RB_TS_THDD] = thdd;
    } else {
#define STILL_STEP(k)                                                            \
    do {                                                                         \
        a = rb_quad_horner(a, t, rb_quad_load(p[k]));                            \
        b = rb_quad_horner(b, t, rb_quad_load(p[k] + 4));                        \
    } while (0)
        RB_DOWN_FROM(n, STILL_STEP)
#undef STILL_STEP
        rb_quad_store(v, a);
        rb_quad_store(v + 4, b);
        v[RB_TS_TH] = p[0][RB_TS_TH];
        v[RB_TS_THD] = p[0][RB_TS_THD];
        v[RB_TS_COS] = p[0][RB_TS_COS];
        v[RB_TS_SIN] = p[0][RB_TS_SIN];
        v[RB_TS_THDD] = 0;
    }
    v[RB_TS_Z] = 0;
    if (ts->vertical) {
        double z = p[n][RB_TS_Z];
#define Z_STEP(k) (z = z * tau + p[k][RB_TS_Z])
        RB_DOWN_FROM(n, Z_STEP)
#undef Z_STEP
        v[RB_TS_Z] = z;
    }
}

static void check_plain(const rb_taylor *ts, double tau, double *v)
{
    check_values(ts, tau, v);
}

RB_SIMD_AVX static void check_avx(const rb_taylor *ts, double tau, double *v)
{
    check_values(ts, tau, v);
}

void rb_taylor_check(const rb_taylor *ts, double tau, double *v)
{
    if (rb_simd_avx())
        check_avx(ts, tau, v);
    else
        check_plain(ts, tau, v);
}

static void all_plain(const rb_taylor *ts, double tau, double *v)
{
    horner_all(ts, tau, v);
}

RB_SIMD_AVX static void all_avx(const rb_taylor *ts, double tau, double *v)
{
    horner_all(ts, tau, v);
}

/* Every component at tau (RB_TS_N values). */
static void all_values(const rb_taylor *ts, double tau, double *v)
{
    if (rb_simd_avx())
        all_avx(ts, tau, v);
    else
        all_plain(ts, tau, v);
}

void rb_taylor_all(const rb_taylor *ts, double tau, double *y)
{
    double v[RB_TS_N];
    all_values(ts, tau, v);
    for (int i = 0; i < RB_NY; i++)
        y[i] = v[state_series[i]];
}

/* What rb_dyn_rhs gives as aux, from the series' values; the powers of
 * the works only where asked (the derivative at a step's end): a check
 * point's tracking reads the floor, the accelerations, the angle's
 * trigonometry and the bolt force alone. */
static inline void aux_values(const rb_sys *S, const rb_disc *D, int rocking, double lever_hold,
                              const double *v, rb_aux *a, int powers)
{
    const rb_derived *d = &S->d;
    double sgn = D->side < 0 ? -1.0 : 1.0;
    int vert = S->motion->vertical != NULL;
    a->x = v[RB_TS_X];
    a->gz = vert ? d->g + v[RB_TS_Z] : d->g;
    a->udd = sgn * v[RB_TS_UDD];
    a->thdd = sgn * v[RB_TS_THDD];
    a->cos_th = v[RB_TS_COS];
    a->sin_th = v[RB_TS_SIN];
    double th = rocking ? sgn * v[RB_TS_TH] : D->stage == RB_STAGE_HELD ? D->theta_hold : 0;
    double ud = sgn * v[RB_TS_UD], xm = sgn * a->x;
    double thd = rocking ? sgn * v[RB_TS_THD] : 0;
    double c = a->cos_th, sn = a->sin_th;
    int small = S->form == RB_FORM_SMALL;
    double in_th = small ? S->M * d->R : S->M * (S->h * c + S->b * sn);
    double W = vert ? S->M * a->gz : d->W;
    if (powers) {
        double in_U = small ? d->Nstar : d->Nstar * c;
        a->p_input = xm * (in_U * ud + in_th * thd);
        /* the gravity terms with W = M gz (dynamics.c's loads) */
        double kh = small ? d->R * (d->alpha - th) : S->b * c - S->h * sn;
        if (vert) /* the vertical floor's power, -z'' M kh theta' */
            a->p_input -= v[RB_TS_Z] * S->M * kh * thd;
        a->p_coupling = d->Nstar * (a->gz * (small ? th : sn) - S->b * thd * thd) * ud;
    } else
        a->p_input = a->p_coupling = NAN;
    a->bolt_force = 0;
    if (D->stage == RB_STAGE_YIELD)
        a->bolt_force = d->fy_row_n;
    else if (D->stage == RB_STAGE_HELD && rocking)
        a->bolt_force = S->bolt->tension(S, D, th);
    else if (D->stage == RB_STAGE_HELD) {
        double Qth = small ? xm * in_th - W * d->R * (d->alpha - th)
                           : xm * in_th - W * (S->b * c - S->h * sn);
        a->bolt_force = (Qth - d->Fstar * a->udd) / lever_hold;
    }
}

void rb_taylor_aux(const rb_sys *S, const rb_disc *D, const rb_taylor *ts, const double *v,
                   rb_aux *a)
{
    aux_values(S, D, ts->rocking, ts->lever_hold, v, a, 1);
}

void rb_taylor_aux_point(const rb_sys *S, const rb_disc *D, const rb_taylor *ts,
                         const double *v, rb_aux *a)
{
    aux_values(S, D, ts->rocking, ts->lever_hold, v, a, 0);
}

void rb_aux_of_values(const rb_sys *S, const rb_disc *D, int rocking, double lever_hold,
                      const double *v, rb_aux *a)
{
    aux_values(S, D, rocking, lever_hold, v, a, 1);
}

void rb_taylor_end(const rb_sys *S, const rb_disc *D, const rb_taylor *ts, double h,
                   double *y1, double *f1, rb_aux *a)
{
    double v[RB_TS_N];
    all_values(ts, h, v);
    for (int i = 0; i < RB_NY; i++)
        y1[i] = v[state_series[i]];
    rb_taylor_aux(S, D, ts, v, a);
    int rocking = ts->rocking;
    f1[RB_Y_U] = v[RB_TS_UD];
    f1[RB_Y_UD] = v[RB_TS_UDD];
    f1[RB_Y_TH] = rocking ? v[RB_TS_THD] : 0;
    f1[RB_Y_THD] = v[RB_TS_THDD];
    f1[RB_Y_WDAMP] = S->d.Cstar * v[RB_TS_UD] * v[RB_TS_UD];
    f1[RB_Y_WIN] = a->p_input;
    f1[RB_Y_WCPL] = a->p_coupling;
}

/* Root of series i minus level in [a, b], where it is fa and fb, starting
 * from x, with di its derivative series: Newton's method kept inside the
 * bracket. Its orientation (the sign beyond the root, at b) comes from fb,
 * or from fa when b is the root, since the near end can sit exactly on the
 * level. Where Newton leaves the bracket (the rising side of a hop, whose
 * derivative points away from the landing) the Illinois secant of the
 * bracket's ends takes over; halving the bracket there took up to 40
 * iterations. */
static double newton_root(const rb_taylor *ts, int i, int di, double level, double a,
                          double b, double fa, double fb, double x, double tol)
{
    const double (*p)[RB_TS_N] = (const double (*)[RB_TS_N])ts->p;
    int n = ts->order, b_positive = fb != 0 ? fb > 0 : !(fa > 0), kept = 0;
    for (int it = 0; it < 60; it++) {
        double f = p[n][i], df = p[n][di];
#define NEWTON_STEP(k)                                                           \
    do {                                                                         \
        f = f * x + p[k][i];                                                     \
        df = df * x + p[k][di];                                                  \
    } while (0)
        RB_DOWN_FROM(n, NEWTON_STEP)
#undef NEWTON_STEP
        f -= level;
        if (f == 0)
            return x;
        /* kept: the end the last move left alone (-1 a, 1 b), whose value
         * the Illinois rule halves when it is left alone twice */
        if ((f > 0) == b_positive) {
            b = x;
            fb = f;
            if (kept == -1)
                fa *= 0.5;
            kept = -1;
        } else {
            a = x;
            fa = f;
            if (kept == 1)
                fb *= 0.5;
            kept = 1;
        }
        double next = x - f / df;
        if (!(next > a && next < b)) {
            next = (a * fb - b * fa) / (fb - fa);
            if (!(next > a && next < b))
                next = 0.5 * (a + b);
        }
        /* quadratic convergence: a step this small lands within the
         * tolerance of the root */
        int done = fabs(next - x) <= tol || b - a <= tol;
        x = next;
        if (done)
            break;
    }
    return x;
}

/* The secant through the bracket's ends, or its middle when the secant
 * hugs an end (a value nudged off zero there): Newton then starts within a
 * few per cent of the root and converges in about three iterations. */
static double start_in(double a, double b, double fa, double fb)
{
    double x = (a * fb - b * fa) / (fb - fa);
    return x > a + 1e-3 * (b - a) && x < b - 1e-3 * (b - a) ? x : 0.5 * (a + b);
}

double rb_taylor_rate_root(const rb_taylor *ts, int c, double a, double b, double fa,
                           double fb, double tol)
{
    return newton_root(ts, c == RB_Y_UD ? RB_TS_UD : RB_TS_THD,
                       c == RB_Y_UD ? RB_TS_UDD : RB_TS_THDD, 0, a, b, fa, fb,
                       start_in(a, b, fa, fb), tol);
}

double rb_taylor_angle_root(const rb_taylor *ts, double a, double b, double level,
                            double fa, double fb, double tol)
{
    return newton_root(ts, RB_TS_TH, RB_TS_THD, level, a, b, fa, fb, start_in(a, b, fa, fb),
                       tol);
}

/* The held force's rate up to a constant factor, in_th x' - F* U''' (the
 * force is (Q_th - F* U'') / lever with Q_th = in_th x + const at the held
 * angle; the mirror's sign and the lever do not move its roots). */
typedef struct {
    const rb_taylor *ts;
    double in_th, fstar;
    double kz; /* side M kh of the vertical's share, 0 without one */
} held_force;

static double held_force_rate(const void *ctx, double tau)
{
    const held_force *h = ctx;
    const double (*p)[RB_TS_N] = (const double (*)[RB_TS_N])h->ts->p;
    double r = 0;
    for (int k = h->ts->order; k >= 1; k--)
        r = r * tau + k * (h->in_th * p[k][RB_TS_X] - h->fstar * p[k][RB_TS_UDD]);
    if (h->kz != 0) {
        double z = 0;
        for (int k = h->ts->order; k >= 1; k--)
            z = z * tau + k * p[k][RB_TS_Z];
        r -= h->kz * z;
    }
    return r;
}

/* The force on side s is s (in_th x - F* U'') - M kh (g + z'') in the
 * physical x and U'' (kh as in rb_aux_of_values, at the held angle):
 * times s, its rate is in_th x' - F* U''' - s M kh z'''. */
static held_force held_force_of(const rb_sys *S, const rb_taylor *ts, int side)
{
    double c = ts->p[0][RB_TS_COS], sn = ts->p[0][RB_TS_SIN];
    held_force h = {ts, S->form == RB_FORM_SMALL ? S->M * S->d.R
                                                : S->M * (S->h * c + S->b * sn),
                    S->d.Fstar, 0};
    if (ts->vertical) {
        double th = side * ts->p[0][RB_TS_TH];
        double kh = S->form == RB_FORM_SMALL ? S->d.R * (S->d.alpha - th)
                                             : S->b * c - S->h * sn;
        h.kz = side * S->M * kh;
    }
    return h;
}

double rb_taylor_held_force_rate(const rb_sys *S, const rb_taylor *ts, int side, double tau)
{
    held_force h = held_force_of(S, ts, side);
    return held_force_rate(&h, tau);
}

double rb_taylor_held_force_scale(const rb_taylor *ts)
{
    return ts->lever_hold > 0 ? 1 / ts->lever_hold : 1;
}

double rb_taylor_held_force_turn(const rb_sys *S, const rb_taylor *ts, int side, double a,
                                 double b, const double *rate, double tol)
{
    held_force h = held_force_of(S, ts, side);
    return rb_root_illinois(held_force_rate, &h, a, b, rate[0], rate[1], tol);
}
