/* The floor's share of the vertical reaction, which the friction demand
 * and the least vertical reaction are read from (the fixed-base case, where
 * it is W, is in test_solve_fixed). With no gap and bolts that never yield,
 * the cabinet is held by a loaded bolt row (stage 4) whose tension pulls
 * the plate onto the floor: the floor then presses with W plus that
 * tension, and the friction demand falls below the shear over W. */
#include <math.h>
#include <stdio.h>
#include "harness.h"
#include "rockbolt/solve.h"

static void held_by_bolts(void)
{
    rb_model m;
    rb_motion mo;
    rb_solve_opts o;
    rb_result r;
    rb_model_reference(&m);
    m.gap_m = 0;
    m.bolt_model = RB_BOLT_NONYIELDING;
    rb_motion_init(&mo);
    mo.kind = RB_MOTION_HARMONIC;
    mo.amplitude_mps2 = 0.5 * RB_G0;
    mo.freq_hz = 4.0;
    mo.duration_s = 3.0;
    rb_solve_opts_init(&o);
    CHECK(rb_solve_run(&m, &mo, &o, &r, NULL) == RB_OK);
    double force = fmax(r.max_bolt_force_n[0], r.max_bolt_force_n[1]);
    printf("held: uplifts %ld, bolt force %.4g W, stage-4 time %.3f s, least vertical "
           "reaction %.6g W, friction demand %.6g, shear %.6g W\n", r.uplifts,
           force / r.weight_n, r.stage_time_s[RB_STAGE_HELD],
           r.min_vertical_reaction_n / r.weight_n, r.max_friction_demand,
           r.max_shear_total_n / r.weight_n);
    CHECK(r.uplifts > 0 && r.stage_time_s[RB_STAGE_HELD] > 0.5);
    CHECK(r.max_theta_rad == 0);
    /* theta stays 0, so floor and bolt together carry W: the floor's share
     * is W plus the tension, never less than W */
    CHECK(r.min_vertical_reaction_n >= r.weight_n * (1 - 1e-12));
    /* the peak shear comes while a bolt row is loaded; had the tension been
     * left out of the floor's reaction the demand would equal the shear
     * over W (as on the fixed base) */
    CHECK(force > 0.5 * r.weight_n);
    CHECK(r.max_friction_demand < 0.99 * r.max_shear_total_n / r.weight_n);
    rb_result_free(&r);
}

int main(void)
{
    held_by_bolts();
    TEST_MAIN_END();
}
