/* A release from the bolt heads followed at once by a new contact, in
 * Dormand-Prince steps (docs/solver.md, "Grazes in Dormand-Prince steps").
 *
 * A 860 kg, 11.6 Hz cabinet on rigid-plastic rows under the Taft record
 * at 0.319 A*: at 11.4159 s the plate meets the bolt heads, and the row's
 * tension from the moment equation is -5.4e-3 N, so the plate is released
 * on the contact angle; the floor then presses it back within the next
 * step. The search for that new contact started from the guard the
 * release left on its boundary, read the boundary itself (0) as the
 * crossing, and put the contact at the release: stages 2 and 4 alternated
 * 1e-12 s apart until the work bound stopped the run with `rk45` at 1e-8
 * (20 491 events). Now every integrator and tolerance runs the 54 s
 * through to the same usage. */
#include <math.h>
#include <stdio.h>
#include "harness.h"
#include "stress_cabinet.h"

int main(void)
{
    rb_series s;
    if (taft_record(&s) != 0) {
        CHECK(0);
        TEST_MAIN_END();
    }
    static const stress_cabinet c = {859.83854783991796, 11.585301869758609,
                                     0.00010267342412192254, 0.0072164673135230355,
                                     0.31927812340725598, 0};
    rb_model m;
    rb_derived d;
    rb_motion mo;
    CHECK(stress_cabinet_setup(&c, &s, &m, &d, &mo) == 0);
    mo.duration_s = s.dt_s * (double)(s.n - 1);
    static const struct {
        rb_integrator integ;
        double rtol;
    } runs[] = {{RB_INTEGRATOR_AUTO, 1e-7}, {RB_INTEGRATOR_RK45, 1e-7},
                {RB_INTEGRATOR_RK45, 1e-8}, {RB_INTEGRATOR_RK45, 1e-9}};
    double usage0 = NAN;
    for (size_t i = 0; i < sizeof runs / sizeof runs[0]; i++) {
        rb_solve_opts o;
        rb_result r;
        rb_diag diag;
        rb_solve_opts_init(&o);
        o.integrator = runs[i].integ;
        o.rtol = runs[i].rtol;
        rb_status st = rb_solve_run(&m, &mo, &o, &r, &diag);
        printf("%s at %.0e: %s, t_end %.3f s, %ld events, usage %.9f\n",
               runs[i].integ == RB_INTEGRATOR_RK45 ? "rk45" : "auto", runs[i].rtol,
               st == RB_OK ? "ok" : diag.msg, r.t_end_s, r.events, r.usage[1]);
        CHECK(st == RB_OK);
        CHECK(r.events < 2000);
        if (i == 0)
            usage0 = r.usage[1];
        else
            CHECK_REL(r.usage[1], usage0, 1e-5);
        rb_result_free(&r);
    }
    CHECK(usage0 > 0.01);
    rb_series_free(&s);
    TEST_MAIN_END();
}
