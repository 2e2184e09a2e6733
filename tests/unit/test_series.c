/* Sampled series and the exact SDOF stepping behind the building filter:
 * closed-form responses, the textbook Nigam-Jennings coefficients, and a
 * fine-step Runge-Kutta reference on piecewise-linear input. */
#include <math.h>
#include <stdlib.h>
#include "harness.h"
#include "rockbolt/motion.h"
#include "../../src/motion/sdof.h"

#define PI 3.14159265358979323846

/* Deterministic pseudo-random accelerations in [-1, 1]. */
static double lcg_next(unsigned long *state)
{
    *state = (*state * 6364136223846793005UL + 1442695040888963407UL) & 0xffffffffffffUL;
    return (double)*state / (double)0xffffffffffffUL * 2.0 - 1.0;
}

static void test_alloc_and_basics(void)
{
    rb_series s;
    CHECK(rb_series_alloc(&s, 0, 0.01) == RB_ERR_INVALID);
    CHECK(s.accel_mps2 == NULL && s.n == 0);
    CHECK(rb_series_alloc(&s, 10, 0.0) == RB_ERR_INVALID);
    CHECK(rb_series_alloc(&s, 10, -0.01) == RB_ERR_INVALID);
    CHECK(rb_series_alloc(&s, 10, NAN) == RB_ERR_INVALID);
    CHECK(rb_series_alloc(&s, 10, INFINITY) == RB_ERR_INVALID);
    CHECK(rb_series_alloc(&s, 5, 0.02) == RB_OK);
    CHECK(s.n == 5 && s.dt_s == 0.02 && s.t0_s == 0.0);
    CHECK(s.accel_mps2[0] == 0.0 && s.accel_mps2[4] == 0.0);
    CHECK(rb_series_peak(&s) == 0.0);
    s.accel_mps2[1] = 1.5;
    s.accel_mps2[3] = -2.5;
    CHECK(rb_series_peak(&s) == 2.5);
    rb_series_scale(&s, -2.0);
    CHECK(s.accel_mps2[1] == -3.0 && s.accel_mps2[3] == 5.0);
    CHECK(rb_series_peak(&s) == 5.0);
    rb_series_free(&s);
    CHECK(s.accel_mps2 == NULL && s.n == 0);
    rb_series_free(&s);
    rb_series_free(NULL);
    CHECK(rb_series_peak(NULL) == 0.0);
}

static void test_window(void)
{
    rb_series s;
    CHECK(rb_series_alloc(&s, 1000, 0.01) == RB_OK);
    for (size_t i = 0; i < s.n; i++)
        s.accel_mps2[i] = (double)i;
    CHECK(rb_series_window(&s, 2.0, 3.0) == RB_OK);
    CHECK(s.n == 101);
    CHECK(s.accel_mps2[0] == 200.0 && s.accel_mps2[100] == 300.0);
    CHECK(s.t0_s == 0.0);
    /* Ends between samples keep only the samples inside. */
    CHECK(rb_series_window(&s, 0.005, 0.5) == RB_OK);
    CHECK(s.n == 50);
    CHECK(s.accel_mps2[0] == 201.0 && s.accel_mps2[49] == 250.0);
    /* Past the end clips; a window with no sample is refused. */
    CHECK(rb_series_window(&s, 0.3, 100.0) == RB_OK);
    CHECK(s.n == 20 && s.accel_mps2[19] == 250.0);
    CHECK(rb_series_window(&s, 50.0, 60.0) == RB_ERR_INVALID);
    CHECK(rb_series_window(&s, 0.1, 0.05) == RB_ERR_INVALID);
    CHECK(rb_series_window(&s, 0.001, 0.009) == RB_ERR_INVALID);
    CHECK(s.n == 20);
    rb_series_free(&s);
}

/* Chopra, Dynamics of Structures, Table 5.2.1 (m = 1, k = w^2, xi < 1):
 * the textbook closed forms, written independently of the matrix
 * exponential in sdof.c. */
