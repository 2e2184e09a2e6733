/* rb_judge_decide against rb_judge_run (include/rockbolt/criteria.h): on
 * random stress cabinets under Taft the two give the same pass and the same
 * reason, and decide makes no confirming run after the first that fails.
 *
 * - Every pass confirmed (confirm: always), usage limit 1: where both
 *   confirming runs pass, decide makes both too.
 * - A limit placed between the run's usage and the usage of the same run
 *   at a tenth of its tolerance (each solved here, apart from the judge),
 *   on the side that makes the first confirming run fail: decide stops
 *   after that run, and its verdict is still rb_judge_run's. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "harness.h"
#include "rockbolt/criteria.h"
#include "stress_cabinet.h"
#include "util/rng.h"

static int solves;

static rb_status counting_solve(void *ctx, const rb_model *model, const rb_motion *motion,
                                const rb_solve_opts *opts, rb_result *out)
{
    (void)ctx;
    solves++;
    rb_status st = rb_solve_run(model, motion, opts, out, NULL);
    rb_result_free(out);
    out->history = NULL;
    return st;
}

/* Judge r both ways; the confirming runs each made. */
static void both(const rb_criteria *cr, const rb_model *m, const rb_motion *mo,
                 const rb_solve_opts *o, const rb_result *r, int *n_run, int *n_decide,
                 int *pass)
{
    rb_verdict full, decided;
    rb_confirm_run runs[RB_CONFIRM_RUNS];
    size_t n_runs;
    solves = 0;
    rb_judge_run(cr, m, mo, o, r, counting_solve, NULL, &full, runs, &n_runs);
    *n_run = solves;
    solves = 0;
    rb_judge_decide(cr, m, mo, o, r, counting_solve, NULL, &decided);
    *n_decide = solves;
    CHECK(decided.pass == full.pass);
    CHECK(strcmp(decided.reason, full.reason) == 0);
    CHECK(*n_run == (int)n_runs);
    *pass = full.pass;
}

int main(void)
{
    rb_series taft = {0};
    if (taft_record(&taft) != 0)
        return 1;
    rb_rng rng;
    rb_rng_seed(&rng, 4141);
    int confirmed = 0, stopped = 0;
    for (int i = 0; i < 10; i++) {
        stress_cabinet c = {300 + 900 * rb_rng_uniform(&rng), 3 + 7 * rb_rng_uniform(&rng),
                            (0.5 + rb_rng_uniform(&rng)) * 1.267e-4,
                            (0.002 + 0.02 * rb_rng_uniform(&rng)) * 0.78,
                            0.2 + 0.4 * rb_rng_uniform(&rng), 8.0};
        rb_model m;
        rb_derived d;
        rb_motion mo;
        if (stress_cabinet_setup(&c, &taft, &m, &d, &mo) != 0)
            continue;
        rb_solve_opts o, tighter;
        rb_solve_opts_init(&o);
        o.rtol = 1e-6;
        o.stretch_past_failure = 1;
        tighter = o;
        tighter.rtol = 1e-7; /* the first confirming run's tolerance */
        rb_result r, r1;
        CHECK(rb_solve_run(&m, &mo, &o, &r, NULL) == RB_OK);
        CHECK(rb_solve_run(&m, &mo, &tighter, &r1, NULL) == RB_OK);
        double u0 = rb_result_governing(&r).usage, u1 = rb_result_governing(&r1).usage;
        rb_result_free(&r1);

        rb_criteria cr;
        rb_criteria_init(&cr);
        cr.confirm = RB_CONFIRM_ALWAYS;
        int n_run, n_decide, pass;
        both(&cr, &m, &mo, &o, &r, &n_run, &n_decide, &pass);
        if (pass) {
            confirmed++;
            CHECK(n_decide == n_run && n_run == RB_CONFIRM_RUNS);
        }
        /* the first confirming run fails where the limit lies between the
         * two usages, above the run's own */
        if (u1 > u0 && u0 > 0) {
            cr.usage_limit = 0.5 * (u0 + u1);
            both(&cr, &m, &mo, &o, &r, &n_run, &n_decide, &pass);
            CHECK(!pass);
            CHECK(n_run == RB_CONFIRM_RUNS);
            CHECK(n_decide == 1);
            stopped++;
        }
        rb_result_free(&r);
    }
    printf("confirmed passes %d, first confirming run failing %d\n", confirmed, stopped);
    CHECK(confirmed > 0);
    CHECK(stopped > 0);
    rb_series_free(&taft);
    TEST_MAIN_END();
}
