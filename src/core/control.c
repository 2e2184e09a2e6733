/* Step control of the restrained-rocking solver, apart from the steps
 * themselves (stepper.h): the tolerances every step is held to, the
 * longest step and the spacing of its check points, the length and check
 * points of a Taylor or exact step, and the Dormand-Prince step's error
 * control. The steppers and the run loop (solve.c) ask it; it asks
 * neither. */
#include <math.h>
#include "bolt.h"
#include "minmax.h"
#include "solver.h"
#include "stepper.h"

/* The highest frequency of the model and the excitation; the rows' own
 * (a stiff spring's) only where taut, so that a run with elastic rows
 * keeps the long steps and the check spacing of the rigid model while
 * they are slack. */
static double highest_frequency(const rb_solver *sv, int taut)
{
    const rb_sys *S = &sv->sys;
    const rb_motion *m = S->motion;
    double f = sqrt(S->d.W * S->d.R / S->d.Io) / (2 * M_PI);
    if (!S->model->rigid)
        f = fmax(f, S->model->freq_hz);
    if (m->kind == RB_MOTION_HARMONIC)
        f = fmax(f, m->freq_hz);
    if (m->kind == RB_MOTION_PULSE && m->pulse_s > 0)
        f = fmax(f, 1 / m->pulse_s);
    if (m->vertical && m->vertical->kind == RB_MOTION_HARMONIC)
        f = fmax(f, m->vertical->freq_hz);
    if (m->vertical && m->vertical->kind == RB_MOTION_PULSE && m->vertical->pulse_s > 0)
        f = fmax(f, 1 / m->vertical->pulse_s);
    if (taut && S->bolt->frequency_hz)
        f = fmax(f, S->bolt->frequency_hz(S));
    return f;
}

/* The highest frequency of the response: the model's and the excitation's,
 * and the frame mode coupled with the rotation in stage 2, whose effective
 * mass (M* I_o - F*^2) / I_o is below M*. */
static double fastest_mode(const rb_solver *sv, int taut)
{
    const rb_derived *d = &sv->sys.d;
    double f = highest_frequency(sv, taut);
    if (!sv->sys.model->rigid)
        f = fmax(f, sqrt(d->Kstar * d->Io / (d->Mstar * d->Io - d->Fstar * d->Fstar))
                    / (2 * M_PI));
    return f;
}

static void set_tolerances(rb_solver *sv)
{
    const rb_sys *S = &sv->sys;
    double a = fmax(sv->res->peak_floor_mps2, 0.01 * S->d.g);
    double p = sqrt(S->d.W * S->d.R / S->d.Io);
    double th = fmin(S->d.alpha, S->bolt->rows ? fmax(S->d.theta0_rad, 1e-3 * S->d.alpha)
                                              : S->d.alpha);
    double w = S->model->rigid ? p : S->d.omega;
    double u = S->model->rigid ? 1 : 4 * a / (M_PI * w * w);
    double rtol = sv->opts.rtol;
    sv->atol[RB_Y_U] = rtol * u;
    sv->atol[RB_Y_UD] = rtol * u * w;
    sv->atol[RB_Y_TH] = rtol * th;
    sv->atol[RB_Y_THD] = rtol * th * fmax(w, p);
    sv->atol[RB_Y_WDAMP] = sv->atol[RB_Y_WIN] = sv->atol[RB_Y_WCPL] = 0;
    sv->atol_x = rtol * a;
    sv->rtol_rk = fmax(rtol * RB_RK_TOL_FACTOR, RB_RTOL_MIN); /* rtol >= RB_RTOL_MIN */
    for (int i = 0; i < RB_NY; i++)
        sv->atol_rk[i] = sv->atol[i] * (sv->rtol_rk / rtol);
}

void rb_control_init(rb_solver *sv)
{
    set_tolerances(sv);
    sv->h_max = sv->opts.max_step_s > 0 ? sv->opts.max_step_s
                                        : 0.1 / highest_frequency(sv, 1);
    sv->h_max_slack = sv->opts.max_step_s > 0 ? sv->opts.max_step_s
                                              : 0.1 / highest_frequency(sv, 0);
    sv->h = fmin(sv->h_max, 1e-3);
    sv->check_spacing = 1 / (8 * fastest_mode(sv, 1));
    sv->check_slack = 1 / (8 * fastest_mode(sv, 0));
}

double rb_control_trial(const rb_solver *sv, double target)
{
    return rb_fmin(rb_fmin(sv->h, sv->h_max), target - sv->t);
}

/* A Taylor step towards the next break or the end, which it lands on
 * exactly when within reach (a sum of steps would stop a rounding error
 * short of it, and leave a step too small to take). */
static int taut(const rb_solver *sv)
{
    return sv->disc.stage == RB_STAGE_HELD && !sv->sys.bolt->rigid_stop;
}

double rb_step_length(const rb_solver *sv, double target, int *landing)
{
    double h_max = taut(sv) ? sv->h_max : sv->h_max_slack;
    double h_want = target - sv->t;
    *landing = h_want <= 1.001 * h_max;
    return *landing ? h_want : h_max;
}

/* The check points a step of length h needs at the check spacing, within
 * [lo, hi]. */
static int checks_within(const rb_solver *sv, double h, int lo, int hi)
{
    int n = (int)ceil(h / (taut(sv) ? sv->check_spacing : sv->check_slack));
    return n < lo ? lo : n > hi ? hi : n;
}

int rb_step_checks(const rb_solver *sv, double h)
{
    return checks_within(sv, h, sv->opts.min_checks < 2 ? 2 : sv->opts.min_checks,
                         RB_SUB_MAX);
}

/* A Dormand-Prince step, held to a thousandth of the tolerance, is a small
 * fraction of the spacing: two points read its guards and peaks far closer
 * than the Taylor steps' points are. */
int rb_step_checks_rk(const rb_solver *sv, double h)
{
    return checks_within(sv, h, 2, RB_SUB);
}

int rb_control_rk_accept(rb_solver *sv, double h, double err)
{
    double fac = err > 0 ? 0.9 * pow(err, -0.2) : 5;
    if (err > 1) {
        sv->res->rejected_steps++;
        sv->h = h * fmax(0.1, fmin(0.9, fac));
        return 0;
    }
    sv->h = fmax(h, 1e-14) * fmin(5, fmax(0.2, fac));
    return 1;
}

/* The window of events per simulated second a step starts in. */
void rb_control_event_window(rb_solver *sv)
{
    if (sv->t - sv->window_start >= 1.0) {
        sv->window_start = sv->t;
        sv->window_events = 0;
    }
}

/* The limit state a run was asked to stop at has been reached
 * (rb_solve_opts.stop_at). */
int rb_control_stop_reached(const rb_solver *sv)
{
    const rb_result *r = sv->res;
    unsigned stop = sv->opts.stop_at;
    if ((stop & RB_STOP_FIRST_YIELD)
        && (r->yielded[0] || r->yielded[1]
            || (r->fy_row_n > 0 && rb_fmax(r->max_bolt_force_n[0], r->max_bolt_force_n[1])
                                   >= r->fy_row_n)))
        return 1;
    return (stop & RB_STOP_LIFT_OFF) && r->min_vertical_reaction_n <= 0;
}

int rb_run_goes_on(rb_solver *sv)
{
    if (sv->done || !(sv->t < sv->t_end) || rb_control_stop_reached(sv))
        return 0;
    rb_control_event_window(sv);
    return !(sv->window_events > sv->opts.max_events_per_s)
           && sv->res->steps < sv->opts.max_steps;
}
