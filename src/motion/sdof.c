/* Exact state transition of a linear SDOF oscillator under a load that is
 * linear over each step (Nigam-Jennings).
 *
 * The coefficients come from the exponential of the 4x4 matrix of the
 * augmented system (u, u', p, p') rather than from the textbook closed
 * forms: the closed forms subtract terms of order 1/(w dt) and lose digits
 * when w dt is small, and they need separate branches for critical and
 * over-damping. Time is scaled by w so that every entry of the matrix is of
 * order one before scaling and squaring. */
#include <math.h>
#include <string.h>
#include "matexp.h"
#include "sdof.h"

/* Bounds that keep the number of squarings small; far beyond any physical
 * oscillator (xi = 100 is a dashpot, w dt = 1e6 a step of 1e5 periods). */
#define RB_SDOF_XI_MAX 100.0
#define RB_SDOF_H_MAX 1e6

rb_status rb_sdof_step_init(rb_sdof_step *st, double omega, double xi, double dt)
{
    if (!st || !isfinite(omega) || !(omega > 0.0) || !(xi >= 0.0)
        || !(xi <= RB_SDOF_XI_MAX) || !isfinite(dt) || !(dt > 0.0))
        return RB_ERR_INVALID;
    /* In tau = w t, with q = p / w^2: u_tt + 2 xi u_t + u = q, and q moves
     * at a constant rate q_t over the step. State (u, u_t, q, q_t). */
    double h = omega * dt;
    if (!(h <= RB_SDOF_H_MAX))
        return RB_ERR_INVALID;
    const double a[4][4] = {{0.0, h, 0.0, 0.0},
                            {-h, -2.0 * xi * h, h, 0.0},
                            {0.0, 0.0, 0.0, h},
                            {0.0, 0.0, 0.0, 0.0}};
    double e[4][4];
    rb_matexp(4, &a[0][0], &e[0][0]);
    /* Back to (u, v, p0, p1): u_t = v / w, q = p / w^2, and
     * q_t = (p1 - p0) / (w^2 h). */
    double w2 = omega * omega;
    st->uu = e[0][0];
    st->uv = e[0][1] / omega;
    st->up0 = (e[0][2] - e[0][3] / h) / w2;
    st->up1 = e[0][3] / (h * w2);
    st->vu = e[1][0] * omega;
    st->vv = e[1][1];
    st->vp0 = (e[1][2] - e[1][3] / h) / omega;
    st->vp1 = e[1][3] / (h * omega);
    st->omega = omega;
    st->xi = xi;
    return RB_OK;
}

void rb_sdof_step_apply(const rb_sdof_step *st, double *u, double *v,
                        double p0, double p1)
{
    double u0 = *u, v0 = *v;
    *u = st->uu * u0 + st->uv * v0 + st->up0 * p0 + st->up1 * p1;
    *v = st->vu * u0 + st->vv * v0 + st->vp0 * p0 + st->vp1 * p1;
}

double rb_sdof_run(const rb_sdof_step *st, const double *p, size_t n,
                   double *u_out, double *v_out)
{
    double u = 0.0, v = 0.0, peak = 0.0;
    for (size_t i = 0; i < n; i++) {
        if (i > 0)
            rb_sdof_step_apply(st, &u, &v, p[i - 1], p[i]);
        if (u_out)
            u_out[i] = u;
        if (v_out)
            v_out[i] = v;
        if (fabs(u) > peak)
            peak = fabs(u);
    }
    return peak;
}

rb_status rb_sdof_peak_within(double omega, double xi, double dt, unsigned k,
                             const double *p, size_t n, double *peak)
{
    rb_sdof_step sub;
    if (k == 0 || !p || !peak)
        return RB_ERR_INVALID;
    rb_status st = rb_sdof_step_init(&sub, omega, xi, dt / k);
    if (st != RB_OK)
        return st;
    double u = 0.0, v = 0.0, best = 0.0;
    for (size_t i = 1; i < n; i++) {
        double slope = (p[i] - p[i - 1]) / k;
        for (unsigned j = 0; j < k; j++) {
            double pa = p[i - 1] + slope * j;
            double pb = (j + 1 == k) ? p[i] : p[i - 1] + slope * (j + 1);
            rb_sdof_step_apply(&sub, &u, &v, pa, pb);
            if (fabs(u) > best)
                best = fabs(u);
        }
    }
    *peak = best;
    return RB_OK;
}
