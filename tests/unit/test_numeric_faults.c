/* Numerical faults of the solver (issue #7): a NaN or infinity in the
 * excitation or in the equations stops the run with RB_ERR_NONFINITE and a
 * message naming the time and the stage; a run that would exceed its work
 * bounds stops with a status that says so; options the integrator cannot
 * honour are refused; extreme but valid models run in bounded work. In no
 * case does a result carry a NaN. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>
#include "harness.h"
#include "rockbolt/solve.h"

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Every number a caller reads from a result. */
static int result_finite(const rb_result *r)
{
    const double v[] = {
        r->a_star_mps2, r->a_uplift_mps2, r->peak_floor_mps2, r->u_static_m, r->alpha_rad,
        r->fy_row_n, r->capacity_j, r->weight_n, r->delta, r->max_theta_rad,
        r->max_theta_over_alpha, r->max_u_m, r->max_u_over_ustatic, r->max_shear_elastic_n,
        r->max_shear_total_n, r->max_friction_demand, r->max_bolt_force_n[0],
        r->max_bolt_force_n[1], r->final_gap_m[0], r->final_gap_m[1], r->absorbed_j[0],
        r->absorbed_j[1], r->usage[0], r->usage[1], r->first_yield_s[0], r->first_yield_s[1],
        r->break_s[0], r->break_s[1], r->overturn_s, r->t_end_s, r->stage_time_s[1],
        r->stage_time_s[2], r->stage_time_s[4], r->stage_time_s[5], r->e_input,
        r->e_kinetic, r->e_potential, r->e_strain, r->e_damping, r->e_impact, r->e_plastic,
        r->e_coupling,
    };
    for (size_t i = 0; i < sizeof v / sizeof v[0]; i++)
        if (!isfinite(v[i]))
            return 0;
    return 1;
}

/* The diag names the time and the stage: "... at t = <s> s in stage <n>". */
static int names_time_and_stage(const rb_diag *d, double *t, int *stage)
{
    const char *p = strstr(d->msg, "at t = ");
    return p && sscanf(p, "at t = %lf s in stage %d", t, stage) == 2;
}

static void reference_under(rb_motion *mo, double a_over_astar, double T)
{
    rb_model m;
    rb_derived d;
    rb_model_reference(&m);
    rb_model_derive(&m, &d, NULL);
    rb_motion_init(mo);
    mo->kind = RB_MOTION_HARMONIC;
    mo->amplitude_mps2 = a_over_astar * d.a_star_mps2;
    mo->freq_hz = 4.0;
    mo->duration_s = T;
}

/* A record with one bad sample: the run stops where the floor acceleration
 * first reads it (the interpolation over the interval that ends there), not
 * with numbers computed from it. */
static void bad_sample(double bad)
{
    rb_model m;
    rb_derived d;
    rb_series s;
    rb_motion mo;
    rb_result r;
    rb_diag dg = {0};
    rb_model_reference(&m);
    rb_model_derive(&m, &d, NULL);
    CHECK(rb_series_alloc(&s, 401, 0.01) == RB_OK);
    for (size_t i = 0; i < s.n; i++)
        s.accel_mps2[i] = 0.4 * d.a_star_mps2 * sin(2 * M_PI * 4.0 * 0.01 * (double)i);
    s.accel_mps2[250] = bad; /* t = 2.5 s, after the cabinet has started rocking */
    rb_motion_init(&mo);
    mo.kind = RB_MOTION_SAMPLED;
    mo.series = &s;
    mo.duration_s = 4.0;
    rb_solve_opts o;
    rb_solve_opts_init(&o);
    o.stretch_past_failure = 1;
    rb_status st = rb_solve_run(&m, &mo, &o, &r, &dg);
    double t = -1;
    int stage = 0;
    printf("sample %g at 2.5 s: %s: %s\n", bad, rb_status_str(st), dg.msg);
    CHECK(st == RB_ERR_NONFINITE);
    CHECK(strstr(dg.msg, "floor acceleration") != NULL);
    CHECK(names_time_and_stage(&dg, &t, &stage));
    /* the sample's interval starts at 2.49 s; the run may stop anywhere on it */
    CHECK(t >= 2.49 - 1e-9 && t <= 2.5 + 1e-9);
    CHECK(stage >= 1 && stage <= 5 && stage != 3);
    CHECK(result_finite(&r));
    rb_result_free(&r);
    rb_series_free(&s);
}

/* A mass so large that the products in the 2x2 solve overflow: the model
 * itself is valid, the equations are not computable. */
static void overflowing_model(void)
{
    rb_model m;
    rb_motion mo;
    rb_result r;
    rb_diag dg = {0};
    reference_under(&mo, 0.4, 2.0);
    rb_model_reference(&m);
    m.mass_kg = 1e300;
    rb_status st = rb_solve_run(&m, &mo, NULL, &r, &dg);
    printf("mass 1e300: %s: %s\n", rb_status_str(st), dg.msg);
    CHECK(st == RB_ERR_NONFINITE || st == RB_ERR_INVALID);
    CHECK(dg.msg[0] != 0);
    if (st == RB_ERR_NONFINITE) {
        double t;
        int stage;
        CHECK(names_time_and_stage(&dg, &t, &stage));
    }
    CHECK(result_finite(&r));
    rb_result_free(&r);
}

/* Work bounds: a rocking run with too small an event budget or step budget
 * ends with the status that names the bound, at the time it was reached. */
