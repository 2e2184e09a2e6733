/* Internal: one step of the Taylor-series integrator, for the stages whose
 * equations are polynomial in U, U', theta' and in cos theta, sin theta and
 * of the half angle (stages 1, 2 and 4 with rigid rows; 1, 2, 4 and 5 with
 * rows that are springs in the chord; large and small formulations).
 *
 * The floor acceleration between two breaks is a polynomial (a sampled
 * record is linear between samples) or a sine, so the solution over a step
 * is an entire function of time whose Taylor coefficients follow from the
 * equations by the usual recurrences (cos and sin of theta by
 * s' = c theta', c' = -s theta'). The order adapts to the step: a step runs
 * to the next sample, and the series is carried until its last two terms
 * are within the tolerance there. The coupled 13 Hz mode of stage 2 that
 * held Dormand-Prince to 35 steps a period then costs one step per sample
 * interval. The polynomial is also the dense output: guards, peaks and
 * history read it at any instant of the step. */
#ifndef RB_TAYLOR_H
#define RB_TAYLOR_H
#include "dynamics.h"

#define RB_TAYLOR_MAX 32

/* Series kept per power of tau, all components side by side, so that one
 * Horner pass evaluates all of them at once (and vectorizes). The first
 * RB_TS_CHECK are what guards and peak tracking read at a check point. */
enum {
    RB_TS_U, RB_TS_UD, RB_TS_TH, RB_TS_THD, /* physical state, as RB_Y_* */
    RB_TS_X,           /* physical floor acceleration */
    RB_TS_COS,         /* cos and sin of the mirrored angle */
    RB_TS_SIN,
    RB_TS_UDD,         /* physical U'' and theta'' */
    RB_TS_THDD,
    RB_TS_Z,           /* the floor's vertical acceleration z'' (0 without) */
    RB_TS_CHECK,
    RB_TS_WDAMP = RB_TS_CHECK, RB_TS_WIN, RB_TS_WCPL,
    RB_TS_N
};

typedef struct {
    int order;                                /* highest power kept */
    double p[RB_TAYLOR_MAX + 2][RB_TS_N];     /* p[k][component] */
    double lever_hold;                        /* stage 4: lever arm at theta_hold */
    int rocking;                              /* theta moves (stage 2) */
    int vertical;                             /* the motion has a vertical */
} rb_taylor;

/* Whether the current stage is integrated by Taylor series. */
int rb_taylor_applies(const rb_sys *S, const rb_disc *D);

/* A step from (t0, y0) towards t0 + h_want (which must not pass a break of
 * the excitation), to the absolute tolerances atol of the state and atol_x
 * of the floor acceleration, and rtol. Returns the step taken, h_want or
 * less when the order bound is met first, or 0 when the series is not
 * finite (ts then holds no series). */
double rb_taylor_step(const rb_sys *S, const rb_disc *D, double t0, const double *y0,
                      double h_want, const double *atol, double atol_x, double rtol,
                      rb_taylor *ts);
/* The same step compiled for the baseline instruction set and for AVX
 * (src/core/simd.h; the plain one where there is no AVX variant), which
 * rb_taylor_step chooses between: the same bits either way. */
double rb_taylor_step_plain(const rb_sys *S, const rb_disc *D, double t0, const double *y0,
                            double h_want, const double *atol, double atol_x, double rtol,
                            rb_taylor *ts);
double rb_taylor_step_avx(const rb_sys *S, const rb_disc *D, double t0, const double *y0,
                          double h_want, const double *atol, double atol_x, double rtol,
                          rb_taylor *ts);

/* Component c (RB_Y_*) of the state tau after t0; the four mechanical
 * components; the whole state; the first RB_TS_CHECK series. */
double rb_taylor_one(const rb_taylor *ts, double tau, int c);
void rb_taylor_state(const rb_taylor *ts, double tau, double *y);
void rb_taylor_all(const rb_taylor *ts, double tau, double *y);
void rb_taylor_check(const rb_taylor *ts, double tau, double *v);

/* What rb_dyn_rhs would give as aux, from the values v of the first
 * RB_TS_CHECK series at one instant (no trigonometry). */
