/* Internal: the state of one solver run, shared by the run loop
 * (solve.c), the steppers (stepper.h) and their control (control.c), the
 * stage transitions (transitions.c) and the peak/history tracking
 * (track.c, history.c). */
#ifndef RB_SOLVER_H
#define RB_SOLVER_H

#include "dynamics.h"
#include "pair.h"
#include "rk45.h"

/* Tolerances the integrator accepts: below RB_RTOL_MIN rounding error
 * dominates and steps shrink to underflow. */
#define RB_RTOL_MIN 1e-13
#define RB_RTOL_MAX 1e-2
/* A Dormand-Prince step is held to this fraction of the case's tolerance
 * (never below RB_RTOL_MIN), so that it meets the accuracy the Taylor
 * steps meet at the tolerance itself (docs/solver.md, "Tolerance of the
 * Dormand-Prince steps"). */
#define RB_RK_TOL_FACTOR 1e-3

/* The most steppers a stage steps with (stepper.h). */
#define RB_STEPPERS_MAX 3

/* Guard functions: a stage ends where one crosses zero in its direction. */
enum {
    G_UP_POS,   /* stage 1: uplift about the left edge (+1) */
    G_UP_NEG,   /* stage 1: uplift about the right edge (-1) */
    G_FLOOR,    /* stage 2: plate comes back to the floor (theta -> 0) */
    G_CONTACT,  /* stage 2: plate reaches the bolt heads (5.9b) */
    G_OVERTURN, /* stages 2, 5: centre of mass passes over the pivot */
    G_SLACK,    /* stage 4: bolt tension falls to zero */
    G_YIELD,    /* stage 4: bolt tension reaches Fy */
    G_UNLOAD,   /* stage 5: plate stops rising, yielding stops */
    G_BREAK,    /* stage 5: absorbed energy reaches toughness x volume */
    G_SWITCH,   /* critical excitation: theta' changes sign */
    G_COUNT
};

/* The lowest guard of the set m, taken out of it: the loops over the
 * active guards (two or three of G_COUNT) run at every check interval.
 * m must not be empty. */
static inline int rb_guard_next(unsigned *m)
{
    int k = __builtin_ctz(*m);
    *m &= *m - 1;
    return k;
}

/* the exact steps' state (exact.c) and the terms of their transition's
 * series in the step's fraction kept for a one-panel table */
#define RB_EXACT_DIM 6
#define RB_EXACT_POLY 30

/* The last three points of a tracked quantity, which bracket a peak
 * between them. */
typedef struct {
    double t[3], v[3];
    int n;
} rb_peak_window;

/* The dense output of the step whose points are being tracked, over
 * [t0, t1]: a live step (st), or a Taylor series built from (t0, y0) over
 * h only if a peak needs it (the exact steps, which carry none); st NULL
 * and lazy 0 between steps. */
typedef struct {
    double t0, t1;
    const rb_rk_step *st;
    int lazy;                   /* 1: to build, 2: built, -1: failed */
    double h, y0[RB_NY];
    rb_rk_step series;
    /* an exact step on the floor (rb_track_span_exact): its table (an
     * index into the run's tables, -1 for none), start state z0, and the
     * polynomials in f = (t - t0) / (t1 - t0) of U, U', u_b, v_b and the
     * total shear less its constant, formed from z0 on first use
     * (exact_formed: bit i for polynomial i, bit 5 for the turns) */
    int exact_tab, exact_formed;
    double exact_z0[RB_EXACT_DIM];
    double exact_poly[5][RB_EXACT_POLY];
    /* the shear's turns last found, between turns_ta and turns_tb */
    double turns_ta, turns_tb, turns[8];
    int n_turns;
} rb_span;

/* The exact steps' transitions for one step length (exact.c): the rows
 * U, U', u_b, v_b of the transition to each check point, and the
 * Gramians of U'^2 and of the floor times U' over the whole step. */

