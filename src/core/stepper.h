/* Internal: the steppers of the restrained-rocking solver, in the manner
 * of GSL's step types (gsl_odeiv2_step_type): one table of operations per
 * way of stepping, all with one signature, so that the run loop (solve.c)
 * only evolves and a new integrator is one table more.
 *
 * A stage's steppers are chosen once, when the stage starts (at every
 * transition), as a chain: the first takes the step unless it declines,
 * and the next is asked then. The step's length, its check points and the
 * Dormand-Prince error control are the control's (control.c), apart from
 * the steps themselves; event location, tracking and history are the run
 * loop's, over the step's dense output. */
#ifndef RB_STEPPER_H
#define RB_STEPPER_H

#include "solver.h"

typedef enum {
    RB_STEP_DENSE,    /* st holds a step with its dense output, to advance over */
    RB_STEP_ADVANCED, /* the stepper advanced the run itself (*status says how) */
    RB_STEP_RETRY,    /* the control rejected the step: again from the same point */
    RB_STEP_DECLINED  /* not this stepper's step: the next in the chain takes it */
} rb_step_outcome;

typedef struct rb_stepper {
    const char *name;
    /* One step from the run's current point towards target (the next
     * break of the excitation or the end), which it never passes; h is
     * the control's trial length (rb_control_trial). */
    rb_step_outcome (*apply)(rb_solver *sv, double target, double h, rb_rk_step *st,
                             double *g, rb_status *status);
    /* After the run was advanced over the step to target, a break it
     * landed on: what the stepper keeps of the point, refreshed with the
     * excitation after the break; NULL where it keeps nothing. */
    void (*landed)(rb_solver *sv);
} rb_stepper;

/* The exact steps on the floor (exact.c), the Taylor series (steppers.c)
 * and Dormand-Prince 5(4) with its error control (steppers.c). */
extern const rb_stepper rb_stepper_exact;
extern const rb_stepper rb_stepper_exact_held; /* exact_held.c */
extern const rb_stepper rb_stepper_taylor;
extern const rb_stepper rb_stepper_rk45;

/* Whether the run loop (solve.c) would start another step from the run's
 * current point with nothing to report first (not done, not at the end, no
 * limit state to stop at, within the work bounds, the events' window
 * moved on as the loop moves it): a stepper that takes several steps in
 * one call (the quiet exact steps, exact.c) asks before each, and leaves
 * the rest to the loop where it is 0. */
int rb_run_goes_on(rb_solver *sv);

/* The chain of steppers of the current stage, at most RB_STEPPERS_MAX
 * (solver.h), the last never declining; returns how many. */
int rb_steppers_of_stage(const rb_solver *sv, const rb_stepper **chain);

#endif
