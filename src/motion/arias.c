/* The Arias intensity of a sampled motion, and the times at which it
 * builds up: the strong-motion duration (5-95 %, Trifunac and Brady 1975)
 * that the synthetic motions and the spectra report. */
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
