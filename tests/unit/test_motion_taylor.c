/* rb_motion_taylor against rb_motion_accel: the Taylor steps of the solver
 * read the floor motion only through these coefficients, so a wrong one
 * would drive the Taylor path with a different excitation than the one
 * the Runge-Kutta path and the reports see. For every kind of motion the
 * polynomial is evaluated across the interval it claims to be valid for
 * (up to rb_motion_next_break) and compared with the motion itself. */
#include <math.h>
#include <stdio.h>
#include "harness.h"
#include "rockbolt/motion.h"

#define N_TERMS 30

/* sum coef[k] tau^k */
static double horner(const double *coef, int deg, double tau)
{
    double v = 0;
    for (int k = deg; k >= 0; k--)
        v = v * tau + coef[k];
    return v;
}

/* The series from t0 against the motion at t0 + tau for tau across
 * [0, span], span = the distance to the next break, or max_span if that is
 * shorter (a sine's series is only summed to rounding for a fraction of a
 * period). At the break itself the motion may jump (the end of a
 * rectangular pulse, a record's last sample): with end_jumps the last point
 * is taken just before it. Returns the largest error over the amplitude. */
static double compare(const char *what, const rb_motion *m, double t0, int n,
                      double max_span, int end_jumps, double amplitude, int want_deg)
{
    double coef[N_TERMS + 1];
    int deg = rb_motion_taylor(m, t0, n, coef);
    CHECK(deg == want_deg);
    if (deg < 0)
        return 0;
    double brk = rb_motion_next_break(m, t0);
    double span = fmin(brk - t0, max_span);
    int to_break = brk - t0 <= max_span;
    static const double frac[] = {0, 0.01, 0.125, 0.3, 0.5, 0.7, 0.9, 0.999, 1};
    double worst = 0;
    for (size_t i = 0; i < sizeof frac / sizeof frac[0]; i++) {
        double tau = frac[i] * span;
        if (frac[i] == 1 && to_break && end_jumps)
            tau = span * (1 - 1e-9);
        double want = rb_motion_accel(m, t0 + tau, 0);
        worst = fmax(worst, fabs(horner(coef, deg, tau) - want) / amplitude);
    }
    printf("%-44s t0 = %8.4f s, degree %2d, span %.4g s%s: worst %.2e of the amplitude\n",
           what, t0, deg, span, to_break ? " (to the break)" : "", worst);
    /* 1e-12 of the amplitude: the series is exact for the polynomial
     * pieces and summed to far below that for the sines (n = 30 terms over
     * a tenth of a period leaves (2 pi / 10)^31 / 31! ~ 1e-40), so what is
     * left is the rounding of the arguments, about 1e-16 w t */
    CHECK_NEAR(worst, 0, 1e-12);
    return worst;
}

static void harmonic(void)
{
    rb_motion m;
    rb_motion_init(&m);
    m.kind = RB_MOTION_HARMONIC;
    m.amplitude_mps2 = 68.86;
    m.freq_hz = 4.0;
    m.duration_s = 10;
    double tenth = 0.1 / m.freq_hz;
    static const double t0s[] = {0, 0.0371, 0.125, 0.6180, 3.3333, 9.87};
    for (size_t i = 0; i < sizeof t0s / sizeof t0s[0]; i++)
        compare("harmonic, no ramp", &m, t0s[i], N_TERMS, tenth, 0, m.amplitude_mps2,
                N_TERMS);
    /* ramped: the envelope t / ramp multiplies the sine up to the ramp's end
     * (a kink, hence a break), and after it the plain sine again */
    m.ramp_s = 1.5;
    static const double r0s[] = {0, 0.0371, 0.7, 1.49, 1.5, 2.2};
    for (size_t i = 0; i < sizeof r0s / sizeof r0s[0]; i++)
        compare("harmonic, ramp 1.5 s", &m, r0s[i], N_TERMS, tenth, 0, m.amplitude_mps2,
                N_TERMS);
    /* a ramp shorter than a tenth of a period: the interval ends at the break */
    m.ramp_s = 0.01;
    compare("harmonic, ramp 0.01 s", &m, 0.002, N_TERMS, tenth, 0, m.amplitude_mps2, N_TERMS);
    /* reversed */
    m.ramp_s = 1.5;
    m.polarity = -1;
    compare("harmonic, ramp 1.5 s, polarity -1", &m, 0.7, N_TERMS, tenth, 0,
            m.amplitude_mps2, N_TERMS);
    compare("harmonic, ramp 1.5 s, polarity -1", &m, 4.1, N_TERMS, tenth, 0,
            m.amplitude_mps2, N_TERMS);
}

