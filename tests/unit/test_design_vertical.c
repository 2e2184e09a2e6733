/* A design search scales a motion's vertical with its horizontal
 * (docs/design.md, "The vertical at another level").
 *
 * - The run a search makes at another level (rb_design_run_at) is, to the
 *   bit, the run of a motion whose horizontal and vertical were both
 *   scaled by hand by the ratio of that level to the motion's own, for a
 *   harmonic and a sampled vertical, above and below the own level.
 * - The design factor's ends, run by hand with both axes scaled: the
 *   failing end fails and the passing end passes.
 * - A level at which the scaled vertical reaches -g is a failing level of
 *   the search, said so, not an error of the search. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "harness.h"
#include "rockbolt/criteria.h"
#include "rockbolt/design.h"
#include "stress_cabinet.h"

static rb_status by_hand(const rb_model *m, const rb_motion *mo, double ratio,
                         rb_result *r)
{
    rb_motion h = *mo, v = *mo->vertical;
    rb_solve_opts o;
    rb_solve_opts_init(&o);
    h.scale *= ratio;
    if (v.kind == RB_MOTION_SAMPLED)
        v.scale *= ratio;
    else
        v.amplitude_mps2 *= ratio;
    h.vertical = &v;
    return rb_solve_run(m, &h, &o, r, NULL);
}

static int same_run(const rb_result *a, const rb_result *b)
{
    return a->max_theta_rad == b->max_theta_rad && a->max_u_m == b->max_u_m
           && a->min_vertical_reaction_n == b->min_vertical_reaction_n
           && a->max_bolt_force_n[0] == b->max_bolt_force_n[0]
           && a->max_bolt_force_n[1] == b->max_bolt_force_n[1]
           && a->usage[0] == b->usage[0] && a->usage[1] == b->usage[1]
           && a->steps == b->steps && a->events == b->events;
}

int main(void)
{
    rb_series taft = {0};
    if (taft_record(&taft) != 0)
        return 1;
    static const stress_cabinet c = {454, 5, 1.267e-4 * 2, 7.8e-3, 0.1, 8.0};
    rb_model m;
    rb_derived d;
    rb_motion mo, harmonic, sampled;
    CHECK(stress_cabinet_setup(&c, &taft, &m, &d, &mo) == 0);
    rb_motion_init(&harmonic);
    harmonic.kind = RB_MOTION_HARMONIC;
    harmonic.amplitude_mps2 = 0.1 * d.g;
    harmonic.freq_hz = 7;
    rb_motion_init(&sampled);
    sampled.kind = RB_MOTION_SAMPLED;
    sampled.series = &taft;
    sampled.scale = 0.1 * d.g / rb_series_peak(&taft);
    rb_criteria cr;
    rb_criteria_init(&cr);
    rb_solve_opts o;
    rb_solve_opts_init(&o);
    const rb_motion *verticals[2] = {&harmonic, &sampled};
    const double ratios[3] = {0.37, 1.9, 2.6};
    for (int k = 0; k < 2; k++) {
        mo.vertical = verticals[k];
        double own = rb_motion_peak(&mo);
        for (int i = 0; i < 3; i++) {
            rb_result searched, hand;
            rb_verdict v;
            rb_confirm_run runs[RB_CONFIRM_RUNS];
            size_t n_runs;
            CHECK(rb_design_run_at(&m, &mo, &o, &cr, own * ratios[i], &searched, &v, runs,
                                   &n_runs, NULL) == RB_OK);
            CHECK(by_hand(&m, &mo, ratios[i], &hand) == RB_OK);
            CHECK(same_run(&searched, &hand));
            printf("vertical %d at %.2f x its level: theta %.6g rad, least reaction %.6g N "
                   "(by hand %.6g rad, %.6g N)\n", k, ratios[i], searched.max_theta_rad,
                   searched.min_vertical_reaction_n, hand.max_theta_rad,
                   hand.min_vertical_reaction_n);
            rb_result_free(&hand);
        }
        /* the design factor's ends, by hand */
        rb_design_opts grid;
        rb_design_opts_defaults(&grid);
        grid.scan_end = 0.6;
        grid.resolution = 0.005;
        rb_design_factor_result f;
        CHECK(rb_design_factor(&m, &mo, &o, &cr, &grid, 1, NULL, &f, NULL) == RB_OK);
        if (!f.no_failure) {
            rb_result lo, hi;
            rb_verdict vlo, vhi;
            CHECK(by_hand(&m, &mo, f.level_mps2 / own, &lo) == RB_OK);
            CHECK(by_hand(&m, &mo, f.fail_mps2 / own, &hi) == RB_OK);
            rb_judge(&cr, &lo, &vlo);
            rb_judge(&cr, &hi, &vhi);
            CHECK(f.level_astar == 0 || vlo.pass);
            CHECK(!vhi.pass);
            printf("vertical %d: design factor %.4g, passes at %.4f A*, fails at %.4f A*\n",
                   k, f.factor, f.level_astar, f.fail_astar);
        }
        CHECK(!f.no_failure);
    }
    /* a vertical of 0.5 g at the own level reaches -g at twice it: the
     * search fails there instead of stopping with an error */
    harmonic.amplitude_mps2 = 0.5 * d.g;
    mo.vertical = &harmonic;
    mo.scale = 0.02 * d.a_star_mps2 / rb_series_peak(&taft);
    rb_design_opts grid;
    rb_design_opts_defaults(&grid);
    grid.scan_start = grid.scan_step = 0.01;
    grid.scan_end = 0.1;
    rb_design_factor_result f;
    cr.usage_limit = INFINITY;
    CHECK(rb_design_factor(&m, &mo, &o, &cr, &grid, 1, NULL, &f, NULL) == RB_OK);
    CHECK(!f.no_failure && f.fail_astar <= 0.04 + 1e-9);
    CHECK(strstr(f.fail_reason, "vertical") != NULL);
    printf("a vertical reaching -g: fails at %.4f A*: %s\n", f.fail_astar, f.fail_reason);
    rb_series_free(&taft);
    TEST_MAIN_END();
}
