/* Synthetic motion benchmark: a suite of 7 motions matched to the AC156
 * required response spectrum for S_DS = 1.0 g on the roof (z/h = 1), 30 s
 * at 200 Hz, on one core: the wall time of the whole suite (best of the
 * repeats), and what each motion took to match. Usage: bench_synth
 * [SEED] [REPEATS] [Z_OVER_H]. Target: the suite under 0.5 s on one core. */
#include <stdio.h>
#include <stdlib.h>
#include "rockbolt/synth.h"
#include "bench_common.h"

#define SUITE 7

int main(int argc, char **argv)
{
    unsigned long long seed = argc > 1 ? strtoull(argv[1], NULL, 10) : 156;
    int reps = argc > 2 ? atoi(argv[2]) : 5;
    double zh = argc > 3 ? atof(argv[3]) : 1.0;
    rb_target t;
    rb_target_ac156(&t, RB_AC156_2010, 9.80665, zh);
    rb_synth_opts o;
    rb_synth_opts_init(&o, &t);
    o.seed = seed;
    double best = 1e30;
    unsigned passes[SUITE] = {0}, starts[SUITE] = {0};
    for (int r = 0; r < (reps > 0 ? reps : 1); r++) {
        double t0 = rb_bench_now_s();
        for (unsigned i = 0; i < SUITE; i++) {
            rb_series s;
            rb_synth_info info;
            o.index = i;
            rb_status st = rb_synth_generate(&o, &s, &info);
            if (st != RB_OK) {
                fprintf(stderr, "motion %u: %s\n", i + 1, rb_status_str(st));
                return 1;
            }
            passes[i] = info.iterations;
            starts[i] = info.attempts;
            rb_series_free(&s);
        }
        double dt = rb_bench_now_s() - t0;
        best = dt < best ? dt : best;
    }
    printf("synth: AC156 S_DS 1.0 g, z/h %g, seed %llu: %d motions of 30 s at 200 Hz\n", zh,
           seed, SUITE);
    printf("synth: passes (starts):");
    for (unsigned i = 0; i < SUITE; i++)
        printf(" %u (%u)", passes[i], starts[i]);
    printf("\nsynth: best of %d: %.3f s on one core (target 0.5 s: %s)\n", reps, best,
           best < 0.5 ? "met" : "NOT met");
    return 0;
}
