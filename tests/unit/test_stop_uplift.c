/* A run stopped at a limit state's first crossing (rb_solve_opts.stop_at)
 * and the uplift level of one held run (rb_design_uplift_level), on random
 * cabinets of the stress runs under Taft (docs/fragility.md, "Fewer
 * runs").
 *
 * - A run that never reaches the state is the full run, bit for bit; one
 *   that does reaches it as the full run does (a yield, a force at Fy, a
 *   reaction at or below zero) and ends no later, and no earlier than the
 *   full run first reached it: the verdict on that state is the full run's.
 * - The uplift level is checked against the real solver's uplift: the
 *   cabinet with its own gap and bolts does not lift its base a millionth
 *   below that level, and does a millionth above it. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "harness.h"
#include "rockbolt/design.h"
#include "stress_cabinet.h"
#include "util/rng.h"

static int reaches(const rb_result *r, unsigned stop)
{
    if (stop == RB_STOP_FIRST_YIELD)
        return r->yielded[0] || r->yielded[1]
               || fmax(r->max_bolt_force_n[0], r->max_bolt_force_n[1]) >= r->fy_row_n;
    return r->min_vertical_reaction_n <= 0;
}

/* when the full run first reached the state (its first yield, its first
 * lift-off; 0 when only the force reached Fy, whose time is not kept) */
static double first_reached(const rb_result *r, unsigned stop)
{
    if (stop == RB_STOP_LIFT_OFF)
        return r->liftoff_first_s;
    double t = HUGE_VAL;
    for (int row = 0; row < 2; row++)
        if (r->yielded[row])
            t = fmin(t, r->first_yield_s[row]);
    return isfinite(t) ? t : 0;
}

static void stop_case(const rb_model *m, const rb_motion *mo, unsigned stop, int *n_reached)
{
    rb_solve_opts o;
    rb_result full, cut;
    rb_solve_opts_init(&o);
    o.stretch_past_failure = 1;
    CHECK(rb_solve_run(m, mo, &o, &full, NULL) == RB_OK);
    o.stop_at = stop;
    CHECK(rb_solve_run(m, mo, &o, &cut, NULL) == RB_OK);
    CHECK(reaches(&cut, stop) == reaches(&full, stop));
    if (!reaches(&full, stop)) {
        CHECK(!memcmp(&cut, &full, sizeof cut));
        return;
    }
    ++*n_reached;
    CHECK(cut.t_end_s <= full.t_end_s);
    CHECK(cut.t_end_s >= first_reached(&full, stop));
    CHECK(cut.steps <= full.steps);
}

int main(void)
{
    rb_series taft = {0};
    if (taft_record(&taft) != 0)
        return 1;
    rb_rng rng;
    rb_rng_seed(&rng, 41);
    int yields = 0, lifts = 0, uplift_checked = 0;
    for (int i = 0; i < 12; i++) {
        stress_cabinet c = {300 + 900 * rb_rng_uniform(&rng), 3 + 7 * rb_rng_uniform(&rng),
                            (0.5 + rb_rng_uniform(&rng)) * 1.267e-4,
                            (0.002 + 0.02 * rb_rng_uniform(&rng)) * 0.78,
                            pow(10, -3 + 3 * rb_rng_uniform(&rng)), 8.0};
        rb_model m;
        rb_derived d;
        rb_motion mo;
        if (stress_cabinet_setup(&c, &taft, &m, &d, &mo) != 0)
            continue;
        stop_case(&m, &mo, RB_STOP_FIRST_YIELD, &yields);
        stop_case(&m, &mo, RB_STOP_LIFT_OFF, &lifts);

        /* the held run at 0.3 A*, where every one of these cabinets lifts */
        double up = 0;
        rb_solve_opts o;
        rb_solve_opts_init(&o);
        mo.scale = 0.3 * d.a_star_mps2 / rb_series_peak(&taft);
        CHECK(rb_design_uplift_level(&m, &mo, &o, NULL, &up, NULL) == RB_OK);
        if (!(up > 0))
            continue;
        uplift_checked++;
        rb_result below, above;
        rb_motion mb = mo, ma = mo;
        double peak = rb_motion_peak(&mo);
        mb.scale = mo.scale * up * (1 - 1e-6) / peak;
        ma.scale = mo.scale * up * (1 + 1e-6) / peak;
        CHECK(rb_solve_run(&m, &mb, &o, &below, NULL) == RB_OK);
        CHECK(rb_solve_run(&m, &ma, &o, &above, NULL) == RB_OK);
        CHECK(below.uplifts == 0);
        CHECK(above.uplifts > 0);
    }
    /* the random levels reach each state some of the time, and lift some */
    printf("reached: first yield %d, lift-off %d of 12; uplift levels checked %d\n", yields,
           lifts, uplift_checked);
    CHECK(yields > 0 && yields < 12);
    CHECK(lifts > 0 && lifts < 12);
    CHECK(uplift_checked == 12);
    rb_series_free(&taft);
    TEST_MAIN_END();
}
