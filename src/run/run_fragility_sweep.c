/* A case's fragility against its gap ratio: the same rb_run_fragility at
 * each ratio on a copy of the case whose model has that gap, as the case
 * loader would set it from gap_ratio:, so that a point is the fragility
 * of the case written with that ratio, to the last bit. The level (motion
 * 1's peak) and A* do not depend on the gap. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/run.h"

/* The least gap ratio other than 0 that the case loader takes. */
#define MIN_GAP_RATIO 1e-9

/* Every ratio before any search: a sweep that would stop half way wastes
 * the points before it. */
static rb_status check(const rb_case *c, const double *r, size_t n, rb_diag *diag)
{
    if (c->model.bolt_model == RB_BOLT_NONE)
        return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, "anchorage",
                           "a case without bolts has no gap to sweep");
    if (n == 0 || n > RB_FRAGILITY_SWEEP_MAX_POINTS)
        return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, "gap_ratio",
                           "a sweep takes 1 to %d gap ratios, not %zu",
                           RB_FRAGILITY_SWEEP_MAX_POINTS, n);
    for (size_t i = 0; i < n; i++) {
        rb_model m = c->model;
        rb_derived d;
        rb_diag why;
        if (!isfinite(r[i]) || r[i] < 0 || (r[i] > 0 && r[i] < MIN_GAP_RATIO))
            return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, "gap_ratio", "gap ratio "
                               "%g: a gap ratio is 0 or at least 1e-9 of the lever arm",
                               r[i]);
        m.gap_m = r[i] * m.lever_arm_m;
        rb_diag_clear(&why);
        if (rb_model_derive(&m, &d, &why) != RB_OK)
            /* the model's messages follow the name of its field */
            return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, "gap_ratio",
                               "gap ratio %g: the %s %.400s", r[i], why.key, why.msg);
    }
    return RB_OK;
}

typedef struct {
    rb_design_progress_fn fn;
    void *ctx;
    size_t before, total;     /* searches of the points done, of all */
} sweep_progress;

static void progress_one(void *arg, size_t done, size_t total, const char *what)
{
    sweep_progress *p = arg;
    (void)total;
    p->fn(p->ctx, p->before + done, p->total, what);
}

rb_status rb_run_fragility_gap_sweep(const rb_case *c, const double *gap_ratios, size_t n,
                                     int n_threads, uint64_t seed, unsigned n_boot,
                                     rb_fragility_sweep *out, rb_diag *diag,
                                     rb_design_progress_fn progress, void *ctx)
{
    memset(out, 0, sizeof *out);
    rb_status st = check(c, gap_ratios, n, diag);
    if (st != RB_OK)
        return st;
    out->gap_ratios = malloc(n * sizeof *out->gap_ratios);
    out->points = calloc(n, sizeof *out->points);
    if (!out->gap_ratios || !out->points) {
        rb_fragility_sweep_free(out);
        return RB_ERR_NOMEM;
    }
    memcpy(out->gap_ratios, gap_ratios, n * sizeof *gap_ratios);
    out->n_points = n;
    size_t per_point = rb_run_fragility_searches(c);
    sweep_progress sp = {progress, ctx, 0, n * per_point};
    for (size_t i = 0; i < n && st == RB_OK; i++) {
        /* the motions and everything else are shared, read only */
        rb_case at = *c;
        at.model.gap_m = gap_ratios[i] * c->model.lever_arm_m;
        st = rb_run_fragility(&at, n_threads, seed, n_boot, &out->points[i], diag,
                              progress ? progress_one : NULL, &sp);
        sp.before += per_point;
        if (st != RB_OK && diag)
            rb_diag_set_msg(diag, "at gap ratio %g: %.400s", gap_ratios[i], diag->msg);
    }
    return st;
}

rb_status rb_run_fragility_sweep_intensity(const rb_case *c, rb_fragility_intensity im,
                                           rb_fragility_sweep *s, rb_diag *diag)
{
    rb_status st = RB_OK;
    for (size_t i = 0; i < s->n_points && st == RB_OK; i++)
        st = rb_run_fragility_intensity(c, im, &s->points[i], diag);
    return st;
}
