/* Shared internals of the design checks: the parallel map over independent
 * solver runs and the evaluation of one run (model, motion at a level,
 * verdict). Not part of the public API. */
#ifndef RB_DESIGN_INTERNAL_H
#define RB_DESIGN_INTERNAL_H

#include <stddef.h>
#include "rockbolt/design.h"

/* The searches' runs are independent jobs of the shared pool. */
#include "util/pool.h"

/* Everything one run needs, read-only and shared by all jobs of a search. */
typedef struct {
    const rb_model *model;
    const rb_motion *motion;     /* the shape */
    rb_solve_opts opts;          /* history off */
    const rb_criteria *criteria; /* may be NULL: meets = -1 */
    double a_star_mps2;
    double g_mps2;               /* the model's gravity */
    double shape_peak;           /* peak of the shape's samples (sampled) */
    rb_design_memo *memo;        /* may be NULL */
    /* judge by rb_judge alone, without confirming a marginal pass: a
     * search that confirms the pass it ends on (design_factor.c) */
    int defer_confirm;
} rb_design_ctx;

/* Prepare ctx: derive the model, copy the options (NULL -> defaults) with
 * the history turned off, take the shape's peak. RB_ERR_INVALID with diag
 * filled for a bad model or a sampled motion of zero peak. */
rb_status rb_design_ctx_init(rb_design_ctx *ctx, const rb_model *model,
                             const rb_motion *motion, const rb_solve_opts *opts,
                             const rb_criteria *criteria, rb_diag *diag);

/* A copy of the shape whose peak floor acceleration is level_mps2. A
 * vertical component is scaled by the same ratio to the shape's own level,
 * into *vertical (the caller's, which must outlive out's runs). */
void rb_design_motion_at(const rb_design_ctx *ctx, double level_mps2, rb_motion *out,
                         rb_motion *vertical);

/* A grid point (a scan level, a sweep's x) to 12 significant digits:
 * grids that name the same level by different arithmetic (a scan's
 * start + k step, a sweep's from + (to - from) i / (n - 1)) then run the
 * same motion and share its run through the memo. */
double rb_design_grid_point(double x);

/* Outcome of one run, what the searches keep of an rb_result. */
typedef struct {
    rb_status status;
    int meets;                   /* 1 / 0; -1 without criteria */
    char reason[256];            /* rb_verdict.reason */
    rb_result r;                 /* summary (no history) */
} rb_design_run;

/* A run the memo holds: 1 with status and r filled, else 0 (memo NULL
 * included). */
int rb_design_memo_get(rb_design_memo *m, const rb_model *model, const rb_motion *motion,
                       const rb_solve_opts *opts, rb_status *status, rb_result *r);
/* A run the memo holds (HIT: status and r filled, waiting first for a run
 * another thread has claimed), or CLAIMED: the caller solves it and must
 * settle the claim with rb_design_memo_put (or _release), since others
 * wait for it; SOLVE: solve it (memo NULL, or one that cannot grow). */
typedef enum { RB_MEMO_SOLVE, RB_MEMO_CLAIMED, RB_MEMO_HIT } rb_design_memo_claim;
rb_design_memo_claim rb_design_memo_take(rb_design_memo *m, const rb_model *model,
                                         const rb_motion *motion, const rb_solve_opts *opts,
                                         rb_status *status, rb_result *r);
/* Give up a claim without a run to keep: a waiting thread solves it. */
void rb_design_memo_release(rb_design_memo *m, const rb_model *model,
                            const rb_motion *motion, const rb_solve_opts *opts);
/* Keep a run's summary, settling a claim on it (a result with a history
 * is not kept). */
void rb_design_memo_put(rb_design_memo *m, const rb_model *model, const rb_motion *motion,
                        const rb_solve_opts *opts, rb_status status, const rb_result *r);

/* Run model under motion (or take it from ctx->memo) and judge it. The rb_result inside out owns
 * nothing (no history is recorded). */
void rb_design_run_one(const rb_design_ctx *ctx, const rb_model *model,
                       const rb_motion *motion, rb_design_run *out);

/* Larger of two doubles (fmax without NaN questions). */
static inline double rb_design_max2(double a, double b)
{
    return a > b ? a : b;
}

/* Fill diag with a message (diag may be NULL); returns st. */
rb_status rb_design_fail(rb_diag *diag, rb_status st, const char *key, const char *msg);

#endif
