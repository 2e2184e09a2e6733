/* The exact stepping of a response-spectrum oscillator and the peaks
 * between its exact states (spectrum_step.h). Displacements are carried
 * as w u so that every entry of the matrix is of order w. */
#include <math.h>
#include <string.h>
#include "spectrum_step.h"
#include "matexp.h"

/* The free period after the samples is stepped as the samples are for at
 * most this long, then at the phase step: a period counted in sample
 * steps made a 1e-6 Hz oscillator take 2e8 steps per spectrum. Periods up
 * to 10 s (0.1 Hz and up) are stepped as they always were. */
#define SPECTRUM_TAIL_FINE_S 10.0

void rb_spec_system(double w, double xi, double wb, double xib,
                          size_t m, double *a, double *b)
{
    memset(a, 0, m * m * sizeof *a);
    size_t o = m - 2;           /* the oscillator's first index */
    if (m == 4) {
        a[0 * 4 + 1] = wb;
        a[1 * 4 + 0] = -wb;
        a[1 * 4 + 1] = -2.0 * xib * wb;
        /* the oscillator's load is -floor = w_b (w_b u_b) + 2 xi_b w_b v_b */
        a[3 * 4 + 0] = wb;
        a[3 * 4 + 1] = 2.0 * xib * wb;
        b[0] = 0.0;
        b[1] = -1.0;
        b[2] = 0.0;
        b[3] = 0.0;
    } else {
        b[0] = 0.0;
        b[1] = -1.0;
    }
    a[o * m + o + 1] = w;
    a[(o + 1) * m + o] = -w;
    a[(o + 1) * m + o + 1] = -2.0 * xi * w;
}

void rb_spec_transition_init(rb_spec_transition *tr, size_t m, const double *a,
                            const double *b, double h)
{
    /* augmented (x, g, h g'), in units of the sub-step */
    size_t n = m + 2;
    double big[RB_MATEXP_MAX * RB_MATEXP_MAX] = {0}, e[RB_MATEXP_MAX * RB_MATEXP_MAX];
    for (size_t i = 0; i < m; i++) {
        for (size_t j = 0; j < m; j++)
            big[i * n + j] = h * a[i * m + j];
        big[i * n + m] = h * b[i];
    }
    big[m * n + m + 1] = 1.0;
    rb_matexp(n, big, e);
    tr->m = m;
    for (size_t i = 0; i < m; i++) {
        for (size_t j = 0; j < m; j++)
            tr->phi[i * m + j] = e[i * n + j];
        tr->in0[i] = e[i * n + m] - e[i * n + m + 1];
        tr->in1[i] = e[i * n + m + 1];
    }
}

void rb_spec_transition_apply(const rb_spec_transition *tr, double *x, double g0, double g1)
{
    if (tr->m == 2) {   /* the common case, unrolled */
        double p = x[0], v = x[1];
        x[0] = tr->phi[0] * p + tr->phi[1] * v + tr->in0[0] * g0 + tr->in1[0] * g1;
        x[1] = tr->phi[2] * p + tr->phi[3] * v + tr->in0[1] * g0 + tr->in1[1] * g1;
        return;
    }
    double y[4];
    size_t m = tr->m;
    for (size_t i = 0; i < m; i++) {
        double s = tr->in0[i] * g0 + tr->in1[i] * g1;
        for (size_t j = 0; j < m; j++)
            s += tr->phi[i * m + j] * x[j];
        y[i] = s;
    }
    memcpy(x, y, m * sizeof *x);
}

/* The largest |y| on [0, h] of the cubic with values y0, y1 and slopes
 * d0, d1 at the ends, given that the ends are already counted. */
static double cubic_peak(double y0, double d0, double y1, double d1, double h)
{
    double b = h * d0, c = 3.0 * (y1 - y0) - h * (2.0 * d0 + d1);
    double d = 2.0 * (y0 - y1) + h * (d0 + d1);
    double roots[2];
    int nr = 0;
    if (fabs(d) < 1e-14 * (fabs(b) + fabs(c))) {
        if (c != 0.0)
            roots[nr++] = -b / (2.0 * c);
    } else {
        double disc = c * c - 3.0 * d * b;
        if (disc >= 0) {
            /* the stable pair of roots of 3 d s^2 + 2 c s + b */
            double q = -(c + copysign(sqrt(disc), c));
            if (q != 0.0) {
                roots[nr++] = q / (3.0 * d);
                roots[nr++] = b / q;
            }
        }
    }
    double best = 0.0;
    for (int i = 0; i < nr; i++) {
        double s = roots[i];
        if (s > 0.0 && s < 1.0) {
            double y = y0 + s * (b + s * (c + s * d));
            if (fabs(y) > best)
                best = fabs(y);
        }
    }
    return best;
}

