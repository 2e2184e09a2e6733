/* The exact steps of the fixed base (docs/solver.md, "Exact steps on the
 * floor") against the Taylor steps they replace, over random cabinets:
 * the same run with rb_solve_opts.exact_floor on and off.
 *
 * - Runs that stay on the floor are linear, and the two must agree to
 *   the Taylor steps' own accuracy: peaks of U and of the total shear,
 *   the input and damping work, with the floor a record (linear between
 *   samples) or the record through a 5, 8, 10 or 30 Hz building. Against
 *   Taylor steps at 1e-13, the exact run at 1e-11 (whose few Taylor steps
 *   are then as fine) is within 1e-9, and at the default 1e-7 it is at
 *   least as close as the Taylor steps at 1e-7 are.
 * - Nearly every step of such a run is exact (the others are the first
 *   ones of each length, and where U' turns at a new peak).
 * - Runs that rock: the reference cabinet under El Centro at 0.4 A*,
 *   whose peak U and usage do not depend on the integrator (docs/solver.md
 *   table), agree to the tolerance.
 * - Plates held by rigid rows over random cabinets (held_cases): the
 *   exact run as close to Taylor steps at 1e-11 as Taylor steps at the
 *   same tolerance are, and with the same hops.
 * - A time history changes nothing in the run: the same bits with and
 *   without one, on the floor and rocking (with one, the end of every
 *   quiet exact step is read at once and each is a step of the run loop;
 *   without, a run of them is taken inside the stepper, quiet_run, and
 *   the end of its last step alone is read, rb_exact_settle). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "harness.h"
#include "elcentro_floor.h"
#include "rockbolt/solve.h"

static double rel(double a, double b)
{
    return a == b ? 0 : fabs(a - b) / fmax(fabs(a), fabs(b));
}

static unsigned long long rng_state = 20261124;
static double uniform(double lo, double hi)
{
    rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * (double)(rng_state >> 11) / 9007199254740992.0;
}

static rb_status solve(const rb_model *m, const rb_motion *mo, int exact, double rtol,
                       double history_dt, rb_result *r)
{
    rb_solve_opts o;
    rb_diag d;
    rb_solve_opts_init(&o);
    o.stretch_past_failure = 1;
    o.exact_floor = exact;
    o.rtol = rtol;
    o.history_dt_s = history_dt;
    rb_status st = rb_solve_run(m, mo, &o, r, &d);
    if (st != RB_OK)
        printf("  run failed: %s\n", d.msg);
    return st;
}

/* The floor s at a random polarity, its peak a random lo to hi of accel. */
static void sampled_motion(const rb_series *s, double lo, double hi, double accel,
                           double duration_s, rb_motion *mo)
{
    rb_motion_init(mo);
    mo->kind = RB_MOTION_SAMPLED;
    mo->series = s;
    mo->polarity = uniform(0, 1) < 0.5 ? 1 : -1;
    mo->scale = uniform(lo, hi) * accel / rb_series_peak(s);
    mo->duration_s = duration_s;
}

/* A random cabinet at a level below its uplift under the floor s. */
static void random_floor_run(const rb_series *s, rb_model *m, rb_motion *mo)
{
    rb_derived d;
    rb_model_reference(m);
    m->mass_kg = uniform(200, 900);
    m->freq_hz = uniform(3, 15);
    m->damping = uniform(0.01, 0.05);
    rb_model_derive(m, &d, NULL);
    /* a floor peak below the uplift acceleration keeps it on the floor
     * (the frame's amplification can still lift it: such runs are
     * skipped) */
    sampled_motion(s, 0.05, 0.4, d.a_uplift_mps2, s->dt_s * (double)(s->n - 1) + 2.0, mo);
}

/* worst[0..3]: max U, total shear, input and damping work */
static void note(double *worst, const rb_result *a, const rb_result *b)
{
    worst[0] = fmax(worst[0], rel(a->max_u_m, b->max_u_m));
    worst[1] = fmax(worst[1], rel(a->max_shear_total_n, b->max_shear_total_n));
    worst[2] = fmax(worst[2], rel(a->e_input, b->e_input));
    worst[3] = fmax(worst[3], rel(a->e_damping, b->e_damping));
}

/* The same bits in every peak, work and count a run on the floor
 * reports. */
static int same_run(const rb_result *a, const rb_result *b)
{
    return a->max_u_m == b->max_u_m && a->max_shear_total_n == b->max_shear_total_n
           && a->max_friction_demand == b->max_friction_demand
           && a->min_vertical_reaction_n == b->min_vertical_reaction_n
           && a->e_input == b->e_input && a->e_damping == b->e_damping
           && a->steps == b->steps && a->exact_steps == b->exact_steps
           && a->t_end_s == b->t_end_s;
}