static void closed_form_coeffs(double w, double xi, double dt, double c[8])
{
    double wd = w * sqrt(1.0 - xi * xi), e = exp(-xi * w * dt);
    double s = sin(wd * dt), co = cos(wd * dt), r = xi / sqrt(1.0 - xi * xi);
    double k = w * w;
    c[0] = e * (r * s + co);
    c[1] = e * s / wd;
    c[2] = (2.0 * xi / (w * dt) + e * (((1.0 - 2.0 * xi * xi) / (wd * dt) - r) * s
            - (1.0 + 2.0 * xi / (w * dt)) * co)) / k;
    c[3] = (1.0 - 2.0 * xi / (w * dt) + e * ((2.0 * xi * xi - 1.0) / (wd * dt) * s
            + 2.0 * xi / (w * dt) * co)) / k;
    c[4] = -e * w / sqrt(1.0 - xi * xi) * s;
    c[5] = e * (co - r * s);
    c[6] = (-1.0 / dt + e * ((w / sqrt(1.0 - xi * xi) + r / dt) * s + co / dt)) / k;
    c[7] = (1.0 - e * (r * s + co)) / (k * dt);
}

static void test_coefficients_match_textbook(void)
{
    const double cases[][3] = {{2 * PI * 5, 0.05, 0.01}, {2 * PI * 5, 0.01, 0.02},
                               {2 * PI * 1, 0.0, 0.005}, {2 * PI * 40, 0.3, 0.01}};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        rb_sdof_step st;
        double c[8];
        CHECK(rb_sdof_step_init(&st, cases[k][0], cases[k][1], cases[k][2]) == RB_OK);
        closed_form_coeffs(cases[k][0], cases[k][1], cases[k][2], c);
        const double got[8] = {st.uu, st.uv, st.up0, st.up1, st.vu, st.vv, st.vp0, st.vp1};
        for (int i = 0; i < 8; i++)
            CHECK_REL(got[i], c[i], 1e-11);
    }
}

static void test_step_init_rejects(void)
{
    rb_sdof_step st;
    CHECK(rb_sdof_step_init(&st, 0.0, 0.05, 0.01) == RB_ERR_INVALID);
    CHECK(rb_sdof_step_init(&st, 10.0, -0.01, 0.01) == RB_ERR_INVALID);
    CHECK(rb_sdof_step_init(&st, 10.0, NAN, 0.01) == RB_ERR_INVALID);
    CHECK(rb_sdof_step_init(&st, 10.0, 0.05, 0.0) == RB_ERR_INVALID);
    CHECK(rb_sdof_step_init(&st, INFINITY, 0.05, 0.01) == RB_ERR_INVALID);
    CHECK(rb_sdof_step_init(&st, 10.0, 1e3, 0.01) == RB_ERR_INVALID);
}

/* Response from rest to a constant load P for under-, critically and
 * over-damped oscillators. */
static double step_response(double w, double xi, double P, double t)
{
    double x0 = P / (w * w);
    if (xi < 1.0) {
        double wd = w * sqrt(1.0 - xi * xi);
        return x0 * (1.0 - exp(-xi * w * t)
                     * (cos(wd * t) + xi / sqrt(1.0 - xi * xi) * sin(wd * t)));
    }
    if (xi == 1.0)
        return x0 * (1.0 - exp(-w * t) * (1.0 + w * t));
    double q = w * sqrt(xi * xi - 1.0), l1 = -xi * w + q, l2 = -xi * w - q;
    return x0 * (1.0 + (l2 * exp(l1 * t) - l1 * exp(l2 * t)) / (l1 - l2));
}

