/* Transitions at rounding level, from real runs that once stopped on the
 * work bound.
 *
 * Grazing release: a bolt row whose force falls to zero with the plate
 * exactly at its contact angle and no rotation speed. The stage-2 contact
 * guard then starts on its boundary; if its unchanged value (0, no motion
 * at all) were read as a new contact, release and bolt impact would follow
 * each other at one instant until the work bound stopped the run. The run
 * must finish, and with a transition count of the ordinary kind (the other
 * El Centro runs need about 1,300 for 40 s).
 *
 * Threshold uplift: the cabinet lifts off with the uplift moment equal to
 * the restoring moment to rounding; theta'' is ~1e-12 and theta in the
 * first step is noise of either sign. A landing read from that noise sent
 * the plate to rest and it lifted again at once. */
#include <stdio.h>
#include "harness.h"
#include "rockbolt/case.h"
#include "rockbolt/solve.h"

static void run_case(const char *path, long max_events)
{
    rb_case c;
    rb_diag_list dl = {0};
    rb_result r;
    rb_diag d;
    rb_status st = rb_case_load(path, &c, &dl);
    rb_diag_list_free(&dl);
    CHECK(st == RB_OK);
    if (st != RB_OK)
        return;
    rb_diag_clear(&d);
    st = rb_solve_run(&c.model, &c.motions[0].motion, &c.solve, &r, &d);
    if (st != RB_OK)
        printf("solver: %s: %s\n", rb_status_str(st), d.msg);
    CHECK(st == RB_OK);
    /* the motion runs its full length (or to an overturn) and a row is
     * engaged at the critical instant: the run must pass it */
    CHECK(r.t_end_s > 39.9 || r.overturned);
    CHECK(r.bolt_impacts > 0);
    CHECK(r.events < max_events);
    rb_result_free(&r);
    rb_case_free(&c);
}

int main(void)
{
    /* an order of magnitude above the ordinary count, far below a chatter */
    run_case("tests/unit/case_data/grazing-release.yaml", 20000);
    run_case("tests/unit/case_data/threshold-uplift.yaml", 20000);
    TEST_MAIN_END();
}
