/* The time history's energy columns follow the row's own angle inside a
 * yielding step (issue 41: the columns read the run's state, the step's
 * start, so that inside a stage-5 step they lagged; 151.1 J at 4.748 s
 * where the row's angle gave 373.6 J).
 *
 * While a row yields (stage 5) at the constant force Fy, its absorbed
 * energy grows by Fy times the growth of its chord, 2 l sin(theta / 2)
 * (the large formulation, eq. 5.9b). Between two successive rows of the
 * history that are both in stage 5 about the same edge, the yielding
 * row's energy must differ by exactly that, computed here from the rows'
 * angles; the other row's energy must not move. The run: the reference
 * cabinet under El Centro through the 5 Hz building at 0.4 A*, rigid-
 * plastic and elastic-plastic rows, stretched past failure, a row every
 * millisecond. The final row's energies are the result's absorbed
 * energies. */
#include <math.h>
#include <stdio.h>
#include "harness.h"
#include "elcentro_floor.h"

static void check_model(const rb_series *floor, rb_bolt_model bolts, const char *name)
{
    rb_model m;
    rb_derived d;
    rb_motion mo;
    rb_solve_opts o;
    rb_result r;
    elcentro_run_setup(floor, bolts, 0.4, 10.0, &m, &d, &mo);
    rb_solve_opts_init(&o);
    o.stretch_past_failure = 1;
    o.history_dt_s = 0.001;
    rb_status st = rb_solve_run(&m, &mo, &o, &r, NULL);
    CHECK(st == RB_OK);
    const rb_history *h = r.history;
    CHECK(h && h->n > 1000);
    if (st != RB_OK || !h || h->n < 2) {
        rb_result_free(&r);
        return;
    }
    double fy = d.fy_row_n, l = m.lever_arm_m, worst = 0, scale = 0;
    long pairs = 0, moved = 0;
    for (size_t i = 1; i < h->n; i++) {
        if (h->stage[i] != RB_STAGE_YIELD || h->stage[i - 1] != RB_STAGE_YIELD
            || (h->theta[i] > 0) != (h->theta[i - 1] > 0))
            continue;
        /* rocking about the left edge (theta > 0) loads the right row */
        int row = h->theta[i] > 0 ? RB_RIGHT : RB_LEFT;
        const double *e = row == RB_RIGHT ? h->energy_right : h->energy_left;
        const double *other = row == RB_RIGHT ? h->energy_left : h->energy_right;
        double chord0 = 2 * l * sin(fabs(h->theta[i - 1]) / 2);
        double chord1 = 2 * l * sin(fabs(h->theta[i]) / 2);
        double want = fy * (chord1 - chord0), got = e[i] - e[i - 1];
        worst = fmax(worst, fabs(got - want));
        scale = fmax(scale, fabs(want));
        CHECK(other[i] == other[i - 1]);
        pairs++;
        moved += want != 0;
    }
    printf("%s: %ld pairs of rows in stage 5 (%ld moving), largest step %.4g J, largest "
           "departure from Fy times the chord's growth %.3g J\n", name, pairs, moved, scale,
           worst);
    CHECK(pairs > 20 && moved > 20);
    /* a difference of two energies of some hundred joules */
    CHECK(worst <= 1e-9 * fmax(fmax(r.absorbed_j[0], r.absorbed_j[1]), 1));
    CHECK_NEAR(h->energy_left[h->n - 1], r.absorbed_j[0], 1e-9 * (1 + r.absorbed_j[0]));
    CHECK_NEAR(h->energy_right[h->n - 1], r.absorbed_j[1], 1e-9 * (1 + r.absorbed_j[1]));
    rb_result_free(&r);
}

int main(void)
{
    rb_series floor = {0};
    if (elcentro_floor(&floor) != 0) {
        fprintf(stderr, "cannot read the El Centro record\n");
        return 1;
    }
    check_model(&floor, RB_BOLT_RIGID_PLASTIC, "rigid-plastic");
    check_model(&floor, RB_BOLT_ELASTIC_PLASTIC, "elastic-plastic");
    rb_series_free(&floor);
    TEST_MAIN_END();
}
