/* Fragility benchmark: `rockbolt fragility` on a suite of the reference
 * cabinet (default cases/fragility-suite.yaml: the four shipped records
 * through the 5 Hz building at 0.4 A*), four limit states each: the wall
 * time of the searches and fits, the runs, and the time per motion, from
 * which a 7-motion suite's time follows. Usage: bench_fragility [CASE]
 * [THREADS] [REPEATS], from the source root. It prints the solves (runs
 * made, a run the searches share counted once) and the runs the searches
 * read (each counted by every search that reads it, as the report says).
 * On one thread (THREADS 1) it also prints where the time went: each
 * limit state's searches (a run two searches share is timed in the one
 * that made it), and the rest (the governing state's confirmations and
 * the fits).
 * Targets: the reference suite in at most 170 solves; a 7-motion
 * fragility (bench/fragility-7.yaml) in under 0.5 s on two cores. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/case.h"
#include "rockbolt/names.h"
#include "rockbolt/run.h"
#include "bench_common.h"

/* The time of each search, told by the progress callback as each ends
 * ("motion 'NAME': STATE"): on one thread the time since the one before. */
typedef struct {
    double last, per_state[RB_N_LIMITS];
} search_times;

static void note_search(void *ctx, size_t done, size_t total, const char *what)
{
    search_times *st = ctx;
    double now = rb_bench_now_s();
    (void)done, (void)total;
    if (!what) /* the last call, once everything is done */
        return;
    const char *state = strrchr(what, ' ');
    for (int k = 0; state && k < RB_N_LIMITS; k++)
        if (strcmp(state + 1, rb_enum_str(rb_limit_state_names, k)) == 0)
            st->per_state[k] += now - st->last;
    st->last = now;
}

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
    search_times times = {0}, best_times = {0};
    for (int r = 0; r < (reps > 0 ? reps : 1); r++) {
        rb_case_fragility f;
        rb_diag d;
        double t0 = rb_bench_now_s();
        times = (search_times){t0, {0}};
        rb_status st = rb_run_fragility(&c, nt, 0, 1000, &f, &d, nt == 1 ? note_search : NULL,
                                        &times);
        double t = rb_bench_now_s() - t0;
        if (st != RB_OK) {
            fprintf(stderr, "fragility: %s: %s: %s\n", rb_status_str(st), d.key, d.msg);
            rb_case_fragility_free(&f);
            rb_case_free(&c);
            return 1;
        }
        runs = f.runs;
        solves = f.solves;
        if (t < best)
            best_times = times;
        best = t < best ? t : best;
        rb_case_fragility_free(&f);
    }
    double per_motion = best / (double)c.n_motions;
    printf("fragility %s: %zu motions x %d limit states, %ld solves (%ld runs read by "
           "the searches)\n", path, c.n_motions, RB_N_LIMITS, solves, runs);
    printf("fragility: best of %d: %.3f s wall on %s threads: %.3f s a motion; "
           "7 motions: %.2f s (target 0.5 s: %s)\n", reps, best, nt > 0 ? argv[2] : "all",
           per_motion, 7 * per_motion, 7 * per_motion < 0.5 ? "met" : "NOT met");
    if (nt == 1) {
        double searched = 0;
        for (int k = 0; k < RB_N_LIMITS; k++)
            if (best_times.per_state[k] > 0) {
                searched += best_times.per_state[k];
                printf("  %-12s %.3f s (%.0f %%)\n", rb_enum_str(rb_limit_state_names, k),
                       best_times.per_state[k], 100 * best_times.per_state[k] / best);
            }
        printf("  %-12s %.3f s (%.0f %%): confirmations and fits\n", "the rest",
               best - searched, 100 * (best - searched) / best);
    }
    rb_case_free(&c);
    return 0;
}
