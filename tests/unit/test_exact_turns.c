/* The peaks an exact step on the floor locates between its check points
 * (docs/solver.md, "Peaks on the step's own polynomial"): the total
 * shear's turns found by Newton on the step's polynomial in the step's
 * fraction. A turn missed or misplaced would leave a run's peak shear,
 * friction demand or anchorage demand low, on the side a check must not
 * err on.
 *
 * Over random cabinets (both formulations that step exactly), buildings
 * (none, or 0.5-60 Hz at 0-50 % damping), step lengths (0.5-40 ms, or
 * 0.2-1.5 rad of the fastest oscillation) and
 * start states, the largest |shear| over 2001 instants of the step,
 * computed here from the physics of the floor stage (the total shear
 * -M x'' + N* U'', 5.3c) over states from the system's exponential at
 * each instant, is held to be no more than the largest of the step's
 * ends and its located turns, the shear at each turn taken from the
 * exponential at that instant too (not from the step's polynomial). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "floor_step_draw.h"

static unsigned long long rng_state = 20261128;

enum { K = 2000, CASES = 400 };

static double shear_of(const floor_draw *f, const double *z)
{
    double x, udd;
    floor_draw_accels(f, z, &x, &udd);
    return fabs(-f->m.mass_kg * x + f->d.Nstar * udd);
}

int main(void)
{
    rb_series raw = {0};
    if (!floor_draw_record(&raw)) {
        CHECK(0);
        TEST_MAIN_END();
    }
    static double z_at[K + 1][RB_EXACT_DIM];
    int probed = 0, turned = 0, inside = 0;
    double worst = 0;
    for (int c = 0; c < CASES; c++) {
        floor_draw f;
        if (!floor_draw_case(c, &raw, &rng_state, &f)) {
            CHECK(0);
            break;
        }
        /* half of them from 0.2 to 1.5 rad of the fastest oscillation,
         * where a step's shear most often turns inside it */
        double wf = fmax(2 * M_PI * f.m.freq_hz, f.wb);
        double h = c % 2 ? exp(draw_uniform(&rng_state, log(5e-4), log(0.04)))
                         : exp(draw_uniform(&rng_state, log(0.2), log(1.5))) / wf;
        double z0[RB_EXACT_DIM];
        floor_draw_state(&rng_state, z0);
        double bound[4], tau[8], zt[8][RB_EXACT_DIM];
        int n = rb_exact_probe_turns(&f.m, &f.mo, &f.o, h, z0, tau, zt);
        if (n < 0 || !rb_exact_probe(&f.m, &f.mo, &f.o, h, z0, K, bound, z_at)) {
            rb_series_free(&f.s);
            continue;
        }
        probed++;
        turned += n > 0;
        double most = 0, located = fmax(shear_of(&f, z_at[0]), shear_of(&f, z_at[K]));
        for (int k = 0; k <= K; k++)
            most = fmax(most, shear_of(&f, z_at[k]));
        for (int k = 0; k < n; k++) {
            CHECK(tau[k] > 0 && tau[k] < h);
            located = fmax(located, shear_of(&f, zt[k]));
        }
        /* the largest instant's shear beyond the located peak, relative to
         * it, past the states' rounding */
        double over = (most - located) / (located + 1e-300);
        worst = fmax(worst, over);
        if (over > 1e-9) {
            if (rb_test_failures < 5)
                printf("case %d (h %.4g, %d turns): the instants reach %.17g, the located "
                       "peak %.17g\n", c, h, n, most, located);
            CHECK(0);
        }
        inside += located > fmax(shear_of(&f, z_at[0]), shear_of(&f, z_at[K]));
        rb_series_free(&f.s);
    }
    rb_series_free(&raw);
    printf("%d of %d random steps with a polynomial, %d with turns, %d peaking inside; the "
           "instants above the located peak by at most %.3g (1e-9 allowed)\n",
           probed, CASES, turned, inside, worst);
    CHECK(probed >= CASES / 2);
    CHECK(inside >= probed / 10);
    TEST_MAIN_END();
}
