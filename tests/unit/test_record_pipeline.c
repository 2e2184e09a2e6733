/* The motion pipeline end to end against the thesis's fixed-base column
 * (Tables 5.1 and 6.2): El Centro N-S through a 5 Hz, 5 % building,
 * scaled to a peak floor acceleration a = 0.4 A*, drives the 5 Hz, 1 %
 * fixed-base frame U'' + 2 xi w U' + w^2 U = (4/pi) x''. The thesis gives
 * max U / U_static = 14.02 with U_static = pi^2 a / (8 w^2), and base
 * shear / W = 51.0. Nothing here depends on the rocking model, so this
 * checks the record reader, the building filter and the exact stepping.
 *
 * The floor the frame feels is the building's exact response between
 * samples (rb_series_at), looked at SUBSTEPS times per sample; the record
 * is scaled to that floor's true peak. An independent calculation
 * (tests/validation/notes.md, note 12: building and frame as one linear
 * system, scipy's matrix exponential) gives U / U_static = 14.1060; the
 * thesis's 14.02 is what straight lines between the floor samples give. */
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include "harness.h"
#include "rockbolt/model.h"
#include "rockbolt/record.h"
#include "../../src/motion/sdof.h"

#define PI 3.14159265358979323846
/* A* of the reference cabinet is 11.7 g; the tables are at 0.4 A*. */
#define A_STAR_G 11.7
/* Points per step at which U is looked at: the peak between samples is
 * then found to (w dt / 32)^2 / 8, about 1e-5. */
#define SUBSTEPS 32

typedef struct {
    double ratio;          /* max |U| / U_static, U looked at within steps */
    double ratio_samples;  /* the same from the samples only */
    double shear_over_w;   /* (pi/4) (U/U_static) (a/g) */
} pipeline_result;

static int run_pipeline(const char *path, double dt_if_missing, pipeline_result *res)
{
    rb_record_opts o;
    rb_series s;
    rb_diag d;
    rb_record_opts_init(&o);
    o.units_to_mps2 = RB_G0;   /* only used by the Taft column file */
    o.dt_s = dt_if_missing;
    if (rb_record_read(path, &o, &s, &d) != RB_OK) {
        fprintf(stderr, "%s:%d:%d: %s\n", d.file, d.line, d.col, d.msg);
        return 0;
    }
    /* a record of fewer than two samples has no step to subdivide, and
     * (s.n - 1) would wrap to a size no malloc can give */
    if (s.n < 2 || s.n > SIZE_MAX / SUBSTEPS / sizeof(double)) {
        fprintf(stderr, "%s: %zu samples\n", path, s.n);
        rb_series_free(&s);
        return 0;
    }
    const double a = 0.4 * A_STAR_G * RB_G0, w = 2 * PI * 5.0, xi = 0.01;
    int ok = rb_series_building_filter(&s, 5.0, 0.05) == RB_OK;
    rb_series_scale(&s, a / rb_series_peak(&s));
    size_t n_fine = (s.n - 1) * SUBSTEPS + 1;
    double *p = malloc(s.n * sizeof *p), *fine = malloc(n_fine * sizeof *fine);
    ok = ok && p && fine && fabs(rb_series_peak(&s) - a) <= 1e-12 * a;
    for (size_t i = 0; ok && i < s.n; i++)
        p[i] = 4.0 / PI * s.accel_mps2[i];
    for (size_t j = 0; ok && j < n_fine; j++)
        fine[j] = 4.0 / PI * rb_series_at(&s, s.t0_s + (double)j * s.dt_s / SUBSTEPS);
    double u_within = 0.0, u_samples = 0.0, u_static = PI * PI * a / (8.0 * w * w);
    ok = ok && rb_sdof_peak_within(w, xi, s.dt_s / SUBSTEPS, 1, fine, n_fine,
                                   &u_within) == RB_OK
         && rb_sdof_peak_within(w, xi, s.dt_s, 1, p, s.n, &u_samples) == RB_OK;
    res->ratio = u_within / u_static;
    res->ratio_samples = u_samples / u_static;
    res->shear_over_w = PI / 4.0 * res->ratio * a / RB_G0;
    printf("%s: max U/U_static = %.4f (samples only %.4f), shear/W = %.2f\n",
           path, res->ratio, res->ratio_samples, res->shear_over_w);
    free(p);
    free(fine);
    rb_series_free(&s);
    return ok;
}

int main(void)
{
    pipeline_result r;
    CHECK(run_pipeline("cases/records/elcentro_1940_ns.at2", 0.0, &r));
    CHECK_NEAR(r.ratio, 14.1060, 0.0005);
    CHECK(r.shear_over_w >= 51.0 && r.shear_over_w <= 52.0);
    /* The samples alone (of the floor, then of U) miss the peaks between
     * them, the floor's and the frame's: 1.8 % here. */
    CHECK(r.ratio_samples < r.ratio && r.ratio_samples > 0.975 * r.ratio);

    /* The 0.02 s digitisation gives about 11 (MODEL.md): its building
     * output is sampled at 10 points per period and peaks differently. */
    CHECK(run_pipeline("cases/records/elcentro_1940_ns_peknold.at2", 0.0, &r));
    CHECK(r.ratio >= 10.5 && r.ratio <= 11.5);
    CHECK_NEAR(r.ratio, 11.4345, 0.002);   /* the independent calculation */

    /* No thesis values for these two. NGA-West2: the independent
     * calculation gives 13.9369. Taft: a regression value of this code,
     * kept so that a change in the reader or the filter shows (12.795
     * with straight lines between the floor samples). */
    CHECK(run_pipeline("cases/records/elcentro_1940_ns_ngawest2.at2", 0.0, &r));
    CHECK_NEAR(r.ratio, 13.9369, 0.002);
    CHECK(run_pipeline("cases/records/taft_1952_s69e.txt", 0.01, &r));
    CHECK_NEAR(r.ratio, 12.893, 0.002);
    TEST_MAIN_END();
}
