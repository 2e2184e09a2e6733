/* Fragility benchmark: `rockbolt fragility` on a suite of the reference
 * cabinet (default cases/fragility-suite.yaml: the four shipped records
 * through the 5 Hz building at 0.4 A*), four limit states each: the wall
 * time of the searches and fits, the runs, and the time per motion, from
 * which a 7-motion suite's time follows. Usage: bench_fragility [CASE]
 * [THREADS] [REPEATS], from the source root. It prints the solves (runs
 * made, a run the searches share counted once) and the runs the searches
 * read (each counted by every search that reads it, as the report says).
 * Targets: the reference suite in at most 170 solves; a 7-motion
 * fragility (bench/fragility-7.yaml) in under 0.5 s on two cores. */
#include <stdio.h>
#include <stdlib.h>
#include "rockbolt/case.h"
#include "rockbolt/run.h"
#include "bench_common.h"

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : "cases/fragility-suite.yaml";
    int nt = argc > 2 ? atoi(argv[2]) : 0, reps = argc > 3 ? atoi(argv[3]) : 3;
    rb_case c;
    rb_diag_list dl = {0};
    if (rb_case_load(path, &c, &dl) != RB_OK) {
        for (size_t i = 0; i < dl.n; i++)
            fprintf(stderr, "%s:%d:%d: %s\n", dl.items[i].file, dl.items[i].line,
                    dl.items[i].col, dl.items[i].msg);
        rb_diag_list_free(&dl);
        return 2;
    }
    rb_diag_list_free(&dl);
    double best = 1e30;
    long runs = 0, solves = 0;
    for (int r = 0; r < (reps > 0 ? reps : 1); r++) {
        rb_case_fragility f;
        rb_diag d;
        double t0 = rb_bench_now_s();
        rb_status st = rb_run_fragility(&c, nt, 0, 1000, &f, &d, NULL, NULL);
        double t = rb_bench_now_s() - t0;
        if (st != RB_OK) {
            fprintf(stderr, "fragility: %s: %s: %s\n", rb_status_str(st), d.key, d.msg);
            rb_case_fragility_free(&f);
            rb_case_free(&c);
            return 1;
        }
        runs = f.runs;
        solves = f.solves;
        best = t < best ? t : best;
        rb_case_fragility_free(&f);
    }
    double per_motion = best / (double)c.n_motions;
    printf("fragility %s: %zu motions x %d limit states, %ld solves (%ld runs read by "
           "the searches)\n", path, c.n_motions, RB_N_LIMITS, solves, runs);
    printf("fragility: best of %d: %.3f s wall on %s threads: %.3f s a motion; "
           "7 motions: %.2f s (target 0.5 s: %s)\n", reps, best, nt > 0 ? argv[2] : "all",
           per_motion, 7 * per_motion, 7 * per_motion < 0.5 ? "met" : "NOT met");
    rb_case_free(&c);
    return 0;
}
