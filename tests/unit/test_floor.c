/* The floor between samples of a record through a building (src/motion/floor.c):
 *   - it passes through the filter's samples;
 *   - it solves the building's equation between them: the floor equals
 *     -(2 xi w u' + w^2 u) for a u that a fine Nigam-Jennings stepping of
 *     the same linear ground reaches;
 *   - its Taylor series sums to its value, to high order;
 *   - the true peak is at least the largest sample and is reached;
 *   - inserting samples into the ground by linear interpolation changes
 *     neither the floor nor its peak (the same ground motion);
 *   - scaling, windowing and copying keep all of it;
 *   - critical damping (w_d = 0) works without a separate branch. */
#include <math.h>
#include <stdlib.h>
#include "harness.h"
#include "rockbolt/motion.h"

#define PI 3.14159265358979323846

/* A ground motion with content near and above the building. */
static void ground(rb_series *s, size_t n, double dt)
{
    rb_series_alloc(s, n, dt);
    for (size_t i = 0; i < n; i++) {
        double t = (double)i * dt;
        s->accel_mps2[i] = 3.0 * sin(2 * PI * 2.3 * t) + 1.5 * sin(2 * PI * 9.1 * t + 0.4)
                           + 0.8 * cos(2 * PI * 17.0 * t) + (i % 7 == 3 ? 1.0 : 0.0);
    }
}

/* Insert k - 1 samples between neighbours, on the straight line. */
static void upsample(const rb_series *from, unsigned k, rb_series *to)
{
    size_t n = (from->n - 1) * k + 1;
    rb_series_alloc(to, n, from->dt_s / k);
    for (size_t i = 0; i + 1 < from->n; i++)
        for (unsigned j = 0; j < k; j++)
            to->accel_mps2[i * k + j] = from->accel_mps2[i]
                + (from->accel_mps2[i + 1] - from->accel_mps2[i]) * j / k;
    to->accel_mps2[n - 1] = from->accel_mps2[from->n - 1];
}

static double series_sum(const double *c, int deg, double tau)
{
    double s = 0.0;
    for (int k = deg; k >= 0; k--)
        s = s * tau + c[k];
    return s;
}

