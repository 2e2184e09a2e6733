/* Design checks on cases whose answer is known: the overturning threshold
 * of the rigid block under a triangular pulse (Table 2.2, eq. 2.17), the
 * static uplift level W b / (M h) of a stiff cabinet under a slow harmonic,
 * the static yield level A* of the same cabinet without a gap, the plate
 * rotation theta0 of a held plate against a rotation limit (gap
 * search), the damped SDOF amplification (frequency sweep); the same
 * numbers with 1, 2 and 3 threads; the sweep writers. */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <cjson/cJSON.h>
#include "harness.h"
#include "thesis_block.h"
#include "rockbolt/design.h"
#include "rockbolt/report.h"
#include "rockbolt/record.h"
#include "design/design_internal.h"

/* ---- Rigid block, triangular-decreasing pulse, p t1 = 7 ------------------ */

static void block_pulse(const rb_model *m, rb_motion *mo, rb_solve_opts *o)
{
    rb_derived d;
    rb_model_derive(m, &d, NULL);
    rb_motion_init(mo);
    mo->kind = RB_MOTION_PULSE;
    mo->pulse = RB_PULSE_TRI_DEC;
    mo->pulse_s = 7.0 / sqrt(d.W * d.R / d.Io);
    mo->amplitude_mps2 = d.g * d.alpha; /* the shape; the search rescales it */
    mo->duration_s = mo->pulse_s + 15.0;
    rb_solve_opts_init(o);
    o->formulation = RB_FORM_SMALL;
    o->rtol = 1e-10;
}

static void factor_finds_overturn_threshold(void)
{
    rb_model m;
    rb_motion mo;
    rb_solve_opts o;
    rb_criteria c;
    rb_design_opts d;
    rb_design_factor_result f;
    rb_derived dv;
    thesis_block_model(&m);
    block_pulse(&m, &mo, &o);
    rb_model_derive(&m, &dv, NULL);
    rb_criteria_init(&c); /* no break, no overturn: for a block, no overturn */
    rb_design_opts_defaults(&d);
    CHECK(rb_design_factor(&m, &mo, &o, &c, &d, 0, NULL, &f, NULL) == RB_OK);
    /* K in A*: a = K g alpha, A* = W b / (M h) for a block without bolts */
    double to_astar = dv.g * dv.alpha / dv.a_uplift_mps2;
    double k = thesis_eq_2_17(7.0);
    printf("block: level %.5f A*, fails at %.5f A* (eq. 2.17: %.5f A*), factor %.4f, "
           "%ld runs (%ld scan, %ld bisection, %ld speculative)\n", f.level_astar,
           f.fail_astar, k * to_astar, f.factor, f.runs, f.scan_runs, f.bisect_runs,
           f.runs_speculative);
    CHECK(!f.no_failure && !f.fails_at_start);
    CHECK(f.fail_astar - f.level_astar <= d.resolution);
    CHECK_NEAR(f.bracket_astar, f.fail_astar - f.level_astar, 1e-15);
    /* the solver's own threshold lies in [1.1662, 1.1668] (test_rigid_block) */
    CHECK(f.level_astar <= 1.1668 * to_astar && f.fail_astar >= 1.1662 * to_astar);
    CHECK_REL(0.5 * (f.level_astar + f.fail_astar), k * to_astar, 1e-3);
    CHECK_NEAR(f.first_fail_astar, 1.15, 1e-12);
    CHECK_NEAR(f.factor, 1.0 / f.level_astar, 1e-12);
    CHECK_NEAR(f.level_mps2, f.level_astar * dv.a_uplift_mps2, 1e-9);
    CHECK(f.a_star_mps2 == dv.a_uplift_mps2);
    CHECK(f.runs == f.scan_runs + f.bisect_runs && f.scan_runs == 23);
    CHECK(strstr(f.fail_reason, "overturns") != NULL);
    /* no failing level up to scan_end */
    d.scan_end = 0.5;
    CHECK(rb_design_factor(&m, &mo, &o, &c, &d, 2, NULL, &f, NULL) == RB_OK);
    CHECK(f.no_failure && f.level_astar == 0.5 && f.factor == 2.0);
    CHECK(f.fail_astar == HUGE_VAL && f.first_fail_astar == HUGE_VAL && f.runs == 10);
    char line[400];
    rb_design_factor_describe(&f, NULL, 0, line, sizeof line);
    printf("%s\n", line);
    CHECK(strstr(line, "no failing level up to scan_end (0.5 A*)") != NULL);
    CHECK(strstr(line, " m/s^2) at least") != NULL);
    /* a report in US customary units gives the level in g */
    rb_design_factor_describe(&f, rb_out_units_of(RB_UNITS_US), RB_G0, line, sizeof line);
    char want[80];
    snprintf(want, sizeof want, "(%.4g g) at least", f.level_mps2 / RB_G0);
    CHECK(strstr(line, want) != NULL);
}

