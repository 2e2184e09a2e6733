/* `design` hands `check`'s run of a motion to its searches instead of
 * solving it again (rb_design_memo_keep, docs/design.md "Runs shared
 * between searches"). That stands only if the run `check` made, with a
 * history, is the run a search makes without one:
 *
 * - for a sampled motion at levels that stay on the floor, rock, yield and
 *   break, and for a harmonic, every field of the result solved with a
 *   history (at check's default interval and at an odd one) is the same
 *   bits as the run without (the history itself aside);
 * - the recommended gap through a memo holding the kept run gives the
 *   same result as through an empty memo, and solves one run fewer: its
 *   run at the case's own gap is the kept one. */
#include <string.h>
#include "harness.h"
#include "rockbolt/design.h"
#include "rockbolt/run.h"
#include "stress_cabinet.h"

/* The two results equal in every field but the history pointer. */
static int same_result(const rb_result *with, const rb_result *without)
{
    rb_result a = *with, b = *without;
    a.history = b.history = NULL;
    return memcmp(&a, &b, sizeof a) == 0;
}

static void holds_with_history(const rb_model *m, const rb_motion *mo, double dt_s)
{
    rb_solve_opts o;
    rb_result with, without;
    memset(&with, 0, sizeof with);
    memset(&without, 0, sizeof without);
    rb_solve_opts_init(&o);
    CHECK(rb_solve_run(m, mo, &o, &without, NULL) == RB_OK);
    o.history_dt_s = dt_s;
    CHECK(rb_solve_run(m, mo, &o, &with, NULL) == RB_OK);
    CHECK(with.history && with.history->n > 1 && !without.history);
    CHECK(same_result(&with, &without));
    rb_result_free(&with);
    rb_result_free(&without);
}

int main(void)
{
    rb_series taft = {0};
    if (taft_record(&taft) != 0)
        return 1;
    static const double levels[] = {0.002, 0.1, 0.3, 0.6, 1.2};
    for (size_t i = 0; i < sizeof levels / sizeof levels[0]; i++) {
        stress_cabinet c = {454, 5, 1.267e-4 * 2, 7.8e-3, levels[i], 12.0};
        rb_model m;
        rb_derived d;
        rb_motion mo;
        CHECK(stress_cabinet_setup(&c, &taft, &m, &d, &mo) == 0);
        holds_with_history(&m, &mo, RB_HISTORY_DT_DEFAULT_S);
        holds_with_history(&m, &mo, 0.0137);
        /* elastic-plastic bolts take the other stages' steps */
        m.bolt_model = RB_BOLT_ELASTIC_PLASTIC;
        holds_with_history(&m, &mo, RB_HISTORY_DT_DEFAULT_S);
    }
    {
        stress_cabinet c = {300, 7, 1.267e-4, 5e-3, 0, 6.0};
        rb_model m;
        rb_derived d;
        rb_motion h;
        CHECK(stress_cabinet_model(&c, &m, &d) == 0);
        rb_motion_init(&h);
        h.kind = RB_MOTION_HARMONIC;
        h.amplitude_mps2 = 0.3 * d.a_star_mps2;
        h.freq_hz = 4;
        h.duration_s = 6;
        holds_with_history(&m, &h, RB_HISTORY_DT_DEFAULT_S);
    }

    /* the recommended gap, given check's run of the motion at its own
     * level and gap, with a history */
    {
        stress_cabinet c = {454, 5, 1.267e-4 * 2, 7.8e-3, 0.15, 12.0};
        rb_model m;
        rb_derived d;
        rb_motion mo;
        rb_solve_opts o;
        rb_criteria crit;
        rb_design_opts dopt;
        rb_result checked;
        rb_gap_result plain, given;
        memset(&checked, 0, sizeof checked);
        CHECK(stress_cabinet_setup(&c, &taft, &m, &d, &mo) == 0);
        rb_solve_opts_init(&o);
        rb_criteria_init(&crit);
        rb_design_opts_defaults(&dopt);
        rb_solve_opts with = o;
        with.history_dt_s = RB_HISTORY_DT_DEFAULT_S;
        CHECK(rb_solve_run(&m, &mo, &with, &checked, NULL) == RB_OK);
        rb_design_memo *empty = rb_design_memo_new(), *kept = rb_design_memo_new();
        CHECK(empty && kept);
        rb_design_memo_keep(kept, &m, &mo, &with, RB_OK, &checked);
        CHECK(rb_design_memo_runs(kept) == 1);
        CHECK(rb_gap_recommend_memo(&m, &mo, &o, &crit, &dopt, 1, empty, &plain, NULL)
              == RB_OK);
        CHECK(rb_gap_recommend_memo(&m, &mo, &o, &crit, &dopt, 1, kept, &given, NULL)
              == RB_OK);
        /* the kept run was asked for and found: no run more than alone */
        CHECK(rb_design_memo_runs(empty) > 0);
        CHECK(rb_design_memo_runs(kept) == rb_design_memo_runs(empty));
        CHECK(plain.found == given.found && plain.gap_ratio == given.gap_ratio);
        CHECK(plain.n_points == given.n_points && plain.runs == given.runs);
        for (size_t i = 0; i < plain.n_points && i < given.n_points; i++) {
            const rb_gap_point *p = &plain.points[i], *q = &given.points[i];
            CHECK(p->evaluated == q->evaluated && p->meets == q->meets);
            CHECK(p->max_force_over_fy == q->max_force_over_fy
                  && p->max_theta_over_alpha == q->max_theta_over_alpha
                  && p->usage_max == q->usage_max && !strcmp(p->reason, q->reason));
        }
        CHECK(plain.yield_final_gap_ratio_max == given.yield_final_gap_ratio_max);
        rb_gap_result_free(&plain);
        rb_gap_result_free(&given);
        rb_design_memo_free(empty);
        rb_design_memo_free(kept);
        rb_result_free(&checked);
        /* the caller's result keeps its history */
    }
    rb_series_free(&taft);
    TEST_MAIN_END();
}
