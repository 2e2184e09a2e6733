/* Evaluation of a floor motion x''(t) for the solver.
 *
 * Closed forms are evaluated directly; sampled records are interpolated
 * linearly, which is the usual reading of a digitised accelerogram, and a
 * record through a building is the building's exact response between
 * samples (floor.c). The solver asks for the next kink
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
    return m->series ? m->scale * rb_series_at(m->series, t) : 0.0;
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

static int floor_line_scaled(const rb_motion *m, rb_floor_line *fl)
{
    double f = m->polarity < 0 ? -m->scale : m->scale;
    fl->g0 *= f;
    fl->slope *= f;
    fl->u *= f;
    fl->v *= f;
    return 1;
}

int rb_motion_floor_line(const rb_motion *m, double t0, rb_floor_line *fl)
{
    return m->kind == RB_MOTION_SAMPLED && rb_series_floor_line(m->series, t0, fl)
           && floor_line_scaled(m, fl);
}

int rb_motion_floor_line_at(const rb_motion *m, long i, rb_floor_line *fl)
{
    return m->kind == RB_MOTION_SAMPLED && m->series && rb_series_floor_line_at(m->series, i, fl)
           && floor_line_scaled(m, fl);
}

static double own_break(const rb_motion *m, double t)
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

double rb_motion_next_break(const rb_motion *m, double t)
{
    double b = own_break(m, t);
    return m->vertical ? fmin(b, own_break(m->vertical, t)) : b;
}

static int own_jump(const rb_motion *m, double t)
{
    return m->kind == RB_MOTION_PULSE && t == m->pulse_s && m->amplitude_mps2 != 0
           && (m->pulse == RB_PULSE_RECT || m->pulse == RB_PULSE_TRI_INC);
}

int rb_motion_jumps_at(const rb_motion *m, double t)
{
    return own_jump(m, t) || (m->vertical && own_jump(m->vertical, t));
}

double rb_motion_gravity(const rb_motion *m, double g, double t)
{
    return m->vertical ? g + rb_motion_accel(m->vertical, t, 0) : g;
}

/* The least of a pulse of signed amplitude a over [0, te]: a times its
 * shape, whose range [lo, hi] there is known in closed form. */
static double pulse_least(const rb_motion *m, double a, double te)
{
    double t1 = m->pulse_s, e = fmin(te, t1), lo = 0, hi = 1;
    switch (m->pulse) {
    case RB_PULSE_RECT: lo = 1; break;
    case RB_PULSE_TRI_DEC: lo = 1 - e / t1; break;
    case RB_PULSE_TRI_INC: hi = e / t1; break;
    case RB_PULSE_HALF_SINE: hi = e >= 0.5 * t1 ? 1 : sin(M_PI * e / t1); break;
    }
    double least = fmin(a * lo, a * hi);
    /* it is 0 once it has ended */
    return te >= t1 ? fmin(least, 0) : least;
}

double rb_motion_least(const rb_motion *m, double t_end)
{
    double sign = m->polarity < 0 ? -1.0 : 1.0, least = HUGE_VAL;
    switch (m->kind) {
    case RB_MOTION_HARMONIC:
    case RB_MOTION_CRITICAL:
        return -fabs(m->amplitude_mps2);
    case RB_MOTION_PULSE:
        return m->pulse_s > 0 ? pulse_least(m, sign * m->amplitude_mps2, t_end) : 0;
    case RB_MOTION_SAMPLED: {
        const rb_series *s = m->series;
        if (!s || s->n == 0)
            return 0;
        if (s->bld.ground_mps2)
            return -rb_motion_peak(m);
        /* before and after its samples the motion is 0 */
        double f = sign * m->scale, t_last = s->t0_s + (double)(s->n - 1) * s->dt_s;
        if (s->t0_s > 0 || t_end > t_last)
            least = 0;
        for (size_t i = 0; i < s->n && s->t0_s + (double)i * s->dt_s <= t_end; i++)
            if (f * s->accel_mps2[i] < least)
                least = f * s->accel_mps2[i];
        return least < HUGE_VAL ? least : 0;
    }
    }
    return 0;
}