static void pulses(void)
{
    static const struct {
        rb_pulse_shape shape;
        const char *name;
        int jumps_at_end; /* x'' does not fall to 0 at t1 */
        int deg;          /* inside the pulse */
    } shapes[] = {
        {RB_PULSE_RECT, "rectangular", 1, 0},
        {RB_PULSE_TRI_DEC, "triangular-decreasing", 0, 1},
        {RB_PULSE_TRI_INC, "triangular-increasing", 1, 1},
        {RB_PULSE_HALF_SINE, "half-sine", 0, N_TERMS},
    };
    for (size_t s = 0; s < sizeof shapes / sizeof shapes[0]; s++) {
        for (int pol = 1; pol >= -1; pol -= 2) {
            rb_motion m;
            char what[80];
            rb_motion_init(&m);
            m.kind = RB_MOTION_PULSE;
            m.pulse = shapes[s].shape;
            m.amplitude_mps2 = 9.3;
            m.pulse_s = 0.42;
            m.duration_s = 3;
            m.polarity = pol;
            /* the half-sine's period is 2 t1 */
            double tenth = shapes[s].deg == N_TERMS ? 0.2 * m.pulse_s : HUGE_VAL;
            snprintf(what, sizeof what, "pulse %s, polarity %+d", shapes[s].name, pol);
            compare(what, &m, 0, N_TERMS, tenth, shapes[s].jumps_at_end, m.amplitude_mps2,
                    shapes[s].deg);
            compare(what, &m, 0.13, N_TERMS, tenth, shapes[s].jumps_at_end,
                    m.amplitude_mps2, shapes[s].deg);
            compare(what, &m, 0.4, N_TERMS, tenth, shapes[s].jumps_at_end, m.amplitude_mps2,
                    shapes[s].deg);
            /* after the pulse: zero for ever, to the end of the run and past it */
            compare(what, &m, 0.42, N_TERMS, 5.0, 0, m.amplitude_mps2, 0);
            compare(what, &m, 1.7, N_TERMS, 5.0, 0, m.amplitude_mps2, 0);
        }
    }
}

static void sampled(void)
{
    rb_series s = {0};
    /* 50 Hz, starting at 0.3 s so that there is a time before the record */
    CHECK(rb_series_alloc(&s, 101, 0.02) == RB_OK);
    s.t0_s = 0.3;
    for (size_t i = 0; i < s.n; i++) {
        double t = (double)i * s.dt_s;
        s.accel_mps2[i] = 1.7 * sin(2 * M_PI * 1.3 * t) + 0.9 * cos(2 * M_PI * 4.1 * t + 0.3)
                          + 0.25;
    }
    rb_motion m;
    rb_motion_init(&m);
    m.kind = RB_MOTION_SAMPLED;
    m.series = &s;
    m.scale = 3.25;
    m.polarity = -1;
    m.duration_s = 5;
    double amp = m.scale * rb_series_peak(&s);
    /* before the first sample the floor is at rest; the first sample is
     * the break, where the motion jumps to it */
    compare("sampled, before the record", &m, 0.0, 5, HUGE_VAL, 1, amp, 0);
    compare("sampled, before the record", &m, 0.29, 5, HUGE_VAL, 1, amp, 0);
    /* on a sample, between samples, on the sample before the last */
    compare("sampled, first sample", &m, 0.3, 5, HUGE_VAL, 0, amp, 1);
    compare("sampled, between samples", &m, 0.3 + 17.37 * 0.02, 5, HUGE_VAL, 0, amp, 1);
    compare("sampled, on sample 40", &m, 0.3 + 40 * 0.02, 5, HUGE_VAL, 0, amp, 1);
    compare("sampled, on sample 40 (rounded down)", &m, 0.3 + 40 * 0.02 - 1e-15, 5,
            HUGE_VAL, 0, amp, 1);
    /* the last sample is a break too: past it the floor is at rest */
    compare("sampled, last interval", &m, 0.3 + 99.5 * 0.02, 5, HUGE_VAL, 1, amp, 1);
    compare("sampled, after the record", &m, 0.3 + 100 * 0.02 + 0.01, 5, 5.0, 0, amp, 0);
    compare("sampled, after the record", &m, 4.0, 5, 5.0, 0, amp, 0);
    /* n = 1 is enough for the straight pieces */
    compare("sampled, n = 1", &m, 0.3 + 17.37 * 0.02, 1, HUGE_VAL, 0, amp, 1);
    rb_series_free(&s);
}

static void critical(void)
{
    rb_motion m;
    double coef[N_TERMS + 1];
    rb_motion_init(&m);
    m.kind = RB_MOTION_CRITICAL;
    m.amplitude_mps2 = 2.0;
    m.duration_s = 10;
    /* its sign follows theta', which a series in time cannot know */
    CHECK(rb_motion_taylor(&m, 0.5, N_TERMS, coef) == -1);
}

int main(void)
{
    harmonic();
    pulses();
    sampled();
    critical();
    TEST_MAIN_END();
}
