/* The check points study (docs/solver.md, "Check points a step"): a run
 * with fewer check points a step held to the runs with 4, 8 and 16, over
 * random cabinets.
 *   check_points_study [N_RANDOM [POINTS [TOL]]]   (from the source root)
 * N_RANDOM cabinets (default 120; 200-900 kg, 3-14 Hz, the reference
 * gap times 0.2-2, 0.05-0.5 A* of Taft or El Centro through a 3-15 Hz
 * building, 5 s, elastic-plastic and rigid-plastic rows in turn, rows
 * stretched past failure), drawn with a fixed seed, each solved with
 * POINTS (default 2) as the least check points a step and with 4, 8 and
 * 16. A rocking run is chaotic: a check point more or less moves an event
 * at the rounding level, its hops part ways after a while, and then every
 * count of points gives another answer, none of them better (one such
 * cabinet's peak U came out 0.03270 m with 3, 5 and 9 points, 0.03380 m
 * with 4, 6, 8 and 16). So each quantity is compared only where the runs
 * with 4, 8 and 16 points agree among themselves to 1e-5 (forces against
 * W, times against the run's 5 s, the rest relative); there POINTS must
 * fall inside their range. Each quantity outside it by more than the
 * range's width (and 1e-6) is printed; a last table gives the largest
 * distance outside the range for each quantity. With TOL, the exit code
 * is 1 where a quantity lies outside by more than the range's width and
 * TOL (the test validation_check_points: 120 cabinets, 2 points, 2e-5,
 * twice the widest range the three give among themselves). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "bench_common.h"
#include "rockbolt/record.h"
#include "rockbolt/solve.h"

enum { Q_USAGE, Q_THETA, Q_U, Q_SHEAR, Q_FORCE, Q_FRICTION, Q_REACTION, Q_OFF, Q_FIRST, Q_N };
static const char *names[Q_N] = {"usage", "peak theta", "peak U", "total shear", "row force",
                                 "friction demand", "least reaction", "time off floor",
                                 "first lift-off"};

static void quantities(const rb_result *r, double *q)
{
    q[Q_USAGE] = fmax(r->usage[0], r->usage[1]);
    q[Q_THETA] = r->max_theta_rad;
    q[Q_U] = r->max_u_m;
    q[Q_SHEAR] = r->max_shear_total_n;
    q[Q_FORCE] = fmax(r->max_bolt_force_n[0], r->max_bolt_force_n[1]);
    q[Q_FRICTION] = r->max_friction_demand;
    q[Q_REACTION] = r->min_vertical_reaction_n;
    q[Q_OFF] = r->liftoff_time_s;
    q[Q_FIRST] = r->liftoff_first_s;
}

static int run(const rb_model *m, const rb_motion *mo, int checks, double *q)
{
    rb_solve_opts o;
    rb_result r;
    rb_solve_opts_init(&o);
    o.stretch_past_failure = 1;
    o.min_checks = checks;
    int ok = rb_solve_run(m, mo, &o, &r, NULL) == RB_OK;
    if (ok)
        quantities(&r, q);
    rb_result_free(&r);
    return ok;
}

int main(int argc, char **argv)
{
    int n = argc > 1 ? atoi(argv[1]) : 120, points = argc > 2 ? atoi(argv[2]) : 2;
    double tol = argc > 3 ? atof(argv[3]) : HUGE_VAL;
    rb_series rec[2] = {{0}, {0}};
    if (n < 1 || points < 2
        || rb_bench_read_record("cases/records/taft_1952_s69e.txt", 1, &rec[0]) != 0
        || rb_bench_read_record("cases/records/elcentro_1940_ns.at2", 0, &rec[1]) != 0) {
        fprintf(stderr, "usage: check_points_study [N_RANDOM [POINTS]] (from the source "
                        "root; POINTS at least 2)\n");
        return 2;
    }
    unsigned long long seed = 20261128;
    double worst[Q_N] = {0}, spread_worst[Q_N] = {0};
    int settled[Q_N] = {0}, runs = 0, out = 0, failed = 0;
    for (int i = 0; i < n; i++) {
        rb_series floor = {0};
        double building = rb_bench_uniform(&seed, 3, 15);
        rb_model m;
        rb_derived d;
        rb_motion mo;
        rb_model_reference(&m);
        m.mass_kg = rb_bench_uniform(&seed, 200, 900);
        m.freq_hz = rb_bench_uniform(&seed, 3, 14);
        m.gap_m *= rb_bench_uniform(&seed, 0.2, 2);
        m.bolt_model = i % 4 < 2 ? RB_BOLT_ELASTIC_PLASTIC : RB_BOLT_RIGID_PLASTIC;
        double level = rb_bench_uniform(&seed, 0.05, 0.5);
        if (rb_series_copy(&rec[i % 2], &floor) != RB_OK
            || rb_series_building_filter(&floor, building, 0.05) != RB_OK
            || rb_model_derive(&m, &d, NULL) != RB_OK) {
            fprintf(stderr, "cabinet %d: not set up\n", i);
            failed++;
            rb_series_free(&floor);
            continue;
        }
        rb_motion_init(&mo);
        mo.kind = RB_MOTION_SAMPLED;
        mo.series = &floor;
        mo.scale = level * d.a_star_mps2 / rb_series_peak(&floor);
        mo.duration_s = 5.0;
        double qp[Q_N], q[3][Q_N];
        static const int more[3] = {4, 8, 16};
        int ok = run(&m, &mo, points, qp);
        for (int k = 0; k < 3; k++)
            ok = ok && run(&m, &mo, more[k], q[k]);
        rb_series_free(&floor);
        if (!ok) {
            fprintf(stderr, "cabinet %d: a run failed\n", i);
            failed++;
            continue;
        }
        runs++;
        for (int j = 0; j < Q_N; j++) {
            double s = j == Q_REACTION ? d.W : j >= Q_OFF ? mo.duration_s : fabs(q[2][j]);
            if (!(s > 0))
                continue;
            double lo = fmin(q[0][j], fmin(q[1][j], q[2][j]));
            double hi = fmax(q[0][j], fmax(q[1][j], q[2][j]));
            double spread = (hi - lo) / s;
            if (spread > 1e-5)
                continue;
            settled[j]++;
            spread_worst[j] = fmax(spread_worst[j], spread);
            double e = fmax(lo - qp[j], qp[j] - hi) / s;
            worst[j] = fmax(worst[j], e);
            failed += e > fmax(spread, tol);
            if (e > fmax(spread, 1e-6)) {
                out++;
                printf("  cabinet %d (%s, %.4g Hz building, %.4g A*): %s %.10g with %d points, "
                       "%.10g to %.10g with 4 to 16\n", i, i % 2 ? "El Centro" : "Taft",
                       building, level, names[j], qp[j], points, lo, hi);
            }
        }
    }
    rb_series_free(&rec[0]);
    rb_series_free(&rec[1]);
    printf("%d random cabinets, 5 s; %d points a step against 4, 8 and 16, where those agree "
           "to 1e-5:\n", runs, points);
    for (int j = 0; j < Q_N; j++)
        printf("  %-16s %3d settled: at most %.1e outside their range (%.1e wide)\n", names[j],
               settled[j], worst[j], spread_worst[j]);
    printf("%d quantities outside the range by more than its width\n", out);
    if (tol < HUGE_VAL)
        printf("%d outside it by more than its width and %g, or not run\n", failed, tol);
    return failed ? 1 : 0;
}
