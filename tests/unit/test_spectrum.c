/* Response spectra (src/motion/spectrum.c):
 *   - a harmonic floor from rest against the closed-form response of the
 *     oscillator (steady state plus the transient that starts it at rest,
 *     then its free vibration once the floor stops), peaks found on a
 *     dense grid of the closed form;
 *   - a floor through a building against the same floor sampled finely
 *     from its exact form (rb_series_at) with no building: the cascade of
 *     building and oscillator is the motion the solver sees;
 *   - the grid: 1/12 octave from 0.5 to 50 Hz has 80 points, both ends in;
 *   - the scale multiplies, the polarity does not matter. */
#include <math.h>
#include <stdlib.h>
#include <time.h>
#include "harness.h"
#include "rockbolt/spectrum.h"

#define PI 3.14159265358979323846

/* The oscillator's response from rest to -A sin(W t) for t <= T, then free:
 * u and u' at t. */
typedef struct {
    double w, xi, wd, W, A, T;
    double c, d, e, f;        /* particular C sin + D cos; transient E, F */
    double uT, vT;            /* state at T */
} closed_form;

static void cf_forced(const closed_form *k, double t, double *u, double *v)
{
    double ex = exp(-k->xi * k->w * t), cs = cos(k->wd * t), sn = sin(k->wd * t);
    *u = k->c * sin(k->W * t) + k->d * cos(k->W * t) + ex * (k->e * cs + k->f * sn);
    *v = k->c * k->W * cos(k->W * t) - k->d * k->W * sin(k->W * t)
         + ex * (-k->xi * k->w * (k->e * cs + k->f * sn) + k->wd * (-k->e * sn + k->f * cs));
}

static void cf_init(closed_form *k, double f_hz, double xi, double F_hz, double A, double T)
{
    k->w = 2 * PI * f_hz;
    k->xi = xi;
    k->wd = k->w * sqrt(1 - xi * xi);
    k->W = 2 * PI * F_hz;
    k->A = A;
    k->T = T;
    double a = k->w * k->w - k->W * k->W, b = 2 * xi * k->w * k->W;
    /* (a C - b D) = -A, (b C + a D) = 0 */
    k->c = -A * a / (a * a + b * b);
    k->d = A * b / (a * a + b * b);
    k->e = -k->d;
    k->f = (xi * k->w * k->e - k->c * k->W) / k->wd;
    cf_forced(k, T, &k->uT, &k->vT);
}

