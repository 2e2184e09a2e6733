/* The floor's vertical acceleration z''(t) (rb_motion.vertical), which
 * enters every gravity term as g + z''.
 *
 * 1. A constant vertical c is a run under gravity g + c: every response
 *    number agrees with the run whose model has gravity_mps2 = g + c, in
 *    all three formulations, with rigid-plastic and elastic-plastic rows,
 *    over random cabinets. The potential is gravity's at the static g and
 *    the vertical's work is booked with the input, so of the energies
 *    input - potential compares (both move by -c H), and the balance
 *    closes.
 * 2. The uplift threshold of a rigid block under a constant horizontal
 *    pulse and a harmonic vertical: uplift where M h x'' = M (g + z'') b
 *    (small formulation: x'' = (g + z'') alpha), the instant solved in
 *    closed form here; a run that stops just before it has not lifted, one
 *    that stops just after it has.
 * 3. Taylor series against Dormand-Prince with a vertical present (harmonic
 *    and sampled), and the energy balance with the vertical's work.
 * 4. The vertical floor reaction of a rigid cabinet that stays down under
 *    a harmonic vertical, M (g + z''), against its least in closed form.
 * 5. A floor that falls faster than gravity is refused. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "harness.h"
#include "thesis_block.h"
#include "rockbolt/solve.h"

static double rel(double a, double b)
{
    return a == b ? 0 : fabs(a - b) / fmax(fabs(a), fabs(b));
}

/* a small deterministic generator: the cases are the same on every run */
static unsigned long long rng_state = 0x9e3779b97f4a7c15ULL;
static double uniform(double lo, double hi)
{
    rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * (double)(rng_state >> 11) / 9007199254740992.0;
}

static void random_cabinet(rb_model *m, rb_bolt_model bolts)
{
    rb_model_reference(m);
    m->mass_kg = uniform(200, 800);
    m->cm_height_m = uniform(0.6, 1.2);
    m->half_width_m = uniform(0.3, 0.5);
    m->freq_hz = uniform(4, 12);
    m->damping = uniform(0.01, 0.05);
    m->lever_arm_m = 2 * m->half_width_m * uniform(0.8, 0.95);
    m->gap_m = m->lever_arm_m * uniform(0.002, 0.02);
    m->bolt_model = bolts;
}

static rb_status run(const rb_model *m, const rb_motion *mo, rb_formulation f,
                     rb_integrator integ, rb_result *r)
{
    rb_solve_opts o;
    rb_diag d;
    rb_solve_opts_init(&o);
    o.formulation = f;
    o.integrator = integ;
    o.rtol = 1e-9;
    o.stretch_past_failure = 1;
    rb_status st = rb_solve_run(m, mo, &o, r, &d);
    if (st != RB_OK)
        printf("  run failed: %s\n", d.msg);
    return st;
}

/* The response numbers a report reads, a against b, to tol relative (of
 * the larger, or of scale where both are near zero). */
static int compare(const rb_result *a, const rb_result *b, double tol, double force_scale,
                   double energy_scale)
{
    int bad = 0;
#define SAME(x, scale) do { double d_ = fabs(a->x - b->x); \
        if (!(d_ <= tol * fmax(fmax(fabs(a->x), fabs(b->x)), scale))) { bad++; \
            printf("    %-26s %.12g vs %.12g (rel %.2e)\n", #x, a->x, b->x, \
                   rel(a->x, b->x)); } } while (0)
    SAME(max_theta_rad, 1e-6);
    SAME(max_u_m, 1e-9);
    SAME(max_shear_elastic_n, force_scale);
    SAME(max_shear_total_n, force_scale);
    SAME(max_friction_demand, 1e-3);
    SAME(min_vertical_reaction_n, force_scale);
    SAME(max_bolt_force_n[0], force_scale);
    SAME(max_bolt_force_n[1], force_scale);
    SAME(usage[0], 1e-6);
    SAME(usage[1], 1e-6);
    SAME(absorbed_j[0], energy_scale);
    SAME(absorbed_j[1], energy_scale);
    SAME(final_gap_m[0], 1e-9);
    SAME(final_gap_m[1], 1e-9);
    SAME(max_bolt_impact_n, force_scale);
    SAME(stage_time_s[1], 1e-6);
    SAME(stage_time_s[2], 1e-6);
    SAME(stage_time_s[4], 1e-6);
    SAME(stage_time_s[5], 1e-6);
    SAME(e_kinetic, energy_scale);
    SAME(e_strain, energy_scale);
    SAME(e_damping, energy_scale);
    SAME(e_impact, energy_scale);
    SAME(e_plastic, energy_scale);
    SAME(e_coupling, energy_scale);
