/* The dense output of the step whose points are being tracked (solver.h,
 * rb_span): what a peak between two of its points is located on. */
#include <math.h>
#include <string.h>
#include "solver.h"

static void set_span(rb_solver *sv, const rb_rk_step *st, double t0, double t1)
{
    sv->span.st = st;
    sv->span.lazy = 0;
    sv->span.t0 = t0;
    sv->span.t1 = t1;
}

/* A pulse that ends with a jump of the floor's acceleration makes every
 * tracked quantity jump with it, between the last step's end and this
 * step's start: the start is tracked as a point of its own, with windows
 * that start afresh, as at a transition. */
void rb_track_span(rb_solver *sv, const rb_rk_step *st, double t0, double t1)
{
    set_span(sv, st, t0, t1);
    if (sv->sys.motion->kind != RB_MOTION_PULSE || !sv->track_have || sv->track_t != t0)
        return;
    double y[RB_NY] = {0};
    rb_aux a;
    /* a step within the pulse starts where the last one ended, to
     * rounding */
    if (rb_span_state(sv, t0, y, &a)
        && fabs(a.x - sv->track_x) > 1e-9 * fmax(fabs(a.x), fabs(sv->track_x))) {
        rb_track_reset(sv);
        rb_track_aux(sv, t0, y, &a);
    }
}

void rb_track_span_series(rb_solver *sv, double t0, const double *y0, double h, double t1)
{
    set_span(sv, NULL, t0, t1);
    sv->span.lazy = 1;
    sv->span.h = h;
    memcpy(sv->span.y0, y0, sizeof sv->span.y0);
}

void rb_track_span_none(rb_solver *sv)
{
    set_span(sv, NULL, 0, 0);
}

/* At the case's tolerance the series put the total shear's located peaks
 * of runs on the floor through a 30 Hz building 1.4e-8 from Taylor steps
 * at 1e-13, no closer than Taylor steps at the case's tolerance; at a
 * tenth, 6.6e-10. */
double rb_exact_dense(const rb_solver *sv, double t0, const double *y0, double h,
                      rb_taylor *ts)
{
    /* never past what double precision can meet, where the series would
     * run to its longest and stop short of the step */
    double f = fmax(RB_DENSE_TOL_FACTOR, fmin(1, RB_RTOL_MIN / sv->opts.rtol)), atol[RB_NY];
    for (int i = 0; i < RB_NY; i++)
        atol[i] = f * sv->atol[i];
    return rb_taylor_step(&sv->sys, &sv->disc, t0, y0, h, atol, f * sv->atol_x,
                          f * sv->opts.rtol, ts);
}

/* The state and what the equations give besides it at t on the span's
 * dense output; 0 where there is none. An exact step's series is built on
 * first use, so that a step whose peaks stay below the running ones costs
 * nothing more. */
int rb_span_state(rb_solver *sv, double t, double *y, rb_aux *a)
{
    rb_span *sp = &sv->span;
    const rb_rk_step *st = sp->st;
    if (!st && sp->lazy == 1) {
        rb_rk_step *s = &sp->series;
        double h = rb_exact_dense(sv, sp->t0, sp->y0, sp->h, &s->ts);
        s->is_taylor = 1;
        s->t0 = sp->t0;
        s->h = h;
        /* a series that the order bound cut short does not reach the end */
        sp->lazy = h >= sp->h ? 2 : -1;
    }
    if (sp->lazy == 2)
        st = &sp->series;
    if (!st)
        return 0;
    if (st->is_taylor) {
        double v[RB_TS_CHECK];
        rb_taylor_check(&st->ts, t - st->t0, v);
        memcpy(y, v, 4 * sizeof *y);
        rb_taylor_aux(&sv->sys, &sv->disc, &st->ts, v, a);
    } else {
        rb_rk_dense_state(st, t, y);
        rb_dyn_rhs(&sv->sys, &sv->disc, t, y, NULL, a);
    }
    return 1;
}
