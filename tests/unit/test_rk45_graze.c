/* Grazes inside one check interval of a Dormand-Prince step
 * (docs/solver.md, "Grazes in Dormand-Prince steps").
 *
 * A rigid body under the 0.02 s El Centro record (Peknold) through a
 * 16.7 Hz building: the floor passes the uplift level by a fraction of a
 * per cent for a few milliseconds and turns back. The Taylor steps read the
 * uplift guards where the moment turns, and see the hop; Dormand-Prince
 * read its guards only at the check points, both of them on the floor's
 * side, and missed it at every tolerance (3 uplifts against 2 at 0.0602 A*,
 * 8 of 200 levels from 0.02 to 0.12 A* one short). Its guards are now also
 * read at each interval's midpoint and followed to a peak the three
 * readings show inside.
 *
 * The Taylor steps at the default tolerance and with 16 check points at
 * 1e-11, and Dormand-Prince at 1e-9 and 1e-12, count the same uplifts and
 * floor impacts and find the same first uplift and largest rotation. */
#include <math.h>
#include <stdio.h>
#include "harness.h"
#include "rockbolt/record.h"
#include "rockbolt/solve.h"

static int peknold_building(rb_series *s)
{
    rb_record_opts ro;
    rb_diag diag;
    rb_record_opts_init(&ro);
    ro.format = RB_REC_AT2;
    if (rb_record_read("cases/records/elcentro_1940_ns_peknold.at2", &ro, s, &diag) != RB_OK) {
        printf("cannot read the Peknold record: %s\n", diag.msg);
        return -1;
    }
    return rb_series_building_filter(s, 16.7, 0.05) == RB_OK ? 0 : -1;
}

/* The rigid reference body under s at a level (A*), for 31 s. */
static int run(const rb_series *s, double level, rb_integrator integ, double rtol,
               int min_checks, rb_result *r)
{
    rb_model m;
    rb_derived d;
    rb_motion mo;
    rb_solve_opts o;
    rb_model_reference(&m);
    m.rigid = 1;
    if (rb_model_derive(&m, &d, NULL) != RB_OK)
        return 0;
    rb_motion_init(&mo);
    mo.kind = RB_MOTION_SAMPLED;
    mo.series = s;
    mo.scale = level * d.a_star_mps2 / rb_series_peak(s);
    mo.duration_s = 31;
    rb_solve_opts_init(&o);
    o.integrator = integ;
    o.rtol = rtol;
    o.min_checks = min_checks;
    return rb_solve_run(&m, &mo, &o, r, NULL) == RB_OK;
}

int main(void)
{
    rb_series s;
    if (peknold_building(&s) != 0)
        return 1;
    static const double levels[3] = {0.0602, 0.070753768844, 0.114974874372};
    for (int i = 0; i < 3; i++) {
        rb_result taylor, fine, dp, dp_fine;
        int ok = run(&s, levels[i], RB_INTEGRATOR_AUTO, 1e-7, 4, &taylor);
        ok &= run(&s, levels[i], RB_INTEGRATOR_AUTO, 1e-11, 16, &fine);
        ok &= run(&s, levels[i], RB_INTEGRATOR_RK45, 1e-9, 4, &dp);
        ok &= run(&s, levels[i], RB_INTEGRATOR_RK45, 1e-12, 4, &dp_fine);
        CHECK(ok);
        if (!ok)
            break;
        const rb_result *all[4] = {&taylor, &fine, &dp, &dp_fine};
        printf("%.6f A*: uplifts", levels[i]);
        for (int k = 0; k < 4; k++)
            printf(" %ld", all[k]->uplifts);
        printf(", floor impacts");
        for (int k = 0; k < 4; k++)
            printf(" %ld", all[k]->floor_impacts);
        printf(", max theta/alpha");
        for (int k = 0; k < 4; k++)
            printf(" %.9g", all[k]->max_theta_over_alpha);
        printf("\n");
        CHECK(taylor.uplifts > 0);
        for (int k = 1; k < 4; k++) {
            CHECK(all[k]->uplifts == taylor.uplifts);
            CHECK(all[k]->floor_impacts == taylor.floor_impacts);
            CHECK_REL(all[k]->max_theta_over_alpha, fine.max_theta_over_alpha, 1e-4);
        }
        for (int k = 0; k < 4; k++)
            rb_result_free((rb_result *)all[k]);
    }
    rb_series_free(&s);
    TEST_MAIN_END();
}