static void test_step_load(void)
{
    const double xis[] = {0.0, 0.02, 1.0, 2.5};
    const double w = 2 * PI * 3, dt = 0.013, P = 4.0;
    double p[400], u[400];
    for (size_t i = 0; i < 400; i++)
        p[i] = P;
    for (size_t k = 0; k < 4; k++) {
        rb_sdof_step st;
        CHECK(rb_sdof_step_init(&st, w, xis[k], dt) == RB_OK);
        double peak = rb_sdof_run(&st, p, 400, u, NULL);
        double err = 0.0, ref_peak = 0.0;
        for (size_t i = 0; i < 400; i++) {
            double ref = step_response(w, xis[k], P, (double)i * dt);
            err = fmax(err, fabs(u[i] - ref));
            ref_peak = fmax(ref_peak, fabs(ref));
        }
        CHECK(err <= 1e-12 * ref_peak);
        CHECK_REL(peak, ref_peak, 1e-12);
    }
    /* Undamped: the sampled peak of P/w^2 (1 - cos wt) is 2 P/w^2. */
    rb_sdof_step st;
    CHECK(rb_sdof_step_init(&st, 2 * PI, 0.0, 0.01) == RB_OK);
    CHECK_REL(rb_sdof_run(&st, p, 400, NULL, NULL), 2.0 * P / (4 * PI * PI), 1e-12);
}

/* Ground acceleration x_g'' = c t is linear, so the filter must reproduce
 * the exact floor acceleration of eq. 5.28 at every sample. */
static void test_building_filter_ramp(void)
{
    const double f = 5.0, xi = 0.05, dt = 0.01, c = 3.0;
    const double w = 2 * PI * f, wd = w * sqrt(1.0 - xi * xi);
    rb_series s;
    CHECK(rb_series_alloc(&s, 600, dt) == RB_OK);
    for (size_t i = 0; i < s.n; i++)
        s.accel_mps2[i] = c * (double)i * dt;
    CHECK(rb_series_building_filter(&s, f, xi) == RB_OK);
    /* x_r = -c/w^2 (t - 2 xi/w) + e^(-xi w t)(A cos + B sin), at rest at 0. */
    double A = -2.0 * xi * c / (w * w * w), B = (c / (w * w) + xi * w * A) / wd;
    double err = 0.0, peak = 0.0;
    for (size_t i = 0; i < s.n; i++) {
        double t = (double)i * dt, e = exp(-xi * w * t);
        double cs = cos(wd * t), sn = sin(wd * t);
        double x = -c / (w * w) * (t - 2.0 * xi / w) + e * (A * cs + B * sn);
        double v = -c / (w * w) + e * ((-xi * w * A + wd * B) * cs
                                       + (-xi * w * B - wd * A) * sn);
        double floor_acc = -(2.0 * xi * w * v + w * w * x);
        err = fmax(err, fabs(s.accel_mps2[i] - floor_acc));
        peak = fmax(peak, fabs(floor_acc));
    }
    CHECK(peak > 1.0);
    CHECK(err <= 1e-11 * peak);
    /* Once the start-up transient (e^(-9.4) of c/w here) has died out, a
     * ramp passes through the building unchanged. */
    CHECK_NEAR(s.accel_mps2[599], c * 5.99, 1e-5);
    rb_series_free(&s);
}

/* Eq. 5.27 as a first-order system driven by linear interpolation of g. */
static void rk4_rhs(double w, double xi, double g, const double y[2], double d[2])
{
    d[0] = y[1];
    d[1] = -g - 2.0 * xi * w * y[1] - w * w * y[0];
}

