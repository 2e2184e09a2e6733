/* Evaluation of a floor motion x''(t) for the solver.
 *
 * Closed forms are evaluated directly; sampled records are interpolated
 * linearly, which is the usual reading of a digitised accelerogram and the
 * one the exact building filter assumes. The solver asks for the next kink
 * so that no Runge-Kutta step straddles one: a step across a kink would drop
 * the method to first order there. */
#include <math.h>
#include <string.h>
#include "rockbolt/motion.h"

void rb_motion_init(rb_motion *m)
{
    memset(m, 0, sizeof *m);
    m->polarity = 1;
    m->scale = 1.0;
}

static double harmonic(const rb_motion *m, double t)
{
    double env = (m->ramp_s > 0 && t < m->ramp_s) ? t / m->ramp_s : 1.0;
    return env * m->amplitude_mps2 * sin(2 * M_PI * m->freq_hz * t);
}

static double pulse(const rb_motion *m, double t)
{
    double t1 = m->pulse_s, a = m->amplitude_mps2;
    if (t < 0 || t >= t1)
        return 0.0;
    switch (m->pulse) {
    case RB_PULSE_RECT: return a;
    case RB_PULSE_TRI_DEC: return a * (1 - t / t1);
    case RB_PULSE_TRI_INC: return a * t / t1;
    case RB_PULSE_HALF_SINE: return a * sin(M_PI * t / t1);
    }
    return 0.0;
}

static double sampled(const rb_motion *m, double t)
{
    const rb_series *s = m->series;
    if (!s || s->n == 0)
        return 0.0;
    double x = (t - s->t0_s) / s->dt_s;
    if (x < 0 || x > (double)(s->n - 1))
        return 0.0;
    size_t i = (size_t)x;
    if (i >= s->n - 1)
        return m->scale * s->accel_mps2[s->n - 1];
    double f = x - (double)i;
    return m->scale * (s->accel_mps2[i] + f * (s->accel_mps2[i + 1] - s->accel_mps2[i]));
}

double rb_motion_accel(const rb_motion *m, double t, double theta_dot)
{
    double a = 0.0;
    switch (m->kind) {
    case RB_MOTION_HARMONIC: a = harmonic(m, t); break;
    case RB_MOTION_PULSE: a = pulse(m, t); break;
    case RB_MOTION_SAMPLED: a = sampled(m, t); break;
    case RB_MOTION_CRITICAL:
        a = theta_dot > 0 ? m->amplitude_mps2 : theta_dot < 0 ? -m->amplitude_mps2 : 0.0;
        break;
    }
    return m->polarity < 0 ? -a : a;
}

double rb_motion_next_break(const rb_motion *m, double t)
{
    switch (m->kind) {
    case RB_MOTION_HARMONIC:
        return (m->ramp_s > 0 && t < m->ramp_s) ? m->ramp_s : HUGE_VAL;
    case RB_MOTION_PULSE:
        return t < m->pulse_s ? m->pulse_s : HUGE_VAL;
    case RB_MOTION_SAMPLED: {
        const rb_series *s = m->series;
        if (!s || s->n < 2)
            return HUGE_VAL;
        double x = (t - s->t0_s) / s->dt_s;
        if (x < 0)
            return s->t0_s;
        double k = floor(x + 1e-9) + 1;
        if (k > (double)(s->n - 1))
            return HUGE_VAL;
        return s->t0_s + k * s->dt_s;
    }
    case RB_MOTION_CRITICAL:
        return HUGE_VAL;
    }
    return HUGE_VAL;
}

double rb_motion_peak(const rb_motion *m)
{
    switch (m->kind) {
    case RB_MOTION_HARMONIC:
    case RB_MOTION_PULSE:
    case RB_MOTION_CRITICAL:
        return fabs(m->amplitude_mps2);
    case RB_MOTION_SAMPLED: {
        const rb_series *s = m->series;
        double p = 0;
        /* a non-finite sample is the solver's to report, at its time */
        for (size_t i = 0; s && i < s->n; i++)
            if (isfinite(s->accel_mps2[i]))
                p = fmax(p, fabs(s->accel_mps2[i]));
        return p * fabs(m->scale);
    }
    }
    return 0.0;
}