/* ---- Stiff cabinet: uplift at W b / (M h) ---------------------------------- */

static void stiff_cabinet(rb_model *m, rb_motion *mo, rb_criteria *c)
{
    rb_model_reference(m);
    m->freq_hz = 50.0;   /* (0.5 / 50)^2: the frame's share is 1e-4 of the level */
    m->damping = 0.05;
    rb_motion_init(mo);
    mo->kind = RB_MOTION_HARMONIC;
    mo->freq_hz = 0.5;
    mo->ramp_s = 2.0;
    mo->duration_s = 4.0;
    mo->amplitude_mps2 = 1.0;
    rb_criteria_init(c);
    c->max_theta_over_alpha = 1e-12; /* any uplift fails */
}

static void factor_finds_uplift_level(void)
{
    rb_model m;
    rb_motion mo;
    rb_criteria c;
    rb_design_opts d;
    rb_design_factor_result f;
    rb_derived dv;
    stiff_cabinet(&m, &mo, &c);
    rb_model_derive(&m, &dv, NULL);
    rb_design_opts_defaults(&d);
    d.scan_start = 0.01;
    d.scan_step = 0.01;
    d.resolution = 1e-4;
    double want = dv.a_uplift_mps2 / dv.a_star_mps2;
    CHECK(rb_design_factor(&m, &mo, NULL, &c, &d, 2, NULL, &f, NULL) == RB_OK);
    printf("uplift: level %.6f A*, fails at %.6f A*, W b / (M h) = %.6f A*; %ld runs\n",
           f.level_astar, f.fail_astar, want, f.runs);
    CHECK(!f.no_failure && !f.fails_at_start && f.first_fail_astar == 0.04);
    CHECK(f.fail_astar - f.level_astar <= d.resolution);
    /* bracket holds the level, to 2e-4 of it for the frame's share */
    CHECK(f.level_astar <= want * (1 + 2e-4) && f.fail_astar >= want * (1 - 2e-4));
    /* the same level when the scan's first level already fails */
    d.scan_start = d.scan_step = 0.05;
    CHECK(rb_design_factor(&m, &mo, NULL, &c, &d, 2, NULL, &f, NULL) == RB_OK);
    printf("uplift from 0: level %.6f A*, fails at %.6f A*; %ld runs\n", f.level_astar,
           f.fail_astar, f.runs);
    CHECK(f.fails_at_start && f.scan_runs == 1 && f.first_fail_astar == 0.05);
    CHECK(f.fail_astar - f.level_astar <= d.resolution);
    CHECK(f.level_astar <= want * (1 + 2e-4) && f.fail_astar >= want * (1 - 2e-4));
}

/* Without a gap and under the same slow motion the held plate loads its bolt
 * row statically: it reaches Fy at exactly A*, so the factor is 1. The
 * non-yielding bolt reads its force against Fy; the rigid-plastic one
 * yields. */
static void factor_finds_static_yield(void)
{
    static const rb_bolt_model bolts[2] = {RB_BOLT_RIGID_PLASTIC, RB_BOLT_NONYIELDING};
    for (int k = 0; k < 2; k++) {
        rb_model m;
        rb_motion mo;
        rb_criteria c;
        rb_design_opts d;
        rb_design_factor_result f;
        stiff_cabinet(&m, &mo, &c);
        m.bolt_model = bolts[k];
        m.gap_m = 0;
        c.kind = RB_CRIT_NO_YIELD;
        c.max_theta_over_alpha = 0;
        rb_design_opts_defaults(&d);
        d.resolution = 1e-4;
        CHECK(rb_design_factor(&m, &mo, NULL, &c, &d, 0, NULL, &f, NULL) == RB_OK);
        printf("static yield (%s bolts): level %.5f A*, fails at %.5f A*: %s\n",
               k ? "non-yielding" : "rigid-plastic", f.level_astar, f.fail_astar,
               f.fail_reason);
        CHECK(f.first_fail_astar == 1.0 || f.first_fail_astar == 1.05);
        CHECK(f.fail_astar - f.level_astar <= d.resolution);
        CHECK(f.level_astar <= 1 + 2e-4 && f.fail_astar >= 1 - 2e-4);
        CHECK_NEAR(f.factor, 1.0, 3e-4);
    }
}

