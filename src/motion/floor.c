/* The floor motion between the samples of a record that came through a
 * building (eqs. 5.27-5.28).
 *
 * Over one sample interval the ground acceleration is linear,
 * g(tau) = g0 + s tau, and the building's relative displacement is a
 * particular solution for that load plus a free vibration. The floor total
 * acceleration -(2 xi w u' + w^2 u) is then
 *
 *     floor(tau) = g0 + s tau - (2 xi w v_h(tau) + w^2 u_h(tau))
 *
 * where (u_h, v_h) is the free vibration from u_h(0) = u0 + g0/w^2
 * - 2 xi s/w^3, v_h(0) = v0 + s/w^2. That is exact: no interpolation of
 * the floor, whose peaks fall between samples and whose phase a straight
 * line would shift by about half a sample. The free vibration is written
 * with tau sinc(w_d tau) in place of sin(w_d tau) / w_d, which holds
 * down to critical damping (w_d = 0) without a separate branch. */
#include <math.h>
#include "sdof.h"

/* A sample interval's ground line and free vibration at its start. */
typedef struct {
    double g0, slope;       /* ground: g0 + slope tau */
    double uh, vh;          /* free vibration at tau = 0 */
    double w, xi, wd;
} segment;

static void segment_at(const rb_series *s, size_t i, segment *g)
{
    const rb_series_building *b = &s->bld;
    double w = b->omega_rps, w2 = w * w;
    g->w = w;
    g->xi = b->xi;
    /* fmax(0, q) inline (it is called out of libm, once per step); a NaN
     * gives 0 as fmax does */
    double q = 1.0 - b->xi * b->xi;
    g->wd = w * sqrt(q > 0 ? q : 0.0);
    g->g0 = b->ground_mps2[i];
    g->slope = (b->ground_mps2[i + 1] - b->ground_mps2[i]) / s->dt_s;
    g->uh = b->u_m[i] + g->g0 / w2 - 2.0 * b->xi * g->slope / (w2 * w);
    g->vh = b->v_mps[i] + g->slope / w2;
}

/* sin(x) / x, accurate near 0 */
static double sinc(double x)
{
    if (fabs(x) < 1e-4)
        return 1.0 - x * x / 6.0;
    return sin(x) / x;
}

/* The free vibration's state at tau. */
static void free_state(const segment *g, double tau, double *u, double *v)
{
    /* at the interval's start (a step from a sample, nearly every step)
     * the state is the one it starts from: the exponential, sine and
     * cosine below give it to the bit there, at the cost of a call each */
    if (tau == 0.0) {
        *u = g->uh;
        *v = g->vh;
        return;
    }
    double e = exp(-g->xi * g->w * tau), c = cos(g->wd * tau);
    double sn = tau * sinc(g->wd * tau), xw = g->xi * g->w;
    *u = e * (g->uh * c + (g->vh + xw * g->uh) * sn);
    *v = e * (g->vh * c - (g->w * g->w * g->uh + xw * g->vh) * sn);
}

static double floor_at(const segment *g, double tau)
{
    double u, v;
    free_state(g, tau, &u, &v);
    return g->g0 + g->slope * tau - (2.0 * g->xi * g->w * v + g->w * g->w * u);
}

/* The interval that starts at or just before x (in samples), as
 * rb_motion_next_break reads it: a step from a sample time belongs to the
 * interval after it. -1 outside. */
static long interval_of(const rb_series *s, double x)
{
    double k = floor(x + 1e-9);
    if (k < 0 || k > (double)(s->n - 2))
        return -1;
    return (long)k;
}

double rb_series_at(const rb_series *s, double t)
{
    if (!s || s->n == 0)
        return 0.0;
    double x = (t - s->t0_s) / s->dt_s;
    if (x < 0 || x > (double)(s->n - 1))
        return 0.0;
    size_t i = (size_t)x;
    if (i >= s->n - 1)
        return s->accel_mps2[s->n - 1];
    double f = x - (double)i;
    if (!s->bld.ground_mps2)
        return s->accel_mps2[i] + f * (s->accel_mps2[i + 1] - s->accel_mps2[i]);
    segment g;
    segment_at(s, i, &g);
    return floor_at(&g, f * s->dt_s);
}

/* The interval a step from t0 belongs to, and t0's offset tau in it;
 * -1 outside the samples. */
static long step_interval(const rb_series *s, double t0, double *tau)
{
    if (!s || s->n < 2)
        return -1;
    long i = interval_of(s, (t0 - s->t0_s) / s->dt_s);
    if (i >= 0)
        *tau = t0 - (s->t0_s + (double)i * s->dt_s);
    return i;
}

/* A floor with no building: the straight line of interval i at tau. */
static void sample_line(const rb_series *s, long i, double tau, double *value,
                        double *slope)
{
    double a0 = s->accel_mps2[i], a1 = s->accel_mps2[i + 1];
    *slope = (a1 - a0) / s->dt_s;
    *value = a0 + *slope * tau;
}

