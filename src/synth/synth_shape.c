/* The time-domain parts of a synthetic motion: its envelope and its
 * baseline correction. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/synth.h"
#include "synth_internal.h"

double rb_synth_envelope(double t, double rise_s, double strong_s, double decay_s)
{
    if (t <= 0)
        return 0.0;
    if (t < rise_s) {
        double s = sin(0.5 * M_PI * t / rise_s);
        return s * s;
    }
    t -= rise_s;
    if (t <= strong_s)
        return 1.0;
    t -= strong_s;
    if (t >= decay_s)
        return 0.0;
    double c = cos(0.5 * M_PI * t / decay_s);
    return c * c;
}

/* Two half-sines of the whole duration, zero at both ends and far below
 * any frequency of interest, cancel the end velocity and displacement:
 * the 2 x 2 system is solved on the same discrete integrals, so the
 * residuals are rounding. */
rb_status rb_synth_baseline_init(rb_synth_baseline_basis *b, size_t n, double dt)
{
    memset(b, 0, sizeof *b);
    b->n = n;
    b->dt = dt;
    b->s1 = malloc(n * sizeof *b->s1);
    b->s2 = malloc(n * sizeof *b->s2);
    if (!b->s1 || !b->s2) {
        rb_synth_baseline_free(b);
        return RB_ERR_NOMEM;
    }
    double T = (double)(n - 1) * dt;
    double q[2][2];   /* q[k] = (v_end, d_end) of sin((k + 1) pi t / T) */
    for (int k = 0; k < 2; k++) {
        double v = 0, d = 0, prev = 0;
        for (size_t i = 1; i < n; i++) {
            double cur = sin((k + 1) * M_PI * (double)i * dt / T);
            d += dt * v + dt * dt * (2.0 * prev + cur) / 6.0;
            v += 0.5 * dt * (prev + cur);
            prev = cur;
        }
        q[k][0] = v;
        q[k][1] = d;
    }
    b->v1 = q[0][0], b->d1 = q[0][1], b->v2 = q[1][0], b->d2 = q[1][1];
    for (size_t i = 0; i < n; i++) {
        double t = (double)i * dt;
        b->s1[i] = sin(M_PI * t / T);
        b->s2[i] = sin(2.0 * M_PI * t / T);
    }
    return RB_OK;
}

void rb_synth_baseline_free(rb_synth_baseline_basis *b)
{
    free(b->s1);
    free(b->s2);
    memset(b, 0, sizeof *b);
}

void rb_synth_baseline(const rb_synth_baseline_basis *b, double *a)
{
    double v0, d0;
    rb_samples_integrate(a, b->n, b->dt, &v0, &d0, NULL, NULL);
    double det = b->v1 * b->d2 - b->v2 * b->d1;
    if (det == 0.0)
        return;
    double alpha = (-v0 * b->d2 + b->v2 * d0) / det;
    double beta = (-b->v1 * d0 + v0 * b->d1) / det;
    for (size_t i = 0; i < b->n; i++)
        a[i] += alpha * b->s1[i] + beta * b->s2[i];
}