/* A resolution finer than doubles can resolve (1e-18 A*: doubles near
 * 0.04 are 6.9e-18 apart, so the bracket can never get that narrow) still
 * ends: the bisection stops where
 * a midpoint equals an end of the bracket, or after its bound on halvings.
 * Before the bound this looped for ever; alarm() turns a hang into a
 * failure. */
static void factor_resolution_below_doubles_ends(void)
{
    rb_model m;
    rb_motion mo;
    rb_criteria c;
    rb_design_opts d;
    rb_design_factor_result f;
    stiff_cabinet(&m, &mo, &c);
    rb_design_opts_defaults(&d);
    d.scan_start = 0.01;
    d.scan_step = 0.01;
    d.resolution = 1e-18;
    alarm(60);
    CHECK(rb_design_factor(&m, &mo, NULL, &c, &d, 2, NULL, &f, NULL) == RB_OK);
    alarm(0);
    printf("resolution 1e-18: level %.17g A*, fails at %.17g A*; %ld bisection runs\n",
           f.level_astar, f.fail_astar, f.bisect_runs);
    CHECK(!f.no_failure && f.level_astar < f.fail_astar);
    /* one ulp apart (or the halving bound, 200): never more runs than that */
    CHECK(f.bisect_runs <= 200);
    CHECK(nextafter(f.level_astar, 1.0) == f.fail_astar);
}

static void invalid_requests(void)
{
    rb_model m, block;
    rb_motion mo;
    rb_criteria c;
    rb_design_opts d;
    rb_design_factor_result f;
    rb_gap_result g;
    rb_diag diag;
    rb_series empty = {0};
    stiff_cabinet(&m, &mo, &c);
    rb_design_opts_defaults(&d);
    d.scan_step = 0;
    CHECK(rb_design_factor(&m, &mo, NULL, &c, &d, 1, NULL, &f, &diag) == RB_ERR_INVALID);
    CHECK(f.runs == 0 && strcmp(diag.key, "design") == 0);
    rb_design_opts_defaults(&d);
    CHECK(rb_design_factor(&m, &mo, NULL, NULL, &d, 1, NULL, &f, &diag) == RB_ERR_INVALID);
    d.gap_ratio_step = -1;
    CHECK(rb_gap_recommend(&m, &mo, NULL, &c, &d, 1, &g, &diag) == RB_ERR_INVALID);
    CHECK(g.points == NULL);
    rb_design_opts_defaults(&d);
    thesis_block_model(&block);
    CHECK(rb_gap_recommend(&block, &mo, NULL, &c, &d, 1, &g, &diag) == RB_ERR_INVALID);
    mo.kind = RB_MOTION_SAMPLED;
    mo.series = &empty;
    CHECK(rb_design_factor(&m, &mo, NULL, &c, &d, 1, NULL, &f, &diag) == RB_ERR_INVALID);
    CHECK(strcmp(diag.key, "motion") == 0);
    m.gap_m = 0.5; /* beyond alpha */
    mo.kind = RB_MOTION_HARMONIC;
    CHECK(rb_design_factor(&m, &mo, NULL, &c, &d, 1, NULL, &f, &diag) == RB_ERR_INVALID);
}

/* ---- Gap search against theta0 --------------------------------------------- */

/* Held by non-yielding bolts under a slow motion twice the uplift level,
 * the plate tips until it meets the bolt heads and stays there: the peak
 * rotation is theta0 = 2 asin(g / 2l), increasing with the gap. */