static void check_building(double f_hz, double xi, double dt)
{
    rb_series g, s, fine, up;
    ground(&g, 400, dt);
    CHECK(rb_series_copy(&g, &s) == RB_OK);
    CHECK(rb_series_building_filter(&s, f_hz, xi) == RB_OK);
    CHECK(s.bld.ground_mps2 != NULL);

    /* through the samples */
    double worst = 0.0;
    for (size_t i = 0; i < s.n; i++)
        worst = fmax(worst, fabs(rb_series_at(&s, (double)i * dt) - s.accel_mps2[i]));
    CHECK(worst < 1e-10);

    /* the floor line from a sample by its index: what the line found
     * from the sample's time gives, to the bit; its ground is the
     * ground's sample and its building state gives the floor's sample */
    int same = 1;
    double line_worst = 0.0;
    for (long i = 0; i + 1 < (long)s.n; i++) {
        rb_floor_line a, b;
        CHECK(rb_series_floor_line_at(&s, i, &a) == 1);
        CHECK(rb_series_floor_line(&s, s.t0_s + (double)i * s.dt_s, &b) == 1);
        same = same && a.g0 == b.g0 && a.slope == b.slope && a.u == b.u && a.v == b.v
               && a.omega == b.omega && a.xi == b.xi;
        double w = 2 * PI * f_hz;
        line_worst = fmax(line_worst, fabs(a.g0 - g.accel_mps2[i]));
        line_worst = fmax(line_worst, fabs(-(2 * xi * w * a.v + w * w * a.u) - s.accel_mps2[i]));
        line_worst = fmax(line_worst, fabs(a.slope - (g.accel_mps2[i + 1] - g.accel_mps2[i]) / dt));
    }
    CHECK(same);
    CHECK(line_worst < 1e-9);
    {
        rb_floor_line a;
        CHECK(rb_series_floor_line_at(&s, (long)s.n - 1, &a) == 0);
        CHECK(rb_series_floor_line_at(&s, -1, &a) == 0);
    }

    /* between them: the same ground sampled 64 times finer through the
     * same building gives the floor at those points */
    upsample(&g, 64, &up);
    CHECK(rb_series_copy(&up, &fine) == RB_OK);
    CHECK(rb_series_building_filter(&fine, f_hz, xi) == RB_OK);
    worst = 0.0;
    double linear_worst = 0.0;
    for (size_t j = 0; j < fine.n; j++) {
        double t = (double)j * fine.dt_s;
        worst = fmax(worst, fabs(rb_series_at(&s, t) - fine.accel_mps2[j]));
        size_t i = j / 64;
        double f = (double)(j % 64) / 64.0, lin = s.accel_mps2[i]
            + (i + 1 < s.n ? f * (s.accel_mps2[i + 1] - s.accel_mps2[i]) : 0.0);
        linear_worst = fmax(linear_worst, fabs(lin - fine.accel_mps2[j]));
    }
    printf("building %.0f Hz, xi %.2f, dt %.3f s: exact floor within %.2e m/s^2 of a "
           "64x finer filter; straight lines within %.2e\n", f_hz, xi, dt, worst,
           linear_worst);
    CHECK(worst < 1e-9 * rb_series_peak(&s));
    CHECK(linear_worst > 1e3 * worst);

    /* the peak: the finer filter's samples come within (w dt/64)^2 of it
     * and never above it */
    double p = rb_series_peak(&s), fine_samples = 0.0, coarse = 0.0;
    for (size_t j = 0; j < fine.n; j++)
        fine_samples = fmax(fine_samples, fabs(fine.accel_mps2[j]));
    for (size_t i = 0; i < s.n; i++)
        coarse = fmax(coarse, fabs(s.accel_mps2[i]));
    CHECK(p >= coarse);
    CHECK(p >= fine_samples * (1 - 1e-12));
    CHECK(p <= fine_samples * (1 + pow(2 * PI * f_hz * dt / 64, 2)));
    /* ... and the finer record's own true peak is the same number */
    CHECK_REL(rb_series_peak(&fine), p, 1e-10);

    /* the Taylor series at a point between samples */
    double coef[25];
    for (size_t i = 5; i < s.n - 1; i += 37) {
        double t0 = ((double)i + 0.3) * dt;
        int deg = rb_series_taylor(&s, t0, 24, coef);
        CHECK(deg == 24);
        for (double tau = 0; tau <= 0.7 * dt; tau += 0.1 * dt)
            CHECK_NEAR(series_sum(coef, deg, tau), rb_series_at(&s, t0 + tau),
                       1e-11 * p);
    }

    /* the building's table of the series per unit state, and the
     * recurrence it was formed by (a building set up by hand, or more
     * terms than the table holds), give the same terms */
    rb_series_building hand = s.bld;
    hand.taylor_du[0] = 0;
    rb_series by_hand = s;
    by_hand.bld = hand;
    double rec[25], worst_term = 0;
    for (size_t i = 3; i < s.n - 1; i += 53) {
        double t0 = ((double)i + 0.6) * dt, scale = 1;
        CHECK(rb_series_taylor(&s, t0, 24, coef) == 24);
        CHECK(rb_series_taylor(&by_hand, t0, 24, rec) == 24);
        for (int k = 0; k <= 24; k++, scale *= dt) {
            worst_term = fmax(worst_term, fabs(coef[k] - rec[k]) * scale);
            CHECK_NEAR(coef[k] * scale, rec[k] * scale, 1e-13 * p);
        }
    }
    printf("  table against recurrence: terms within %.2e m/s^2 over a sample\n",
           worst_term);
    /* they round differently, which shows the two paths were both taken */
    CHECK(worst_term > 0);

    /* scaling, windowing and copying keep the floor exact */
    rb_series w;
    CHECK(rb_series_copy(&s, &w) == RB_OK);
    rb_series_scale(&w, -2.5);
    CHECK_REL(rb_series_peak(&w), 2.5 * p, 1e-14);
    CHECK_NEAR(rb_series_at(&w, 100.4 * dt), -2.5 * rb_series_at(&s, 100.4 * dt), 1e-12 * p);
    CHECK(rb_series_window(&w, 50 * dt, 300 * dt) == RB_OK);
    CHECK_NEAR(rb_series_at(&w, 7.7 * dt), -2.5 * rb_series_at(&s, 57.7 * dt), 1e-12 * p);
    CHECK(rb_series_peak(&w) <= 2.5 * p * (1 + 1e-14));

    rb_series_free(&g);
    rb_series_free(&s);
    rb_series_free(&fine);
    rb_series_free(&up);
    rb_series_free(&w);
}

int main(void)
{
    check_building(5.0, 0.05, 0.01);
    check_building(8.0, 0.05, 0.02);
    check_building(10.0, 0.02, 0.02);
    check_building(4.0, 1.0, 0.01);   /* critical damping */

    /* a floor record without a building: straight lines, degree 1 */
    rb_series g;
    double coef[4];
    ground(&g, 50, 0.02);
    CHECK(rb_series_taylor(&g, 0.215, 3, coef) == 1);
    CHECK_NEAR(coef[0], rb_series_at(&g, 0.215), 1e-14);
    CHECK_NEAR(rb_series_at(&g, 0.21), 0.5 * (g.accel_mps2[10] + g.accel_mps2[11]), 1e-14);
    rb_floor_line fl;
    CHECK(rb_series_floor_line_at(&g, 10, &fl) == 1);
    CHECK(fl.g0 == g.accel_mps2[10] && fl.u == 0 && fl.v == 0 && fl.omega == 0);
    CHECK_NEAR(fl.slope, (g.accel_mps2[11] - g.accel_mps2[10]) / 0.02, 1e-9);
    CHECK(rb_series_floor_line_at(&g, 49, &fl) == 0);
    rb_series_free(&g);
    TEST_MAIN_END();
}