#define RB_EXACT_TABLES 4
/* the quantities bounded over a step: U, the total shear and the two
 * uplift guards (exact.c) */
#define RB_EXACT_NQ 4
typedef struct {
    double h;
    int n;
    double row[RB_SUB_MAX][4][RB_EXACT_DIM];
    /* the rows of U and U' at the step's end, side by side (exact.c,
     * end_state) */
    rb_pair end_uv[RB_EXACT_DIM];
    double gvv[RB_EXACT_DIM][RB_EXACT_DIM], gxv[RB_EXACT_DIM][RB_EXACT_DIM];
    /* the damping and input works over the step as symmetric quadratic
     * forms of its start state, their coefficients (C* gvv, N* gxv) packed
     * by pairs i <= j, work[k]'s lane 0 the damping's and lane 1 the input's
     * side by side (both sums then take one vector product a pair) */
    rb_pair work[RB_EXACT_DIM * (RB_EXACT_DIM + 1) / 2];
    /* bound[j][q / 2] lane q % 2: the largest |row j| over the step of
     * quantity q's row (exact.c, "Bounds over a step"), the four
     * quantities of a component side by side; bounded 0 where none was
     * proved */
    int bounded;
    rb_pair bound[RB_EXACT_DIM][RB_EXACT_NQ / 2];
    /* vary[j][k / 2] lane k % 2: how far quantity k (U, the total shear,
     * the uplift moment, the floor acceleration, U'') can move from its
     * start over the step per unit |z0_j|, which a plate held by a rigid
     * row reads (exact.c, held_bounds); held_bounded 0 where none was
     * proved, -1 before they are formed (on first use) */
    int held_bounded;
    rb_pair vary[RB_EXACT_DIM][3];
    /* a table of one panel: the rows of U, U', u_b, v_b (0-3) and of the
     * total shear less its constant (4) of E(f h) as polynomials in f,
     * poly[k][i][j] the coefficient of f^k, nterm of them; nterm 0 where
     * the table has several panels (exact.c, "Peaks on the step's own
     * polynomial") */
    int nterm;
    double poly[RB_EXACT_POLY][5][RB_EXACT_DIM];
} rb_exact_table;

struct rb_solver_s;

/* A plate held by a rigid row, as its exact steps read it (exact_held.c):
 * for the hold at angle th on side s (ok: its forms were checked), U's
 * scale c and shift us, the angle's sine, the lever arm, the row force's
 * coefficients of the uplift moment and the floor (kg, kx), the shear's
 * of U'' (kh), the force, shear and floor reaction at z = 0 (f0, h0, fv0)
 * and the coupling power per unit U'. */
typedef struct {
    int ok, side;
    double th, c, sn, s, us, lever, kg, kx, kh, f0, h0, fv0, cpl;
} rb_exact_held;

typedef struct {
    int on;
    double wb, xib;                       /* the building; 0 without one */
    double inv_ms, in_th;                 /* 1 / M*, the floor's lever M h */
    /* each bounded quantity as lin[q] . z + lin0[q], taken from the
     * functions that evaluate it (exact.c, linear_forms) */
    int lin_ready, lin_side;
    double lin[RB_EXACT_NQ][RB_EXACT_DIM], lin0[RB_EXACT_NQ];
    /* the floor acceleration and U'' as lin_x . z and lin_a . z */
    double lin_x[RB_EXACT_DIM], lin_a[RB_EXACT_DIM];
    rb_exact_table tab[RB_EXACT_TABLES];
    int n_tab;
    double seen[RB_EXACT_TABLES];         /* step lengths met once */
    int n_seen;
    /* the last quiet step, whose end the guards, the rates and the
     * tracking have not read yet (exact.c, rb_exact_settle): its table,
     * start state, start time and the floor line's g0 and slope */
    int pending;
    const rb_exact_table *pend_tab;
    /* the step lengths last looked up, to the bit, and their tables (a
     * sample interval's length comes in a few roundings) */
    double memo_h[RB_EXACT_TABLES];
    const rb_exact_table *memo_tab[RB_EXACT_TABLES];
    int memo_next;
    double pend_z0[RB_EXACT_DIM], pend_t0, pend_g0, pend_slope;
    /* what reads the pending step's end where it is not a floor step's
     * (exact_held.c), NULL for a floor step */
    void (*pend_settle)(struct rb_solver_s *sv, double *g);
    rb_exact_held held;
} rb_exact_cache;

