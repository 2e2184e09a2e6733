/* Solver benchmark: the reference cabinet under a 50 s floor motion sampled
 * at 50 Hz (El Centro through a 5 Hz, 5 % building, every second sample of
 * the 0.01 s record, zero-padded to 50 s), scaled to 0.4 A*, yielding bolts
 * that stretch on past their capacity (as chapter 6 runs earthquakes) so the
 * whole 50 s is simulated, summary only. Prints the median wall time of a solve, the time per
 * simulated second and the work counters, so the cost of each part shows, and each
 * figure over a plain linear SDOF loop through the same record timed in the same
 * process (the physical floor; bench/solve-ratios.sh gives the figures as ratios to
 * another commit's build).
 * Usage: bench_solve [RECORD] [RUNS] [RTOL]. Target: median under 2 ms. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "bench_common.h"
#include "rockbolt/solve.h"

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

static int floor_motion_50hz(const char *path, rb_series *out)
{
    rb_series raw = {0};
    if (rb_bench_floor_motion(path, &raw) != 0 || rb_series_alloc(out, 2500, 0.02) != RB_OK) {
        rb_series_free(&raw);
        return -1;
    }
    for (size_t i = 0; i < out->n && 2 * i < raw.n; i++)
        out->accel_mps2[i] = raw.accel_mps2[2 * i];
    rb_series_free(&raw);
    return 0;
}

/* The median time of the plain linear SDOF loop over the same record
 * (bench_common.h), n runs: what each figure is also given over, as its
 * distance to the physical floor. */
static double sdof_median(const rb_series *s, double scale, const rb_model *m, int n,
                          double *t)
{
    volatile double sink = 0;
    for (int i = 0; i < n; i++) {
        double t0 = rb_bench_now_s();
        sink += rb_bench_sdof_newmark(s, scale, m->freq_hz, m->damping);
        t[i] = rb_bench_now_s() - t0;
    }
    (void)sink;
    qsort(t, (size_t)n, sizeof *t, cmp);
    return t[n / 2];
}

/* Solve n times into r; the times, sorted, into t. 0, or -1 after
 * printing why a solve failed. */
