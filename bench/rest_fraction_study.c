/* The rest_fraction study (docs/solver.md, "When rocking stops"): how the
 * criterion that ends a series of floor impacts moves a run's results.
 * After a floor impact, rocking whose rise would be below rest_fraction
 * times the smaller of alpha and the bolt contact angle is taken as at
 * rest (stage 1). Each run is solved at rest_fraction 1e-8, 1e-7, 1e-6
 * (the default), 1e-5 and 1e-4, and its usage (the larger row's) and
 * floor impacts printed with the usage's change from the run at
 * 1e-8, the finest; and at the default with a tenth of the tolerance,
 * which tells a choice that moves a result from a run that any change
 * moves (a chaotic one).
 *   rest_fraction_study [N_RANDOM [CASE...]]   (from the source root)
 * The cases' motions as the pipeline runs them (rb_run_motion, the case's
 * own options), then N_RANDOM random cabinets (default 40; 200-900 kg,
 * 3-15 Hz, 10-16 mm bolts, gap ratios 0.002-0.03, 0.1-0.6 A* of El
 * Centro or Taft through a 3-10 Hz building, 20 s, rows stretched past
 * failure), drawn with a fixed seed. A last line sums up: the largest
 * change of usage at the default against the finest, over all runs. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "bench_common.h"
#include "rockbolt/case.h"
#include "rockbolt/record.h"
#include "rockbolt/run.h"
#include "rockbolt/solve.h"

#define N_FRAC 5
#define N_RUNS (N_FRAC + 1) /* and the default at a tenth of the tolerance */
static const double fracs[N_FRAC] = {1e-8, 1e-7, 1e-6, 1e-5, 1e-4};
static double worst_default, worst_any;
static long n_runs, n_moved, n_within_tol;

static double usage_of(const rb_result *r)
{
    return fmax(r->usage[0], r->usage[1]);
}

static void report(const char *name, const rb_result *r, const int *ok)
{
    double u0 = usage_of(&r[0]);
    printf("%-44s", name);
    for (int k = 0; k < N_FRAC; k++) {
        if (!ok[k]) {
            printf(" | failed");
            continue;
        }
        double u = usage_of(&r[k]);
        printf(" | %.4f %+.1e %ld", u, u0 > 0 ? (u - u0) / u0 : u - u0, r[k].floor_impacts);
    }
    printf("\n");
    double u2 = usage_of(&r[2]);
    if (ok[N_FRAC])
        printf("%-44s | at a tenth of the tolerance %.4f %+.1e from the default\n", "",
               usage_of(&r[N_FRAC]), u2 > 0 ? (usage_of(&r[N_FRAC]) - u2) / u2 : 0);
    if (!ok[0] || !ok[2] || !ok[N_FRAC])
        return;
    double d = fabs(u2 - u0) / fmax(u0, 1e-3);
    double dt = fabs(usage_of(&r[N_FRAC]) - u2) / fmax(u2, 1e-3);
    worst_default = fmax(worst_default, d);
    n_runs++;
    n_moved += d > 1e-3;
    n_within_tol += d <= fmax(dt, 1e-3);
    for (int k = 1; k < N_FRAC; k++)
        if (ok[k])
            worst_any = fmax(worst_any, fabs(usage_of(&r[k]) - u0) / fmax(u0, 1e-3));
}

static void study_case(const char *path)
{
    rb_case c;
    rb_diag_list dl = {0};
    if (rb_case_load(path, &c, &dl) != RB_OK) {
        fprintf(stderr, "%s: does not load\n", path);
        rb_diag_list_free(&dl);
        return;
    }
    rb_diag_list_free(&dl);
    for (size_t i = 0; i < c.n_motions; i++) {
        rb_result r[N_RUNS];
        int ok[N_RUNS];
        double rtol = c.solve.rtol;
        for (int k = 0; k < N_RUNS; k++) {
            rb_report_motion rm;
            rb_diag diag;
            c.solve.rest_fraction = k < N_FRAC ? fracs[k] : 1e-6;
            c.solve.rtol = k < N_FRAC ? rtol : fmax(0.1 * rtol, 1e-13);
            ok[k] = rb_run_motion(&c, i, 0, &r[k], &rm, &diag) == RB_OK;
        }
        c.solve.rtol = rtol;
        char name[256];
        snprintf(name, sizeof name, "%s [%s]", path, c.motions[i].name);
        report(name, r, ok);
        for (int k = 0; k < N_RUNS; k++)
            rb_result_free(&r[k]);
    }
    rb_case_free(&c);
}

