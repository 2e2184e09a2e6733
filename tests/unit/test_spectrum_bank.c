/* The bank of oscillators (src/motion/spectrum_bank.c), which steps each
 * oscillator once per sample and walks again only the intervals whose
 * bound can hold a peak above the running one, against the sub-stepped
 * walk of every interval (spectrum.c) over random floors (sines up to the
 * Nyquist frequency, noise, a spike, a quiet stretch), sample steps of up
 * to 3 rad of the oscillator, dampings from 0 to 0.7:
 *   - at the same 0.2 rad sub-steps, within 1e-10 (measured 1.6e-12): an
 *     interval the bound skipped held no higher peak; one that held the
 *     peak, skipped, would leave the bank low by up to the 12 % a sample
 *     step of 1 rad misses;
 *   - against the walk at 0.01 rad (its cubic within 3e-11 of the true
 *     peak), within 2.5e-5: the cubic at 0.2 rad on these rough floors
 *     (measured 2.05e-5; (0.2)^4 / 384 = 4.2e-6 is what it gives on a
 *     smooth one, test_spectrum.c).
 * Also: a floor at rest gives zeros, and so does a series of one sample;
 * a bank made once gives, series after series, what a bank made for each
 * gives, to the bit (check_banked). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include "harness.h"
#include "rockbolt/spectrum.h"
#include "motion/spectrum_bank.h"

#define PI 3.14159265358979323846
#define CASES 60
#define FREQS 10

static uint64_t state = 0x2545F4914F6CDD1Dull;

static double uniform(void)
{
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return (double)(state >> 11) / 9007199254740992.0;
}

/* Sines of random frequencies up to the Nyquist frequency, noise, a
 * spike and a quiet stretch: content at and between every oscillator. */
static void random_floor(rb_series *s)
{
    double f[5], a[5], ph[5];
    for (int k = 0; k < 5; k++) {
        f[k] = uniform() * 0.5 / s->dt_s;
        a[k] = uniform() * 5.0;
        ph[k] = uniform() * 2 * PI;
    }
    double noise = uniform() * 3.0;
    size_t quiet = (size_t)(uniform() * (double)s->n), spike = (size_t)(uniform() * (double)s->n);
    for (size_t i = 0; i < s->n; i++) {
        double t = (double)i * s->dt_s, x = noise * (2 * uniform() - 1);
        for (int k = 0; k < 5; k++)
            x += a[k] * sin(2 * PI * f[k] * t + ph[k]);
        if (i >= quiet && i < quiet + s->n / 5)
            x = 0;
        if (i == spike)
            x += 20.0 * (2 * uniform() - 1);
        s->accel_mps2[i] = x;
    }
}

static void check_case(void)
{
    static const double xis[] = {0.0, 0.01, 0.02, 0.05, 0.1, 0.3, 0.7};
    size_t n = 2 + (size_t)(uniform() * 2500);
    double dt = 0.002 + uniform() * 0.028;
    double xi = xis[(int)(uniform() * 7)];
    rb_series s;
    CHECK(rb_series_alloc(&s, n, dt) == RB_OK);
    random_floor(&s);
    /* up to 3 rad a sample, from 0.05 Hz */
    double f[FREQS];
    for (int k = 0; k < FREQS; k++)
        f[k] = 0.05 * exp(uniform() * log(3.0 / (2 * PI * dt) / 0.05));
    for (int k = 1; k < FREQS; k++)   /* ascending, distinct */
        for (int j = k; j > 0 && f[j] < f[j - 1]; j--) {
            double t = f[j];
            f[j] = f[j - 1];
            f[j - 1] = t;
        }
    for (int k = 1; k < FREQS; k++)
        if (!(f[k] > f[k - 1]))
            f[k] = f[k - 1] * 1.001;
    rb_spectrum sp;
    CHECK(rb_spectrum_alloc(&sp, f, FREQS, xi) == RB_OK);
    CHECK(rb_spectrum_of_series(&s, 1.0, &sp) == RB_OK);
    for (int k = 0; k < FREQS; k++) {
        double psa, sa;
        rb_spec_substep_peaks(&s, f[k], xi, 0.01, &psa, &sa);
        double psa2, sa2;
        rb_spec_substep_peaks(&s, f[k], xi, 0.2, &psa2, &sa2);
        CHECK_REL(sp.psa_mps2[k], psa2, 1e-10);
        CHECK_REL(sp.sa_mps2[k], sa2, 1e-10);
        CHECK_REL(sp.psa_mps2[k], psa, 2.5e-5);
        CHECK_REL(sp.sa_mps2[k], sa, 2.5e-5);
    }
    rb_spectrum_free(&sp);
    rb_series_free(&s);
}