static void cf_at(const closed_form *k, double t, double *u, double *v)
{
    if (t <= k->T) {
        cf_forced(k, t, u, v);
        return;
    }
    double s = t - k->T, ex = exp(-k->xi * k->w * s), cs = cos(k->wd * s), sn = sin(k->wd * s);
    double e = k->uT, f = (k->vT + k->xi * k->w * k->uT) / k->wd;
    *u = ex * (e * cs + f * sn);
    *v = ex * (-k->xi * k->w * (e * cs + f * sn) + k->wd * (-e * sn + f * cs));
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static void check_harmonic(double F_hz, double T)
{
    const double dt = 1e-4, A = 2.5, xi = 0.05;
    size_t n = (size_t)llround(T / dt) + 1;
    rb_series s;
    rb_series_alloc(&s, n, dt);
    for (size_t i = 0; i < n; i++)
        s.accel_mps2[i] = A * sin(2 * PI * F_hz * (double)i * dt);
    double freqs[] = {0.5, 1.3, 2.0, F_hz, 8.3, 20.0, 33.3, 50.0};
    qsort(freqs, 8, sizeof *freqs, cmp_double);
    size_t at_f = 0;
    while (freqs[at_f] != F_hz)
        at_f++;
    rb_spectrum sp;
    CHECK(rb_spectrum_alloc(&sp, freqs, 8, xi) == RB_OK);
    CHECK(rb_spectrum_of_series(&s, 1.0, &sp) == RB_OK);
    for (size_t j = 0; j < sp.n; j++) {
        closed_form k;
        cf_init(&k, sp.freq_hz[j], xi, F_hz, A, T);
        double umax = 0, amax = 0, end = T + 1.0 / sp.freq_hz[j];
        size_t m = (size_t)(end / 2e-5);
        for (size_t i = 0; i <= m; i++) {
            double u, v;
            cf_at(&k, end * (double)i / (double)m, &u, &v);
            if (fabs(u) > umax)
                umax = fabs(u);
            double acc = fabs(2 * xi * k.w * v + k.w * k.w * u);
            if (acc > amax)
                amax = acc;
        }
        /* the sine sampled every 1e-4 s is a straight line between samples:
         * (W dt)^2 / 8 of the load at most, below 2e-5 here */
        CHECK_REL(sp.psa_mps2[j], k.w * k.w * umax, 3e-5);
        CHECK_REL(sp.sa_mps2[j], amax, 3e-5);
    }
    /* scale multiplies; a reversed motion has the same spectrum */
    double psa0 = sp.psa_mps2[at_f];
    CHECK(rb_spectrum_of_series(&s, -2.0, &sp) == RB_OK);
    CHECK_REL(sp.psa_mps2[at_f], 2.0 * psa0, 1e-14);
    rb_spectrum_free(&sp);
    rb_series_free(&s);
}

/* A floor through a 10 Hz building, sampled at 0.02 s (w_b dt = 1.26),
 * against its exact floor resampled 100 times finer without a building. */
static void check_building(void)
{
    const double dt = 0.02;
    size_t n = 400;
    rb_series s, fine;
    rb_series_alloc(&s, n, dt);
    for (size_t i = 0; i < n; i++) {
        double t = (double)i * dt;
        s.accel_mps2[i] = 3.0 * sin(2 * PI * 2.3 * t) + 1.5 * sin(2 * PI * 9.1 * t + 0.4)
                          + (i % 7 == 3 ? 1.0 : 0.0);
    }
    CHECK(rb_series_building_filter(&s, 10.0, 0.05) == RB_OK);
    const unsigned k = 100;
    rb_series_alloc(&fine, (n - 1) * k + 1, dt / k);
    for (size_t i = 0; i < fine.n; i++)
        fine.accel_mps2[i] = rb_series_at(&s, (double)i * fine.dt_s);
    rb_spectrum_opts o;
    rb_spectrum_opts_init(&o);
    rb_spectrum a, b;
    CHECK(rb_spectrum_grid(&o, &a) == RB_OK);
    CHECK(rb_spectrum_grid(&o, &b) == RB_OK);
    CHECK(a.n == 80);
    CHECK_NEAR(a.freq_hz[0], 0.5, 1e-15);
    CHECK_REL(a.freq_hz[a.n - 1], 0.5 * exp2(79.0 / 12.0), 1e-15);
    CHECK(rb_spectrum_of_series(&s, 1.0, &a) == RB_OK);
    CHECK(rb_spectrum_of_series(&fine, 1.0, &b) == RB_OK);
    double worst = 0;
    for (size_t j = 0; j < a.n; j++) {
        double r = fabs(a.sa_mps2[j] / b.sa_mps2[j] - 1);
        if (r > worst)
            worst = r;
        /* straight lines between the fine samples: (w_b dt / 100)^2 / 8 */
        CHECK_REL(a.sa_mps2[j], b.sa_mps2[j], 5e-5);
        CHECK_REL(a.psa_mps2[j], b.psa_mps2[j], 5e-5);
    }
    printf("building cascade against a fine floor: worst %.2e\n", worst);
    rb_spectrum_free(&a);
    rb_spectrum_free(&b);
    rb_series_free(&s);
    rb_series_free(&fine);
}

/* Oscillators slower than 0.1 Hz: the free period after the samples is
 * stepped at the sample interval for 10 s, then at the phase step. Their
 * peaks still match the closed form, and a 1e-6 Hz oscillator (a free
 * period of 11 days) takes no longer than a fast one: stepped at the
 * sample interval, its tail took 1e9 steps. */
static void check_slow_tail(void)
{
    const double dt = 1e-3, A = 2.5, xi = 0.05, F_hz = 3.0, T = 2.0;
    size_t n = (size_t)llround(T / dt) + 1;
    rb_series s;
    rb_series_alloc(&s, n, dt);
    for (size_t i = 0; i < n; i++)
        s.accel_mps2[i] = A * sin(2 * PI * F_hz * (double)i * dt);
    double freqs[] = {0.02, 0.07};
    rb_spectrum sp;
    CHECK(rb_spectrum_alloc(&sp, freqs, 2, xi) == RB_OK);
    CHECK(rb_spectrum_of_series(&s, 1.0, &sp) == RB_OK);
    for (size_t j = 0; j < sp.n; j++) {
        closed_form k;
        cf_init(&k, sp.freq_hz[j], xi, F_hz, A, T);
        double umax = 0, end = T + 1.0 / sp.freq_hz[j];
        size_t m = (size_t)(end / 1e-3);
        for (size_t i = 0; i <= m; i++) {
            double u, v;
            cf_at(&k, end * (double)i / (double)m, &u, &v);
            if (fabs(u) > umax)
                umax = fabs(u);
        }
        /* the sampled sine's straight lines: (W dt)^2 / 8, 4e-5 */
        CHECK_REL(sp.psa_mps2[j], k.w * k.w * umax, 1e-4);
    }
    rb_spectrum_free(&sp);
    double slow[] = {1e-6, 1e-3};
    struct timespec t0, t1;
    CHECK(rb_spectrum_alloc(&sp, slow, 2, xi) == RB_OK);
    clock_gettime(CLOCK_MONOTONIC, &t0);
    CHECK(rb_spectrum_of_series(&s, 1.0, &sp) == RB_OK);
    clock_gettime(CLOCK_MONOTONIC, &t1);
    double took = (double)(t1.tv_sec - t0.tv_sec) + 1e-9 * (double)(t1.tv_nsec - t0.tv_nsec);
    printf("1e-6 and 1e-3 Hz after 2 s of samples: %.3f s\n", took);
    CHECK(took < 5.0);
    CHECK(isfinite(sp.psa_mps2[0]) && isfinite(sp.sa_mps2[0]));
    rb_spectrum_free(&sp);
    rb_series_free(&s);
}

int main(void)
{
    check_slow_tail();
    check_harmonic(3.0, 4.0);
    check_harmonic(12.5, 2.0);
    check_building();
    rb_spectrum_opts o;
    rb_spectrum_opts_init(&o);
    rb_spectrum sp;
    o.f_max_hz = o.f_min_hz;
    CHECK(rb_spectrum_grid(&o, &sp) == RB_ERR_INVALID);
    rb_spectrum_opts_init(&o);
    o.per_octave = 1000;
    CHECK(rb_spectrum_grid(&o, &sp) == RB_ERR_INVALID);
    TEST_MAIN_END();
}
