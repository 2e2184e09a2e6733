/* The elastic-plastic bolt of thesis sec. 5.7: a stiff spring (n E A / L,
 * 507 MN/m per row for the reference cabinet) that yields at Fy.
 *
 * What must hold whatever the thesis's claim about the two bolt models
 * (docs/solver.md): the energy balance closes in runs that yield, including
 * one that ends while a row yields; as the spring stiffens the response
 * tends to the rigid-plastic bolt's wherever no impact feeds the spring
 * (the plate starts on the bolts, gap 0, and the load rises slowly); and a
 * run whose bolts are engaged but stay below yield leaves no plastic work and
 * the gaps as they were. */
#include <math.h>
#include <stdio.h>
#include "harness.h"
#include "rockbolt/solve.h"

static rb_status run(double gap_ratio, double a_over_astar, double f_hz, double ramp_s,
                     double T, rb_bolt_model bolts, double e_factor, rb_result *r)
{
    rb_model m;
    rb_derived d;
    rb_motion mo;
    rb_solve_opts o;
    rb_model_reference(&m);
    m.gap_m = gap_ratio * m.lever_arm_m;
    m.bolt_model = bolts;
    m.elastic_modulus_pa = 200e9 * e_factor;
    rb_model_derive(&m, &d, NULL);
    rb_motion_init(&mo);
    mo.kind = RB_MOTION_HARMONIC;
    mo.amplitude_mps2 = a_over_astar * d.a_star_mps2;
    mo.freq_hz = f_hz;
    mo.ramp_s = ramp_s;
    mo.duration_s = T;
    rb_solve_opts_init(&o);
    o.stretch_past_failure = 1;
    return rb_solve_run(&m, &mo, &o, r, NULL);
}

static double imbalance(const rb_result *r)
{
    double out = r->e_kinetic + r->e_potential + r->e_strain + r->e_damping + r->e_impact
                 + r->e_plastic;
    return (r->e_input + r->e_coupling - out) / r->e_input;
}

/* tolerance: 1 % of the input work, as for the rigid-plastic bolt (issue
 * test 6). The second run ends with a row still yielding at the overturning
 * angle, where the spring's stored energy is Fy^2 / 2k and not the square of
 * the whole stretch. */
static void energy_balance(void)
{
    rb_result r;
    CHECK(run(0.01, 0.2, 4.0, 0, 3.0, RB_BOLT_ELASTIC_PLASTIC, 1, &r) == RB_OK);
    printf("gap 0.01, 0.2 A*, 4 Hz: usage %.3f/%.3f, %ld bolt impacts, imbalance %.2e\n",
           r.usage[0], r.usage[1], r.bolt_impacts, imbalance(&r));
    CHECK(r.yielded[0] || r.yielded[1]);
    CHECK(r.e_plastic > 0);
    CHECK_NEAR(imbalance(&r), 0, 0.01);
    rb_result_free(&r);

    CHECK(run(0, 1.2, 1.0, 1.0, 3.0, RB_BOLT_ELASTIC_PLASTIC, 1, &r) == RB_OK);
    printf("gap 0, 1.2 A*, 1 Hz: max theta/alpha %.4f, usage %.3f/%.3f, imbalance %.2e\n",
           r.max_theta_over_alpha, r.usage[0], r.usage[1], imbalance(&r));
    CHECK(r.yielded[0] || r.yielded[1]);
    CHECK_NEAR(imbalance(&r), 0, 0.01);
    rb_result_free(&r);
}

/* The spring's compliance is 1/k: its elastic rotation at Fy is Fy / (k l),
 * 1.6e-4 rad at the reference stiffness k0. With the plate starting on the
 * bolts and a slow (1 Hz, ramped) load, nothing else separates the two
 * models, so every difference must shrink as k grows, and at 100 k0 (elastic
 * rotation 1.6e-6 rad, 4e-6 alpha) be within the thesis's own resolution of
 * 1e-3 of the normalising quantity (sec. 5.7). Two loads: one that stays
 * below yield (bolt forces compared, in Fy) and one that yields (plastic work
 * compared, relative). */
