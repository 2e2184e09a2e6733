/* The time history of a run: one row every history_dt_s, read from the
 * steps' dense output. */
#include <stdlib.h>
#include "solver.h"

static rb_status history_grow(rb_history *h)
{
    size_t cap = h->cap ? 2 * h->cap : 1024;
    double **cols[] = {&h->t, &h->accel, &h->theta, &h->u, &h->bolt_force_left,
                       &h->bolt_force_right, &h->shear_elastic, &h->shear_total,
                       &h->vertical, &h->energy_left, &h->energy_right, &h->kinetic,
                       &h->potential, &h->strain};
    for (size_t i = 0; i < sizeof cols / sizeof cols[0]; i++) {
        double *p = realloc(*cols[i], cap * sizeof **cols[i]);
        if (!p)
            return RB_ERR_NOMEM;
        *cols[i] = p;
    }
    int *s = realloc(h->stage, cap * sizeof *s);
    if (!s)
        return RB_ERR_NOMEM;
    h->stage = s;
    h->cap = cap;
    return RB_OK;
}

rb_status rb_history_push(rb_solver *sv, double t, const double *y)
{
    rb_history *h = sv->res->history;
    const rb_sys *S = &sv->sys;
    rb_aux a;
    double H, V;
    if (!h)
        return RB_OK;
    if (h->n == h->cap && history_grow(h) != RB_OK)
        return RB_ERR_NOMEM;
    rb_dyn_rhs(S, &sv->disc, t, y, NULL, &a);
    rb_dyn_reactions(S, &sv->disc, y, &a, &H, &V);
    size_t i = h->n++;
    int row = sv->disc.side ? rb_row_of_side(sv->disc.side) : -1;
    h->t[i] = t;
    h->accel[i] = a.x;
    h->theta[i] = y[RB_Y_TH];
    h->u[i] = y[RB_Y_U];
    h->bolt_force_left[i] = row == RB_LEFT ? a.bolt_force : 0;
    h->bolt_force_right[i] = row == RB_RIGHT ? a.bolt_force : 0;
    h->shear_elastic[i] = S->d.Nstar * S->d.omega * S->d.omega * y[RB_Y_U];
    h->shear_total[i] = H;
    h->vertical[i] = V;
    /* the row's own state: inside a yielding step the run's state is still
     * the step's start */
    h->energy_left[i] = rb_absorbed_at(sv, RB_LEFT, y);
    h->energy_right[i] = rb_absorbed_at(sv, RB_RIGHT, y);
    h->kinetic[i] = rb_dyn_kinetic(S, &sv->disc, y);
    h->potential[i] = rb_dyn_potential(S, &sv->disc, y);
    h->strain[i] = rb_dyn_strain(S, &sv->disc, y);
    h->stage[i] = sv->disc.stage;
    return RB_OK;
}

/* The time of the next history row: k dt rather than a running sum, so
 * long runs do not drift. */
static double history_next(const rb_solver *sv)
{
    return (double)sv->hist_k * sv->opts.history_dt_s;
}

int rb_history_due(const rb_solver *sv, double tb)
{
    double next = history_next(sv);
    return sv->res->history && next <= tb && next <= sv->t_end;
}

rb_status rb_history_sample(rb_solver *sv, const rb_rk_step *st, double ta, double tb)
{
    double y[RB_NY];
    while (rb_history_due(sv, tb)) {
        double next = history_next(sv);
        rb_rk_dense_eval(st, next < ta ? ta : next, y);
        if (rb_history_push(sv, next, y) != RB_OK)
            return RB_ERR_NOMEM;
        sv->hist_k++;
    }
    return RB_OK;
}

void rb_history_free(rb_history *h)
{
    if (!h)
        return;
    free(h->t); free(h->accel); free(h->theta); free(h->u);
    free(h->bolt_force_left); free(h->bolt_force_right);
    free(h->shear_elastic); free(h->shear_total); free(h->vertical);
    free(h->energy_left); free(h->energy_right);
    free(h->kinetic); free(h->potential); free(h->strain);
    free(h->stage);
    free(h);
}