static void work_bounds(void)
{
    rb_model m;
    rb_motion mo;
    rb_solve_opts o;
    rb_result r;
    rb_diag dg = {0};
    double t;
    int stage;
    rb_model_reference(&m);
    reference_under(&mo, 0.4, 3.0);
    rb_solve_opts_init(&o);
    o.stretch_past_failure = 1;
    o.max_events_per_s = 5;
    rb_status st = rb_solve_run(&m, &mo, &o, &r, &dg);
    printf("5 events/s: %s: %s\n", rb_status_str(st), dg.msg);
    CHECK(st == RB_ERR_WORK_LIMIT);
    CHECK(names_time_and_stage(&dg, &t, &stage));
    CHECK(t < 3.0 && r.t_end_s < 3.0);
    CHECK(result_finite(&r));
    rb_result_free(&r);

    rb_solve_opts_init(&o);
    o.max_steps = 50;
    rb_diag_clear(&dg);
    st = rb_solve_run(&m, &mo, &o, &r, &dg);
    printf("50 steps: %s: %s\n", rb_status_str(st), dg.msg);
    CHECK(st == RB_ERR_LIMIT);
    CHECK(r.steps == 50);
    CHECK(names_time_and_stage(&dg, &t, &stage));
    CHECK(result_finite(&r));
    rb_result_free(&r);
}

/* Tolerances the integrator cannot meet, and options that would make the run
 * unbounded, are refused before any work, naming the option. */
static void refused_options(void)
{
    rb_model m;
    rb_motion mo;
    rb_solve_opts o;
    rb_result r;
    rb_diag dg = {0};
    rb_model_reference(&m);
    reference_under(&mo, 0.4, 1.0);
    const double rtols[] = {1e-16, 0, -1e-6, NAN, 0.5};
    for (size_t i = 0; i < sizeof rtols / sizeof rtols[0]; i++) {
        rb_solve_opts_init(&o);
        o.rtol = rtols[i];
        rb_diag_clear(&dg);
        CHECK(rb_solve_run(&m, &mo, &o, &r, &dg) == RB_ERR_INVALID);
        CHECK(strcmp(dg.key, "rtol") == 0);
        CHECK(r.steps == 0);
        rb_result_free(&r);
    }
    rb_solve_opts_init(&o);
    o.max_events_per_s = 0;
    rb_diag_clear(&dg);
    CHECK(rb_solve_run(&m, &mo, &o, &r, &dg) == RB_ERR_INVALID);
    CHECK(strcmp(dg.key, "max_events_per_s") == 0);
    rb_result_free(&r);
    mo.duration_s = HUGE_VAL;
    rb_diag_clear(&dg);
    CHECK(rb_solve_run(&m, &mo, NULL, &r, &dg) == RB_ERR_INVALID);
    rb_result_free(&r);
    mo.duration_s = 1.0;
    mo.amplitude_mps2 = NAN;
    rb_diag_clear(&dg);
    CHECK(rb_solve_run(&m, &mo, NULL, &r, &dg) == RB_ERR_INVALID);
    CHECK(result_finite(&r));
    rb_result_free(&r);
}

/* Extreme but valid parameters on the reference cabinet, under the
 * reference's 0.4 A* at 4 Hz for 10 s with bolts stretching on (so the whole
 * 10 s runs): each either runs to the end with finite results or is refused
 * with the limit named. The work bound asserted is 200 steps per period of
 * the fastest motion the model has (the frame, the stage-2 coupled mode at
 * most 3 times the frame frequency for this geometry, or the excitation):
 * a smooth run at the default tolerance needs 20 to 40. */
static void extreme_parameters(void)
{
    static const char *what[] = {"gap ratio 1e-9", "frequency 1000 Hz", "damping 0.999",
                                 "mass 1e9 kg", "frequency 1001 Hz", "damping 1"};
    rb_derived dref;
    rb_model ref;
    rb_model_reference(&ref);
    rb_model_derive(&ref, &dref, NULL);
    for (int c = 0; c < 6; c++) {
        rb_model m;
        rb_motion mo;
        rb_solve_opts o;
        rb_result r;
        rb_diag dg = {0};
        rb_model_reference(&m);
        switch (c) {
        case 0: m.gap_m = 1e-9 * m.lever_arm_m; break;
        case 1: m.freq_hz = 1000; break;
        case 2: m.damping = 0.999; break;
        case 3: m.mass_kg = 1e9; break;
        case 4: m.freq_hz = 1001; break;
        case 5: m.damping = 1; break;
        }
        reference_under(&mo, 0.4, 10.0);
        rb_solve_opts_init(&o);
        o.stretch_past_failure = 1;
        double t0 = now_s();
        rb_status st = rb_solve_run(&m, &mo, &o, &r, &dg);
        double dt = now_s() - t0;
        printf("%s: %s in %.3f s, %ld steps, %ld events, t_end %.2f s%s%s\n", what[c],
               rb_status_str(st), dt, r.steps, r.events, r.t_end_s, dg.msg[0] ? ": " : "",
               dg.msg);
        if (c >= 4) {
            /* beyond the documented limits: refused, naming the field */
            CHECK(st == RB_ERR_INVALID);
            CHECK(strcmp(dg.key, c == 4 ? "frequency" : "damping") == 0);
        } else {
            CHECK(st == RB_OK);
            CHECK(r.t_end_s == 10.0);
            CHECK(result_finite(&r));
            double f = fmax(3 * m.freq_hz, mo.freq_hz);
            CHECK(r.steps <= (long)(200 * f * 10.0));
            CHECK(r.events <= o.max_events_per_s * 10);
            /* a loose wall-clock bound (sanitizer builds and loaded machines
             * included); the counters above are the real measure */
            CHECK(dt < 60.0);
        }
        rb_result_free(&r);
    }
}

int main(void)
{
    bad_sample(NAN);
    bad_sample(HUGE_VAL);
    overflowing_model();
    work_bounds();
    refused_options();
    extreme_parameters();
    TEST_MAIN_END();
}