static void gap_search_known_rotation(void)
{
    rb_model m;
    rb_motion mo;
    rb_criteria c;
    rb_design_opts d;
    rb_gap_result g;
    rb_derived dv;
    stiff_cabinet(&m, &mo, &c);
    m.bolt_model = RB_BOLT_NONYIELDING;
    rb_model_derive(&m, &dv, NULL);
    mo.amplitude_mps2 = 2 * dv.a_uplift_mps2;
    c.max_theta_over_alpha = 2 * asin(0.03125 / 2) / dv.alpha; /* between 0.03 and 0.0325 */
    rb_design_opts_defaults(&d);
    CHECK(d.gap_ratio_max == 0.03 && d.max_gap_m == 6.35e-3);   /* 1/4 in */
    d.max_gap_m = 0;   /* the grid alone bounds the range here */
    CHECK(rb_gap_recommend(&m, &mo, NULL, &c, &d, 1, &g, NULL) == RB_OK);
    CHECK(g.found && g.gap_ratio == 0 && g.fail_index == -1 && g.n_points == 13);
    for (size_t i = 0; i < g.n_points; i++) {
        double th0 = 2 * asin(g.points[i].gap_ratio / 2);
        CHECK(g.points[i].evaluated && g.points[i].meets);
        CHECK_NEAR(g.points[i].max_theta_over_alpha, th0 / dv.alpha, 2e-3 * th0 / dv.alpha);
    }
    CHECK(g.runs == 14 && g.yield_run);
    char line[512];
    rb_gap_describe(&g, NULL, line, sizeof line);
    CHECK(strstr(line, "recommended gap ratio 0 (gap 0 mm)") != NULL);
    rb_gap_describe(&g, rb_out_units_of(RB_UNITS_US), line, sizeof line);
    CHECK(strstr(line, "recommended gap ratio 0 (gap 0 in)") != NULL);
    rb_gap_result_free(&g);
    /* wider range: the largest gaps rotate too far; the case's own gap
     * ratio 0.01 (rotation 0.01 rad, below the limit's 0.03125) is run all
     * the same, passes, and is the recommendation */
    d.gap_ratio_max = 0.06;
    CHECK(rb_gap_recommend(&m, &mo, NULL, &c, &d, 1, &g, NULL) == RB_OK);
    CHECK(g.found && g.own_only && g.own_meets && g.gap_ratio == 0.01);
    CHECK(g.fail_index == 24 && g.runs == 3 && g.points[24].evaluated);
    CHECK(!g.points[24].meets && !g.points[23].evaluated && g.points[4].evaluated);
    CHECK(g.bound == RB_GAP_BOUND_RATIO && g.range_max == g.points[24].gap_ratio);
    rb_gap_describe(&g, NULL, line, sizeof line);
    printf("%s\n", line);
    CHECK(strstr(line, "the case's own: it meets the criteria, and the larger gap ratio "
                       "0.06 fails (searched [0, 0.06], bounded by design.gap_ratio_max)")
          != NULL);
    rb_gap_result_free(&g);
    /* the default bound: 6.35 mm over the lever arm 0.78 m = 0.00814, so
     * the grid ends at 0.0075 and the own gap 0.01 above it joins it */
    d.gap_ratio_max = 0.03;
    d.max_gap_m = 6.35e-3;
    CHECK(rb_gap_recommend(&m, &mo, NULL, &c, &d, 1, &g, NULL) == RB_OK);
    CHECK(g.bound == RB_GAP_BOUND_MAX_GAP && g.own_above && g.n_points == 5);
    CHECK(g.points[3].gap_ratio == 0.0075 && g.range_max == 0.01 && g.found);
    rb_gap_result_free(&g);
    rb_gap_result_free(NULL);
}

/* ---- El Centro: consistency and determinism ---------------------------------- */

static int elcentro(rb_series *s, rb_motion *mo, const rb_model *m, double level)
{
    rb_record_opts ro;
    rb_derived d;
    rb_record_opts_init(&ro);
    if (rb_record_read("cases/records/elcentro_1940_ns.at2", &ro, s, NULL) != RB_OK
        || rb_series_building_filter(s, 5.0, 0.05) != RB_OK
        || rb_series_window(s, 0.0, 12.0) != RB_OK)
        return 0;
    rb_model_derive(m, &d, NULL);
    rb_motion_init(mo);
    mo->kind = RB_MOTION_SAMPLED;
    mo->series = s;
    mo->scale = level * d.a_star_mps2 / rb_series_peak(s);
    mo->duration_s = 12.0;
    return 1;
}

static int run_meets(const rb_model *m, const rb_motion *mo, const rb_criteria *c)
{
    rb_result r;
    rb_verdict v;
    int ok = rb_solve_run(m, mo, NULL, &r, NULL) == RB_OK;
    if (ok)
        rb_judge(c, &r, &v);
    ok = ok && v.pass;
    rb_result_free(&r);
    return ok;
}

