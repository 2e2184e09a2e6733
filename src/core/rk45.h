/* Internal: one Dormand-Prince 5(4) step with its 4th-order dense output.
 *
 * Chosen because the stages between transitions are smooth but nonlinear
 * (large-angle trigonometry, the th'^2 terms), the transitions must be found
 * as roots of guard functions between steps (the dense output gives the state
 * at any instant of the step at 4th order, Hairer-Norsett-Wanner II.6), and
 * FSAL makes an accepted step cost six evaluations. */
#ifndef RB_RK45_H
#define RB_RK45_H

#include "dynamics.h"
#include "taylor.h"

/* Most check points of one step (guards, peaks). */
#define RB_SUB_MAX 16

typedef struct {
    double t0, h;
    double t1;              /* end: t0 + h, or the break it lands on exactly */
    double y0[RB_NY], y1[RB_NY];
    double k[7][RB_NY];     /* stage derivatives; k[6] = f(t0 + h, y1) */
    double cont[5][RB_NY];  /* dense-output coefficients */
    rb_aux aux1;            /* what the evaluation of k[6] yields besides it */
    int n_sub;              /* check points of the step (guards, peaks) */
    int lands;              /* taken to land on the break it was taken towards */
    int is_taylor;          /* a Taylor step: the dense output is ts */
    rb_taylor ts;
    /* a Taylor step's series at its check points, what tracking reads */
    double vcheck[RB_SUB_MAX][RB_TS_CHECK];
} rb_rk_step;

/* Take a step of size h from (t0, y0) whose derivative f0 is known. Writes
 * the 5th-order solution to st->y1 and returns the scaled error norm
 * (accept when <= 1). scale[i] <= 0 leaves component i out of the norm.
 * The two stages at the step's end are evaluated at t_end: t0 + h, or just
 * short of a break the step lands on, so that they see the excitation's
 * value before a jump there (a pulse's end), not after it. */
double rb_rk_step_try(const rb_sys *S, const rb_disc *D, double t0, const double *y0,
                      const double *f0, double h, double t_end, const double *atol,
                      double rtol, rb_rk_step *st);

/* Prepare the dense output of an accepted step. */
void rb_rk_dense_init(rb_rk_step *st);

/* The state at time t in [t0, t0 + h]. */
void rb_rk_dense_eval(const rb_rk_step *st, double t, double *y);

/* Only the mechanical state (U, U', theta, theta') at t: what guards and
 * peaks read, at about half the cost. The work components are left alone. */
void rb_rk_dense_state(const rb_rk_step *st, double t, double *y);

/* Component c alone at t. */
double rb_rk_dense_one(const rb_rk_step *st, double t, int c);

#endif
