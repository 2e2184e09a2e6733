/* The floor's share of the vertical reaction, which the friction demand
 * and the least vertical reaction are read from (the fixed-base case, where
 * it is W, is in test_solve_fixed). With no gap and bolts that never yield,
 * the cabinet is held by a loaded bolt row (stage 4) whose tension pulls
 * the plate onto the floor: the floor then presses with W plus that
 * tension, and the friction demand falls below the shear over W. */
#include <math.h>
#include <stdio.h>
#include "harness.h"
#include "elcentro_floor.h"
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

/* The floor reaction two ways over a record run: in closed form through
 * the mode's integrals, and summed over the frame's mass points (Newton's
 * law on each, with the frame's deflection). Each formulation and bolt
 * model, rocking hard enough to leave the floor. Also the lift-off record:
 * a least reaction at or below zero comes with a first time and a time
 * spent there, and none without. */
static void reactions_two_ways(const rb_series *s, rb_formulation form, rb_bolt_model bolts,
                               double level)
{
    rb_model m;
    rb_derived d;
    rb_motion mo;
    rb_solve_opts o;
    rb_result r;
    elcentro_run_setup(s, bolts, level, 15.0, &m, &d, &mo);
    rb_solve_opts_init(&o);
    o.formulation = form;
    o.stretch_past_failure = 1;
    o.check_reactions = 1;
    CHECK(rb_solve_run(&m, &mo, &o, &r, NULL) == RB_OK);
    printf("form %d bolts %d at %.2f A*: reaction mismatch %.3g W, least reaction %.4g W, "
           "lift-off first %.4f s for %.4f s, impact force %.4g Fy at %.3f s\n", form, bolts,
           level, r.reaction_mismatch_n / r.weight_n, r.min_vertical_reaction_n / r.weight_n,
           r.liftoff_first_s, r.liftoff_time_s, r.max_bolt_impact_n / r.fy_row_n,
           r.max_bolt_impact_s);
    CHECK(r.reaction_mismatch_n < 1e-6 * r.weight_n);
    if (r.min_vertical_reaction_n <= 0) {
        CHECK(r.liftoff_first_s >= 0 && r.liftoff_first_s <= r.t_end_s);
        CHECK(r.liftoff_time_s >= 0 && r.liftoff_time_s <= r.t_end_s);
    } else {
        CHECK(r.liftoff_first_s < 0);
        CHECK(r.liftoff_time_s == 0);
    }
    /* the friction demand is read only where the floor presses with more
     * than 5 % of W, so it is bounded by |H| / (0.05 W) */
    CHECK(r.max_friction_demand <= r.max_shear_total_n / (RB_FRICTION_FLOOR * r.weight_n)
                                   * (1 + 1e-9));
    if (bolts == RB_BOLT_ELASTIC_PLASTIC)
        CHECK(r.max_bolt_impact_n == 0);
    else if (r.bolt_impacts > 0)
        CHECK(r.max_bolt_impact_n > 0 && r.max_bolt_impact_s > 0);
    rb_result_free(&r);
}

static void record_runs(void)
{
    rb_series s;
    CHECK(elcentro_floor(&s) == 0);
    static const rb_formulation forms[] = {RB_FORM_LARGE, RB_FORM_SMALL, RB_FORM_CONSISTENT};
    for (int f = 0; f < 3; f++)
        reactions_two_ways(&s, forms[f], RB_BOLT_RIGID_PLASTIC, 0.4);
    reactions_two_ways(&s, RB_FORM_LARGE, RB_BOLT_NONYIELDING, 0.1);
    reactions_two_ways(&s, RB_FORM_LARGE, RB_BOLT_ELASTIC_PLASTIC, 0.3);
    reactions_two_ways(&s, RB_FORM_LARGE, RB_BOLT_RIGID_PLASTIC, 0.02);
    rb_series_free(&s);
}

int main(void)
{
    held_by_bolts();
    record_runs();
    TEST_MAIN_END();
}