static void gap_search_consistent(const rb_model *m, const rb_motion *mo)
{
    rb_criteria c;
    rb_design_opts d;
    rb_gap_result g[3];
    rb_criteria_init(&c);
    c.kind = RB_CRIT_NO_YIELD;
    rb_design_opts_defaults(&d);
    d.gap_ratio_max = 0.06;   /* the thesis's grid */
    d.max_gap_m = 0;
    for (int t = 0; t < 3; t++)
        CHECK(rb_gap_recommend(m, mo, NULL, &c, &d, t + 1, &g[t], NULL) == RB_OK);
    printf("El Centro 0.3 A*: recommended gap ratio %.4f, %ld runs; yielding run final "
           "gaps %.4f / %.4f\n", g[0].gap_ratio, g[0].runs, g[0].yield_final_gap_ratio[0],
           g[0].yield_final_gap_ratio[1]);
    CHECK(g[0].found && g[0].fail_index >= 0);
    for (size_t i = 0; i < g[0].n_points; i++)
        CHECK(g[0].points[i].evaluated == ((long)i >= g[0].fail_index
                                           || g[0].points[i].gap_ratio == g[0].own_gap_ratio));
    /* the recommendation and the gap below it, run directly */
    rb_model mm = *m;
    mm.gap_m = g[0].gap_ratio * m->lever_arm_m;
    CHECK(run_meets(&mm, mo, &c));
    mm.gap_m = g[0].points[g[0].fail_index].gap_ratio * m->lever_arm_m;
    CHECK(!run_meets(&mm, mo, &c));
    for (int t = 1; t < 3; t++) {
        CHECK(g[t].found == g[0].found && g[t].gap_ratio == g[0].gap_ratio);
        CHECK(g[t].runs == g[0].runs && g[t].fail_index == g[0].fail_index);
        CHECK(memcmp(g[t].points, g[0].points, g[0].n_points * sizeof *g[0].points) == 0);
        CHECK(memcmp(g[t].yield_final_gap_ratio, g[0].yield_final_gap_ratio,
                     sizeof g[0].yield_final_gap_ratio) == 0);
    }
    for (int t = 0; t < 3; t++)
        rb_gap_result_free(&g[t]);
}

static void factor_deterministic(const rb_model *m, const rb_motion *mo)
{
    rb_criteria c;
    rb_design_opts d;
    rb_design_factor_result f[3];
    rb_criteria_init(&c);
    c.kind = RB_CRIT_NO_YIELD;
    rb_design_opts_defaults(&d);
    d.gap_ratio_max = 0.06;   /* the thesis's grid */
    d.max_gap_m = 0;
    for (int t = 0; t < 3; t++)
        CHECK(rb_design_factor(m, mo, NULL, &c, &d, t + 1, NULL, &f[t], NULL) == RB_OK);
    printf("El Centro no-yield factor %.4f (level %.5f A*), %ld runs; speculative with "
           "1/2/3 threads: %ld/%ld/%ld\n", f[0].factor, f[0].level_astar, f[0].runs,
           f[0].runs_speculative, f[1].runs_speculative, f[2].runs_speculative);
    CHECK(f[0].runs_speculative == 0);
    for (int t = 0; t < 3; t++)
        f[t].runs_speculative = 0;
    CHECK(memcmp(&f[1], &f[0], sizeof f[0]) == 0);
    CHECK(memcmp(&f[2], &f[0], sizeof f[0]) == 0);
    /* the verdicts the search relied on hold in direct runs */
    rb_motion at = *mo;
    double peak = mo->scale * rb_series_peak(mo->series);
    at.scale = mo->scale * f[0].level_mps2 / peak;
    CHECK(run_meets(m, &at, &c));
    at.scale = mo->scale * f[0].fail_mps2 / peak;
    CHECK(!run_meets(m, &at, &c));
}

/* What the memo tests search with: no-break criteria, the default scan,
 * and an amplitude sweep from 0.05 A* to `to` in n points. */
static void shared_setup(rb_criteria *cb, rb_design_opts *d, rb_sweep_opts *so, double to,
                         size_t n)
{
    rb_criteria_init(cb);
    cb->kind = RB_CRIT_NO_BREAK;
    rb_design_opts_defaults(d);
    rb_sweep_opts_init(so, RB_SWEEP_AMPLITUDE);
    so->from = 0.05;
    so->to = to;
    so->n_points = n;
}

/* Searches sharing a memo give the results they give alone, bit for bit,
 * and the second factor search finds the first one's scan levels there. */
