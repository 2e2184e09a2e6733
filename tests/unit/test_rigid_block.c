/* The rigid free-standing block of chapters 2 and 3, as a limit of the same
 * engine: no frame deformation, no anchorage, linearised eq. 2.6 (the small
 * formulation), delta = 0.778 (issue tests 3 and 4). */
#include <math.h>
#include <stdio.h>
#include "harness.h"
#include "thesis_block.h"
#include "rockbolt/solve.h"

static double block_p(const rb_model *m)
{
    rb_derived d;
    rb_model_derive(m, &d, NULL);
    return sqrt(d.W * d.R / d.Io);
}

/* 1 if a pulse of normalised amplitude K = a / (g alpha) overturns the block. */
static int pulse_overturns(rb_pulse_shape shape, double pt1, double K, int *ok)
{
    rb_model m;
    rb_motion mo;
    rb_solve_opts o;
    rb_result r;
    rb_derived d;
    thesis_block_model(&m);
    rb_model_derive(&m, &d, NULL);
    rb_motion_init(&mo);
    mo.kind = RB_MOTION_PULSE;
    mo.pulse = shape;
    mo.pulse_s = pt1 / block_p(&m);
    mo.amplitude_mps2 = K * d.g * d.alpha;
    mo.duration_s = mo.pulse_s + 15.0;
    rb_solve_opts_init(&o);
    o.formulation = RB_FORM_SMALL;
    o.rtol = 1e-10;
    *ok = rb_solve_run(&m, &mo, &o, &r, NULL) == RB_OK;
    rb_result_free(&r);
    return r.overturned;
}

static double bisect_threshold(rb_pulse_shape shape, double pt1, double lo, double hi)
{
    int ok = 1, ok1;
    while (hi - lo > 1e-6) {
        double mid = 0.5 * (lo + hi);
        if (pulse_overturns(shape, pt1, mid, &ok1))
            hi = mid;
        else
            lo = mid;
        ok &= ok1;
    }
    CHECK(ok);
    return 0.5 * (lo + hi);
}

static void table_2_2(void)
{
    int ok;
    CHECK(!pulse_overturns(RB_PULSE_TRI_DEC, 7.0, 1.1662, &ok) && ok);
    CHECK(pulse_overturns(RB_PULSE_TRI_DEC, 7.0, 1.1668, &ok) && ok);
    CHECK(!pulse_overturns(RB_PULSE_TRI_INC, 5.5, 1.50, &ok) && ok);
    CHECK(pulse_overturns(RB_PULSE_TRI_INC, 5.5, 1.53, &ok) && ok);
    CHECK(!pulse_overturns(RB_PULSE_HALF_SINE, 1.48, 1.85, &ok) && ok);
    double k1 = bisect_threshold(RB_PULSE_TRI_DEC, 7.0, 1.0, 1.5);
    double k_half = bisect_threshold(RB_PULSE_HALF_SINE, 1.48, 1.5, 2.5);
    printf("triangular-1 threshold %.6f (eq. 2.17: %.6f); half-sine threshold %.6f\n",
           k1, thesis_eq_2_17(7.0), k_half);
    /* tolerance 1e-3 relative (issue test 3) */
    CHECK_REL(k1, thesis_eq_2_17(7.0), 1e-3);
    CHECK(k_half > 1.85 && k_half < 1.87);
}

/* Critical rectangular excitation (ch. 3) from rest at theta = v1 alpha. */
static rb_result critical_run(double K, double v1)
{
    rb_model m;
    rb_motion mo;
    rb_solve_opts o;
    rb_result r;
    rb_derived d;
    thesis_block_model(&m);
    rb_model_derive(&m, &d, NULL);
    rb_motion_init(&mo);
    mo.kind = RB_MOTION_CRITICAL;
    mo.amplitude_mps2 = K * d.g * d.alpha;
    mo.duration_s = 60.0;
    rb_solve_opts_init(&o);
    o.formulation = RB_FORM_SMALL;
    o.theta_init_rad = v1 * d.alpha;
    o.rtol = 1e-10;
    CHECK(rb_solve_run(&m, &mo, &o, &r, NULL) == RB_OK);
    return r;
}

static double eq_3_20(double delta, double v1)
{
    return (1 - delta * delta) / (1 + delta * delta) * (1 - v1 / 2);
}

static void table_3_1(void)
{
    static const double K[3] = {1.46, 0.74, 0.37};
    static const double v1[4] = {0.0005, 0.005, 0.05, 0.5};
    for (int i = 0; i < 3; i++)
        for (int j = 0; j < 4; j++) {
            rb_result r = critical_run(K[i], v1[j]);
            CHECK(r.overturned);
        }
    rb_result d3 = critical_run(0.194, 0.05);
    CHECK(!d3.overturned);
    CHECK(d3.max_theta_over_alpha <= 0.05 * (1 + 1e-9));
    printf("D-3: %ld floor impacts, max theta/alpha %.4f, at rest after %.3f s of rocking\n",
           d3.floor_impacts, d3.max_theta_over_alpha, d3.stage_time_s[2]);
    /* eq. 3.20 separates growth from decay: 2 % either side of K0 */
    double k0 = eq_3_20(0.778, 0.05);
    rb_result below = critical_run(0.98 * k0, 0.05), above = critical_run(1.02 * k0, 0.05);
    CHECK(!below.overturned);
    CHECK(above.overturned);
    CHECK_NEAR(k0, 0.2397, 5e-5);
}

int main(void)
{
    table_2_2();
    table_3_1();
    TEST_MAIN_END();
}
