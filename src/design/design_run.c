/* One run of a design search: the model under the motion's shape scaled to a
 * level, judged against the criteria. Shared by the searches and sweeps so
 * that they scale motions and judge runs the same way. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "design_internal.h"

int rb_design_threads_default(void)
{
    return rb_pool_threads_default();
}

void rb_design_opts_defaults(rb_design_opts *o)
{
    o->scan_start = 0.05;
    o->scan_step = 0.05;
    o->scan_end = 1.5;
    o->resolution = 0.001;
    o->gap_ratio_min = 0.0;
    o->gap_ratio_max = 0.03;
    o->gap_ratio_step = 0.0025;
    o->max_gap_m = RB_DESIGN_MAX_GAP_M;
}

rb_status rb_design_fail(rb_diag *diag, rb_status st, const char *key, const char *msg)
{
    return rb_diag_set(diag, st, NULL, 0, 0, key, "%s", msg);
}

rb_status rb_design_ctx_init(rb_design_ctx *ctx, const rb_model *model,
                             const rb_motion *motion, const rb_solve_opts *opts,
                             const rb_criteria *criteria, rb_diag *diag)
{
    rb_derived d;
    rb_status st = rb_model_derive(model, &d, diag);
    if (st != RB_OK)
        return st;
    memset(ctx, 0, sizeof *ctx);
    ctx->model = model;
    ctx->motion = motion;
    ctx->criteria = criteria;
    ctx->g_mps2 = d.g;
    /* without bolts A* = (Fy l + W b) / (M h) has Fy = 0: the uplift level */
    ctx->a_star_mps2 = model->bolt_model == RB_BOLT_NONE ? d.a_uplift_mps2 : d.a_star_mps2;
    if (opts)
        ctx->opts = *opts;
    else
        rb_solve_opts_init(&ctx->opts);
    /* a search keeps only summaries; histories would cost memory per run */
    ctx->opts.history_dt_s = 0;
    if (!(ctx->a_star_mps2 > 0) || !isfinite(ctx->a_star_mps2))
        return rb_design_fail(diag, RB_ERR_INVALID, "model", "A* of the model is not positive");
    if (motion && motion->kind == RB_MOTION_SAMPLED) {
        const rb_series *s = motion->series;
        ctx->shape_peak = s ? rb_series_peak(s) : 0;
        if (!(ctx->shape_peak > 0) || !isfinite(ctx->shape_peak))
            return rb_design_fail(diag, RB_ERR_INVALID, "motion",
                                  "the sampled motion has no nonzero sample to scale");
    }
    return RB_OK;
}

double rb_design_grid_point(double x)
{
    char buf[32];
    /* the nearest double to the 12-digit decimal, correctly rounded both
     * ways, so that two grids agree whenever their decimals do */
    snprintf(buf, sizeof buf, "%.11e", x);
    return strtod(buf, NULL);
}

void rb_design_motion_at(const rb_design_ctx *ctx, double level_mps2, rb_motion *out,
                         rb_motion *vertical)
{
    double own = rb_motion_peak(ctx->motion);
    *out = *ctx->motion;
    /* the motion's own level is the motion itself, not a rescaling that
     * could land an ulp away from it */
    if (level_mps2 == own)
        return;
    /* the sign of the shape's factor is kept: it is part of the shape */
    if (out->kind == RB_MOTION_SAMPLED)
        out->scale = copysign(level_mps2 / ctx->shape_peak, ctx->motion->scale);
    else
        out->amplitude_mps2 = copysign(level_mps2, ctx->motion->amplitude_mps2);
    /* a floor at another level shakes along every axis in proportion (the
     * AC156 spectra, horizontal and vertical, are both proportional to
     * S_DS): the vertical takes the horizontal's ratio to its own level */
    if (ctx->motion->vertical && own > 0) {
        double ratio = level_mps2 / own;
        *vertical = *ctx->motion->vertical;
        if (vertical->kind == RB_MOTION_SAMPLED)
            vertical->scale *= ratio;
        else
            vertical->amplitude_mps2 *= ratio;
        out->vertical = vertical;
    }
}

/* A solve through the search's memo: the searches of one design share
 * their runs, confirming runs included. */
static rb_status solve_memo(void *vctx, const rb_model *model, const rb_motion *motion,
                            const rb_solve_opts *opts, rb_result *out)
{
    const rb_design_ctx *ctx = vctx;
    rb_status st;
    if (rb_design_memo_take(ctx->memo, model, motion, opts, &st, out) == RB_MEMO_HIT)
        return st;
    st = rb_solve_run(model, motion, opts, out, NULL);
    /* no history was asked for, but free whatever the result might own */
    rb_result_free(out);
    out->history = NULL;
    rb_design_memo_put(ctx->memo, model, motion, opts, st, out);
    return st;
}

void rb_design_run_one(const rb_design_ctx *ctx, const rb_model *model,
                       const rb_motion *motion, rb_design_run *out)
{
    memset(out, 0, sizeof *out);
    out->meets = -1;
    if (motion->vertical && rb_motion_vertical_check(motion, ctx->g_mps2, NULL) != RB_OK) {
        /* the vertical, scaled with the level, throws the body off the
         * floor: the model does not follow it, and no criterion can be met
         * there (a lift-off, at least) */
        out->meets = ctx->criteria ? 0 : -1;
        out->status = ctx->criteria ? RB_OK : RB_ERR_INVALID;
        snprintf(out->reason, sizeof out->reason, "the vertical floor acceleration at this "
                 "level reaches -g: the base would leave the floor, which the model does "
                 "not follow");
        return;
    }
    out->status = solve_memo((void *)ctx, model, motion, &ctx->opts, &out->r);
    if (out->status == RB_OK && ctx->criteria)
    {
        rb_verdict v;
        if (ctx->defer_confirm)
            rb_judge(ctx->criteria, &out->r, &v);
        else
            rb_judge_decide(ctx->criteria, model, motion, &ctx->opts, &out->r, solve_memo,
                            (void *)ctx, &v);
        out->meets = v.pass;
        _Static_assert(sizeof out->reason == sizeof v.reason, "one reason, one size");
        memcpy(out->reason, v.reason, sizeof out->reason);
    }
    else if (out->status != RB_OK)
        snprintf(out->reason, sizeof out->reason, "the run failed: %s",
                 rb_status_str(out->status));
}

rb_status rb_design_run_at(const rb_model *model, const rb_motion *motion,
                           const rb_solve_opts *opts, const rb_criteria *criteria,
                           double level_mps2, rb_result *out, rb_verdict *verdict,
                           rb_confirm_run *runs, size_t *n_runs, rb_diag *diag)
{
    rb_design_ctx ctx;
    rb_motion at;
    memset(out, 0, sizeof *out);
    *n_runs = 0;
    rb_status st = rb_design_ctx_init(&ctx, model, motion, opts, criteria, diag);
    if (st != RB_OK)
        return st;
    rb_motion vertical;
    rb_design_motion_at(&ctx, level_mps2, &at, &vertical);
    st = rb_solve_run(model, &at, &ctx.opts, out, diag);
    if (st == RB_OK)
        rb_judge_run(criteria, model, &at, &ctx.opts, out, NULL, NULL, verdict, runs, n_runs);
    return st;
}