static void study_random(int n)
{
    unsigned long long seed = 20261127;
    rb_series rec[2] = {{0}, {0}};
    if (rb_bench_read_record("cases/records/elcentro_1940_ns.at2", 0, &rec[0]) != 0
        || rb_bench_read_record("cases/records/taft_1952_s69e.txt", 1, &rec[1]) != 0) {
        fprintf(stderr, "cannot read the records\n");
        return;
    }
    for (int i = 0; i < n; i++) {
        int which = rb_bench_uniform(&seed, 0, 1) < 0.5;
        double mass = rb_bench_uniform(&seed, 200, 900);
        double f = rb_bench_uniform(&seed, 3, 15);
        double dia = rb_bench_uniform(&seed, 0.010, 0.016);
        double gr = rb_bench_uniform(&seed, 0.002, 0.03);
        double level = rb_bench_uniform(&seed, 0.1, 0.6);
        double fb = rb_bench_uniform(&seed, 3, 10);
        rb_series s = {0};
        if (rb_series_copy(&rec[which], &s) != RB_OK
            || rb_series_building_filter(&s, fb, 0.05) != RB_OK) {
            rb_series_free(&s);
            continue;
        }
        rb_model m;
        rb_derived d;
        rb_model_reference(&m);
        m.mass_kg = mass;
        m.freq_hz = f;
        m.bolt_area_m2 = M_PI * dia * dia / 4;
        m.gap_m = gr * m.lever_arm_m;
        if (rb_model_derive(&m, &d, NULL) != RB_OK) {
            rb_series_free(&s);
            continue;
        }
        rb_motion mo;
        rb_motion_init(&mo);
        mo.kind = RB_MOTION_SAMPLED;
        mo.series = &s;
        mo.scale = level * d.a_star_mps2 / rb_series_peak(&s);
        mo.duration_s = 20;
        rb_result r[N_RUNS];
        int ok[N_RUNS];
        for (int k = 0; k < N_RUNS; k++) {
            rb_solve_opts o;
            rb_solve_opts_init(&o);
            o.stretch_past_failure = 1;
            o.rest_fraction = k < N_FRAC ? fracs[k] : 1e-6;
            if (k == N_FRAC)
                o.rtol *= 0.1;
            ok[k] = rb_solve_run(&m, &mo, &o, &r[k], NULL) == RB_OK;
        }
        char name[256];
        snprintf(name, sizeof name, "random %d (%s, %.0f kg, %.1f Hz, %.2f A*)", i + 1,
                 which ? "Taft" : "El Centro", mass, f, level);
        report(name, r, ok);
        for (int k = 0; k < N_RUNS; k++)
            rb_result_free(&r[k]);
        rb_series_free(&s);
    }
    rb_series_free(&rec[0]);
    rb_series_free(&rec[1]);
}

int main(int argc, char **argv)
{
    int n_random = argc > 1 ? atoi(argv[1]) : 40;
    printf("%-44s", "run: usage, change from 1e-8, floor impacts at");
    for (int k = 0; k < N_FRAC; k++)
        printf(" | rest_fraction %-8g", fracs[k]);
    printf("\n");
    for (int i = 2; i < argc; i++)
        study_case(argv[i]);
    study_random(n_random);
    printf("%ld runs: usage at the default 1e-6 moved more than 1e-3 (relative) from 1e-8 in "
           "%ld; largest change %.3g at the default, %.3g at any fraction; in %ld runs the "
           "change from 1e-8 to the default is within 1e-3 or within what a tenth of the "
           "tolerance moves the default run\n", n_runs, n_moved, worst_default, worst_any,
           n_within_tol);
    return 0;
}
