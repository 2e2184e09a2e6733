/* Frequency-response and amplitude sweeps: the same model run at each point
 * of a range, every point independent, summarised in one row per point.
 * Unlike the searches, a sweep is a survey: a point whose run fails keeps
 * its status and the sweep goes on. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "design_internal.h"

#define RB_SWEEP_MAX_POINTS 100000

typedef struct {
    const rb_design_ctx *ctx;
    rb_sweep *sw;
    const rb_sweep_opts *o;
} sweep_job_ctx;

void rb_sweep_opts_init(rb_sweep_opts *o, rb_sweep_kind kind)
{
    memset(o, 0, sizeof *o);
    o->kind = kind;
    if (kind == RB_SWEEP_FREQUENCY) {
        o->from = 0.2;
        o->to = 2.0;
        o->n_points = 37;
        o->amplitude_astar = 0.1;
        o->duration_s = 8.0;
    } else {
        o->from = 0.05;
        o->to = 1.0;
        o->n_points = 20;
    }
}

void rb_sweep_free(rb_sweep *s)
{
    if (!s)
        return;
    free(s->points);
    s->points = NULL;
    s->n_points = 0;
}

static double x_at(const rb_sweep_opts *o, size_t i)
{
    if (o->n_points < 2)
        return o->from;
    return rb_design_grid_point(o->from + (o->to - o->from) * (double)i / (double)(o->n_points - 1));
}

static void keep_point(rb_sweep_point *p, const rb_design_run *run, double a_star)
{
    const rb_result *r = &run->r;
    p->status = run->status;
    p->meets = run->meets;
    if (run->status != RB_OK)
        return;
    p->peak_mps2 = r->peak_floor_mps2;
    p->level_astar = r->peak_floor_mps2 / a_star;
    p->max_u_over_ustatic = r->max_u_over_ustatic;
    p->max_theta_over_alpha = r->max_theta_over_alpha;
    p->overturned = r->overturned;
    for (int s = 0; s < 2; s++) {
        p->max_force_over_fy[s] = r->fy_row_n > 0 ? r->max_bolt_force_n[s] / r->fy_row_n : 0;
        p->usage[s] = r->usage[s];
        p->yielded[s] = r->yielded[s];
        p->broken[s] = r->broken[s];
    }
}

static rb_status sweep_job(void *v, size_t i)
{
    sweep_job_ctx *c = v;
    rb_sweep_point *p = &c->sw->points[i];
    rb_design_run run;
    rb_motion m, vertical;
    p->x = x_at(c->o, i);
    if (c->o->kind == RB_SWEEP_FREQUENCY) {
        rb_motion_init(&m);
        m.kind = RB_MOTION_HARMONIC;
        m.amplitude_mps2 = c->o->amplitude_astar * c->ctx->a_star_mps2;
        m.freq_hz = p->x * c->sw->fixed_base_hz;
        m.ramp_s = c->o->ramp_s;
        m.duration_s = c->o->duration_s > 0 ? c->o->duration_s : 8.0;
    } else {
        rb_design_motion_at(c->ctx, p->x * c->ctx->a_star_mps2, &m, &vertical);
    }
    p->freq_hz = m.kind == RB_MOTION_HARMONIC ? m.freq_hz : 0;
    rb_design_run_one(c->ctx, c->ctx->model, &m, &run);
    keep_point(p, &run, c->ctx->a_star_mps2);
    return run.status;
}

static rb_status check_range(const rb_sweep_opts *o, rb_sweep_kind kind, rb_diag *diag)
{
    if (o->kind != kind)
        return rb_design_fail(diag, RB_ERR_INVALID, "sweep", "options of the other sweep kind");
    if (o->n_points < 1 || o->n_points > RB_SWEEP_MAX_POINTS || !isfinite(o->from)
        || !isfinite(o->to) || !(o->from >= 0) || !(o->to >= o->from)
        || (kind == RB_SWEEP_FREQUENCY && !(o->from > 0)))
        return rb_design_fail(diag, RB_ERR_INVALID, "sweep",
                              "the range needs 0 <= from <= to (from > 0 for frequency "
                              "ratios) and 1 to 100000 points");
    if (kind == RB_SWEEP_FREQUENCY
        && (!(o->amplitude_astar >= 0) || !isfinite(o->amplitude_astar)
            || !(o->ramp_s >= 0) || !isfinite(o->duration_s)))
        return rb_design_fail(diag, RB_ERR_INVALID, "sweep",
                              "the amplitude and ramp must be finite and >= 0");
    return RB_OK;
}

static rb_status sweep_run(const rb_model *model, const rb_motion *motion,
                           const rb_solve_opts *opts, const rb_criteria *criteria,
                           const rb_sweep_opts *o, int n_threads, rb_design_memo *memo,
                           rb_sweep *out, rb_diag *diag)
{
    rb_design_ctx ctx;
    rb_status st = rb_design_ctx_init(&ctx, model, motion, opts, criteria, diag);
    if (st != RB_OK)
        return st;
    ctx.memo = memo;
    out->kind = o->kind;
    out->a_star_mps2 = ctx.a_star_mps2;
    out->fixed_base_hz = model->freq_hz;
    out->amplitude_astar = o->kind == RB_SWEEP_FREQUENCY ? o->amplitude_astar : 0;
    out->points = calloc(o->n_points, sizeof *out->points);
    if (!out->points)
        return RB_ERR_NOMEM;
    out->n_points = o->n_points;
    sweep_job_ctx c = {&ctx, out, o};
    st = rb_pool_map(o->n_points, n_threads, sweep_job, &c, NULL);
    if (st != RB_OK)
        rb_sweep_free(out);
    return st;
}

rb_status rb_sweep_frequency(const rb_model *model, const rb_solve_opts *opts,
                             const rb_criteria *criteria, const rb_sweep_opts *sw,
                             int n_threads, rb_sweep *out, rb_diag *diag)
{
    rb_status st;
    memset(out, 0, sizeof *out);
    if (!model || !sw)
        return rb_design_fail(diag, RB_ERR_INVALID, "", "missing model or sweep options");
    if ((st = check_range(sw, RB_SWEEP_FREQUENCY, diag)) != RB_OK)
        return st;
    if (model->rigid || !(model->freq_hz > 0))
        return rb_design_fail(diag, RB_ERR_INVALID, "equipment.frequency",
                              "a frequency sweep needs a fixed-base frequency");
    return sweep_run(model, NULL, opts, criteria, sw, n_threads, NULL, out, diag);
}

rb_status rb_sweep_amplitude(const rb_model *model, const rb_motion *motion,
                             const rb_solve_opts *opts, const rb_criteria *criteria,
                             const rb_sweep_opts *sw, int n_threads,
                             rb_design_memo *memo, rb_sweep *out, rb_diag *diag)
{
    rb_status st;
    memset(out, 0, sizeof *out);
    if (!model || !motion || !sw)
        return rb_design_fail(diag, RB_ERR_INVALID, "", "missing model, motion or options");
    if ((st = check_range(sw, RB_SWEEP_AMPLITUDE, diag)) != RB_OK)
        return st;
    return sweep_run(model, motion, opts, criteria, sw, n_threads, memo, out, diag);
}
