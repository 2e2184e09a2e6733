/* Guards between the check points of a rocking Taylor step: two turns of
 * theta' inside one check interval (docs/solver.md, "Taylor series").
 *
 * A random cabinet under Taft through a 6.7 Hz building, at 0.28 A*: at
 * 2.1228 s a floor impact leaves theta' at 1.3e-3 rad/s, the plate hops
 * 2e-7 rad for 1.3 ms and lands, and the floor lifts it on the far side.
 * The step's series, run on past the landing, is carried back across by
 * that same floor motion, so that with both ends of a check interval on
 * the far side the landing was unseen where a step has two check points,
 * and the run went on rocking on the wrong edge (7 uplifts and 139 floor
 * impacts in 5 s became 5 and 127). A bound on |theta''| over the step
 * tells which intervals could hold two turns; there the interval is
 * halved until its turns show.
 *
 * The run with 2, 3, 4 and 16 check points a step and with Dormand-Prince
 * at 1e-11 has the same uplifts, floor and bolt impacts, and the same
 * peaks of U and theta to 1e-6.
 *
 * In stage 5, theta' is itself the guard that ends a row's yielding. A
 * random cabinet (small formulation, rigid-plastic rows) under a
 * rectangular pulse yields, stops and yields again every 45 ms; at
 * 0.2767 s theta' touches zero and comes back within 0.3 ms, inside one
 * check interval. The search found the sign change between the two turns
 * and read the guards at the turns alone, where theta' is zero, on the
 * guard's boundary, so the row went on yielding through the dip and gave
 * back part of its stretch: its usage came out 6.355843 against
 * Dormand-Prince's 6.356243 at every tolerance from 1e-9 to 1e-13, and the
 * other row's 0.0068589 against 0.0068334. The guards are now read
 * between the turns as well. */
#include <math.h>
#include <stdio.h>
#include "harness.h"
#include "stress_cabinet.h"

static int run(const rb_series *s, int min_checks, rb_integrator integ, double rtol,
               rb_result *r)
{
    static const stress_cabinet c = {825.93154907226562, 9.7127823829650879,
                                     0.00012716710834022934, 0.040883229287624355,
                                     0.28002117872238158, 5.0};
    rb_model m;
    rb_derived d;
    rb_motion mo;
    rb_solve_opts o;
    if (stress_cabinet_setup(&c, s, &m, &d, &mo) != 0)
        return 0;
    rb_solve_opts_init(&o);
    o.stretch_past_failure = 1;
    o.min_checks = min_checks;
    o.integrator = integ;
    o.rtol = rtol;
    return rb_solve_run(&m, &mo, &o, r, NULL) == RB_OK;
}

/* The pulse cabinet of stage 5 at a tolerance, with an integrator. */
static int pulse_run(rb_integrator integ, double rtol, rb_result *r)
{
    static const stress_cabinet c = {695.33435106277466, 8.3479313850402832,
                                     8.8105437973833576e-05, 0.012790230319976805,
                                     0.84587353467941284, 1.0};
    rb_model m;
    rb_derived d;
    rb_motion mo;
    rb_solve_opts o;
    if (stress_cabinet_model(&c, &m, &d) != 0)
        return 0;
    rb_motion_init(&mo);
    mo.kind = RB_MOTION_PULSE;
    mo.pulse = RB_PULSE_RECT;
    mo.pulse_s = 0.51036021113395691;
    mo.amplitude_mps2 = c.level * d.a_star_mps2;
    mo.duration_s = c.duration_s;
    rb_solve_opts_init(&o);
    o.stretch_past_failure = 1;
    o.formulation = RB_FORM_SMALL;
    o.integrator = integ;
    o.rtol = rtol;
    return rb_solve_run(&m, &mo, &o, r, NULL) == RB_OK;
}

/* A row that stops yielding for 0.3 ms inside one check interval. */
static void yield_dip(void)
{
    rb_result ref, r;
    int ok = pulse_run(RB_INTEGRATOR_RK45, 1e-12, &ref);
    CHECK(ok);
    static const double tols[] = {1e-7, 1e-9, 1e-11};
    for (int i = 0; ok && i < 3; i++) {
        if (!pulse_run(RB_INTEGRATOR_AUTO, tols[i], &r)) {
            CHECK(0);
            continue;
        }
        printf("pulse, rtol %g: usages %.10g / %.10g, %ld events; Dormand-Prince at 1e-12 "
               "%.10g / %.10g, %ld events\n", tols[i], r.usage[0], r.usage[1], r.events,
               ref.usage[0], ref.usage[1], ref.events);
        CHECK(r.events == ref.events);
        CHECK_REL(r.usage[0], ref.usage[0], i == 0 ? 1e-6 : 1e-8);
        CHECK_REL(r.usage[1], ref.usage[1], i == 0 ? 1e-7 : 1e-8);
        rb_result_free(&r);
    }
    if (ok)
        CHECK(ref.usage[0] > 0.005 && ref.usage[1] > 5);
    rb_result_free(&ref);
}

int main(void)
{
    rb_series s = {0};
    if (taft_record(&s) != 0)
        return 1;
    if (rb_series_building_filter(&s, 6.6534668803215027, 0.05) != RB_OK) {
        rb_series_free(&s);
        return 1;
    }
    rb_result ref;
    CHECK(run(&s, 4, RB_INTEGRATOR_RK45, 1e-11, &ref));
    printf("Dormand-Prince at 1e-11: %ld uplifts, %ld floor impacts, %ld bolt impacts, "
           "max U/U_static %.10g\n", ref.uplifts, ref.floor_impacts, ref.bolt_impacts,
           ref.max_u_over_ustatic);
    static const int checks[] = {2, 3, 4, 16};
    for (int i = 0; i < 4; i++) {
        rb_result r;
        if (!run(&s, checks[i], RB_INTEGRATOR_AUTO, 1e-7, &r)) {
            CHECK(0);
            continue;
        }
        printf("%2d check points a step: %ld uplifts, %ld floor impacts, %ld bolt impacts, "
               "max U/U_static %.10g, max theta/alpha %.10g\n", checks[i], r.uplifts,
               r.floor_impacts, r.bolt_impacts, r.max_u_over_ustatic, r.max_theta_over_alpha);
        CHECK(r.uplifts == ref.uplifts);
        CHECK(r.floor_impacts == ref.floor_impacts);
        CHECK(r.bolt_impacts == ref.bolt_impacts);
        CHECK_REL(r.max_u_over_ustatic, ref.max_u_over_ustatic, 1e-6);
        CHECK_REL(r.max_theta_over_alpha, ref.max_theta_over_alpha, 1e-6);
        rb_result_free(&r);
    }
    rb_result_free(&ref);
    rb_series_free(&s);
    yield_dip();
    TEST_MAIN_END();
}