typedef struct rb_solver_s {
    rb_sys sys;
    rb_disc disc;
    rb_solve_opts opts;
    rb_result *res;
    double t, y[RB_NY], f[RB_NY];
    double atol[RB_NY];
    double atol_x;              /* the floor acceleration's, for the series */
    /* what a Dormand-Prince step is held to (set_tolerances in control.c) */
    double rtol_rk, atol_rk[RB_NY];
    double h, h_max, t_end;
    double check_spacing;       /* largest spacing of a Taylor step's checks */
    /* the same two while no row is a taut spring (bolt.h's frequency_hz) */
    double h_max_slack, check_slack;
    double e_impact;
    double rest_theta;          /* rocking amplitude that counts as at rest */
    /* the floor reaction above which a friction demand is taken:
     * RB_FRICTION_FLOOR of the weight, under a vertical of the least
     * weight M (g + z'') the run sees (a constant level, which the
     * crossings are located against; the lower, the more is judged) */
    double friction_floor;
    double window_start;        /* work bound: events since window_start */
    long window_events;
    long hist_k;                /* next history row is at hist_k * dt */
    /* the last three points of each quantity whose peaks are located
     * between points (track.c), reset at every transition (a peak is only
     * searched for where the quantity is smooth) */
    rb_peak_window win_shear, win_friction, win_bolt, win_vertical, win_anchor;
    /* the step whose points are being tracked, where a sampled peak is
     * located between them */
    rb_span span;
    /* the last point tracked and the floor acceleration there, to see a
     * pulse's end jump at a step's start */
    double track_t, track_x;
    int track_have;
    /* the last point's floor reaction, for the time spent at or below 0 */
    double lift_t, lift_v;
    int lift_have;
    /* the last point's shear and floor reaction, for where the reaction
     * crosses the friction floor (reset at every transition) */
    double fric_t, fric_h, fric_v;
    int fric_have;
    int done;
    /* the last Dormand-Prince trial gave non-finite values */
    int nonfinite_trial;
    /* the stage's steppers (stepper.h), chosen as it starts */
    const struct rb_stepper *steppers[RB_STEPPERS_MAX];
    int n_steppers;
    rb_exact_cache exact;
    rb_eval_memo memo;
} rb_solver;

/* transitions.c */
unsigned rb_guard_mask(const rb_solver *sv);
void rb_guard_eval(const rb_solver *sv, double t, const double *y, double *g);
/* The same where the floor acceleration x at t and the apparent gravity
 * ge = g + z'' are known (a Taylor step's series at its check points):
 * the uplift guards read them instead of the motion's closed form, which
 * through a building is an exponential, a sine and a cosine. x NAN:
 * evaluate both. */
void rb_guard_eval_x(const rb_solver *sv, double t, const double *y, double x, double ge,
                     double *g);
/* The same where the equations have been evaluated at (t, y) in the
 * current stage (a is rb_dyn_rhs's aux there): the floor and a row's
 * force are read from a, the same bits as evaluated anew. */
void rb_guard_eval_aux(const rb_solver *sv, double t, const double *y, const rb_aux *a,
                       double *g);
/* One guard; what locating its root needs. */
double rb_guard_one(const rb_solver *sv, int guard, double t, const double *y);
int rb_guard_crossed(int guard, double before, double after);
/* The way a guard crosses: +1 upward, -1 downward, 0 either way. */
int rb_guard_direction(int guard);
/* Whether a guard that reads ga and gb at the ends of an interval, and
 * can move by at most reach_a and reach_b from them inside it, stays on
 * its side throughout (both bounds must hold); 0 for a guard with no
 * side (the critical excitation's switch). */