#undef SAME
    /* a vertical c books -c H in the input and leaves c H out of the
     * potential, H the height function of g H: their difference is the
     * run's under gravity g + c */
    double sa = a->e_input - a->e_potential, sb = b->e_input - b->e_potential;
    if (!(fabs(sa - sb) <= tol * fmax(fmax(fabs(sa), fabs(sb)), energy_scale))) {
        bad++;
        printf("    input - potential          %.12g vs %.12g\n", sa, sb);
    }
    if (a->overturned != b->overturned || a->yielded[0] != b->yielded[0]
        || a->yielded[1] != b->yielded[1] || a->uplifts != b->uplifts
        || a->floor_impacts != b->floor_impacts || a->bolt_impacts != b->bolt_impacts) {
        bad++;
        printf("    counts: overturned %d/%d yielded %d%d/%d%d uplifts %ld/%ld floor "
               "impacts %ld/%ld bolt impacts %ld/%ld\n", a->overturned, b->overturned,
               a->yielded[0], a->yielded[1], b->yielded[0], b->yielded[1], a->uplifts,
               b->uplifts, a->floor_impacts, b->floor_impacts, a->bolt_impacts,
               b->bolt_impacts);
    }
    return bad;
}

static double balance(const rb_result *r)
{
    double out = r->e_kinetic + r->e_potential + r->e_strain + r->e_damping + r->e_impact
                 + r->e_plastic;
    return (r->e_input + r->e_coupling - out) / fmax(fabs(r->e_input), 1e-9);
}

/* ---- 1. a constant vertical is a change of gravity ---------------------- */

static void constant_is_gravity(void)
{
    static const rb_formulation forms[] = {RB_FORM_LARGE, RB_FORM_SMALL, RB_FORM_CONSISTENT};
    static const char *const form_names[] = {"large", "small", "consistent"};
    static const rb_bolt_model bolts[] = {RB_BOLT_RIGID_PLASTIC, RB_BOLT_ELASTIC_PLASTIC};
    printf("1. constant z'' = c against gravity g + c\n");
    for (int i = 0; i < 4; i++) {
        for (int b = 0; b < 2; b++) {
            rb_model m, mg;
            rb_derived d;
            random_cabinet(&m, bolts[b]);
            double c = uniform(-0.35, 0.35) * RB_G0;
            CHECK(rb_model_derive(&m, &d, NULL) == RB_OK);
            /* enough shaking to lift, hit the rows and (often) yield them */
            double a = uniform(1.3, 3.0) * d.a_uplift_mps2 * (RB_G0 + c) / RB_G0;
            mg = m;
            mg.gravity_mps2 = RB_G0 + c;
            rb_motion h, v, h0;
            rb_motion_init(&h);
            h.kind = RB_MOTION_HARMONIC;
            h.amplitude_mps2 = a;
            h.freq_hz = uniform(1.5, 4);
            h.ramp_s = 0.5;
            h.duration_s = 3;
            h0 = h;
            /* the constant as a rectangular pulse longer than the run */
            rb_motion_init(&v);
            v.kind = RB_MOTION_PULSE;
            v.pulse = RB_PULSE_RECT;
            v.amplitude_mps2 = c;
            v.pulse_s = 10;
            h.vertical = &v;
            for (int f = 0; f < 3; f++) {
                rb_result rv, rg;
                if (run(&m, &h, forms[f], RB_INTEGRATOR_AUTO, &rv) != RB_OK
                    || run(&mg, &h0, forms[f], RB_INTEGRATOR_AUTO, &rg) != RB_OK) {
                    CHECK(0);
                    continue;
                }
                double W = m.mass_kg * RB_G0;
                printf("  case %d %s %-10s c = %+.3f g, a = %.3f g: theta %.5f/%.5f, "
                       "usage %.4f/%.4f, uplifts %ld, balance %.1e\n", i,
                       b ? "elastic-plastic" : "rigid-plastic", form_names[f], c / RB_G0,
                       a / RB_G0, rv.max_theta_rad, rg.max_theta_rad,
                       fmax(rv.usage[0], rv.usage[1]), fmax(rg.usage[0], rg.usage[1]),
                       rv.uplifts, balance(&rv));
                CHECK(rv.uplifts > 0);
                /* 2e-5: the two runs take different steps (the step bound
                 * and the rest test read the static weight), each at
                 * rtol 1e-9 */
                CHECK(compare(&rv, &rg, 2e-5, 1e-3 * W, 1e-6 * W * m.cm_height_m) == 0);
                CHECK_NEAR(balance(&rv), 0, f == RB_FORM_CONSISTENT ? 1e-5 : 1e-6);
                rb_result_free(&rv);
                rb_result_free(&rg);
            }
        }
    }
}