static void stiff_spring_tends_to_rigid_plastic(void)
{
    static const double factors[3] = {1, 10, 100};
    rb_result rp, ep;
    double dprev = HUGE_VAL;

    CHECK(run(0, 0.8, 1.0, 1.0, 3.0, RB_BOLT_RIGID_PLASTIC, 1, &rp) == RB_OK);
    CHECK(!rp.yielded[0] && !rp.yielded[1] && rp.max_bolt_force_n[1] > 0);
    for (int i = 0; i < 3; i++) {
        CHECK(run(0, 0.8, 1.0, 1.0, 3.0, RB_BOLT_ELASTIC_PLASTIC, factors[i], &ep) == RB_OK);
        double d = 0;
        for (int row = 0; row < 2; row++)
            d = fmax(d, fabs(ep.max_bolt_force_n[row] - rp.max_bolt_force_n[row]) / rp.fy_row_n);
        d = fmax(d, fabs(ep.max_u_m - rp.max_u_m) / rp.max_u_m);
        printf("0.8 A*, k = %3g k0: max force %.5f/%.5f Fy (rigid-plastic %.5f/%.5f), "
               "difference %.2e\n", factors[i], ep.max_bolt_force_n[0] / ep.fy_row_n,
               ep.max_bolt_force_n[1] / ep.fy_row_n, rp.max_bolt_force_n[0] / rp.fy_row_n,
               rp.max_bolt_force_n[1] / rp.fy_row_n, d);
        CHECK(!ep.yielded[0] && !ep.yielded[1]);
        CHECK(d < dprev);
        dprev = d;
        rb_result_free(&ep);
    }
    CHECK_NEAR(dprev, 0, 1e-3);
    rb_result_free(&rp);

    dprev = HUGE_VAL;
    CHECK(run(0, 1.1, 1.0, 1.0, 3.0, RB_BOLT_RIGID_PLASTIC, 1, &rp) == RB_OK);
    CHECK(rp.yielded[1] && rp.absorbed_j[1] > 0);
    for (int i = 0; i < 3; i++) {
        CHECK(run(0, 1.1, 1.0, 1.0, 3.0, RB_BOLT_ELASTIC_PLASTIC, factors[i], &ep) == RB_OK);
        double d = 0;
        for (int row = 0; row < 2; row++)
            if (rp.absorbed_j[row] > 0)
                d = fmax(d, fabs(ep.absorbed_j[row] - rp.absorbed_j[row]) / rp.absorbed_j[row]);
        printf("1.1 A*, k = %3g k0: plastic work %.2f/%.2f J (rigid-plastic %.2f/%.2f), "
               "difference %.2e\n", factors[i], ep.absorbed_j[0], ep.absorbed_j[1],
               rp.absorbed_j[0], rp.absorbed_j[1], d);
        CHECK(d < dprev);
        dprev = d;
        rb_result_free(&ep);
    }
    CHECK_NEAR(dprev, 0, 1e-3);
    rb_result_free(&rp);
}

/* A small gap (1e-4 l) under a slow load: the plate lifts and meets the
 * bolts many times, but the force stays below Fy. Nothing may be absorbed and
 * the gaps must come back exactly as they were (only yielding moves them). */
static void below_yield_leaves_no_trace(void)
{
    rb_result r;
    double gap = 1e-4 * 0.78;
    CHECK(run(1e-4, 0.3, 1.0, 1.0, 3.0, RB_BOLT_ELASTIC_PLASTIC, 1, &r) == RB_OK);
    printf("gap 1e-4 l, 0.3 A*: %ld bolt impacts, max force %.3f/%.3f Fy, plastic %.3g J, "
           "final gaps %.9g/%.9g m\n", r.bolt_impacts, r.max_bolt_force_n[0] / r.fy_row_n,
           r.max_bolt_force_n[1] / r.fy_row_n, r.e_plastic, r.final_gap_m[0],
           r.final_gap_m[1]);
    CHECK(r.bolt_impacts > 0);
    CHECK(r.max_bolt_force_n[0] > 0 && r.max_bolt_force_n[1] > 0);
    CHECK(r.max_bolt_force_n[0] < r.fy_row_n && r.max_bolt_force_n[1] < r.fy_row_n);
    CHECK(!r.yielded[0] && !r.yielded[1]);
    CHECK(r.e_plastic == 0 && r.absorbed_j[0] == 0 && r.absorbed_j[1] == 0);
    CHECK(r.final_gap_m[0] == gap && r.final_gap_m[1] == gap);
    CHECK_NEAR(imbalance(&r), 0, 0.01);
    rb_result_free(&r);
}

int main(void)
{
    energy_balance();
    stiff_spring_tends_to_rigid_plastic();
    below_yield_leaves_no_trace();
    TEST_MAIN_END();
}
