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

/* The components of z. */
enum { ZU, ZV, ZUB, ZVB, ZG, ZS, ZN = RB_EXACT_DIM };

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