/* ---- 2. the uplift threshold ---------------------------------------------- */

/* First instant after 0 at which a rigid block under the constant
 * horizontal a and z'' = Z sin(w t) lifts: a = (g + z'') k, k = b / h
 * (alpha / 1 in the small formulation's moment M R x'' = W R alpha),
 * i.e. sin(w t) = (a / k - g) / Z, on the falling side of the sine when
 * a is below the static threshold g k. */
static double uplift_instant(double a, double k, double Z, double w)
{
    double s = (a / k - RB_G0) / Z; /* in (-1, 0) */
    return (M_PI - asin(s)) / w;
}

static void uplift_threshold(void)
{
    printf("2. uplift threshold of a rigid block under a harmonic vertical\n");
    static const rb_formulation forms[] = {RB_FORM_LARGE, RB_FORM_SMALL, RB_FORM_CONSISTENT};
    for (int f = 0; f < 3; f++)
        for (int integ = 0; integ < 2; integ++) {
            rb_model m;
            rb_derived d;
            thesis_block_model(&m);
            CHECK(rb_model_derive(&m, &d, NULL) == RB_OK);
            double k = forms[f] == RB_FORM_SMALL ? d.alpha : m.half_width_m / m.cm_height_m;
            double a = 0.8 * RB_G0 * k, Z = 0.5 * RB_G0, w = 2 * M_PI * 3.0;
            double t_up = uplift_instant(a, k, Z, w);
            for (int side = 0; side < 2; side++) {
                double dt = side ? 1e-6 : -1e-6;
                rb_motion h, v;
                rb_result r;
                rb_motion_init(&h);
                h.kind = RB_MOTION_PULSE;
                h.pulse = RB_PULSE_RECT;
                h.amplitude_mps2 = a;
                h.pulse_s = 10;
                h.duration_s = t_up + dt;
                rb_motion_init(&v);
                v.kind = RB_MOTION_HARMONIC;
                v.amplitude_mps2 = Z;
                v.freq_hz = 3.0;
                h.vertical = &v;
                CHECK(run(&m, &h, forms[f], integ ? RB_INTEGRATOR_RK45 : RB_INTEGRATOR_AUTO,
                          &r) == RB_OK);
                printf("  form %d %s: closed-form uplift at %.7f s; run to %+.0e s of it: "
                       "%ld uplift(s)\n", f, integ ? "rk45" : "auto", t_up, dt, r.uplifts);
                CHECK(r.uplifts == (side ? 1 : 0));
                rb_result_free(&r);
            }
            /* and without the vertical the block never lifts at 0.8 of its
             * static threshold */
            rb_motion h;
            rb_result r;
            rb_motion_init(&h);
            h.kind = RB_MOTION_PULSE;
            h.pulse = RB_PULSE_RECT;
            h.amplitude_mps2 = a;
            h.pulse_s = 10;
            h.duration_s = 1;
            CHECK(run(&m, &h, forms[f], RB_INTEGRATOR_AUTO, &r) == RB_OK);
            CHECK(r.uplifts == 0);
            rb_result_free(&r);
        }
}

