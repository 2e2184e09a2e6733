/* The Taylor step's series against the equations of motion themselves.
 *
 * rb_taylor_step forms the series of U, U', theta, theta', the floor and
 * the three work integrals by recurrences (src/core/taylor.c), one pass
 * over the products per order. A series that solves the equations has, at
 * every instant of the step, the derivative rb_dyn_rhs gives at the state
 * it reads there (rb_dyn_rhs reads the floor from its closed form, the
 * building's exact response, and forms every load anew from cos and sin
 * of the angle: nothing of the recurrences). Over random cabinets (rigid
 * and with a frame, both bolt models, both formulations), random states
 * in every stage the series carry (1, 2, 4 against a rigid row and a
 * spring, 5), on both edges, under Taft as recorded and through a 5 Hz
 * building, and a harmonic, each with and without a vertical, the
 * derivative of each series (term by term) is held to rb_dyn_rhs's at
 * four instants of the step, to 1e-8 of the largest of that rate over
 * the step (the work integrals, which the order test does not read, to
 * 1e-4). A term formed wrongly at any order above the first moves the
 * derivative by its own size times the step's powers: about 1e-3 of the
 * rate for a 13 Hz swing over a 0.01 s step at the third order.
 *
 * Where the processor has AVX, every step is also formed by the baseline
 * variant and the AVX variant of the step (src/core/simd.h) and the two
 * must agree to the bit: the same series, order and step length. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "harness.h"
#include "stress_cabinet.h"
#include "../../src/core/simd.h"
#include "../../src/core/solver.h"
#include "../../src/core/taylor.h"

static double urand(unsigned *st, double lo, double hi)
{
    *st = *st * 1103515245u + 12345u;
    return lo + (hi - lo) * (double)((*st >> 8) & 0xffffff) / (double)0xffffff;
}

/* d/dtau of series i at tau */
static double series_rate(const rb_taylor *ts, int i, double tau)
{
    double r = 0;
    for (int k = ts->order; k >= 1; k--)
        r = r * tau + k * ts->p[k][i];
    return r;
}

static const int series_of[RB_NY] = {
    RB_TS_U, RB_TS_UD, RB_TS_TH, RB_TS_THD, RB_TS_WDAMP, RB_TS_WIN, RB_TS_WCPL,
};

static double worst = 0, worst_work = 0;
static int steps_checked = 0, capped = 0, per_stage[6], variants_same = 0;

/* rb_taylor_check, rb_taylor_all and rb_taylor_state, which read
 * components side by side in vectors, against each component's own
 * scalar Horner chain, bit for bit (a still stage's angle terms are its
 * start's, as they are). */
static int readings_same = 0;
static void check_readings(const rb_taylor *ts, double tau)
{
    double v[RB_TS_N], all[RB_NY], chain[RB_TS_N];
    rb_taylor_check(ts, tau, v);
    rb_taylor_all(ts, tau, all);
    for (int i = 0; i < RB_TS_N; i++) {
        chain[i] = ts->p[ts->order][i];
        for (int k = ts->order - 1; k >= 0; k--)
            chain[i] = chain[i] * tau + ts->p[k][i];
    }
    int same = 1;
    for (int i = 0; i < RB_TS_CHECK; i++) {
        int held = !ts->rocking && (i == RB_TS_TH || i == RB_TS_THD || i == RB_TS_COS
                                    || i == RB_TS_SIN || i == RB_TS_THDD);
        double want = held ? (i == RB_TS_THDD ? 0 : ts->p[0][i])
                           : i == RB_TS_Z && !ts->vertical ? 0 : chain[i];
        same &= memcmp(&v[i], &want, sizeof want) == 0;
    }
    for (int c = 0; c < RB_NY; c++)
        same &= memcmp(&all[c], &chain[series_of[c]], sizeof all[c]) == 0;
    double mech[RB_NY];
    rb_taylor_state(ts, tau, mech);
    for (int c = RB_Y_U; c <= RB_Y_THD; c++)
        same &= memcmp(&mech[c], &chain[series_of[c]], sizeof mech[c]) == 0;
    if (!same)
        printf("tau %.6e: a vector reading differs from its scalar chain\n", tau);
    CHECK(same);
    readings_same += same;
}