/* An upper bound of |y| on [0, h] for that cubic, cheap enough to skip
 * cubic_peak where it cannot raise the peak: the cubic departs from the
 * chord by h s (1 - s) [(1 - s)(d0 - m) - s (d1 - m)], m the chord's slope,
 * so by at most a quarter of the larger of |h d0 - dy| and |h d1 - dy|. */
static double cubic_bound(double y0, double d0, double y1, double d1, double h)
{
    double dy = y1 - y0;
    return fmax(fabs(y0), fabs(y1)) + 0.25 * fmax(fabs(h * d0 - dy), fabs(h * d1 - dy));
}

/* The oscillator's absolute acceleration -(2 xi w v + w^2 u) and its
 * rate, for its load (-floor) now. */
void rb_spec_tracker_read(rb_spec_tracker *t, double pw, double v, double load)
{
    double dv = -t->w * pw - 2.0 * t->xi * t->w * v + load;
    t->p = pw;
    t->v = v;
    t->acc = -(2.0 * t->xi * t->w * v + t->w * pw);
    t->jerk = -(2.0 * t->xi * t->w * dv + t->w * t->w * v);
}

void rb_spec_tracker_step(rb_spec_tracker *t, double pw, double v, double load, double h)
{
    double p0 = t->p, dp0 = t->w * t->v, a0 = t->acc, j0 = t->jerk;
    rb_spec_tracker_read(t, pw, v, load);
    double dp1 = t->w * t->v;
    if (fabs(pw) > t->psa)
        t->psa = fabs(pw);
    if (fabs(t->acc) > t->sa)
        t->sa = fabs(t->acc);
    if (dp0 * dp1 <= 0.0 && cubic_bound(p0, dp0, pw, dp1, h) > t->psa) {
        double c = cubic_peak(p0, dp0, pw, dp1, h);
        if (c > t->psa)
            t->psa = c;
    }
    if (j0 * t->jerk <= 0.0 && cubic_bound(a0, j0, t->acc, t->jerk, h) > t->sa) {
        double c = cubic_peak(a0, j0, t->acc, t->jerk, h);
        if (c > t->sa)
            t->sa = c;
    }
}


void rb_spec_sub_transition(rb_spec_transition *tr, double w, double xi, double dt,
                            double phase, unsigned *k)
{
    double a[4], b[2];
    rb_spec_system(w, xi, 0.0, 0.0, 2, a, b);
    unsigned kf = (unsigned)ceil(w * dt / phase);
    *k = kf ? kf : 1;
    rb_spec_transition_init(tr, 2, a, b, dt / *k);
}

void rb_spec_free_tail(rb_spec_tracker *t, const double *y0, double f_hz, double dt,
                       double phase)
{
    rb_spec_transition tr;
    unsigned kf;
    rb_spec_sub_transition(&tr, t->w, t->xi, dt, phase, &kf);
    rb_spec_free_tail_with(t, y0, f_hz, dt, phase, &tr, kf);
}

void rb_spec_free_tail_with(rb_spec_tracker *t, const double *y0, double f_hz, double dt,
                            double phase, const rb_spec_transition *sub, unsigned kf)
{
    double w = t->w, a[4], b[2];
    double hf = dt / kf;
    rb_spec_transition tr = *sub;
    double y[2] = {y0[0], y0[1]};
    rb_spec_tracker_read(t, y[0], y[1], 0.0);
    double period = 1.0 / f_hz, rest = 0.0;
    size_t steps;
    if (period > SPECTRUM_TAIL_FINE_S) {
        steps = (size_t)ceil(SPECTRUM_TAIL_FINE_S / hf);
        rest = period - (double)steps * hf;
    } else {
        steps = (size_t)ceil(period / hf);
    }
    for (size_t i = 0; i < steps; i++) {
        rb_spec_transition_apply(&tr, y, 0.0, 0.0);
        rb_spec_tracker_step(t, y[0], y[1], 0.0, hf);
    }
    if (rest > 0) {
        /* no load: the transition is exact at any step, and the cubic's
         * error depends only on the phase a step covers */
        size_t nb = (size_t)ceil(rest * w / phase);
        double hb = rest / (double)(nb ? nb : 1);
        rb_spec_system(w, t->xi, 0.0, 0.0, 2, a, b);
        rb_spec_transition_init(&tr, 2, a, b, hb);
        for (size_t i = 0; i < nb; i++) {
            rb_spec_transition_apply(&tr, y, 0.0, 0.0);
            rb_spec_tracker_step(t, y[0], y[1], 0.0, hb);
        }
    }
}