/* ---- 3. Taylor against Dormand-Prince with a vertical --------------------- */

static void taylor_vs_rk45(void)
{
    printf("3. Taylor series against Dormand-Prince with a vertical\n");
    static const rb_formulation forms[] = {RB_FORM_LARGE, RB_FORM_SMALL};
    static const rb_bolt_model bolts[] = {RB_BOLT_RIGID_PLASTIC, RB_BOLT_ELASTIC_PLASTIC};
    /* a sampled vertical: a decaying 7 Hz sine at 200 samples a second */
    rb_series s;
    CHECK(rb_series_alloc(&s, 801, 0.005) == RB_OK);
    for (size_t i = 0; i < s.n; i++) {
        double t = (double)i * s.dt_s;
        s.accel_mps2[i] = 0.4 * RB_G0 * exp(-0.3 * t) * sin(2 * M_PI * 7 * t);
    }
    for (int kind = 0; kind < 2; kind++)
        for (int f = 0; f < 2; f++)
            for (int b = 0; b < 2; b++) {
                rb_model m;
                rb_derived d;
                rb_model_reference(&m);
                m.bolt_model = bolts[b];
                CHECK(rb_model_derive(&m, &d, NULL) == RB_OK);
                rb_motion h, v;
                rb_motion_init(&h);
                h.kind = RB_MOTION_HARMONIC;
                h.amplitude_mps2 = 0.5 * d.a_star_mps2;
                h.freq_hz = 2.5;
                h.ramp_s = 0.4;
                h.duration_s = 3;
                rb_motion_init(&v);
                if (kind == 0) {
                    v.kind = RB_MOTION_HARMONIC;
                    v.amplitude_mps2 = 0.5 * RB_G0;
                    v.freq_hz = 4.3;
                } else {
                    v.kind = RB_MOTION_SAMPLED;
                    v.series = &s;
                    v.polarity = -1;
                }
                h.vertical = &v;
                rb_result ra, rr;
                if (run(&m, &h, forms[f], RB_INTEGRATOR_AUTO, &ra) != RB_OK
                    || run(&m, &h, forms[f], RB_INTEGRATOR_RK45, &rr) != RB_OK) {
                    CHECK(0);
                    continue;
                }
                double W = m.mass_kg * RB_G0;
                printf("  %s vertical, %s, %s: theta %.6f/%.6f, usage %.5f/%.5f, "
                       "steps %ld/%ld, balance %.1e/%.1e\n", kind ? "sampled" : "harmonic",
                       f ? "small" : "large", b ? "elastic-plastic" : "rigid-plastic",
                       ra.max_theta_rad, rr.max_theta_rad, fmax(ra.usage[0], ra.usage[1]),
                       fmax(rr.usage[0], rr.usage[1]), ra.steps, rr.steps, balance(&ra),
                       balance(&rr));
                CHECK(ra.bolt_impacts > 0);
                /* the Taylor path really ran (far fewer steps) */
                CHECK(ra.steps < rr.steps);
                CHECK(compare(&ra, &rr, 2e-5, 1e-3 * W, 1e-6 * W * m.cm_height_m) == 0);
                CHECK_NEAR(balance(&ra), 0, 1e-6);
                CHECK_NEAR(balance(&rr), 0, 1e-6);
                rb_result_free(&ra);
                rb_result_free(&rr);
            }
    rb_series_free(&s);
}

