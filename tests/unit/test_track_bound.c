/* The bounds a rocking Taylor step's tracking is skipped by
 * (src/core/track_bound.c, rb_track_step_bounds): |U|, |theta|, the total
 * shear and the least floor reaction over the whole step, from the step's
 * own series. A bound that a reading inside the step passed would let a
 * step that moves a peak (or dips to the friction floor) go untracked, so
 * every bound is held against dense sampling of the same step: random
 * cabinets (both formulations, with and without a vertical floor motion),
 * random stage-2 states and step lengths, the quantities read at 2 001
 * instants as the tracking reads them at a check point (the series'
 * values, rb_taylor_aux, rb_dyn_reactions). The bounds must also be
 * useful: on median within a few times the largest change sampled. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "harness.h"
#include "rockbolt/solve.h"
#include "../../src/core/solver.h"

static uint64_t rng = 0x9E3779B97F4A7C15ULL;

static double uniform(double lo, double hi)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return lo + (hi - lo) * (double)(rng >> 11) / 9007199254740992.0;
}

static int by_value(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

#define TRIALS 400
#define SAMPLES 2000

int main(void)
{
    int steps = 0, over[4] = {0, 0, 0, 0};
    double closest[4] = {0, 0, 0, 0}, slack_h[TRIALS], slack_v[TRIALS];
    for (int trial = 0; trial < TRIALS; trial++) {
        rb_model m;
        rb_model_reference(&m);
        m.mass_kg = uniform(100, 3000);
        m.freq_hz = uniform(2, 30);
        m.half_width_m *= uniform(0.5, 1.5);
        m.cm_height_m *= uniform(0.6, 1.6);
        m.lever_arm_m = m.half_width_m * uniform(1.1, 1.9);
        rb_motion mo, vert;
        rb_motion_init(&mo);
        mo.kind = RB_MOTION_HARMONIC;
        mo.freq_hz = uniform(0.5, 15);
        mo.amplitude_mps2 = uniform(1, 20);
        mo.duration_s = 10;
        if (trial % 3 == 2) {
            rb_motion_init(&vert);
            vert.kind = RB_MOTION_HARMONIC;
            vert.freq_hz = uniform(1, 20);
            vert.amplitude_mps2 = uniform(0.5, 5);
            vert.duration_s = 10;
            mo.vertical = &vert;
        }
        rb_solve_opts o;
        rb_solve_opts_init(&o);
        o.formulation = trial % 2 ? RB_FORM_SMALL : RB_FORM_LARGE;
        static rb_solver sv;
        rb_result r;
        rb_diag diag;
        if (rb_solver_setup(&sv, &m, &mo, &o, &r, &diag) != RB_OK) {
            printf("setup: %s\n", diag.msg);
            continue;
        }
        sv.disc.stage = RB_STAGE_UPLIFT;
        sv.disc.side = trial % 4 < 2 ? 1 : -1;
        double alpha = sv.sys.d.alpha, side = sv.disc.side;
        double y0[RB_NY] = {0};
        y0[RB_Y_U] = uniform(-1, 1) * 1e-3 * 9.81 / pow(2 * M_PI * m.freq_hz, 2);
        y0[RB_Y_UD] = uniform(-1, 1) * y0[RB_Y_U] * 2 * M_PI * m.freq_hz;
        y0[RB_Y_TH] = side * uniform(0, 0.5) * alpha;
        y0[RB_Y_THD] = uniform(-1, 1) * 0.5 * sqrt(alpha);
        /* steps of up to a radian of the fastest of the frame, the floor
         * and the vertical, as the check spacing keeps them (a longer
         * step's reach grows as e^(omega h)) */
        double f_max = fmax(m.freq_hz, fmax(mo.freq_hz, mo.vertical ? vert.freq_hz : 0));
        double t0 = uniform(0, 5), h_want = uniform(0.05, 1) / (2 * M_PI * f_max), atol[RB_NY];
        for (int i = 0; i < RB_NY; i++)
            atol[i] = sv.atol[i];
        rb_taylor ts;
        double h = rb_taylor_step(&sv.sys, &sv.disc, t0, y0, h_want, atol, sv.atol_x,
                                  o.rtol, &ts);
        if (!(h > 0)) {
            printf("no step\n");
            continue;
        }
        rb_track_bounds b;
        CHECK(rb_track_step_bounds(&sv, &ts, h, &b));
        double seen[4] = {0, 0, 0, HUGE_VAL}, H0 = 0, V0 = 0, move_h = 0, move_v = 0;
        for (int i = 0; i <= SAMPLES; i++) {
            double v[RB_TS_CHECK], y[RB_NY] = {0}, H, V;
            rb_aux a;
            rb_taylor_check(&ts, i == SAMPLES ? h : h * i / SAMPLES, v);
            memcpy(y, v, 4 * sizeof *y);
            rb_taylor_aux(&sv.sys, &sv.disc, &ts, v, &a);
            rb_dyn_reactions(&sv.sys, &sv.disc, y, &a, &H, &V);
            if (i == 0) {
                H0 = H;
                V0 = V;
            }
            move_h = fmax(move_h, fabs(H - H0));
            move_v = fmax(move_v, fabs(V - V0));
            seen[0] = fmax(seen[0], fabs(y[RB_Y_U]));
            seen[1] = fmax(seen[1], fabs(y[RB_Y_TH]));
            seen[2] = fmax(seen[2], fabs(H));
            seen[3] = fmin(seen[3], V);
        }
        double bound[4] = {b.u, b.theta, b.shear, b.floor_lo};
        for (int q = 0; q < 3; q++) {
            over[q] += seen[q] > bound[q];
            closest[q] = fmax(closest[q], seen[q] / bound[q]);
        }
        over[3] += seen[3] < bound[3];
        closest[3] = fmax(closest[3], (V0 - seen[3]) / fmax(V0 - bound[3], DBL_MIN));
        /* how far the bounds reach from the step's start against how far
         * the sampled readings moved from it */
        slack_h[steps] = (b.shear - fabs(H0)) / fmax(move_h, 1e-9 * b.shear);
        slack_v[steps] = (V0 - b.floor_lo) / fmax(move_v, 1e-9 * fabs(V0));
        steps++;
    }
    qsort(slack_h, (size_t)steps, sizeof *slack_h, by_value);
    qsort(slack_v, (size_t)steps, sizeof *slack_v, by_value);
    printf("%d random stage-2 steps, %d readings each: bounds passed %d (U), %d (theta), "
           "%d (shear), %d (least reaction); closest approach %.6f %.6f %.6f %.6f of the "
           "bound; median reach over the sampled change: shear %.2f, reaction %.2f\n",
           steps, SAMPLES + 1, over[0], over[1], over[2], over[3], closest[0], closest[1],
           closest[2], closest[3], slack_h[steps / 2], slack_v[steps / 2]);
    CHECK(steps > TRIALS * 3 / 4);
    for (int q = 0; q < 4; q++) {
        CHECK(over[q] == 0);
        CHECK(closest[q] <= 1);
    }
    /* useful, not only safe: the bounds stay within a few times the
     * change the step makes */
    CHECK(slack_h[steps / 2] < 4);
    CHECK(slack_v[steps / 2] < 4);
    TEST_MAIN_END();
}
