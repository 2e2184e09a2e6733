/* A spring row's stage-4 guards as angles (docs/solver.md, "A spring
 * row's guards as angles"): a row that is a force law goes slack where
 * its chord is the gap and reaches Fy where the chord is the gap plus
 * Fy / k, so the guards read the mirrored angle against the contact angle
 * and yield_at instead of the tension against 0 and Fy.
 *
 * Checked here against the tension written out from eq. 5.9b (chord
 * 2 l sin(theta / 2), or l theta small) and the spring k (chord - gap),
 * over random cabinets, both formulations, both sides and gaps grown by
 * yielding: every angle's guards have the tension's signs, the levels are
 * where the tension is 0 and Fy, and rb_guard_angle gives them in the
 * physical frame. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "harness.h"
#include "../../src/core/solver.h"

static double uniform(unsigned *st, double lo, double hi)
{
    *st = *st * 1103515245u + 12345u;
    return lo + (hi - lo) * ((*st >> 8) & 0xffffff) / 16777216.0;
}

static double chord_of(int small, double l, double th)
{
    return small ? l * th : 2 * l * sin(0.5 * th);
}

int main(void)
{
    unsigned st = 20261128u;
    int angles = 0, cabinets = 0;
    double worst_level = 0;
    for (int n = 0; n < 200; n++) {
        rb_model m;
        rb_derived d;
        rb_model_reference(&m);
        m.mass_kg = uniform(&st, 150, 900);
        m.bolt_area_m2 *= uniform(&st, 0.3, 2);
        m.gap_m = uniform(&st, 0, 0.04) * m.lever_arm_m;
        m.bolt_model = RB_BOLT_ELASTIC_PLASTIC;
        if (rb_model_derive(&m, &d, NULL) != RB_OK) {
            CHECK(0);
            continue;
        }
        rb_motion mo;
        rb_motion_init(&mo);
        mo.kind = RB_MOTION_HARMONIC;
        mo.freq_hz = 3;
        mo.amplitude_mps2 = 0.3 * d.a_star_mps2;
        mo.duration_s = 1;
        rb_solve_opts o;
        rb_solve_opts_init(&o);
        int small = n % 3 == 1;
        o.formulation = small ? RB_FORM_SMALL : RB_FORM_LARGE;
        rb_solver *sv = malloc(sizeof *sv);
        rb_result r;
        if (!sv || rb_solver_setup(sv, &m, &mo, &o, &r, NULL) != RB_OK) {
            CHECK(0);
            free(sv);
            continue;
        }
        cabinets++;
        rb_disc *D = &sv->disc;
        const rb_sys *S = &sv->sys;
        double l = S->l, k = S->d.k_row_npm, fy = S->d.fy_row_n;
        /* a row that has yielded before: its gap grown by a plastic stretch */
        int row = n % 2 ? RB_RIGHT : RB_LEFT;
        if (n % 4 >= 2) {
            D->gap[row] += uniform(&st, 0, 0.01) * l;
            D->contact[row] = rb_dyn_contact_angle(S, D->gap[row]);
            rb_disc_yield_angles(S, D);
        }
        D->stage = RB_STAGE_HELD;
        D->side = row == RB_RIGHT ? 1 : -1;
        double gap = D->gap[row];
        /* the levels: the tension 0 at the contact angle and Fy at yield_at */
        double at_contact = chord_of(small, l, D->contact[row]) - gap;
        double at_yield = k * (chord_of(small, l, D->yield_at[row]) - gap);
        CHECK_NEAR(at_contact, 0, 1e-15 * l);
        CHECK_REL(at_yield, fy, 1e-12);
        worst_level = fmax(worst_level, fabs(at_yield - fy) / fy);
        double level;
        CHECK(rb_guard_angle(sv, G_SLACK, &level) && level == D->side * D->contact[row]);
        CHECK(rb_guard_angle(sv, G_YIELD, &level) && level == D->side * D->yield_at[row]);
        /* every angle reads the tension's side of both guards */
        double span = D->yield_at[row] - D->contact[row];
        for (int i = 0; i < 50; i++) {
            double th = D->contact[row] + uniform(&st, -0.5, 1.5) * span;
            double tension = k * (chord_of(small, l, th) - gap), y[RB_NY] = {0};
            y[RB_Y_TH] = D->side * th;
            double slack = rb_guard_one(sv, G_SLACK, 0, y);
            double yield = rb_guard_one(sv, G_YIELD, 0, y);
            /* away from the boundaries by more than rounding */
            if (fabs(tension) > 1e-9 * fy)
                CHECK((slack > 0) == (tension > 0));
            if (fabs(tension - fy) > 1e-9 * fy)
                CHECK((yield > 0) == (tension > fy));
            angles++;
        }
        rb_result_free(&r);
        free(sv);
    }
    printf("%d cabinets, %d angles; the tension at yield_at within %.2e of Fy\n", cabinets,
           angles, worst_level);
    CHECK(cabinets == 200);
    TEST_MAIN_END();
}
