/* Design benchmark: wall time of a full design of the reference cabinet
 * under the El Centro 1940 N-S floor motion (5 Hz, 5 % building, scaled to
 * 0.4 A*): the design factor for both criteria (bolts stay elastic; bolts
 * may yield but not break) and the recommended gap ratio. Prints the
 * figures and the time of each part, then times the same searches as
 * `rockbolt design cases/reference-elcentro.yaml` runs them, and the whole
 * of cases/reference-design.yaml (its sweeps and code inputs too). Usage:
 * bench_design [RECORD] [THREADS], from the source root. Targets: the
 * whole design in under 1 s, reference-design.yaml in under 0.2 s (the
 * searches here; bench/design-command.sh times the whole command, its
 * check, loading and report included). */
#include <stdio.h>
#include <stdlib.h>
#include "rockbolt/design.h"
#include "rockbolt/case.h"
#include "rockbolt/run.h"
#include "bench_common.h"

static int factor(const char *name, const rb_model *m, const rb_motion *mo,
                  rb_criterion_kind kind, const rb_design_opts *d, int nt)
{
    rb_criteria c;
    rb_design_factor_result f;
    rb_diag diag;
    rb_criteria_init(&c);
    c.kind = kind;
    double t0 = rb_bench_now_s();
    rb_status st = rb_design_factor(m, mo, NULL, &c, d, nt, NULL, &f, &diag);
    double t = rb_bench_now_s() - t0;
    if (st != RB_OK) {
        fprintf(stderr, "design factor (%s): %s: %s\n", name, rb_status_str(st), diag.msg);
        return -1;
    }
    printf("design factor, %-9s %6.2f  (withstands %.4f A* = %.3f g; first failing scan "
           "level %.2f A*; fails at %.4f A*: %s)\n", name, f.factor, f.level_astar,
           f.level_mps2 / RB_G0, f.first_fail_astar, f.fail_astar, f.fail_reason);
    printf("  %ld runs (%ld scan, %ld bisection, %ld speculative), %.3f s\n", f.runs,
           f.scan_runs, f.bisect_runs, f.runs_speculative, t);
    return 0;
}

static int gap(const rb_model *m, const rb_motion *mo, const rb_design_opts *d, int nt)
{
    rb_criteria c;
    rb_gap_result g;
    rb_diag diag;
    rb_criteria_init(&c);
    c.kind = RB_CRIT_NO_YIELD;
    double t0 = rb_bench_now_s();
    rb_status st = rb_gap_recommend(m, mo, NULL, &c, d, nt, &g, &diag);
    double t = rb_bench_now_s() - t0;
    if (st != RB_OK) {
        fprintf(stderr, "gap: %s: %s\n", rb_status_str(st), diag.msg);
        return -1;
    }
    if (g.found)
        printf("recommended gap ratio %.4f (bolts stay elastic from there to %.4f)\n",
               g.gap_ratio, d->gap_ratio_max);
    else
        printf("recommended gap ratio: none in [%.4f, %.4f]\n", d->gap_ratio_min,
               d->gap_ratio_max);
    printf("  yielding run at g_r = %.4f: final gap ratios L/R %.4f / %.4f, usage "
           "%.3f / %.3f\n", g.yield_initial_gap_ratio, g.yield_final_gap_ratio[0],
           g.yield_final_gap_ratio[1], g.yield_usage[0], g.yield_usage[1]);
    printf("  grid (+ meets, - fails, . not needed):");
    for (size_t i = 0; i < g.n_points; i++)
        printf(" %.4f%s", g.points[i].gap_ratio,
               !g.points[i].evaluated ? "." : g.points[i].meets ? "+" : "-");
    printf("\n  %ld runs (%ld speculative), %.3f s\n", g.runs, g.runs_speculative, t);
    rb_gap_result_free(&g);
    return 0;
}

/* What `rockbolt design CASE` runs after the check: rb_run_design on the
 * loaded case (both factors, the gap, and any sweeps and code inputs the
 * case carries). The loading is timed apart: it is the record read and
 * the building filter, paid once per command. */
static int whole_case(const char *case_path, int nt, double target_s)
{
    rb_case c;
    rb_diag_list dl = {0};
    rb_case_design cd;
    rb_diag diag;
    double t0 = rb_bench_now_s(), t_load, t_design;
    rb_status st = rb_case_load(case_path, &c, &dl);
    rb_diag_list_free(&dl);
    if (st != RB_OK) {
        fprintf(stderr, "%s: %s\n", case_path, rb_status_str(st));
        return -1;
    }
    t_load = rb_bench_now_s() - t0;
    t0 = rb_bench_now_s();
    st = rb_run_design(&c, nt, &cd, &diag, NULL, NULL);
    t_design = rb_bench_now_s() - t0;
    if (st == RB_OK)
        printf("rockbolt design %s: load %.3f s, searches %.3f s, total %.3f s "
               "(target %g s: %s); factors %.2f / %.2f\n", case_path, t_load, t_design,
               t_load + t_design, target_s, t_load + t_design < target_s ? "met" : "NOT met",
               cd.motions[0].factor[RB_CRIT_NO_YIELD].factor,
               cd.motions[0].factor[RB_CRIT_NO_BREAK].factor);
    else
        fprintf(stderr, "design: %s: %s: %s\n", rb_status_str(st), diag.key, diag.msg);
    rb_case_design_free(&cd);
    rb_case_free(&c);
    return st == RB_OK ? 0 : -1;
}

int main(int argc, char **argv)
{
    const char *path = argc > 1 ? argv[1] : "cases/records/elcentro_1940_ns.at2";
    int nt = argc > 2 ? atoi(argv[2]) : 0;
    rb_series s = {0};
    rb_model m;
    rb_derived dv;
    rb_motion mo;
    rb_design_opts d;
    if (rb_bench_floor_motion(path, &s) != 0)
        return 2;
    rb_model_reference(&m);
    rb_model_derive(&m, &dv, NULL);
    rb_motion_init(&mo);
    mo.kind = RB_MOTION_SAMPLED;
    mo.series = &s;
    mo.scale = 0.4 * dv.a_star_mps2 / rb_series_peak(&s);
    mo.duration_s = s.t0_s + (double)s.n * s.dt_s;
    rb_design_opts_defaults(&d);
    printf("reference cabinet (A* = %.2f g, g_r = %.4f), %s through a 5 Hz, 5 %% "
           "building, %.1f s, at 0.4 A*; %d threads\n", dv.a_star_mps2 / RB_G0,
           m.gap_m / m.lever_arm_m, path, mo.duration_s,
           nt > 0 ? nt : rb_design_threads_default());
    double t0 = rb_bench_now_s();
    int rc = factor("no-yield", &m, &mo, RB_CRIT_NO_YIELD, &d, nt)
             || factor("no-break", &m, &mo, RB_CRIT_NO_BREAK, &d, nt)
             || gap(&m, &mo, &d, nt);
    double t = rb_bench_now_s() - t0;
    printf("full design         %.3f s (target 1 s: %s)\n", t, t < 1.0 ? "met" : "NOT met");
    if (!rc)
        rc = whole_case("cases/reference-elcentro.yaml", nt, 1.0);
    /* issue 16's target: the design case with its sweeps and code inputs,
     * the whole command on two cores */
    if (!rc)
        rc = whole_case("cases/reference-design.yaml", nt, 0.2);
    rb_series_free(&s);
    return rc ? 3 : 0;
}