static void check_rest(void)
{
    rb_series s;
    double f[3] = {0.5, 5.0, 50.0};
    CHECK(rb_series_alloc(&s, 1000, 0.005) == RB_OK);
    rb_spectrum sp;
    CHECK(rb_spectrum_alloc(&sp, f, 3, 0.05) == RB_OK);
    CHECK(rb_spectrum_of_series(&s, 1.0, &sp) == RB_OK);
    for (int k = 0; k < 3; k++)
        CHECK(sp.psa_mps2[k] == 0.0 && sp.sa_mps2[k] == 0.0);
    rb_series_free(&s);
    /* one sample: the floor drops to zero at once, the oscillator at rest */
    CHECK(rb_series_alloc(&s, 1, 0.005) == RB_OK);
    s.accel_mps2[0] = 3.0;
    CHECK(rb_spectrum_of_series(&s, 1.0, &sp) == RB_OK);
    for (int k = 0; k < 3; k++)
        CHECK(sp.psa_mps2[k] == 0.0 && sp.sa_mps2[k] == 0.0);
    rb_spectrum_free(&sp);
    rb_series_free(&s);
}

/* A bank made once and run on series after series of one step (the
 * synthetic motions' passes): each run gives what rb_spectrum_of_series
 * gives alone, through the hints the last run left, whether the peaks
 * grew (the hints held), fell under them (the run made again without) or
 * the floor is a new one; at the quick phase and the default. A bank made
 * for another step or grid is not used. */
static void check_banked(double phase)
{
    static const double scales[] = {1.0, 1.1, 0.95, 3.0, 0.2, 1.0, 0.79, 1.3};
    size_t n = 3000;
    double dt = 0.005, xi = 0.05, f[FREQS];
    for (int k = 0; k < FREQS; k++)
        f[k] = 0.6 * exp2(0.75 * k);
    rb_series s, other;
    CHECK(rb_series_alloc(&s, n, dt) == RB_OK);
    CHECK(rb_series_alloc(&other, n, 2 * dt) == RB_OK);
    rb_spectrum sp, alone;
    CHECK(rb_spectrum_alloc(&sp, f, FREQS, xi) == RB_OK);
    CHECK(rb_spectrum_alloc(&alone, f, FREQS, xi) == RB_OK);
    sp.step_phase = alone.step_phase = phase;
    rb_spectrum_bank *b;
    CHECK(rb_spectrum_bank_new(&sp, dt, &b) == RB_OK);
    for (int floor = 0; floor < 3; floor++) {
        random_floor(&s);
        for (size_t r = 0; r < sizeof scales / sizeof *scales; r++) {
            for (size_t i = 0; i < n; i++)
                s.accel_mps2[i] *= scales[r];
            CHECK(rb_spectrum_of_series_banked(b, &s, 2.0, &sp) == RB_OK);
            CHECK(rb_spectrum_of_series(&s, 2.0, &alone) == RB_OK);
            for (int k = 0; k < FREQS; k++) {
                CHECK(sp.psa_mps2[k] == alone.psa_mps2[k]);
                CHECK(sp.sa_mps2[k] == alone.sa_mps2[k]);
            }
        }
    }
    random_floor(&other);
    CHECK(rb_spectrum_of_series_banked(b, &other, 1.0, &sp) == RB_OK);
    CHECK(rb_spectrum_of_series(&other, 1.0, &alone) == RB_OK);
    for (int k = 0; k < FREQS; k++)
        CHECK(sp.sa_mps2[k] == alone.sa_mps2[k] && sp.sa_mps2[k] > 0);
    rb_spectrum_bank_free(b);
    rb_spectrum_free(&sp);
    rb_spectrum_free(&alone);
    rb_series_free(&s);
    rb_series_free(&other);
}

int main(void)
{
    check_rest();
    for (int c = 0; c < CASES; c++)
        check_case();
    check_banked(1.0);
    check_banked(0.2);
    TEST_MAIN_END();
}
