/* Internal: exact steps of the fixed base (stage 1) under a sampled floor.
 *
 * On the floor the frame is a linear oscillator driven by the floor, and
 * the floor is a line between samples or a linear building driven by a
 * line (motion.h, rb_floor_line). Together they are one linear system
 * with constant coefficients, z = (U, U', u_b, v_b, g, g'), whose
 * transition over a step is a matrix exponential: formed once per step
 * length and run, it carries a step at the cost of a few dot products,
 * whatever the frame's frequency, where a Taylor step forms a series of
 * order ten or more. The work integrals (damping, input) are quadratic
 * forms of z at the step's start, with their Gramians formed alongside.
 *
 * The exact step keeps the Taylor step's length and check points, reads
 * the guards and tracks the sampled quantities at the same instants, and
 * hands the step back to the Taylor series wherever a root is to be
 * found inside it: a guard that crosses, a turn of the uplift moment that
 * could reach uplift, a turn of U' that could be a new peak. */
#ifndef RB_EXACT_H
#define RB_EXACT_H

#include "solver.h"
#include "stepper.h"

/* The components of z. */
enum { ZU, ZV, ZUB, ZVB, ZG, ZS, ZN = RB_EXACT_DIM };

/* The quantities bounded over a step (exact.c, "Bounds over a step"):
 * the rows of rb_exact_cache's lin and of a table's bounds. */
enum { RB_XQ_U, RB_XQ_SHEAR, RB_XQ_UP_POS, RB_XQ_UP_NEG };

/* One point of an exact step (exact_point.c): the state, the floor, U''
 * and the rate of the uplift moment M h x' - F* U''' (as
 * rb_taylor_held_force_rate on the floor), from z at its instant; and what
 * rb_dyn_rhs gives besides the derivatives there. The check points, the
 * bounds' forms and the peaks located between points all read these. */
typedef struct {
    double y[RB_NY], x, udd, rate;
} rb_exact_point;
void rb_exact_point_at(const rb_solver *sv, const double *z, rb_exact_point *p);
void rb_exact_aux_of(const rb_solver *sv, const rb_exact_point *p, rb_aux *a);

/* Decide whether the run's floor stage steps exactly (a sampled motion, a
 * flexible frame, the Taylor steps in use) and keep what every step reads:
 * the building and the run's constants. */
void rb_exact_setup(rb_solver *sv);

/* A run of quiet steps (exact.c, "Bounds over a step") reads nothing at
 * the steps' ends but the state and the works: what the guards, the rates
 * and the tracking read of the last one's end is read here, when anything
 * else is to read them (the next step that is not quiet, a Taylor step,
 * the end of the run). g, where not NULL, takes the guards at that end. */
void rb_exact_settle(rb_solver *sv, double *g);

/* Shared by the floor's exact steps and the held plate's (exact_held.c):
 * the table for steps of length h (NULL: a Taylor step); U and U' at the
 * end of a step from z0; the damping and input works over it added to *wd
 * and *wi; the time history's rows over it; the state at check point j;
 * the step counted. */
const rb_exact_table *rb_exact_table_of_length(rb_solver *sv, double h);
void rb_exact_end_state(const rb_exact_table *tab, const double *z0, double *u, double *v);
void rb_exact_work_forms(const rb_exact_table *tab, const double *z, double *wd, double *wi);
rb_status rb_exact_history(rb_solver *sv, double t0, const double *y0, double h, double t1);
void rb_exact_check_state(const rb_exact_table *tab, const rb_floor_line *fl, const double *z0,
                          int j, double *z);
void rb_exact_count_step(rb_solver *sv, double t1);
/* Whether table t bounds how far the held stage's quantities move over a
 * step (formed on first use; exact.c, held_bounds). */
int rb_exact_table_held(rb_solver *sv, rb_exact_table *t);

