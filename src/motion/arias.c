/* What a sampled motion's integrals say of it: the Arias intensity and
 * the times at which it builds up (the strong-motion duration, 5-95 %,
 * Trifunac and Brady 1975), and the velocity and displacement a table
 * must travel to play it. */
#include <math.h>
#include "rockbolt/motion.h"

#define STANDARD_GRAVITY 9.80665

void rb_series_arias(const rb_series *s, double *arias_mps, double *t5_s, double *t95_s)
{
    double total = 0;
    const double *a = s->accel_mps2;
    for (size_t i = 1; i < s->n; i++)
        total += s->dt_s * (a[i - 1] * a[i - 1] + a[i - 1] * a[i] + a[i] * a[i]) / 3.0;
    *arias_mps = M_PI / (2.0 * STANDARD_GRAVITY) * total;
    *t5_s = *t95_s = s->t0_s;
    if (!(total > 0))
        return;
    double cum = 0, want[2] = {0.05 * total, 0.95 * total};
    double *out[2] = {t5_s, t95_s};
    int w = 0;
    for (size_t i = 1; i < s->n && w < 2; i++) {
        double step = s->dt_s * (a[i - 1] * a[i - 1] + a[i - 1] * a[i] + a[i] * a[i]) / 3.0;
        while (w < 2 && cum + step >= want[w]) {
            double f = step > 0 ? (want[w] - cum) / step : 0.0;
            *out[w] = s->t0_s + ((double)(i - 1) + f) * s->dt_s;
            w++;
        }
        cum += step;
    }
}

void rb_samples_integrate(const double *a, size_t n, double dt, double *v_end,
                          double *d_end, double *v_peak, double *d_peak)
{
    /* exact for an acceleration linear between samples */
    double v = 0, d = 0, vp = 0, dp = 0;
    for (size_t i = 1; i < n; i++) {
        d += dt * v + dt * dt * (2.0 * a[i - 1] + a[i]) / 6.0;
        v += 0.5 * dt * (a[i - 1] + a[i]);
        if (fabs(v) > vp)
            vp = fabs(v);
        if (fabs(d) > dp)
            dp = fabs(d);
    }
    *v_end = v;
    *d_end = d;
    if (v_peak)
        *v_peak = vp;
    if (d_peak)
        *d_peak = dp;
}