void rb_taylor_aux(const rb_sys *S, const rb_disc *D, const rb_taylor *ts, const double *v,
                   rb_aux *a);
/* The same without the works' powers (p_input and p_coupling NaN): what
 * the tracking reads at a point inside a step. */
void rb_taylor_aux_point(const rb_sys *S, const rb_disc *D, const rb_taylor *ts,
                         const double *v, rb_aux *a);

/* The same from values v laid out as the series are, for a plate that
 * rocks or not, held (stage 4) with the lever arm lever_hold: the exact
 * steps' points give their aux this way. */
void rb_aux_of_values(const rb_sys *S, const rb_disc *D, int rocking, double lever_hold,
                      const double *v, rb_aux *a);

/* Root in [a, b] (tau) of U' (c = RB_Y_UD) or theta' (RB_Y_THD), which
 * change sign from fa to fb there: Newton's method on the series and its
 * derivative, kept inside the bracket, to tol in tau. */
double rb_taylor_rate_root(const rb_taylor *ts, int c, double a, double b, double fa,
                           double fb, double tol);

/* A bound on |d/dtau| of component c (RB_Y_*) over [0, h]: the sum of
 * |k p_k| h^(k-1) over the series' terms. */
double rb_taylor_rate_bound(const rb_taylor *ts, int c, double h);

/* How far component c (RB_Y_*) can move from its start over [0, h]: the
 * sum of |p_k| h^k, k >= 1, a rigorous bound of the series. */
double rb_taylor_reach(const rb_taylor *ts, int c, double h);

/* Where component c can read over [0, h] as the Horner passes of the
 * dense output read it (rb_taylor_one, _check, _state, _end): the range
 * of its first three terms over [0, h] (ends and vertex), widened by the
 * reach of the rest and the rounding of those passes and of the bound
 * itself. NaN ends where the series is not finite. */
void rb_taylor_range(const rb_taylor *ts, int c, double h, double *lo, double *hi);

/* Whether component c stays strictly on its start's side of level at
 * every instant of [0, h] as the Horner passes of the dense output read
 * it (rb_taylor_one, _check, _state, _end): the reach plus the rounding
 * of those passes and of the bound itself leave level outside. A guard
 * that is c less a level then reads no crossing anywhere in the step. */
int rb_taylor_stays_off(const rb_taylor *ts, int c, double h, double level);

/* Where theta (physical) passes level in [a, b] (tau), theta - level
 * being fa and fb at the ends (either may be nudged off zero): Newton's
 * method on theta and theta', kept inside the bracket, to tol in tau. */
double rb_taylor_angle_root(const rb_taylor *ts, double a, double b, double level,
                            double fa, double fb, double tol);

/* Where a rigid row's force turns in (a, b) (tau) while the plate is held
 * at theta_hold (stage 4), or the uplift moment on the floor (stage 1):
 * the force is affine in the floor, U'' and the vertical z'', and a peak
 * between two check points can pass Fy (or a trough reach slack) with
 * both ends short of it. rb_taylor_held_force_rate gives its rate at tau,
 * up to a constant factor; times rb_taylor_held_force_scale, the
 * magnitude of the rate of the stage's guards (the uplift guards', or the
 * row's force). side is the edge whose guard is read (+1 about the left,
 * -1 the right): under a vertical the two uplift guards turn apart, the
 * mirror changing the sign of the horizontal's share but not of
 * gravity's.
 * rb_taylor_held_force_turn finds the root where that rate changes sign
 * from rate[0] at a to rate[1] at b, by rb_root_illinois to
 * tol (1 + |tau|). */
double rb_taylor_held_force_rate(const rb_sys *S, const rb_taylor *ts, int side, double tau);
double rb_taylor_held_force_scale(const rb_taylor *ts);
double rb_taylor_held_force_turn(const rb_sys *S, const rb_taylor *ts, int side, double a,
                                 double b, const double *rate, double tol);

/* The end of the step: state, derivative and aux, as rb_dyn_rhs gives them. */
void rb_taylor_end(const rb_sys *S, const rb_disc *D, const rb_taylor *ts, double h,
                   double *y1, double *f1, rb_aux *a);

#endif