static int floor_cases(const char *what, const rb_series *s, int n)
{
    double exact_fine[4] = {0}, exact_dflt[4] = {0}, taylor_dflt[4] = {0}, least_exact = 1;
    int runs = 0;
    for (int i = 0; i < n; i++) {
        rb_model m;
        rb_motion mo;
        rb_result a, b, c, t;
        random_floor_run(s, &m, &mo);
        if (solve(&m, &mo, 1, 1e-11, 0, &a) != RB_OK || solve(&m, &mo, 0, 1e-13, 0, &b) != RB_OK
            || solve(&m, &mo, 1, 1e-7, 0, &c) != RB_OK
            || solve(&m, &mo, 0, 1e-7, 0, &t) != RB_OK) {
            CHECK(0);
            continue;
        }
        if (a.uplifts || b.uplifts || c.uplifts || t.uplifts)
            continue;
        runs++;
        note(exact_fine, &a, &b);
        note(exact_dflt, &c, &b);
        note(taylor_dflt, &t, &b);
        least_exact = fmin(least_exact, (double)c.exact_steps / (double)c.steps);
        CHECK(b.exact_steps == 0 && t.exact_steps == 0);
        /* a time history reads every quiet step's end at once; without
         * one, a run of quiet steps is read at its last step alone
         * (rb_exact_settle): the same bits either way */
        rb_result hc;
        if (solve(&m, &mo, 1, 1e-7, 0.01, &hc) != RB_OK) {
            CHECK(0);
            continue;
        }
        CHECK(same_run(&c, &hc));
        rb_result_free(&hc);
    }
    printf("%s: %d runs on the floor, against Taylor steps at 1e-13 (max U, total shear, "
           "input work, damping work):\n"
           "  exact at 1e-11  %.1e %.1e %.1e %.1e\n"
           "  exact at 1e-7   %.1e %.1e %.1e %.1e\n"
           "  Taylor at 1e-7  %.1e %.1e %.1e %.1e\n"
           "  least share of exact steps %.3f\n", what, runs,
           exact_fine[0], exact_fine[1], exact_fine[2], exact_fine[3],
           exact_dflt[0], exact_dflt[1], exact_dflt[2], exact_dflt[3],
           taylor_dflt[0], taylor_dflt[1], taylor_dflt[2], taylor_dflt[3], least_exact);
    CHECK(runs >= n / 2);
    for (int k = 0; k < 4; k++) {
        /* the exact steps are exact to rounding: what is left is the
         * Taylor steps' they hand back, at 1e-11 (at 1e-11 the Taylor
         * steps alone are 1.3e-9 off through the 30 Hz building) */
        CHECK(exact_fine[k] <= 1e-9);
        /* and at the default tolerance at least as close as the Taylor
         * steps they replace */
        CHECK(exact_dflt[k] <= fmax(taylor_dflt[k], 1e-9));
    }
    CHECK(least_exact >= 0.9);
    return runs;
}

static void rocking_reference(const rb_series *s)
{
    rb_model m;
    rb_derived d;
    rb_motion mo;
    rb_result a, b, c;
    elcentro_run_setup(s, RB_BOLT_RIGID_PLASTIC, 0.4, 40.0, &m, &d, &mo);
    if (solve(&m, &mo, 1, 1e-7, 0, &a) != RB_OK || solve(&m, &mo, 0, 1e-7, 0, &b) != RB_OK
        || solve(&m, &mo, 1, 1e-7, 0.01, &c) != RB_OK) {
        CHECK(0);
        return;
    }
    printf("reference cabinet, El Centro 0.4 A*: max U/U_static %.9f / %.9f, usage "
           "%.9f / %.9f (exact / Taylor), %ld of %ld steps exact\n",
           a.max_u_over_ustatic, b.max_u_over_ustatic, a.usage[RB_RIGHT], b.usage[RB_RIGHT],
           a.exact_steps, a.steps);
    CHECK(a.uplifts > 0);
    CHECK(a.exact_steps > 0);
    CHECK(rel(a.max_u_over_ustatic, b.max_u_over_ustatic) <= 1e-6);
    CHECK(rel(a.usage[RB_RIGHT], b.usage[RB_RIGHT]) <= 1e-6);
    /* a time history reads the steps without changing them */
    CHECK(c.history != NULL && c.history->n > 3000);
    CHECK(same_run(&a, &c) && a.usage[RB_RIGHT] == c.usage[RB_RIGHT]
          && a.max_theta_rad == c.max_theta_rad && a.events == c.events);
    rb_result_free(&a);
    rb_result_free(&b);
    rb_result_free(&c);
}

/* A random cabinet held by rigid rows: a gap ratio of 0.002-0.03, bolts
 * of 10-16 mm, at 0.15-0.5 A* for 5 s (short enough that its hops do
 * not part ways with rounding). */
