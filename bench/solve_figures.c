/* One figure of issue 41's solver targets, timed in this build: the
 * reference cabinet, rigid-plastic or elastic-plastic rows named (both
 * builds then do the same work), under El Centro at its own 100 Hz
 * through the 5 Hz, 5 % building, 40 s, stretched past failure as
 * bench_solve runs it; and, in the same process, a plain linear SDOF
 * loop (Newmark, the frame's frequency) over the same record, the
 * distance to the physical floor. bench/baseline.sh builds this file into
 * the build of another commit, and bench/solve-ratios.sh alternates the
 * two builds' runs.
 *   solve_figures FIGURE [RUNS [RECORD]]
 * FIGURE: floor (0.002 A*, never leaves the floor, rigid-plastic rows),
 * rigid (0.4 A*, rigid-plastic), elastic (0.4 A*, elastic-plastic).
 * Prints one line: FIGURE median_ms least_ms largest_ms steps
 * sdof_median_ms. */
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

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: solve_figures floor|rigid|elastic [RUNS [RECORD]]\n");
        return 2;
    }
    const char *fig = argv[1];
    int runs = argc > 2 ? atoi(argv[2]) : 50;
    const char *path = argc > 3 ? argv[3] : "cases/records/elcentro_1940_ns.at2";
    double level = strcmp(fig, "floor") == 0 ? 0.002 : 0.4;
    if (runs < 1 || (strcmp(fig, "floor") && strcmp(fig, "rigid") && strcmp(fig, "elastic")))
        return 2;
    rb_series s = {0};
    if (rb_bench_floor_motion(path, &s) != 0)
        return 2;
    rb_model m;
    rb_derived d;
    rb_motion mo;
    rb_solve_opts o;
    rb_result r;
    rb_model_reference(&m);
    m.bolt_model = strcmp(fig, "elastic") == 0 ? RB_BOLT_ELASTIC_PLASTIC
                                                 : RB_BOLT_RIGID_PLASTIC;
    rb_model_derive(&m, &d, NULL);
    rb_motion_init(&mo);
    mo.kind = RB_MOTION_SAMPLED;
    mo.series = &s;
    mo.scale = level * d.a_star_mps2 / rb_series_peak(&s);
    mo.duration_s = (double)(s.n - 1) * s.dt_s;
    rb_solve_opts_init(&o);
    o.stretch_past_failure = 1;
    double *t = malloc((size_t)runs * sizeof *t), *ts = malloc((size_t)runs * sizeof *ts);
    if (!t || !ts)
        return 3;
    volatile double sink = 0;
    for (int i = 0; i < runs; i++) {
        double t0 = rb_bench_now_s();
        rb_status st = rb_solve_run(&m, &mo, &o, &r, NULL);
        t[i] = rb_bench_now_s() - t0;
        if (st != RB_OK) {
            fprintf(stderr, "solve failed: %s\n", rb_status_str(st));
            return 3;
        }
        t0 = rb_bench_now_s();
        sink += rb_bench_sdof_newmark(&s, mo.scale, m.freq_hz, m.damping);
        ts[i] = rb_bench_now_s() - t0;
    }
    (void)sink;
    qsort(t, (size_t)runs, sizeof *t, cmp);
    qsort(ts, (size_t)runs, sizeof *ts, cmp);
    printf("%s %.4f %.4f %.4f %ld %.4f\n", fig, 1e3 * t[runs / 2], 1e3 * t[0],
           1e3 * t[runs - 1], r.steps, 1e3 * ts[runs / 2]);
    free(t);
    free(ts);
    rb_series_free(&s);
    return 0;
}
