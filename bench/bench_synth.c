/* Synthetic motion benchmark: a suite of 7 triaxial sets (H1, H2, V)
 * matched to the AC156 required response spectra for S_DS = 1.0 g on the
 * roof (z/h = 1), 30 s at 200 Hz, on one core: the wall time of the whole
 * suite (best of the repeats), and what each component took to match.
 * Usage: bench_synth [SEED] [REPEATS] [Z_OVER_H]. Target: the suite under
 * 1.5 s on one core. */
#include <stdio.h>
#include <stdlib.h>
#include "rockbolt/synth.h"
#include "bench_common.h"

#define SUITE 21   /* 7 sets of 3 */

int main(int argc, char **argv)
{
    unsigned long long seed = argc > 1 ? strtoull(argv[1], NULL, 10) : 156;
    int reps = argc > 2 ? atoi(argv[2]) : 5;
    double zh = argc > 3 ? atof(argv[3]) : 1.0;
    rb_target t, tv;
    rb_target_ac156(&t, RB_AC156_2010, 9.80665, zh);
    rb_target_ac156_vertical(&tv, 9.80665);
    rb_synth_opts o;
    double best = 1e30;
    unsigned passes[SUITE] = {0}, starts[SUITE] = {0};
    for (int r = 0; r < (reps > 0 ? reps : 1); r++) {
        double t0 = rb_bench_now_s();
        for (unsigned i = 0; i < SUITE; i++) {
            rb_series s;
            rb_synth_info info;
            unsigned comp = i % 3;
            rb_synth_opts_init(&o, comp == RB_SYNTH_V ? &tv : &t);
            o.seed = seed;
            o.index = i / 3 + comp * RB_SYNTH_COMPONENT_STREAM;
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
    printf("synth: AC156 S_DS 1.0 g, z/h %g, seed %llu: %d sets of 3 motions of 30 s at "
           "200 Hz\n", zh, seed, SUITE / 3);
    printf("synth: passes (starts):");
    for (unsigned i = 0; i < SUITE; i++)
        printf(" %u (%u)", passes[i], starts[i]);
    printf("\nsynth: best of %d: %.3f s on one core (target 1.5 s: %s)\n", reps, best,
           best < 1.5 ? "met" : "NOT met");
    return 0;
}
