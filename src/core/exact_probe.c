/* For tests: the bounds of an exact step (exact.h, rb_exact_probe),
 * apart from exact.c so that the run's setup it calls (solve.c) and the
 * steps it probes form no circle of calls. */
#include <math.h>
#include <stdlib.h>
#include "../motion/matexp.h"
#include "bolt.h"
#include "exact.h"

int rb_exact_probe(const rb_model *model, const rb_motion *motion, const rb_solve_opts *opts,
                   double h, const double *z0, int K, double *bound,
                   double (*z_at)[RB_EXACT_DIM])
{
    rb_solver *sv = malloc(sizeof *sv);
    rb_result res = {0};
    int ok = sv && rb_solver_setup(sv, model, motion, opts, &res, NULL) == RB_OK
             && sv->exact.on;
    if (ok) {
        rb_exact_table *t = &sv->exact.tab[0];
        rb_exact_table_build(sv, h, rb_step_checks(sv, h), t);
        ok = t->bounded;
    }
    if (ok) {
        double a[ZN][ZN], at[ZN][ZN], e[ZN][ZN];
        rb_exact_bounds_of(&sv->exact.tab[0], z0, bound);
        rb_exact_system(sv, a);
        for (int k = 0; k <= K; k++) {
            for (int i = 0; i < ZN; i++)
                for (int j = 0; j < ZN; j++)
                    at[i][j] = a[i][j] * h * k / K;
            rb_matexp(ZN, &at[0][0], &e[0][0]);
            for (int i = 0; i < ZN; i++) {
                z_at[k][i] = 0;
                for (int j = 0; j < ZN; j++)
                    z_at[k][i] += e[i][j] * z0[j];
            }
        }
    }
    if (sv)
        rb_history_free(res.history);
    free(sv);
    return ok;
}

int rb_exact_probe_turns(const rb_model *model, const rb_motion *motion,
                         const rb_solve_opts *opts, double h, const double *z0,
                         double *tau_turn, double (*z_turn)[RB_EXACT_DIM])
{
    rb_solver *sv = malloc(sizeof *sv);
    rb_result res = {0};
    int n = -1;
    if (sv && rb_solver_setup(sv, model, motion, opts, &res, NULL) == RB_OK && sv->exact.on) {
        rb_exact_table *t = &sv->exact.tab[0];
        rb_exact_table_build(sv, h, rb_step_checks(sv, h), t);
        sv->exact.n_tab = 1;
        rb_track_span_exact(sv, 0, sv->y, h, h, 0, z0);
        n = rb_exact_span_shear_turns(sv, 0, h, tau_turn, 8);
    }
    if (n > 0) {
        double a[ZN][ZN], at[ZN][ZN], e[ZN][ZN];
        rb_exact_system(sv, a);
        for (int k = 0; k < n; k++) {
            for (int i = 0; i < ZN; i++)
                for (int j = 0; j < ZN; j++)
                    at[i][j] = a[i][j] * tau_turn[k];
            rb_matexp(ZN, &at[0][0], &e[0][0]);
            for (int i = 0; i < ZN; i++) {
                z_turn[k][i] = 0;
                for (int j = 0; j < ZN; j++)
                    z_turn[k][i] += e[i][j] * z0[j];
            }
        }
    }
    if (sv)
        rb_history_free(res.history);
    free(sv);
    return n;
}

int rb_exact_probe_held(const rb_model *model, const rb_motion *motion,
                        const rb_solve_opts *opts, double h, int side, double th,
                        const double *uv, const double *floor_z, double *range)
{
    rb_solver *sv = malloc(sizeof *sv);
    rb_result res = {0};
    int ok = sv && rb_solver_setup(sv, model, motion, opts, &res, NULL) == RB_OK
             && sv->exact.on && sv->sys.bolt->rigid_stop;
    if (ok) {
        sv->disc.stage = RB_STAGE_HELD;
        sv->disc.side = side;
        sv->disc.theta_hold = th;
        sv->y[RB_Y_TH] = side * th;
        sv->y[RB_Y_THD] = 0;
        sv->y[RB_Y_U] = uv[0];
        sv->y[RB_Y_UD] = uv[1];
        ok = rb_exact_held_probe(sv, h, floor_z, range);
    }
    if (sv)
        rb_history_free(res.history);
    free(sv);
    return ok;
}
