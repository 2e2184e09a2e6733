/* The level of a motion's shape at which the base first lifts, from one
 * run (design.h). On the floor the response is linear in the level, and
 * the base lifts where stage 1's overturning moment about an edge,
 * M h x'' - F* U'', first reaches W b (thesis eq. 5.3d). Held down by
 * rigid bolts at no gap, the cabinet never leaves that linear response,
 * and a row's force is the moment's excess over W b on the lever arm
 * (eq. 5.13 at theta0 = 0): the largest row force F of the held run at a
 * level s gives the largest moment, F l + W b, at s, and the moment scales
 * with the level. */
#include <math.h>
#include "design_internal.h"

rb_status rb_design_uplift_level(const rb_model *model, const rb_motion *motion,
                                 const rb_solve_opts *opts, rb_design_memo *memo,
                                 double *level_mps2, rb_diag *diag)
{
    rb_design_ctx ctx;
    rb_derived d;
    *level_mps2 = 0;
    /* a vertical floor motion moves W b with the level: not one ratio */
    if (!motion || motion->vertical || model->bolt_model == RB_BOLT_NONE)
        return RB_OK;
    rb_model held = *model;
    held.bolt_model = RB_BOLT_NONYIELDING;
    held.gap_m = 0;
    rb_status st = rb_model_derive(&held, &d, diag);
    if (st == RB_OK)
        st = rb_design_ctx_init(&ctx, &held, motion, opts, NULL, diag);
    if (st != RB_OK)
        return st;
    ctx.opts.stop_at = 0;
    double level = rb_motion_peak(motion);
    rb_result r = {0};
    if (!rb_design_memo_get(memo, &held, motion, &ctx.opts, &st, &r)) {
        st = rb_solve_run(&held, motion, &ctx.opts, &r, diag);
        rb_result_free(&r);
        r.history = NULL;
        rb_design_memo_put(memo, &held, motion, &ctx.opts, st, &r);
    }
    if (st != RB_OK)
        return st;
    double force = fmax(r.max_bolt_force_n[0], r.max_bolt_force_n[1]);
    double wb = d.W * model->half_width_m;
    /* a motion that never lifts the base at its own level gives no ratio */
    if (force > 0 && level > 0)
        *level_mps2 = level * wb / (force * model->lever_arm_m + wb);
    return RB_OK;
}