static int time_solves(const rb_model *m, const rb_motion *mo, const rb_solve_opts *o,
                       int n, double *t, rb_result *r)
{
    for (int i = 0; i < n; i++) {
        double t0 = rb_bench_now_s();
        rb_status st = rb_solve_run(m, mo, o, r, NULL);
        t[i] = rb_bench_now_s() - t0;
        if (st != RB_OK) {
            fprintf(stderr, "solve failed: %s\n", rb_status_str(st));
            return -1;
        }
    }
    qsort(t, (size_t)n, sizeof *t, cmp);
    return 0;
}

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : "cases/records/elcentro_1940_ns.at2";
    int runs = argc > 2 ? atoi(argv[2]) : 200;
    rb_series s = {0};
    rb_model m;
    rb_derived d;
    rb_motion mo;
    rb_solve_opts o;
    rb_result r;
    if (runs < 1 || floor_motion_50hz(path, &s) != 0)
        return 2;
    rb_model_reference(&m);
    rb_model_derive(&m, &d, NULL);
    rb_motion_init(&mo);
    mo.kind = RB_MOTION_SAMPLED;
    mo.series = &s;
    mo.scale = 0.4 * d.a_star_mps2 / rb_series_peak(&s);
    mo.duration_s = 50.0;
    rb_solve_opts_init(&o);
    o.stretch_past_failure = 1;
    if (argc > 3)
        o.rtol = atof(argv[3]);
    double *t = malloc((size_t)runs * sizeof *t);
    if (!t)
        return 3;
    if (time_solves(&m, &mo, &o, runs, t, &r) != 0)
        return 3;
    double med = t[runs / 2];
    printf("reference cabinet, 50 s at 50 Hz, 0.4 A*, rigid-plastic bolts, %d runs\n", runs);
    printf("median solve        %.3f ms (min %.3f, max %.3f)\n", 1e3 * med, 1e3 * t[0],
           1e3 * t[runs - 1]);
    printf("per simulated s     %.1f us\n", 1e6 * med / 50.0);
    printf("steps               %ld accepted (%ld exact on the floor), %ld rejected\n",
           r.steps, r.exact_steps, r.rejected_steps);
    printf("steps per stage     1: %ld  2: %ld  4: %ld  5: %ld\n", r.stage_steps[1],
           r.stage_steps[2], r.stage_steps[4], r.stage_steps[5]);
    printf("rhs evaluations     %ld\n", r.rhs_evals);
    printf("events              %ld (uplifts %ld, floor impacts %ld, bolt impacts %ld)\n",
           r.events, r.uplifts, r.floor_impacts, r.bolt_impacts);
    printf("stage time (s)      1: %.2f  2: %.2f  4: %.2f  5: %.2f\n", r.stage_time_s[1],
           r.stage_time_s[2], r.stage_time_s[4], r.stage_time_s[5]);
    printf("simulated           %.2f s\n", r.t_end_s);
    printf("usage L/R           %.3f / %.3f\n", r.usage[0], r.usage[1]);
    printf("target              2 ms: %s\n", med < 2e-3 ? "met" : "NOT met");
    double sdof = sdof_median(&s, mo.scale, &m, runs, t);
    printf("linear SDOF loop    %.4f ms over the same record (Newmark, %zu steps); the "
           "solve is %.1f x that\n", 1e3 * sdof, s.n - 1, med / sdof);

    /* What users run: the 40 s record at its own 100 Hz through the building,
     * whose floor is exact between samples, with yielding and with
     * elastic-plastic bolts (targets 1 ms and 2 ms) */
    rb_series full = {0};
    if (rb_bench_floor_motion(path, &full) != 0)
        return 2;
    mo.series = &full;
    mo.scale = 0.4 * d.a_star_mps2 / rb_series_peak(&full);
    mo.duration_s = (double)(full.n - 1) * full.dt_s;
    for (int model = 0; model < 2; model++) {
        m.bolt_model = model == 0 ? RB_BOLT_RIGID_PLASTIC : RB_BOLT_ELASTIC_PLASTIC;
        int n_runs = model == 0 ? runs : (runs + 9) / 10;
        if (time_solves(&m, &mo, &o, n_runs, t, &r) != 0)
            return 3;
        med = t[n_runs / 2];
        double sdof_full = sdof_median(&full, mo.scale, &m, n_runs, t);
        printf("%s bolts, El Centro %.0f s at %.0f Hz through the 5 Hz building, "
               "0.4 A*: median solve %.3f ms over %d runs (%ld steps; target %s: %s); "
               "%.1f x the linear SDOF loop (%.4f ms)\n",
               model == 0 ? "rigid-plastic" : "elastic-plastic", mo.duration_s,
               1 / full.dt_s, 1e3 * med, n_runs, r.steps, model == 0 ? "1 ms" : "2 ms",
               med < (model == 0 ? 1e-3 : 2e-3) ? "met" : "NOT met", med / sdof_full,
               1e3 * sdof_full);
    }
    /* the same record at 0.002 A*: the cabinet never leaves the floor and
     * nearly every step is an exact one, so this is what the check points,
     * guards and tracked peaks cost with next to no integration (no
     * target: it bounds what any integrator can bring to the runs above) */
    m.bolt_model = RB_BOLT_RIGID_PLASTIC;
    mo.scale = 0.002 * d.a_star_mps2 / rb_series_peak(&full);
    if (time_solves(&m, &mo, &o, runs, t, &r) != 0)
        return 3;
    med = t[runs / 2];
    double sdof_floor = sdof_median(&full, mo.scale, &m, runs, t);
    printf("on the floor throughout, the same at 0.002 A*: median solve %.3f ms over %d runs "
           "(%ld steps, %ld exact, %ld events); %.1f x the linear SDOF loop (%.4f ms)\n",
           1e3 * med, runs, r.steps, r.exact_steps, r.events, med / sdof_floor,
           1e3 * sdof_floor);
    mo.scale = 0.4 * d.a_star_mps2 / rb_series_peak(&full);
    /* the independent cross-check, Dormand-Prince throughout at a
     * thousandth of the tolerance (no target: it is what a user pays to
     * confirm a result) */
    m.bolt_model = RB_BOLT_RIGID_PLASTIC;
    o.integrator = RB_INTEGRATOR_RK45;
    int n_rk = (runs + 9) / 10;
    if (time_solves(&m, &mo, &o, n_rk, t, &r) != 0)
        return 3;
    med = t[n_rk / 2];
    double sdof_rk = sdof_median(&full, mo.scale, &m, n_rk, t);
    printf("rigid-plastic bolts, the same with integrator rk45: median solve %.3f ms over %d "
           "runs (%ld steps); %.1f x the linear SDOF loop\n", 1e3 * med, n_rk, r.steps,
           med / sdof_rk);
    rb_series_free(&full);
    free(t);
    rb_series_free(&s);
    return 0;
}