static void memo_changes_nothing(const rb_model *m, const rb_motion *mo)
{
    rb_criteria cy, cb;
    rb_design_opts d;
    rb_sweep_opts so;
    rb_design_factor_result alone[2], shared[2];
    rb_sweep sw_alone, sw_shared;
    rb_design_memo *memo = rb_design_memo_new();
    CHECK(memo != NULL);
    shared_setup(&cb, &d, &so, 0.3, 6);
    cy = cb;
    cy.kind = RB_CRIT_NO_YIELD;
    CHECK(rb_design_factor(m, mo, NULL, &cy, &d, 2, NULL, &alone[0], NULL) == RB_OK);
    CHECK(rb_design_factor(m, mo, NULL, &cb, &d, 2, NULL, &alone[1], NULL) == RB_OK);
    CHECK(rb_sweep_amplitude(m, mo, NULL, &cb, &so, 2, NULL, &sw_alone, NULL) == RB_OK);
    CHECK(rb_design_factor(m, mo, NULL, &cy, &d, 2, memo, &shared[0], NULL) == RB_OK);
    size_t after_first = rb_design_memo_runs(memo);
    CHECK(rb_design_factor(m, mo, NULL, &cb, &d, 2, memo, &shared[1], NULL) == RB_OK);
    size_t after_second = rb_design_memo_runs(memo);
    CHECK(rb_sweep_amplitude(m, mo, NULL, &cb, &so, 2, memo, &sw_shared, NULL) == RB_OK);
    size_t after_sweep = rb_design_memo_runs(memo);
    printf("memo: %zu runs after the no-yield factor, %zu after no-break (%ld runs asked), "
           "%zu after a %zu-point sweep\n", after_first, after_second, alone[1].runs,
           after_sweep, so.n_points);
    /* the second search alone, in a memo of its own: how many solves it
     * makes, its confirming runs included */
    rb_design_factor_result again;
    rb_design_memo *memo_b = rb_design_memo_new();
    CHECK(memo_b != NULL);
    CHECK(rb_design_factor(m, mo, NULL, &cb, &d, 2, memo_b, &again, NULL) == RB_OK);
    size_t second_alone = rb_design_memo_runs(memo_b);
    rb_design_memo_free(memo_b);
    printf("memo: the no-break factor alone solves %zu runs\n", second_alone);
    /* every scan level of the first search is asked again by the second */
    CHECK(after_first >= (size_t)alone[0].runs);
    CHECK(after_second - after_first < second_alone);
    CHECK(after_sweep - after_second < so.n_points);
    for (int i = 0; i < 2; i++) {
        alone[i].runs_speculative = shared[i].runs_speculative = 0;
        CHECK(memcmp(&alone[i], &shared[i], sizeof alone[i]) == 0);
    }
    CHECK(sw_alone.n_points == sw_shared.n_points);
    if (sw_alone.n_points == sw_shared.n_points)
        CHECK(memcmp(sw_alone.points, sw_shared.points,
                     sw_alone.n_points * sizeof *sw_alone.points) == 0);
    rb_sweep_free(&sw_alone);
    rb_sweep_free(&sw_shared);
    rb_design_memo_free(memo);
}

/* A sweep's levels, from + (to - from) i / (n - 1), land on the scan's
 * start + k step wherever the two name the same level, however the two
 * round: 0.15, 0.35 and 0.4 of 0.05 to 0.6 in 12 points differ from the
 * scan's doubles in the last bit. Without criteria nothing is confirmed,
 * so the sweep's solves are exactly its levels the scan did not reach. */
static void sweep_levels_meet_scan(const rb_model *m, const rb_motion *mo)
{
    rb_criteria cb;
    rb_design_opts d;
    rb_sweep_opts so;
    rb_design_factor_result f;
    rb_sweep sw;
    rb_design_memo *memo = rb_design_memo_new();
    CHECK(memo != NULL);
    shared_setup(&cb, &d, &so, 0.6, 12);
    CHECK(rb_design_factor(m, mo, NULL, &cb, &d, 2, memo, &f, NULL) == RB_OK);
    size_t before = rb_design_memo_runs(memo);
    CHECK(rb_sweep_amplitude(m, mo, NULL, NULL, &so, 2, memo, &sw, NULL) == RB_OK);
    size_t solved = rb_design_memo_runs(memo) - before, unscanned = 0;
    for (size_t i = 0; i < sw.n_points; i++)
        unscanned += sw.points[i].x > f.first_fail_astar * (1 + 1e-12);
    printf("sweep of 12 levels after a scan to %.2f A*: %zu solved, %zu above the scan\n",
           f.first_fail_astar, solved, unscanned);
    CHECK(unscanned < so.n_points);
    CHECK(solved == unscanned);
    rb_sweep_free(&sw);
    rb_design_memo_free(memo);
}