rb_status rb_motion_vertical_check(const rb_motion *m, double g, rb_diag *diag)
{
    const rb_motion *v = m->vertical;
    if (!v)
        return RB_OK;
    if (v->kind == RB_MOTION_CRITICAL || v->vertical)
        return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, "vertical",
                           "must be a harmonic, pulse or sampled motion without a "
                           "vertical of its own");
    if (v->kind == RB_MOTION_SAMPLED && !v->series)
        return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, "vertical",
                           "a sampled vertical needs its series");
    double least = rb_motion_least(v, m->duration_s);
    if (!(least > -g))
        return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, "vertical",
                           "the floor's downward acceleration reaches %.4g m/s^2, at or "
                           "beyond gravity %.4g m/s^2: the body would leave the floor in "
                           "free flight, which the model does not follow",
                           -least, g);
    return RB_OK;
}

double rb_motion_peak(const rb_motion *m)
{
    switch (m->kind) {
    case RB_MOTION_HARMONIC:
    case RB_MOTION_PULSE:
    case RB_MOTION_CRITICAL:
        return fabs(m->amplitude_mps2);
    case RB_MOTION_SAMPLED:
        return rb_series_peak(m->series) * fabs(m->scale);
    }
    return 0.0;
}

/* sin(w (t0 + tau)) = sum_k w^k / k! sin(w t0 + k pi / 2) tau^k */
static void sine_series(double w, double t0, double amp, int n, double *coef)
{
    double s = sin(w * t0), c = cos(w * t0), p = amp;
    const double cycle[4] = {s, c, -s, -c};
    for (int k = 0; k <= n; k++) {
        coef[k] = p * cycle[k & 3];
        p *= w / (k + 1);
    }
}

/* Multiply the series by (e0 + e1 tau), in place, keeping n terms. */
static void times_linear(double e0, double e1, int n, double *coef)
{
    for (int k = n; k >= 0; k--)
        coef[k] = e0 * coef[k] + (k > 0 ? e1 * coef[k - 1] : 0.0);
}

int rb_motion_taylor(const rb_motion *m, double t0, int n, double *coef)
{
    int deg = 0;
    if (m->kind == RB_MOTION_SAMPLED) {
        /* a record's series is a step's every time (rb_series_taylor
         * clears coef itself); the scale carries the polarity's sign,
         * since -(c s) and c (-s) are the same double */
        double f = m->polarity < 0 ? -m->scale : m->scale;
        deg = rb_series_taylor(m->series, t0, n, coef);
        for (int k = 0; k <= deg; k++)
            coef[k] *= f;
        return deg;
    }
    for (int k = 0; k <= n; k++)
        coef[k] = 0.0;
    switch (m->kind) {
    case RB_MOTION_HARMONIC:
        sine_series(2 * M_PI * m->freq_hz, t0, m->amplitude_mps2, n, coef);
        if (m->ramp_s > 0 && t0 < m->ramp_s)
            times_linear(t0 / m->ramp_s, 1 / m->ramp_s, n, coef);
        deg = n;
        break;
    case RB_MOTION_PULSE: {
        double t1 = m->pulse_s, a = m->amplitude_mps2;
        if (t0 < 0 || t0 >= t1)
            break;
        switch (m->pulse) {
        case RB_PULSE_RECT: coef[0] = a; break;
        case RB_PULSE_TRI_DEC: coef[0] = a * (1 - t0 / t1); coef[1] = -a / t1; deg = 1; break;
        case RB_PULSE_TRI_INC: coef[0] = a * t0 / t1; coef[1] = a / t1; deg = 1; break;
        case RB_PULSE_HALF_SINE: sine_series(M_PI / t1, t0, a, n, coef); deg = n; break;
        }
        break;
    }
    case RB_MOTION_SAMPLED: /* above */
        break;
    case RB_MOTION_CRITICAL:
        return -1;
    }
    if (m->polarity < 0)
        for (int k = 0; k <= deg; k++)
            coef[k] = -coef[k];
    return deg;
}