/* ---- 4. the floor's vertical reaction ------------------------------------- */

/* A rigid cabinet that stays on the floor carries M (g + z''): the least
 * vertical reaction under a harmonic vertical Z is M (g - Z), located
 * between check points; the friction floor is 5 % of that least weight. */
static void reaction_at_rest(void)
{
    printf("4. vertical reaction of a cabinet that stays down\n");
    for (int integ = 0; integ < 2; integ++) {
        rb_model m;
        rb_model_reference(&m);
        m.rigid = 1;
        rb_motion h, v;
        rb_motion_init(&h);
        h.kind = RB_MOTION_HARMONIC;
        h.amplitude_mps2 = 0.05 * RB_G0;
        h.freq_hz = 1.3;
        h.duration_s = 2;
        rb_motion_init(&v);
        v.kind = RB_MOTION_HARMONIC;
        v.amplitude_mps2 = 0.6 * RB_G0;
        v.freq_hz = 7.7;
        h.vertical = &v;
        rb_result r;
        CHECK(run(&m, &h, RB_FORM_LARGE, integ ? RB_INTEGRATOR_RK45 : RB_INTEGRATOR_AUTO,
                  &r) == RB_OK);
        double want = m.mass_kg * (RB_G0 - v.amplitude_mps2);
        printf("  %s: least vertical reaction %.9g N, M (g - Z) = %.9g N; uplifts %ld\n",
               integ ? "rk45" : "auto", r.min_vertical_reaction_n, want, r.uplifts);
        CHECK(r.uplifts == 0);
        CHECK_REL(r.min_vertical_reaction_n, want, 1e-7);
        /* the horizontal reaction is M x'' alone, so the friction demand
         * is largest where the vertical is least: M a / (M (g - Z)) at
         * most, and at least the demand at the horizontal's peak */
        CHECK(r.max_friction_demand <= h.amplitude_mps2 / (RB_G0 - v.amplitude_mps2) + 1e-9);
        CHECK(r.max_friction_demand >= h.amplitude_mps2 / (RB_G0 + v.amplitude_mps2));
        rb_result_free(&r);
    }
}

/* ---- 5. a floor that falls faster than gravity ---------------------------- */

static void refused(void)
{
    printf("5. z'' below -g is refused\n");
    rb_model m;
    rb_model_reference(&m);
    rb_motion h, v;
    rb_motion_init(&h);
    h.kind = RB_MOTION_HARMONIC;
    h.amplitude_mps2 = 1;
    h.freq_hz = 2;
    h.duration_s = 1;
    rb_motion_init(&v);
    v.kind = RB_MOTION_HARMONIC;
    v.amplitude_mps2 = 1.01 * RB_G0;
    v.freq_hz = 5;
    h.vertical = &v;
    rb_solve_opts o;
    rb_solve_opts_init(&o);
    rb_result r;
    rb_diag d;
    CHECK(rb_solve_run(&m, &h, &o, &r, &d) == RB_ERR_INVALID);
    CHECK(strcmp(d.key, "vertical") == 0);
    printf("  %s: %s\n", d.key, d.msg);
    rb_result_free(&r);
    /* an upward pulse of any size is fine; a downward one of 1 g is not */
    v.kind = RB_MOTION_PULSE;
    v.pulse = RB_PULSE_HALF_SINE;
    v.pulse_s = 0.1;
    v.amplitude_mps2 = 2 * RB_G0;
    CHECK(rb_solve_run(&m, &h, &o, &r, &d) == RB_OK);
    rb_result_free(&r);
    v.polarity = -1;
    v.amplitude_mps2 = RB_G0;
    CHECK(rb_solve_run(&m, &h, &o, &r, &d) == RB_ERR_INVALID);
    rb_result_free(&r);
}

int main(void)
{
    constant_is_gravity();
    uplift_threshold();
    taylor_vs_rk45();
    reaction_at_rest();
    refused();
    TEST_MAIN_END();
}