int rb_series_taylor(const rb_series *s, double t0, int n, double *coef)
{
    double tau = 0;
    long i = n < 1 ? -1 : step_interval(s, t0, &tau);
    if (i < 0 || !s->bld.ground_mps2) {
        /* a building's series writes every term below */
        for (int k = 0; k <= n; k++)
            coef[k] = 0.0;
        if (i < 0)
            return 0;
        sample_line(s, i, tau, &coef[0], &coef[1]);
        return 1;
    }
    segment g;
    segment_at(s, (size_t)i, &g);
    double u, v;
    free_state(&g, tau, &u, &v);
    /* the building's series per unit state where it was formed; past the
     * table, or for a building set up by hand, the recurrence it comes from */
    const rb_series_building *b = &s->bld;
    if (b->taylor_du[0] != 0 && n < RB_FLOOR_TAYLOR_TERMS)
        for (int k = 0; k <= n; k++)
            coef[k] = b->taylor_du[k] * u + b->taylor_dv[k] * v;
    else {
        /* (u, v)_{k+1} = (v_k, -w^2 u_k - 2 xi w v_k) / (k + 1) */
        double w2 = g.w * g.w, c = 2.0 * g.xi * g.w;
        for (int k = 0; k <= n; k++) {
            coef[k] = -(c * v + w2 * u);
            double un = v / (k + 1), vn = -(w2 * u + c * v) / (k + 1);
            u = un;
            v = vn;
        }
    }
    coef[0] += g.g0 + g.slope * tau;
    coef[1] += g.slope;
    return n;
}

int rb_series_floor_line_at(const rb_series *s, long i, rb_floor_line *fl)
{
    if (i < 0 || !(i < (long)s->n - 1))
        return 0;
    if (!s->bld.ground_mps2) {
        sample_line(s, i, 0.0, &fl->g0, &fl->slope);
        fl->u = fl->v = fl->omega = fl->xi = 0.0;
        return 1;
    }
    /* the building's state is the table's, and no free vibration is
     * formed */
    const rb_series_building *b = &s->bld;
    double slope = (b->ground_mps2[i + 1] - b->ground_mps2[i]) / s->dt_s;
    fl->slope = slope;
    fl->g0 = b->ground_mps2[i] + slope * 0.0;
    fl->omega = b->omega_rps;
    fl->xi = b->xi;
    fl->u = b->u_m[i];
    fl->v = b->v_mps[i];
    return 1;
}

int rb_series_floor_line(const rb_series *s, double t0, rb_floor_line *fl)
{
    double tau = 0;
    long i = step_interval(s, t0, &tau);
    if (i < 0)
        return 0;
    /* a step from a sample (nearly every step) */
    if (tau == 0.0 || !s->bld.ground_mps2) {
        if (tau == 0.0)
            return rb_series_floor_line_at(s, i, fl);
        sample_line(s, i, tau, &fl->g0, &fl->slope);
        fl->u = fl->v = fl->omega = fl->xi = 0.0;
        return 1;
    }
    segment g;
    segment_at(s, (size_t)i, &g);
    double w2 = g.w * g.w;
    fl->slope = g.slope;
    fl->g0 = g.g0 + g.slope * tau;
    fl->omega = g.w;
    fl->xi = g.xi;
    /* the free vibration plus the particular solution of the line */
    double uh, vh;
    free_state(&g, tau, &uh, &vh);
    fl->u = uh - fl->g0 / w2 + 2.0 * g.xi * g.slope / (w2 * g.w);
    fl->v = vh - g.slope / w2;
    return 1;
}

/* Golden-section search for the largest |floor| on [a, b]. */
static double refine(const segment *g, double a, double b)
{
    const double r = 0.6180339887498949;
    double c = b - r * (b - a), d = a + r * (b - a);
    double fc = fabs(floor_at(g, c)), fd = fabs(floor_at(g, d));
    for (int it = 0; it < 60 && b - a > 1e-15 * (1.0 + fabs(b)); it++) {
        if (fc >= fd) {
            b = d, d = c, fd = fc;
            c = b - r * (b - a);
            fc = fabs(floor_at(g, c));
        } else {
            a = c, c = d, fc = fd;
            d = a + r * (b - a);
            fd = fabs(floor_at(g, d));
        }
    }
    return fmax(fc, fd);
}

/* Points per interval: close enough that |floor| is one hump between
 * neighbours (w tau <= 0.4), so that a hump's top lies within one point of
 * the largest point on it. */
static int points_per_interval(const rb_series *s)
{
    double k = ceil(s->bld.omega_rps * s->dt_s / 0.4);
    return k < 2 ? 2 : k > 4096 ? 4096 : (int)k;
}

/* The largest point of interval i, and its neighbours as a bracket. */
static double interval_scan(const rb_series *s, size_t i, int k, segment *g, double *lo,
                            double *hi)
{
    double h = s->dt_s / k, best = -1.0;
    int jb = 0;
    segment_at(s, i, g);
    for (int j = 0; j <= k; j++) {
        double a = fabs(floor_at(g, j * h));
        if (a > best)
            best = a, jb = j;
    }
    *lo = jb > 0 ? (jb - 1) * h : 0.0;
    *hi = jb < k ? (jb + 1) * h : s->dt_s;
    return best;
}

double rb_series_floor_peak(const rb_series *s)
{
    double best = 0.0;
    if (!s || s->n < 2 || !s->bld.ground_mps2) {
        for (size_t i = 0; s && i < s->n; i++)
            if (isfinite(s->accel_mps2[i]))
                best = fmax(best, fabs(s->accel_mps2[i]));
        return best;
    }
    int k = points_per_interval(s);
    double lo, hi;
    segment g;
    /* first the points, then only the intervals whose points come near
     * the largest: a hump between points is at most 1 - cos(0.2), 2 %,
     * above its highest point */
    for (size_t i = 0; i + 1 < s->n; i++) {
        double a = interval_scan(s, i, k, &g, &lo, &hi);
        if (isfinite(a))
            best = fmax(best, a);
    }
    double sampled = best;
    for (size_t i = 0; i + 1 < s->n; i++) {
        double a = interval_scan(s, i, k, &g, &lo, &hi);
        if (isfinite(a) && a >= 0.95 * sampled)
            best = fmax(best, refine(&g, lo, hi));
    }
    for (size_t i = 0; i < s->n; i++)
        if (isfinite(s->accel_mps2[i]))
            best = fmax(best, fabs(s->accel_mps2[i]));
    return best;
}
