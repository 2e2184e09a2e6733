/* A jump of the floor at a pulse's end can carry a guard across its
 * boundary (docs/solver.md, "Breaks where the excitation jumps").
 *
 * The reference cabinet with an 8 Hz frame under a rectangular pulse of
 * 0.025 A*, 0.215 s long: on the floor at the pulse's end, its frame
 * swinging against the plate's near edge, the uplift moment stands 39.5 N m
 * short of uplift before the drop and 1.3 N m past it after, then falls
 * back within a millisecond. The Taylor steps read the guard before the
 * drop at the step that lands on the break and from after it at the next
 * step's first check point, by which time it was back: over pulse lengths
 * of 0.2126 to 0.2178 s they counted one uplift where Dormand-Prince,
 * which reads its landing step's end after the drop, counts two. */
#include <stdio.h>
#include "harness.h"
#include "rockbolt/model.h"
#include "rockbolt/motion.h"
#include "rockbolt/solve.h"

static long uplifts_of(const rb_model *m, const rb_motion *mo, rb_integrator integ, double rtol,
                       int min_checks, double *theta_over_alpha)
{
    rb_solve_opts o;
    rb_result r;
    rb_diag diag;
    rb_solve_opts_init(&o);
    o.integrator = integ;
    o.rtol = rtol;
    if (min_checks)
        o.min_checks = min_checks;
    if (rb_solve_run(m, mo, &o, &r, &diag) != RB_OK) {
        printf("solve failed: %s\n", diag.msg);
        return -1;
    }
    long n = r.uplifts;
    *theta_over_alpha = r.max_theta_over_alpha;
    rb_result_free(&r);
    return n;
}

int main(void)
{
    rb_model m;
    rb_derived d;
    rb_model_reference(&m);
    m.freq_hz = 8;
    CHECK(rb_model_derive(&m, &d, NULL) == RB_OK);
    static const double lengths[3] = {0.2130, 0.2150, 0.2175};
    for (int i = 0; i < 3; i++) {
        rb_motion mo;
        rb_motion_init(&mo);
        mo.kind = RB_MOTION_PULSE;
        mo.pulse = RB_PULSE_RECT;
        mo.amplitude_mps2 = 0.025 * d.a_star_mps2;
        mo.pulse_s = lengths[i];
        mo.duration_s = mo.pulse_s + 0.5;
        CHECK(rb_motion_jumps_at(&mo, mo.pulse_s));
        CHECK(!rb_motion_jumps_at(&mo, 0.5 * mo.pulse_s));
        double th[3] = {0, 0, 0}; /* set by every run that solves */
        long taylor = uplifts_of(&m, &mo, RB_INTEGRATOR_AUTO, 1e-7, 0, &th[0]);
        long fine = uplifts_of(&m, &mo, RB_INTEGRATOR_AUTO, 1e-11, 16, &th[1]);
        long dp = uplifts_of(&m, &mo, RB_INTEGRATOR_RK45, 1e-10, 0, &th[2]);
        printf("pulse %.4f s: uplifts %ld (Taylor, 1e-7), %ld (Taylor, 16 points, 1e-11), "
               "%ld (rk45, 1e-10); largest theta/alpha %.9g %.9g %.9g\n", mo.pulse_s, taylor,
               fine, dp, th[0], th[1], th[2]);
        CHECK(taylor == 2);
        CHECK(fine == 2);
        CHECK(dp == 2);
        CHECK_REL(th[0], th[2], 1e-6);
        CHECK_REL(th[1], th[2], 1e-6);
    }
    /* the other kinds are continuous at their breaks */
    rb_motion h;
    rb_motion_init(&h);
    h.kind = RB_MOTION_HARMONIC;
    h.amplitude_mps2 = 1;
    h.freq_hz = 2;
    h.ramp_s = 1;
    CHECK(!rb_motion_jumps_at(&h, 1.0));
    rb_motion p;
    rb_motion_init(&p);
    p.kind = RB_MOTION_PULSE;
    p.pulse = RB_PULSE_HALF_SINE;
    p.amplitude_mps2 = 1;
    p.pulse_s = 0.3;
    CHECK(!rb_motion_jumps_at(&p, 0.3));
    p.pulse = RB_PULSE_TRI_DEC;
    CHECK(!rb_motion_jumps_at(&p, 0.3));
    p.pulse = RB_PULSE_TRI_INC;
    CHECK(rb_motion_jumps_at(&p, 0.3));
    TEST_MAIN_END();
}