static void rk4_filter(const double *g, size_t n, double dt, double f, double xi,
                       int sub, double *out)
{
    double w = 2 * PI * f, y[2] = {0.0, 0.0}, h = dt / sub;
    out[0] = 0.0;
    for (size_t i = 1; i < n; i++) {
        for (int k = 0; k < sub; k++) {
            double s0 = (double)k / sub, s1 = (k + 0.5) / sub, s2 = (k + 1.0) / sub;
            double g0 = g[i - 1] + (g[i] - g[i - 1]) * s0;
            double g1 = g[i - 1] + (g[i] - g[i - 1]) * s1;
            double g2 = g[i - 1] + (g[i] - g[i - 1]) * s2;
            double k1[2], k2[2], k3[2], k4[2], yt[2];
            rk4_rhs(w, xi, g0, y, k1);
            yt[0] = y[0] + 0.5 * h * k1[0]; yt[1] = y[1] + 0.5 * h * k1[1];
            rk4_rhs(w, xi, g1, yt, k2);
            yt[0] = y[0] + 0.5 * h * k2[0]; yt[1] = y[1] + 0.5 * h * k2[1];
            rk4_rhs(w, xi, g1, yt, k3);
            yt[0] = y[0] + h * k3[0]; yt[1] = y[1] + h * k3[1];
            rk4_rhs(w, xi, g2, yt, k4);
            y[0] += h / 6.0 * (k1[0] + 2.0 * k2[0] + 2.0 * k3[0] + k4[0]);
            y[1] += h / 6.0 * (k1[1] + 2.0 * k2[1] + 2.0 * k3[1] + k4[1]);
        }
        out[i] = -(2.0 * xi * w * y[1] + w * w * y[0]);
    }
}

static void test_building_filter_vs_rk4(void)
{
    const size_t n = 1500;
    const double dt = 0.01, f = 5.0, xi = 0.05;
    unsigned long seed = 12345;
    rb_series s;
    double *g = malloc(n * sizeof *g), *ref = malloc(n * sizeof *ref);
    CHECK(g && ref && rb_series_alloc(&s, n, dt) == RB_OK);
    if (!g || !ref || !s.accel_mps2) {
        free(g); free(ref); rb_series_free(&s);
        return;
    }
    for (size_t i = 0; i < n; i++)
        g[i] = s.accel_mps2[i] = 3.0 * lcg_next(&seed);
    rk4_filter(g, n, dt, f, xi, 100, ref);
    CHECK(rb_series_building_filter(&s, f, xi) == RB_OK);
    double err = 0.0, peak = 0.0;
    for (size_t i = 0; i < n; i++) {
        err = fmax(err, fabs(s.accel_mps2[i] - ref[i]));
        peak = fmax(peak, fabs(ref[i]));
    }
    CHECK(peak > 3.0);
    CHECK(err <= 1e-8 * peak);
    /* The reference itself must be converged: RK4 twenty times coarser is off by
     * far more, so the tolerance above is not trivially met. */
    rk4_filter(g, n, dt, f, xi, 5, ref);
    double coarse = 0.0;
    for (size_t i = 0; i < n; i++)
        coarse = fmax(coarse, fabs(s.accel_mps2[i] - ref[i]));
    CHECK(coarse > 1e-8 * peak);
    free(g);
    free(ref);
    rb_series_free(&s);
}

static void test_building_filter_rejects(void)
{
    rb_series s;
    CHECK(rb_series_alloc(&s, 10, 0.01) == RB_OK);
    s.accel_mps2[3] = 1.0;
    CHECK(rb_series_building_filter(&s, 0.0, 0.05) == RB_ERR_INVALID);
    CHECK(rb_series_building_filter(&s, 5.0, -0.05) == RB_ERR_INVALID);
    CHECK(rb_series_building_filter(&s, NAN, 0.05) == RB_ERR_INVALID);
    CHECK(s.accel_mps2[3] == 1.0);
    rb_series_free(&s);
    CHECK(rb_series_building_filter(&s, 5.0, 0.05) == RB_ERR_INVALID);
}

int main(void)
{
    test_alloc_and_basics();
    test_window();
    test_coefficients_match_textbook();
    test_step_init_rejects();
    test_step_load();
    test_building_filter_ramp();
    test_building_filter_vs_rk4();
    test_building_filter_rejects();
    TEST_MAIN_END();
}
