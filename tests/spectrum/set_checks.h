/* What the synthetic-set tests (synth_sets.c, synth_ieee693.c) measure of
 * a generated motion apart from the generator: its peaks, integrated here,
 * and the correlation of two components, summed here. One copy, so that
 * both tests hold the motions to the same reading. */
#ifndef RB_TEST_SET_CHECKS_H
#define RB_TEST_SET_CHECKS_H

#include <math.h>
#include "rockbolt/record.h"

typedef struct {
    double pga, pgv, pgd;
} set_peaks;

/* Velocity by trapezoids and displacement by the exact steps of a
 * piecewise-linear acceleration, both from rest. */
static set_peaks motion_peaks(const rb_series *s)
{
    set_peaks p = {0, 0, 0};
    double v = 0, d = 0;
    for (size_t i = 0; i < s->n; i++) {
        p.pga = fmax(p.pga, fabs(s->accel_mps2[i]));
        if (i == 0)
            continue;
        double a0 = s->accel_mps2[i - 1], a1 = s->accel_mps2[i], h = s->dt_s;
        d += h * v + h * h * (2 * a0 + a1) / 6;
        v += 0.5 * h * (a0 + a1);
        p.pgv = fmax(p.pgv, fabs(v));
        p.pgd = fmax(p.pgd, fabs(d));
    }
    return p;
}

/* The largest |sum_j a[j + k] b[j]| / (n sd_a sd_b) of a and b (same
 * length) over every lag k, summed directly: the generator's definition
 * (src/synth/independence.c, by FFT), which synth_sets holds it to. */
static double set_correlation(const rb_series *a, const rb_series *b)
{
    size_t n = a->n;
    double ma = 0, mb = 0, va = 0, vb = 0;
    for (size_t i = 0; i < n; i++) {
        ma += a->accel_mps2[i] / (double)n;
        mb += b->accel_mps2[i] / (double)n;
    }
    for (size_t i = 0; i < n; i++) {
        va += (a->accel_mps2[i] - ma) * (a->accel_mps2[i] - ma) / (double)n;
        vb += (b->accel_mps2[i] - mb) * (b->accel_mps2[i] - mb) / (double)n;
    }
    double best = 0;
    for (long lag = -(long)n + 1; lag < (long)n; lag++) {
        double s = 0;
        size_t i0 = lag > 0 ? (size_t)lag : 0, i1 = lag > 0 ? n : n + (size_t)lag;
        for (size_t i = i0; i < i1; i++)
            s += a->accel_mps2[i] * b->accel_mps2[(size_t)((long)i - lag)];
        best = fmax(best, fabs(s));
    }
    return best / ((double)n * sqrt(va * vb));
}

/* The RRS at f for the test's own target. */
typedef double (*set_rrs_fn)(double f, const void *ctx);

/* TRS / RRS at one of the 12 offsets of the 1/72-octave grid fq (fq[0] at
 * k0 steps above 0.1 Hz): the offset's points within [lo, hi] and the
 * nearest one outside each end, as the laboratory's code takes them. The
 * largest ratio within [lo, hi] goes to *most (NULL: not asked). Returns
 * the number of points written to f and q (each at least 80 long). */
static size_t offset_ratios(const double *fq, const double *sa, size_t n, int k0, int off,
                            double lo, double hi, set_rrs_fn rrs, const void *ctx,
                            double *f, double *q, double *most)
{
    size_t m = 0;
    long below = -1, above = -1;
    for (size_t i = 0; i < n; i++) {
        if (((k0 + (int)i) % 12) != off)
            continue;
        if (fq[i] < lo)
            below = (long)i;
        else if (fq[i] > hi) {
            if (above < 0)
                above = (long)i;
        } else {
            if (m == 0 && below >= 0) {
                f[m] = fq[below];
                q[m++] = sa[below] / rrs(fq[below], ctx);
            }
            f[m] = fq[i];
            q[m] = sa[i] / rrs(fq[i], ctx);
            if (most)
                *most = fmax(*most, q[m]);
            m++;
        }
    }
    if (above >= 0) {
        f[m] = fq[above];
        q[m++] = sa[above] / rrs(fq[above], ctx);
    }
    return m;
}

#endif