/* The baseline and AVX variants of one step, compared bit for bit. */
static void check_variants(const rb_solver *sv, double t0, const double *y0, double h_want)
{
    if (!rb_simd_avx())
        return;
    static rb_taylor a, b;
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    double ha = rb_taylor_step_plain(&sv->sys, &sv->disc, t0, y0, h_want, sv->atol, sv->atol_x,
                                     sv->opts.rtol, &a);
    double hb = rb_taylor_step_avx(&sv->sys, &sv->disc, t0, y0, h_want, sv->atol, sv->atol_x,
                                   sv->opts.rtol, &b);
    int same = memcmp(&ha, &hb, sizeof ha) == 0 && memcmp(&a, &b, sizeof a) == 0;
    if (!same)
        printf("t0 %.6f stage %d: the AVX step differs from the baseline's (orders %d, %d)\n",
               t0, sv->disc.stage, a.order, b.order);
    CHECK(same);
    variants_same += same;
}

/* One random step of sv's system from t0: its series against rb_dyn_rhs. */
static void check_step(rb_solver *sv, double t0, unsigned *st, const char *what)
{
    const rb_sys *S = &sv->sys;
    rb_disc *D = &sv->disc;
    if (!rb_taylor_applies(S, D))
        return;
    double y0[RB_NY] = {0}, sgn = D->side;
    double alpha = S->d.alpha, u_scale = 1e-3 * (1 + urand(st, 0, 4));
    y0[RB_Y_U] = urand(st, -1, 1) * u_scale;
    y0[RB_Y_UD] = urand(st, -1, 1) * u_scale * 60;
    int rocking = rb_dyn_rocking(S, D);
    if (rocking) {
        double lo = D->stage == RB_STAGE_UPLIFT ? 0.02 * alpha : D->theta_hold;
        double hi = D->stage == RB_STAGE_UPLIFT ? 0.5 * alpha : D->theta_hold + 0.1 * alpha;
        y0[RB_Y_TH] = sgn * urand(st, lo, hi);
        y0[RB_Y_THD] = urand(st, -0.2, 0.2);
    } else if (D->stage == RB_STAGE_HELD)
        y0[RB_Y_TH] = sgn * D->theta_hold;
    y0[RB_Y_WDAMP] = urand(st, 0, 10);
    y0[RB_Y_WIN] = urand(st, -10, 10);
    y0[RB_Y_WCPL] = urand(st, -10, 10);
    double brk = rb_motion_next_break(S->motion, t0);
    double h_want = fmin(brk - t0, 0.02);
    check_variants(sv, t0, y0, h_want);
    rb_taylor ts;
    double h = rb_taylor_step(S, D, t0, y0, h_want, sv->atol, sv->atol_x, sv->opts.rtol, &ts);
    if (!(h > 0)) {
        printf("%s: no step from t0 = %.6f (stage %d)\n", what, t0, D->stage);
        CHECK(h > 0);
        return;
    }
    /* a series cut at the longest order has its step shortened by an
     * estimate, not held to the tolerance (the run loop keeps a taut
     * spring's steps far shorter than this test asks for) */
    if (ts.order == RB_TAYLOR_MAX) {
        capped++;
        return;
    }
    double taus[4] = {0.2 * h, 0.5 * h, 0.8 * h, h}, dy[4][RB_NY], rate[4][RB_NY];
    double scale[RB_NY] = {0};
    int valid[4];
    for (int q = 0; q < 4; q++) {
        double y[RB_NY];
        check_readings(&ts, taus[q]);
        rb_taylor_all(&ts, taus[q], y);
        /* a spring pulls only while taut: past its slack guard the series
         * goes on pulling, the equations do not (the run stops there) */
        valid[q] = !(rocking && D->stage == RB_STAGE_HELD && sgn * y[RB_Y_TH] < D->theta_hold);
        if (!valid[q])
            continue;
        rb_dyn_rhs(S, D, t0 + taus[q], y, dy[q], NULL);
        for (int c = 0; c < RB_NY; c++) {
            rate[q][c] = series_rate(&ts, series_of[c], taus[q]);
            scale[c] = fmax(scale[c], fmax(fabs(dy[q][c]), fabs(rate[q][c])));
        }
    }
    for (int q = 0; q < 4; q++)
        for (int c = 0; c < RB_NY && valid[q]; c++) {
            /* a still stage's angle is held; its work rates can all be
             * zero (a rigid body on the floor) */
            double floor_ = c == RB_Y_TH || c == RB_Y_THD ? 1e-12 : 1e-9;
            double e = fabs(rate[q][c] - dy[q][c]) / fmax(scale[c], floor_);
            /* the order test reads the state's and the floor's terms; the
             * work integrals ride along, a few terms short of it */
            int work = c >= RB_Y_WDAMP;
            double tol = work ? 1e-4 : 1e-8;
            double *w = work ? &worst_work : &worst;
            if (e > *w)
                *w = e;
            if (!(e <= tol)) {
                printf("%s: stage %d side %d t0 %.6f h %.3e order %d: component %d at "
                       "tau %.3e: series rate %.12e, equations %.12e (%.2e of %.3e)\n",
                       what, D->stage, D->side, t0, h, ts.order, c, taus[q], rate[q][c],
                       dy[q][c], e, scale[c]);
                CHECK(e <= tol);
            }
        }
    steps_checked++;
    per_stage[D->stage]++;
}