/* A quiet step of a plate held by a rigid row (exact_held.c): 1 when
 * taken, as exact_quiet takes one on the floor; 0 when the step is to be
 * a Taylor step (nothing changed). rb_exact_held_settle reads its end as
 * rb_exact_settle reads a quiet floor step's. */
int rb_exact_held_step(rb_solver *sv, double target, double *g, rb_status *status);
void rb_exact_held_settle(rb_solver *sv, double *g);
/* For rb_exact_probe_held: what a step of length h from the hold and
 * state of sv, with the floor's line state floor_z (u_b, v_b, g, s), can
 * reach by the held bounds, into range[RB_HELD_N]; 0 where no bound or
 * no checked frame. */
enum { RB_HELD_F_LO, RB_HELD_F_HI, RB_HELD_SHEAR_HI, RB_HELD_FLOOR_LO, RB_HELD_U_HI, RB_HELD_N };
int rb_exact_held_probe(rb_solver *sv, double h, const double *floor_z, double *range);

/* For tests (test_exact_held): a run's solver held by the rigid row on
 * side (+1 or -1) at the mirrored angle th, the frame at U and U' (uv),
 * the floor's line state floor_z: what a step of length h can reach
 * (rb_exact_held_probe). 0 where the run takes no exact steps or no bound
 * or frame was proved. */
int rb_exact_probe_held(const rb_model *model, const rb_motion *motion,
                        const rb_solve_opts *opts, double h, int side, double th,
                        const double *uv, const double *floor_z, double *range);

/* The held plate's quiet steps are a stepper of their own,
 * rb_stepper_exact_held (exact_held.c). An exact stepper's outcome: the
 * step taken, or declined with the end of the quiet steps before it read
 * for the next stepper. */
rb_step_outcome rb_exact_outcome(rb_solver *sv, int taken, double *g);

/* The exact step is a stepper (stepper.h): rb_stepper_exact, which
 * declines a step it cannot take (a root inside, a length it keeps no
 * table for), for the Taylor step to take. */

/* A table for steps of length h with n check points, with its bounds
 * (t->bounded says whether they were proved); the system matrix A of
 * dz/dt = A z. */
void rb_exact_table_build(rb_solver *sv, double h, int n, rb_exact_table *t);
/* The bounds of the four quantities over a step of table tab from z0,
 * less their value at z = 0: b[q] = sum_j bound[j][q] |z0_j|. */
void rb_exact_bounds_of(const rb_exact_table *tab, const double *z0, double *b);
void rb_exact_system(const rb_solver *sv, double a[RB_EXACT_DIM][RB_EXACT_DIM]);

/* For tests (test_exact_bounds, exact_probe.c): the bounds a run's exact step forms for
 * a step of length h from z0 = (U, U', u_b, v_b, g, s), for U, the total
 * shear and the two uplift guards less their value at z = 0, into
 * bound[4]; and the state at tau = k h / K, k = 0..K, from the system's
 * exponential at each instant (rb_matexp, not the table's rows), into
 * z_at[K + 1]. 0 where the run takes no exact steps or no bound was
 * proved (bound and z_at untouched). */
int rb_exact_probe(const rb_model *model, const rb_motion *motion, const rb_solve_opts *opts,
                   double h, const double *z0, int K, double *bound,
                   double (*z_at)[RB_EXACT_DIM]);

/* For tests (test_exact_turns): the instants tau in (0, h) where the total
 * shear turns on the step of length h from z0, as an exact step locates
 * its peaks (rb_exact_span_shear_turns, up to 8), into tau_turn, and the
 * state at each from the system's exponential (rb_matexp, not the
 * step's polynomial) into z_turn; the count, -1 where the run takes no
 * exact steps or the step's table keeps no polynomial. */
int rb_exact_probe_turns(const rb_model *model, const rb_motion *motion,
                         const rb_solve_opts *opts, double h, const double *z0,
                         double *tau_turn, double (*z_turn)[RB_EXACT_DIM]);

#endif
