/* The bounds over a step that let an exact step on the floor skip its
 * check points (docs/solver.md, "Bounds over a step"). A bound that is
 * short of the quantity it bounds would let an uplift pass unseen inside
 * a step, and a case would pass that should not: each bound must hold at
 * every instant of the step.
 *
 * Over random cabinets (both formulations that step exactly), buildings
 * (none, or 0.5-60 Hz at 0-50 % damping), step lengths (0.5-40 ms) and
 * start states, the bounds of U, of the total shear and of both uplift
 * guards are held against the quantities at 4001 instants of the step,
 * computed here from the physics of the floor stage (5.3c and the
 * moment equation at theta = 0; the total shear -M x'' + N* U'') over
 * states from the system's exponential at each instant, not from the
 * rows the step reads. The bounds are also held to be of use: within a
 * few times the largest value the instants show, on median. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "floor_step_draw.h"

static unsigned long long rng_state = 20261127;

enum { K = 4000, CASES = 400 };

int main(void)
{
    rb_series raw = {0};
    if (!floor_draw_record(&raw)) {
        CHECK(0);
        TEST_MAIN_END();
    }
    static double z_at[K + 1][RB_EXACT_DIM];
    double ratio[CASES][4];
    int n_ratio = 0, probed = 0;
    double worst = 0;
    for (int c = 0; c < CASES; c++) {
        floor_draw f;
        if (!floor_draw_case(c, &raw, &rng_state, &f)) {
            CHECK(0);
            break;
        }
        double h = exp(draw_uniform(&rng_state, log(5e-4), log(0.04)));
        double z0[RB_EXACT_DIM];
        floor_draw_state(&rng_state, z0);
        double bound[4];
        if (!rb_exact_probe(&f.m, &f.mo, &f.o, h, z0, K, bound, z_at)) {
            rb_series_free(&f.s);
            continue;
        }
        probed++;
        int small = f.o.formulation == RB_FORM_SMALL;
        /* the uplift moment's floor lever at theta = 0 (the weight's
         * moment, W b or W R alpha, is the part the bound leaves out) */
        double lever = small ? f.m.mass_kg * f.d.R : f.m.mass_kg * f.m.cm_height_m;
        double most[4] = {0};
        for (int k = 0; k <= K; k++) {
            const double *z = z_at[k];
            double x, udd;
            floor_draw_accels(&f, z, &x, &udd);
            double q[4] = {z[0], -f.m.mass_kg * x + f.d.Nstar * udd,
                           lever * x - f.d.Fstar * udd, -lever * x + f.d.Fstar * udd};
            for (int i = 0; i < 4; i++) {
                most[i] = fmax(most[i], fabs(q[i]));
                /* relative to the bound, beyond the state's rounding */
                double scale = fabs(q[i]) + 1e-12 * bound[i] + 1e-300;
                double over = (fabs(q[i]) - bound[i]) / scale;
                if (over > 1e-9) {
                    if (rb_test_failures < 5)
                        printf("case %d quantity %d at tau %.6g of %.6g: %.17g over the bound "
                               "%.17g\n", c, i, h * k / K, h, fabs(q[i]), bound[i]);
                    CHECK(0);
                }
                worst = fmax(worst, fabs(q[i]) / (bound[i] + 1e-300));
                (void)over;
            }
        }
        for (int i = 0; i < 4; i++)
            ratio[n_ratio][i] = most[i] > 0 ? bound[i] / most[i] : 1;
        n_ratio++;
        rb_series_free(&f.s);
    }
    rb_series_free(&raw);
    printf("%d of %d random steps bounded; the largest ratio of a quantity to its bound: "
           "%.9f (at most 1 + 1e-9 allowed)\n", probed, CASES, worst);
    CHECK(probed >= CASES * 9 / 10);
    static const char *names[4] = {"U", "total shear", "uplift guard +", "uplift guard -"};
    for (int i = 0; i < 4 && n_ratio; i++) {
        double r[CASES];
        for (int k = 0; k < n_ratio; k++)
            r[k] = ratio[k][i];
        qsort(r, (size_t)n_ratio, sizeof *r, draw_cmp);
        printf("  %-15s bound over the largest value sampled: median %.3f, 90th percentile %.3f\n",
               names[i], r[n_ratio / 2], r[n_ratio * 9 / 10]);
        CHECK(r[n_ratio / 2] >= 1 && r[n_ratio / 2] < 3);
    }
    TEST_MAIN_END();
}
