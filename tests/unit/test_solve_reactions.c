/* The floor's reactions on the base, which the friction demand and the
 * least vertical reaction are read from. On a fixed base (stage 1) the
 * floor carries the weight and nothing more vertically, so the least
 * vertical reaction is W and the friction demand is the total shear over W.
 * With no gap and bolts that never yield, the cabinet is held by a loaded
 * bolt row (stage 4) whose tension pulls the plate onto the floor: the
 * floor then presses with W plus that tension, and the friction demand
 * falls below the shear over W. */
#include <math.h>
#include <stdio.h>
#include "harness.h"
#include "rockbolt/solve.h"

static void fixed_base(void)
{
    rb_model m;
    rb_motion mo;
    rb_solve_opts o;
    rb_result r;
    rb_model_reference(&m);
    rb_motion_init(&mo);
    mo.kind = RB_MOTION_HARMONIC;
    mo.amplitude_mps2 = 0.05 * RB_G0;
    mo.freq_hz = 3.0;
    mo.duration_s = 4.0;
    rb_solve_opts_init(&o);
    CHECK(rb_solve_run(&m, &mo, &o, &r, NULL) == RB_OK);
    CHECK(r.uplifts == 0);
    printf("fixed base: least vertical reaction %.15g W, friction demand %.10g, "
           "shear %.10g W\n", r.min_vertical_reaction_n / r.weight_n, r.max_friction_demand,
           r.max_shear_total_n / r.weight_n);
    /* the vertical reaction is W exactly in stage 1 (theta = 0): 1e-12
     * leaves room for rounding only */
    CHECK_REL(r.min_vertical_reaction_n, r.weight_n, 1e-12);
    /* the same samples and parabola vertices, scaled by 1 / W */
    CHECK_REL(r.max_friction_demand, r.max_shear_total_n / r.weight_n, 1e-12);
    rb_result_free(&r);
}

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
     * over W (as on the fixed base above) */
    CHECK(force > 0.5 * r.weight_n);
    CHECK(r.max_friction_demand < 0.99 * r.max_shear_total_n / r.weight_n);
    rb_result_free(&r);
}

int main(void)
{
    fixed_base();
    held_by_bolts();
    TEST_MAIN_END();
}