int rb_guard_stays(int guard, double ga, double reach_a, double gb, double reach_b);
/* Whether a guard is the mirrored angle passing a level, and the level of
 * the physical angle where it does: such a root is found on theta alone. */
int rb_guard_angle(const rb_solver *sv, int guard, double *level);
void rb_guard_nudge(double *g);
/* D's yield_at from its gaps, for rows that are force laws. */
void rb_disc_yield_angles(const rb_sys *S, rb_disc *D);
/* Apply the transition of 'guard' at the current (t, y). */
void rb_transition(rb_solver *sv, int guard);
/* Transitions that hold the moment a stage starts (a bolt impact that
 * leaves the bolt slack or beyond yield, a jump in the excitation). a is
 * the evaluation of the equations at the run's (t, y) in the stage it
 * tested: where none holds (0), the stage the run goes on in. */
int rb_transition_immediate(rb_solver *sv, rb_aux *a);
/* A row's absorbed energy at the state y of the current stage (a yielding
 * row's grows with the chord), and at the run's own state. */
double rb_absorbed_at(const rb_solver *sv, int row, const double *y);
double rb_absorbed_now(const rb_solver *sv, int row);

/* Guards and peaks are checked at n_sub equally spaced points of a step,
 * as many as the check spacing (an eighth of the fastest mode's period)
 * asks for: at least the option min_checks (default RB_MIN_CHECKS) for a
 * Taylor or exact step, at least two and at most RB_SUB for a Runge-Kutta
 * step, whose steps are short. Two is the least a step's peak windows
 * and turn searches were built for (docs/solver.md, "Check points a
 * step"). */
#define RB_SUB 4
#define RB_MIN_CHECKS 2

/* control.c (step control, apart from the steps): the tolerances, the
 * longest steps and the check spacing of a run; the control's trial
 * length of a step towards target (a break or the end); the length of a
 * Taylor or exact step from the current point towards target, whether it
 * lands there, and the check points of a step of length h (of a
 * Dormand-Prince step: rb_step_checks_rk); whether a Dormand-Prince step
 * of scaled error err is accepted, with the next trial length set either
 * way. */
void rb_control_init(rb_solver *sv);
double rb_control_trial(const rb_solver *sv, double target);
/* The run loop's conditions (solve.c), shared with a stepper that takes
 * several steps in one call (stepper.h, rb_run_goes_on): the window of
 * events per simulated second moved on to the current step; whether the
 * limit state the run was asked to stop at (rb_solve_opts.stop_at) has
 * been reached. */
void rb_control_event_window(rb_solver *sv);
int rb_control_stop_reached(const rb_solver *sv);
double rb_step_length(const rb_solver *sv, double target, int *landing);
int rb_step_checks(const rb_solver *sv, double h);
int rb_step_checks_rk(const rb_solver *sv, double h);
int rb_control_rk_accept(rb_solver *sv, double h, double err);
/* Whether the guards of a force that turns inside a check interval of
 * length dt stay short of their boundaries at the turn, given the
 * magnitudes of their rates at its ends (transitions.c). */
int rb_force_turn_stays(unsigned mask, double dt, double rate_a, double rate_b,
                        const double *ga, const double *gb);

/* A run's solver at its start (solve.c): the model's constants, the
 * options checked, the motion's, the first stage; out gets the run's
 * constants. */
rb_status rb_solver_setup(rb_solver *sv, const rb_model *model, const rb_motion *motion,
                          const rb_solve_opts *opts, rb_result *out, rb_diag *diag);