static void elcentro_checks(void)
{
    rb_series s = {0};
    rb_model m;
    rb_motion mo;
    rb_model_reference(&m);
    CHECK(elcentro(&s, &mo, &m, 0.3));
    if (s.n) {
        factor_deterministic(&m, &mo);
        gap_search_consistent(&m, &mo);
        memo_changes_nothing(&m, &mo);
        sweep_levels_meet_scan(&m, &mo);
    }
    rb_series_free(&s);
}

/* ---- Sweeps -------------------------------------------------------------------- */

static void frequency_sweep_sdof(void)
{
    rb_model m;
    rb_sweep_opts o;
    rb_sweep s[2];
    rb_derived dv;
    rb_model_reference(&m);
    m.damping = 0.05;
    rb_model_derive(&m, &dv, NULL);
    rb_sweep_opts_init(&o, RB_SWEEP_FREQUENCY);
    o.from = 0.2;
    o.to = 0.6;
    o.n_points = 3;
    o.amplitude_astar = 0.2 * dv.a_uplift_mps2 / dv.a_star_mps2; /* never uplifts */
    /* the kink at the end of the ramp starts a free vibration that adds
     * about r^2 / (omega T) to the peak: 0.5 % at r = 0.6 */
    o.ramp_s = 10.0;
    o.duration_s = 14.0;
    for (int t = 0; t < 2; t++)
        CHECK(rb_sweep_frequency(&m, NULL, NULL, &o, t + 1, &s[t], NULL) == RB_OK);
    CHECK(s[0].n_points == 3 && s[0].kind == RB_SWEEP_FREQUENCY);
    for (size_t i = 0; i < s[0].n_points; i++) {
        const rb_sweep_point *p = &s[0].points[i];
        double r = p->x;
        /* steady state N* a / K* over U_static = pi^2 a / (8 omega^2): 32 / pi^3 */
        double want = 32 / (M_PI * M_PI * M_PI)
                      / sqrt(pow(1 - r * r, 2) + pow(2 * 0.05 * r, 2));
        printf("sweep r = %.2f: U/U_static %.4f (SDOF %.4f), force/Fy %.3f/%.3f\n", r,
               p->max_u_over_ustatic, want, p->max_force_over_fy[0], p->max_force_over_fy[1]);
        CHECK(p->status == RB_OK && p->meets == -1);
        CHECK_NEAR(p->freq_hz, r * 5.0, 1e-12);
        CHECK_NEAR(p->level_astar, o.amplitude_astar, 1e-12);
        CHECK_REL(p->max_u_over_ustatic, want, 0.01);
        CHECK(p->max_theta_over_alpha == 0 && !p->yielded[0] && !p->overturned);
    }
    CHECK(memcmp(s[0].points, s[1].points, 3 * sizeof *s[0].points) == 0);
    rb_sweep_free(&s[0]);
    rb_sweep_free(&s[1]);
    rb_sweep_free(NULL);
    /* a rigid model has no frequency to sweep */
    m.rigid = 1;
    CHECK(rb_sweep_frequency(&m, NULL, NULL, &o, 1, &s[0], NULL) == RB_ERR_INVALID);
}

static int count_lines(FILE *fp)
{
    int n = 0, ch;
    rewind(fp);
    while ((ch = fgetc(fp)) != EOF)
        n += ch == '\n';
    return n;
}

static void writers(const rb_sweep *s)
{
    FILE *fp = tmpfile();
    CHECK(fp && rb_sweep_write_csv(s, fp) == RB_OK);
    if (fp) {
        CHECK(count_lines(fp) == (int)s->n_points + 1);
        fclose(fp);
    }
}