static const int stages[] = {RB_STAGE_FIXED, RB_STAGE_UPLIFT, RB_STAGE_HELD, RB_STAGE_YIELD};

static void run_cases(const rb_series *taft, const rb_series *building)
{
    unsigned st = 41;
    rb_motion vertical;
    rb_motion_init(&vertical);
    vertical.kind = RB_MOTION_HARMONIC;
    vertical.freq_hz = 3.7;
    vertical.duration_s = 100;
    for (int n = 0; n < 160; n++) {
        stress_cabinet c = {urand(&st, 300, 2000), urand(&st, 4, 20), urand(&st, 5e-5, 4e-4),
                            urand(&st, 0, 0.03), urand(&st, 0.1, 1.2), 20};
        rb_model m;
        rb_derived d;
        rb_motion mo;
        int kind = n % 3;
        if (stress_cabinet_setup(&c, kind == 1 ? building : taft, &m, &d, &mo) != 0) {
            CHECK(0);
            continue;
        }
        m.rigid = n % 7 == 3;
        m.bolt_model = n % 2 ? RB_BOLT_ELASTIC_PLASTIC : RB_BOLT_RIGID_PLASTIC;
        if (kind == 2) {
            rb_motion_init(&mo);
            mo.kind = RB_MOTION_HARMONIC;
            mo.freq_hz = urand(&st, 1, 12);
            mo.amplitude_mps2 = c.level * d.a_star_mps2;
            mo.duration_s = 20;
        }
        if (n % 4 == 1) {
            vertical.amplitude_mps2 = urand(&st, 0.1, 0.5) * 9.80665;
            mo.vertical = &vertical;
        }
        rb_solve_opts o;
        rb_solve_opts_init(&o);
        o.formulation = n % 5 == 2 ? RB_FORM_SMALL : RB_FORM_LARGE;
        o.rtol = 1e-10;
        rb_solver *sv = malloc(sizeof *sv);
        rb_result r;
        if (!sv || rb_solver_setup(sv, &m, &mo, &o, &r, NULL) != RB_OK) {
            printf("case %d: no setup\n", n);
            CHECK(0);
            free(sv);
            continue;
        }
        for (int i = 0; i < 4; i++) {
            rb_disc *D = &sv->disc;
            D->stage = stages[i];
            D->side = urand(&st, 0, 1) < 0.5 ? -1 : 1;
            D->theta_hold = D->stage == RB_STAGE_HELD ? D->contact[0] : 0;
            D->chord_entry = rb_dyn_chord(&sv->sys, D->contact[0]);
            char what[64];
            snprintf(what, sizeof what, "case %d (%s%s%s)", n,
                     kind == 0 ? "Taft" : kind == 1 ? "5 Hz building" : "harmonic",
                     mo.vertical ? ", vertical" : "", m.rigid ? ", rigid" : "");
            for (int k = 0; k < 2; k++)
                check_step(sv, urand(&st, 0.5, 15), &st, what);
        }
        rb_result_free(&r);
        free(sv);
    }
}

int main(void)
{
    rb_series taft = {0}, building = {0};
    if (taft_record(&taft) != 0 || rb_series_copy(&taft, &building) != RB_OK
        || rb_series_building_filter(&building, 5.0, 0.05) != RB_OK) {
        CHECK(0);
        TEST_MAIN_END();
    }
    run_cases(&taft, &building);
    printf("%d steps (stage 1: %d, 2: %d, 4: %d, 5: %d; %d more cut at the longest order); "
           "largest difference %.2e of the rate's scale (state), %.2e (work integrals)\n",
           steps_checked, per_stage[1], per_stage[2], per_stage[4], per_stage[5], capped,
           worst, worst_work);
    printf("AVX: %s; %d steps the same to the bit in both variants; %d readings the same "
           "as their scalar chains\n", rb_simd_avx() ? "yes" : "no", variants_same,
           readings_same);
    CHECK(readings_same == 4 * steps_checked);
    CHECK(steps_checked > 800);
    CHECK(!rb_simd_avx() || variants_same > steps_checked);
    CHECK(per_stage[1] > 100 && per_stage[2] > 100 && per_stage[4] > 100
          && per_stage[5] > 100);
    rb_series_free(&taft);
    rb_series_free(&building);
    TEST_MAIN_END();
}