/* track.c, history.c */
void rb_track_point(rb_solver *sv, double t, const double *y);
/* The same with the evaluation at (t, y) already done. */
void rb_track_aux(rb_solver *sv, double t, const double *y, const rb_aux *a);
/* A transition: the sampled quantities start afresh. */
void rb_track_reset(rb_solver *sv);
/* Whether a stretch on the floor with no vertical motion, whose total
 * shear stays within shear_bound, can move none of the quantities
 * tracked from the shear and the reactions (the floor's reaction is then
 * the weight, the bolts are slack). */
int rb_track_quiet_bound(const rb_solver *sv, double shear_bound);
/* Such a stretch's last two points (times t, top displacements u, total
 * shears H, the floor x at the second) tracked as rb_track_reset and
 * rb_track_aux at each would, with no dense output: the peaks' windows
 * hold the two points and nothing else moves but what they pass. */
void rb_track_quiet_points(rb_solver *sv, const double *t, const double *u, const double *H,
                           double x_last);
/* The same for a plate held by a loaded row (exact_held.c): whether a
 * stretch whose row force stays at or below force_hi, whose |shear| stays
 * at or below shear_hi and whose floor reaction stays at or above
 * floor_lo (all above zero) moves no tracked peak of the row, the shear,
 * the reaction, the friction or the anchors' demand; and its last two
 * points (times t, states y, what the equations give there a) tracked as
 * after rb_track_reset. */
int rb_track_held_quiet(const rb_solver *sv, double force_hi, double shear_hi, double floor_lo);
void rb_track_held_points(rb_solver *sv, const double *t, const double (*y)[RB_NY],
                          const rb_aux *a);
/* The points tracked next lie on st's dense output between t0 and t1, or
 * on the Taylor series from (t0, y0) over h (an exact step); none: on no
 * step (a transition's point). */
void rb_track_span(rb_solver *sv, const rb_rk_step *st, double t0, double t1);
void rb_track_span_series(rb_solver *sv, double t0, const double *y0, double h, double t1);
void rb_track_span_none(rb_solver *sv);
/* The points tracked next lie on an exact step of table tab (an index into
 * sv->exact.tab) from z0 over [t0, t1]: the state between them is the
 * step's own polynomial where the table has one panel
 * (rb_exact_span_state), else the Taylor series from (t0, y0) over h. */
void rb_track_span_exact(rb_solver *sv, double t0, const double *y0, double h, double t1,
                         int tab, const double *z0);
/* exact.c: the state y (RB_NY) and what the equations give besides it at
 * t on the span's exact step, from the step's polynomial; 0 where the span
 * has none. */
int rb_exact_span_state(rb_solver *sv, double t, double *y, rb_aux *a);
/* exact.c: the instants in (ta, tb) where the total shear turns on the
 * span's exact step (roots of its derivative, Newton on the step's
 * polynomial kept inside a bracket), into at[], at most max of them;
 * -1 where the span has no polynomial. */
int rb_exact_span_shear_turns(rb_solver *sv, double ta, double tb, double *at, int max);
/* An exact step's dense output: the Taylor series from (t0, y0) over h, to
 * RB_DENSE_TOL_FACTOR of the tolerances, not below RB_RTOL_MIN (the step
 * itself is exact to rounding; its peaks and history rows are read from
 * this series).
 * Returns the length it reaches, 0 if it is not finite. */
double rb_exact_dense(const rb_solver *sv, double t0, const double *y0, double h,
                      rb_taylor *ts);
#define RB_DENSE_TOL_FACTOR 0.1
/* Peaks inside [ta, tb] of a step; ys, when not NULL, holds the state at
 * the n_sub check points of the whole step (tb = its end). */
void rb_track_interval(rb_solver *sv, const rb_rk_step *st, double ta, double tb,
                       const double (*ys)[RB_NY]);
rb_status rb_history_sample(rb_solver *sv, const rb_rk_step *st, double ta, double tb);
/* Whether a row of the time history falls at or before tb. */
int rb_history_due(const rb_solver *sv, double tb);
rb_status rb_history_push(rb_solver *sv, double t, const double *y);

#endif