static void amplitude_sweep_block(void)
{
    rb_model m;
    rb_motion mo;
    rb_solve_opts so;
    rb_criteria c;
    rb_sweep_opts o;
    rb_sweep s;
    rb_derived dv;
    thesis_block_model(&m);
    block_pulse(&m, &mo, &so);
    rb_model_derive(&m, &dv, NULL);
    rb_criteria_init(&c);
    rb_sweep_opts_init(&o, RB_SWEEP_AMPLITUDE);
    double kt = thesis_eq_2_17(7.0) * dv.g * dv.alpha / dv.a_uplift_mps2;
    /* no point on the threshold itself: there the block reaches alpha
     * asymptotically, and whether it goes over is integration noise (the
     * two integrators at rtol 1e-10 stop 2e-5 alpha apart) */
    o.from = kt - 0.025;
    o.to = kt + 0.015;
    o.n_points = 5;
    if (rb_sweep_amplitude(&m, &mo, &so, &c, &o, 0, NULL, &s, NULL) != RB_OK) {
        CHECK(!"amplitude sweep");
        return;
    }
    for (size_t i = 0; i < s.n_points; i++) {
        const rb_sweep_point *p = &s.points[i];
        CHECK(p->status == RB_OK);
        CHECK_NEAR(p->level_astar, p->x, 1e-12);
        printf("block sweep %.5f A*: status %d, overturned %d, meets %d\n", p->x, p->status,
               p->overturned, p->meets);
        CHECK(p->overturned == (i > 2) && p->meets == (i <= 2));
    }
    writers(&s);
    rb_sweep_free(&s);
}

/* A run claimed by one search is waited for by another that asks for it,
 * which then gets the claimer's result, not a solve of its own; a claim
 * given up passes to the one waiting. */
typedef struct {
    rb_design_memo *memo;
    const rb_model *m;
    const rb_motion *mo;
    const rb_solve_opts *o;
    rb_design_memo_claim got;
    rb_status st;
    rb_result r;
} memo_asker;

static void *memo_ask(void *v)
{
    memo_asker *a = v;
    a->got = rb_design_memo_take(a->memo, a->m, a->mo, a->o, &a->st, &a->r);
    return NULL;
}

static void memo_claims_wait(void)
{
    rb_model m;
    rb_motion mo;
    rb_solve_opts o;
    rb_model_init(&m);
    rb_motion_init(&mo);
    rb_solve_opts_init(&o);
    mo.kind = RB_MOTION_HARMONIC;
    mo.amplitude_mps2 = 3;
    mo.freq_hz = 2;
    rb_design_memo *memo = rb_design_memo_new();
    CHECK(memo != NULL);
    rb_status st;
    rb_result r, kept;
    memset(&kept, 0, sizeof kept);
    kept.max_theta_over_alpha = 0.25;
    kept.usage[1] = 0.5;
    CHECK(rb_design_memo_take(memo, &m, &mo, &o, &st, &r) == RB_MEMO_CLAIMED);
    memo_asker a;
    memset(&a, 0, sizeof a);
    a.memo = memo;
    a.m = &m;
    a.mo = &mo;
    a.o = &o;
    pthread_t t;
    CHECK(pthread_create(&t, NULL, memo_ask, &a) == 0);
    usleep(50000);
    /* still waiting: nothing is held yet */
    CHECK(rb_design_memo_runs(memo) == 0);
    rb_design_memo_put(memo, &m, &mo, &o, RB_ERR_LIMIT, &kept);
    pthread_join(t, NULL);
    CHECK(a.got == RB_MEMO_HIT && a.st == RB_ERR_LIMIT);
    CHECK(a.r.max_theta_over_alpha == 0.25 && a.r.usage[1] == 0.5);
    CHECK(rb_design_memo_runs(memo) == 1);

    /* another run: claimed, then given up, so the waiter claims it */
    mo.freq_hz = 3;
    CHECK(rb_design_memo_take(memo, &m, &mo, &o, &st, &r) == RB_MEMO_CLAIMED);
    a.got = RB_MEMO_SOLVE;
    CHECK(pthread_create(&t, NULL, memo_ask, &a) == 0);
    usleep(50000);
    rb_design_memo_release(memo, &m, &mo, &o);
    pthread_join(t, NULL);
    CHECK(a.got == RB_MEMO_CLAIMED);
    rb_design_memo_put(memo, &m, &mo, &o, RB_OK, &kept);
    CHECK(rb_design_memo_take(memo, &m, &mo, &o, &st, &r) == RB_MEMO_HIT && st == RB_OK);
    CHECK(rb_design_memo_runs(memo) == 2);
    rb_design_memo_free(memo);
}

int main(void)
{
    memo_claims_wait();
    factor_finds_overturn_threshold();
    factor_finds_uplift_level();
    factor_finds_static_yield();
    factor_resolution_below_doubles_ends();
    invalid_requests();
    gap_search_known_rotation();
    elcentro_checks();
    frequency_sweep_sdof();
    amplitude_sweep_block();
    TEST_MAIN_END();
}
