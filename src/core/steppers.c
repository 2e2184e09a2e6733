/* The Taylor and Dormand-Prince steppers (stepper.h), and the chain a
 * stage steps with. */
#include <math.h>
#include <string.h>
#include "bolt.h"
#include "exact.h"
#include "stepper.h"

/* A Taylor step towards the next break or the end, which it lands on
 * exactly when within reach; declined when its series is not finite (the
 * Runge-Kutta step after it meets the same values and says where they
 * come from). */
static rb_step_outcome taylor_apply(rb_solver *sv, double target, double h_trial,
                                    rb_rk_step *st, double *g, rb_status *status)
{
    (void)h_trial;
    (void)g;
    (void)status;
    int landing;
    double h_want = rb_step_length(sv, target, &landing);
    double h = rb_taylor_step(&sv->sys, &sv->disc, sv->t, sv->y, h_want, sv->atol,
                              sv->atol_x, sv->opts.rtol, &st->ts);
    if (!(h > 0))
        return RB_STEP_DECLINED;
    st->is_taylor = 1;
    st->t0 = sv->t;
    st->h = h;
    st->lands = landing && h == h_want;
    st->t1 = st->lands ? target : sv->t + h;
    memcpy(st->y0, sv->y, sizeof st->y0);
    rb_taylor_end(&sv->sys, &sv->disc, &st->ts, h, st->y1, st->k[6], &st->aux1);
    st->n_sub = rb_step_checks(sv, h);
    sv->res->steps++;
    sv->res->stage_steps[sv->disc.stage]++;
    return RB_STEP_DENSE;
}

const rb_stepper rb_stepper_taylor = {"taylor", taylor_apply, NULL};

/* A step to the break or the end lands on it exactly (t + (target - t) can
 * round short of it, leaving a step a rounding error long), and its last
 * stages see the excitation from before the break: a pulse that ends at
 * its peak drops to zero there, and read after the drop it put an error
 * of h times the drop into the step, which held to a tight tolerance
 * shrank the steps to underflow. */
static rb_step_outcome rk45_apply(rb_solver *sv, double target, double h, rb_rk_step *st,
                                  double *g, rb_status *status)
{
    (void)g;
    (void)status;
    int landing = h == target - sv->t;
    double err = rb_rk_step_try(&sv->sys, &sv->disc, sv->t, sv->y, sv->f, h,
                                landing ? nextafter(target, -HUGE_VAL) : sv->t + h,
                                sv->atol_rk, sv->rtol_rk, st);
    if (landing)
        st->t1 = target;
    st->lands = landing;
    st->n_sub = rb_step_checks_rk(sv, h);
    sv->res->rhs_evals += 6;
    sv->nonfinite_trial = err == HUGE_VAL;
    if (!rb_control_rk_accept(sv, h, err))
        return RB_STEP_RETRY;
    sv->res->steps++;
    sv->res->stage_steps[sv->disc.stage]++;
    rb_rk_dense_init(st);
    return RB_STEP_DENSE;
}

/* The next step starts from the excitation after the break (its first
 * stage is the last step's last, FSAL). */
static void rk45_landed(rb_solver *sv)
{
    rb_dyn_rhs(&sv->sys, &sv->disc, sv->t, sv->y, sv->f, NULL);
}

const rb_stepper rb_stepper_rk45 = {"rk45", rk45_apply, rk45_landed};

int rb_steppers_of_stage(const rb_solver *sv, const rb_stepper **chain)
{
    int n = 0;
    if (sv->exact.on && sv->disc.stage == RB_STAGE_FIXED)
        chain[n++] = &rb_stepper_exact;
    /* held still by a rigid row (exact_held.c) */
    if (sv->exact.on && sv->disc.stage == RB_STAGE_HELD && sv->sys.bolt->rigid_stop)
        chain[n++] = &rb_stepper_exact_held;
    if (sv->opts.integrator == RB_INTEGRATOR_AUTO && rb_taylor_applies(&sv->sys, &sv->disc))
        chain[n++] = &rb_stepper_taylor;
    chain[n++] = &rb_stepper_rk45;
    return n;
}