static void random_held_run(const rb_series *s, rb_model *m, rb_motion *mo)
{
    rb_derived d;
    rb_model_reference(m);
    m->bolt_model = RB_BOLT_RIGID_PLASTIC;
    m->mass_kg = uniform(200, 900);
    m->freq_hz = uniform(3, 15);
    double dia = uniform(0.010, 0.016);
    m->bolt_area_m2 = M_PI / 4 * dia * dia;
    m->gap_m = uniform(0.002, 0.03) * m->lever_arm_m;
    rb_model_derive(m, &d, NULL);
    sampled_motion(s, 0.15, 0.5, d.a_star_mps2, 5, mo);
}

/* worst[0..3]: max U, the larger row's usage and largest force, and the
 * largest shear, relative to the largest of the two runs */
static void note_held(double *worst, const rb_result *a, const rb_result *b)
{
    int r = a->usage[RB_LEFT] > a->usage[RB_RIGHT] ? RB_LEFT : RB_RIGHT;
    worst[0] = fmax(worst[0], rel(a->max_u_m, b->max_u_m));
    worst[1] = fmax(worst[1], rel(a->usage[r], b->usage[r]));
    worst[2] = fmax(worst[2], rel(a->max_bolt_force_n[r], b->max_bolt_force_n[r]));
    worst[3] = fmax(worst[3], rel(a->max_shear_total_n, b->max_shear_total_n));
}

/* Plates held by rigid rows (docs/solver.md, "Exact steps of a held
 * plate"): exact steps on against off, both against Taylor steps at
 * 1e-11, at 1e-9, where the rows' usages come from short stretches past
 * Fy and are the runs' most sensitive numbers. The exact run must be as
 * close as the Taylor run at the same tolerance (or within 1e-7), with
 * the same counts of hops and bolt impacts, and take exact held steps. */
static void held_cases(const rb_series *s, int n)
{
    double ex[4] = {0}, ty[4] = {0};
    int runs = 0, held = 0, same_counts = 0;
    for (int i = 0; i < n; i++) {
        rb_model m;
        rb_motion mo;
        rb_result a, b, t;
        random_held_run(s, &m, &mo);
        if (solve(&m, &mo, 1, 1e-9, 0, &a) != RB_OK || solve(&m, &mo, 0, 1e-9, 0, &t) != RB_OK
            || solve(&m, &mo, 0, 1e-11, 0, &b) != RB_OK) {
            CHECK(0);
            continue;
        }
        if (!b.bolt_impacts || b.overturned)
            continue;
        runs++;
        /* an exact step of stage 1 is one of the floor's steps */
        held += a.exact_steps > a.stage_steps[RB_STAGE_FIXED];
        same_counts += a.uplifts == t.uplifts && a.bolt_impacts == t.bolt_impacts;
        double e[4] = {0}, w[4] = {0};
        note_held(e, &a, &b);
        note_held(w, &t, &b);
        for (int k = 0; k < 4; k++) {
            ex[k] = fmax(ex[k], e[k]);
            ty[k] = fmax(ty[k], w[k]);
            if (!(e[k] <= fmax(3 * w[k], 1e-7))) {
                printf("  held case %d quantity %d: exact %.3g, Taylor %.3g off\n", i, k,
                       e[k], w[k]);
                CHECK(0);
            }
        }
    }
    printf("%d held runs (%d with exact held steps), against Taylor steps at 1e-11 "
           "(max U, usage, row force, shear):\n"
           "  exact at 1e-9   %.1e %.1e %.1e %.1e\n"
           "  Taylor at 1e-9  %.1e %.1e %.1e %.1e\n"
           "  the same hops and bolt impacts in %d\n", runs, held, ex[0], ex[1], ex[2], ex[3],
           ty[0], ty[1], ty[2], ty[3], same_counts);
    CHECK(runs >= n / 2);
    CHECK(held >= runs * 3 / 4);
    CHECK(same_counts >= runs * 9 / 10);
}

int main(void)
{
    rb_series raw, bld;
    rb_record_opts ro;
    rb_diag diag;
    rb_record_opts_init(&ro);
    if (rb_record_read("cases/records/elcentro_1940_ns.at2", &ro, &raw, &diag) != RB_OK) {
        fprintf(stderr, "cannot read the El Centro record: %s\n", diag.msg);
        return 1;
    }
    floor_cases("El Centro as the floor", &raw, 12);
    /* 30 Hz: a stiff building turns twice as far as the step's first
     * Gauss panel covers */
    static const double buildings[4] = {5, 8, 10, 30};
    for (int i = 0; i < 4; i++) {
        char what[64];
        if (rb_series_copy(&raw, &bld) != RB_OK
            || rb_series_building_filter(&bld, buildings[i], 0.05) != RB_OK) {
            CHECK(0);
            continue;
        }
        snprintf(what, sizeof what, "El Centro through a %g Hz building", buildings[i]);
        floor_cases(what, &bld, 12);
        if (i == 0) {
            rocking_reference(&bld);
            held_cases(&bld, 40);
        }
        rb_series_free(&bld);
    }
    rb_series_free(&raw);
    TEST_MAIN_END();
}
