/* A case's fragility: for every motion and limit state the capacity by the
 * design factor's search, with a criterion that fails exactly when the
 * limit state is reached, then a lognormal fit per limit state
 * (rockbolt/fragility.h). The searches are independent, so they share the
 * threads (one thread each: a search's own speculative runs would be
 * wasted work), each writing its own slot; the result does not depend on
 * the thread count. */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/names.h"
#include "rockbolt/run.h"
#include "util/pool.h"

/* The base lifts at a few thousandths of A* (the frame amplifies the
 * floor): the design searches' 0.001 A* would be a third of it. */
#define RB_LIFT_OFF_RESOLUTION 1e-5

/* The judge's criteria and the solver options under which a run fails
 * exactly when limit state k is reached (or a worse state: a yield comes
 * before any usage, a row that breaks before it overturns is stretched on). */
static void limit_criteria(const rb_case *c, rb_limit_state k, int confirm,
                           rb_criteria *cr, rb_solve_opts *so)
{
    rb_criteria_init(cr);
    *so = c->solve;
    switch (k) {
    case RB_LIMIT_FIRST_YIELD:
        cr->kind = RB_CRIT_NO_YIELD;
        so->stop_at = RB_STOP_FIRST_YIELD;
        break;
    case RB_LIMIT_USAGE:
        cr->kind = RB_CRIT_NO_BREAK;
        if (c->criteria.kind == RB_CRIT_NO_BREAK)
            cr->usage_limit = c->criteria.usage_limit;
        /* the usage is read at the end of the run: keep stretching */
        so->stretch_past_failure = 1;
        break;
    case RB_LIMIT_OVERTURN:
    case RB_LIMIT_LIFT_OFF:
        cr->kind = RB_CRIT_NO_BREAK;
        cr->usage_limit = INFINITY;
        so->stretch_past_failure = 1;
        if (k == RB_LIMIT_LIFT_OFF) {
            cr->validity = RB_VALIDITY_FAIL;
            cr->validity_mask = 1u << RB_CHECK_LIFT_OFF;
            so->stop_at = RB_STOP_LIFT_OFF;
        }
        break;
    case RB_LIMIT_ANCHORAGE:
        /* the judge's own concrete check (the utilization the run tracks,
         * the route it applies) with nothing else to fail a run but
         * overturning, which fails every criterion: a cabinet that
         * overturns has pulled its anchorage out whatever the concrete */
        cr->kind = RB_CRIT_NO_BREAK;
        cr->usage_limit = INFINITY;
        cr->concrete = 1;
        cr->anchor_seismic = c->criteria.anchor_seismic;
        cr->anchor_route = c->criteria.anchor_route;
        cr->anchor_not_ductile = c->criteria.anchor_not_ductile;
        cr->anchor_attachment_margin = c->criteria.anchor_attachment_margin;
        cr->anchor_static_utilization = c->criteria.anchor_static_utilization;
        so->stretch_past_failure = 1;
        break;
    case RB_N_LIMITS:
        break;
    }
    /* A capacity is a point of a fitted curve, not a verdict: it is
     * confirmed at tighter tolerances only where it signs one, as the
     * governing state's (rb_run_fragility) */
    if (!confirm)
        cr->confirm = RB_CONFIRM_OFF;
}

unsigned rb_run_fragility_present(const rb_case *c)
{
    unsigned all = (1u << RB_N_LIMITS) - 1;
    /* the concrete check's strengths are on the solver's options once the
     * case resolved its concrete: section */
    if (!(c->has_concrete && c->solve.anchor_phi_nn_n > 0))
        all &= ~(1u << RB_LIMIT_ANCHORAGE);
    return all;
}

unsigned rb_run_fragility_judged(const rb_case *c)
{
    const rb_criteria *cr = &c->criteria;
    unsigned m = 1u << RB_LIMIT_OVERTURN;
    m |= 1u << (cr->kind == RB_CRIT_NO_YIELD ? RB_LIMIT_FIRST_YIELD : RB_LIMIT_USAGE);
    if (cr->validity == RB_VALIDITY_FAIL && (cr->validity_mask >> RB_CHECK_LIFT_OFF) & 1u)
        m |= 1u << RB_LIMIT_LIFT_OFF;
    if (cr->concrete)
        m |= 1u << RB_LIMIT_ANCHORAGE;
    return m & rb_run_fragility_present(c);
}

size_t rb_run_fragility_searches(const rb_case *c)
{
    size_t n = 0;
    unsigned present = rb_run_fragility_present(c);
    for (int k = 0; k < RB_N_LIMITS; k++)
        n += (present >> k) & 1u;
    return n * c->n_motions;
}

/* The level of motion m at which its vertical, scaled with it, reaches
 * -g (the searches' runs fail there: src/design/design_run.c); HUGE_VAL
 * where none does. */
static double model_limit(const rb_case *c, size_t m, double g_mps2)
{
    const rb_motion *mo = &c->motions[m].motion;
    if (!mo->vertical)
        return HUGE_VAL;
    double own = rb_motion_peak(mo), least = rb_motion_least(mo->vertical, mo->duration_s);
    return least < 0 && own > 0 ? own * g_mps2 / -least : HUGE_VAL;
}

static rb_status search(const rb_case *c, size_t m, rb_limit_state k, int confirm,
                        double a_star_mps2, double g_mps2, rb_design_memo *memo,
                        rb_motion_fragility *out, rb_diag *diag)
{
    rb_criteria cr;
    rb_solve_opts so;
    rb_design_factor_result f;
    rb_design_opts grid = c->design;
    limit_criteria(c, k, confirm, &cr, &so);
    /* the bracket narrowed by the margin's secant where the criteria give
     * one (usage, first yield: docs/fragility.md, "Fewer runs") */
    rb_design_hints hints = {0, 1};
    rb_status st = RB_OK;
    if (k == RB_LIMIT_LIFT_OFF) {
        /* the base cannot leave the floor below the level at which it first
         * lifts, and it does soon after: the bracket starts there */
        double uplift_mps2 = 0;
        if (grid.resolution > RB_LIFT_OFF_RESOLUTION)
            grid.resolution = RB_LIFT_OFF_RESOLUTION;
        st = rb_design_uplift_level(&c->model, &c->motions[m].motion, &so, memo,
                                    &uplift_mps2, diag);
        hints.near_astar = uplift_mps2 / a_star_mps2;
    }
    if (st == RB_OK)
        st = rb_design_factor_near(&c->model, &c->motions[m].motion, &so, &cr, &grid,
                                   1, memo, &hints, &f, diag);
    if (st != RB_OK) {
        char key[sizeof diag->key];
        if (snprintf(key, sizeof key, "motion '%.60s': %s", c->motions[m].name ?
                     c->motions[m].name : "?",
                     rb_enum_str(rb_limit_state_names, (int)k)) < 0)
            key[0] = '\0';
        return rb_diag_set(diag, st, diag->file, diag->line, diag->col, key, "%s",
                           diag->msg[0] ? diag->msg : rb_status_str(st));
    }
    out->censored[k] = f.no_failure;
    out->capacity_mps2[k] = f.no_failure ? f.level_mps2 : f.fail_mps2;
    out->runs = f.runs;
    /* A failing end at or past the level where the vertical reaches -g
     * failed there, whatever the bolts did: the capacity is the model's
     * limit, that level. (A lift-off is reached there: the floor falls
     * away from the base, which is what the state is.) The relative
     * slack covers the scaling's rounding in the searches' runs. */
    double limit = model_limit(c, m, g_mps2);
    out->model_limit_mps2 = limit;
    out->model_limited[k] = k != RB_LIMIT_LIFT_OFF && !f.no_failure && isfinite(limit)
                            && f.fail_mps2 >= limit * (1 - 1e-9);
    if (out->model_limited[k])
        out->capacity_mps2[k] = limit;
    return RB_OK;
}

typedef struct {
    const rb_case *c;
    rb_case_fragility *out;
    rb_diag *diags;             /* one per search */
    rb_design_progress_fn progress;
    void *progress_ctx;
    size_t done, total;
    pthread_mutex_t lock;       /* progress is told one call at a time */
    /* runs shared by the searches: the usage, overturning, lift-off and
     * anchorage searches of a motion run with the same options and scan
     * the same levels */
    rb_design_memo *memo;
    rb_limit_state order[RB_N_LIMITS]; /* the case's limit states, longest first */
    int confirming;             /* -1, or the state whose searches confirm */
    long *runs;                 /* per motion and limit state: the runs its
                                   search read (its last search's) */
} job_ctx;

/* The limit states in the order their searches are handed out: the
 * longest first (overturning runs to the highest levels, rocking hard), so
 * that the last searches, which decide when the threads finish, are short. */
static const rb_limit_state longest_first[RB_N_LIMITS] = {
    RB_LIMIT_OVERTURN, RB_LIMIT_USAGE, RB_LIMIT_ANCHORAGE, RB_LIMIT_FIRST_YIELD,
    RB_LIMIT_LIFT_OFF};

/* Search i: limit state order[i / n], motion i % n. The limit states of
 * one motion write their own fields of its slot. */
static rb_status job(void *arg, size_t i)
{
    job_ctx *jc = arg;
    size_t n = jc->out->n_motions, m = i % n;
    int k = jc->confirming >= 0 ? jc->confirming : (int)jc->order[i / n];
    rb_motion_fragility one = {{0}, {0}, {0}, 0, 1.0, HUGE_VAL};
    rb_diag_clear(&jc->diags[i]);
    rb_status st = search(jc->c, m, (rb_limit_state)k, jc->confirming >= 0,
                          jc->out->a_star_mps2, jc->out->g_mps2, jc->memo, &one,
                          &jc->diags[i]);
    pthread_mutex_lock(&jc->lock);
    rb_motion_fragility *slot = &jc->out->motions[m];
    slot->capacity_mps2[k] = one.capacity_mps2[k];
    slot->censored[k] = one.censored[k];
    slot->model_limited[k] = one.model_limited[k];
    slot->model_limit_mps2 = one.model_limit_mps2;
    jc->runs[m * RB_N_LIMITS + (size_t)k] = one.runs;
    if (jc->progress && jc->confirming < 0) {
        char what[160];
        snprintf(what, sizeof what, "motion '%.100s': %s", jc->c->motions[m].name
                 ? jc->c->motions[m].name : "?", rb_enum_str(rb_limit_state_names, k));
        jc->progress(jc->progress_ctx, ++jc->done, jc->total, what);
    }
    pthread_mutex_unlock(&jc->lock);
    return st;
}

/* n searches of jc through the pool; the first that failed, in the order
 * they were handed out, gives the status and the diag. */
static rb_status searches(job_ctx *jc, size_t n, int n_threads, rb_status *sts,
                          rb_diag *diag)
{
    rb_status st = rb_pool_map(n, n_threads, job, jc, sts);
    for (size_t i = 0; i < n && st == RB_OK; i++)
        if (sts[i] != RB_OK) {
            st = sts[i];
            if (diag)
                *diag = jc->diags[i];
        }
    return st;
}

static void fit_one(rb_case_fragility *fr, rb_limit_state k)
{
    size_t n = fr->n_motions;
    double *cap = malloc((n ? n : 1) * sizeof *cap);
    int *cens = malloc((n ? n : 1) * sizeof *cens);
    if (cap && cens) {
        for (size_t i = 0; i < n; i++) {
            cap[i] = fr->motions[i].capacity_mps2[k];
            cens[i] = fr->motions[i].censored[k];
        }
        rb_fragility_fit *f = &fr->fit[k];
        fr->fitted[k] = rb_fragility_mle(cap, cens, n, f) == RB_OK;
        if (fr->fitted[k]) {
            fr->p_at_level[k] = rb_fragility_prob(f, fr->level_mps2);
            fr->im10[k] = rb_fragility_quantile(f, 0.1);
            fr->im50[k] = f->median;
            if (rb_fragility_bootstrap(cap, cens, n, fr->n_boot, fr->seed + (uint64_t)k,
                                       RB_FRAGILITY_INTERVAL, &fr->median_lo[k],
                                       &fr->median_hi[k], NULL) != RB_OK)
                fr->median_lo[k] = fr->median_hi[k] = NAN;
        }
    }
    free(cap);
    free(cens);
}

/* Every limit state the case has, and the one that governs. */
static void fit_all(rb_case_fragility *fr)
{
    double median[RB_N_LIMITS];
    for (int k = 0; k < RB_N_LIMITS; k++) {
        if ((fr->present >> k) & 1u)
            fit_one(fr, (rb_limit_state)k);
        median[k] = fr->fit[k].median;
    }
    fr->governing = rb_fragility_governing(fr->judged, fr->fitted, median);
}

rb_status rb_run_fragility(const rb_case *c, int n_threads, uint64_t seed, unsigned n_boot,
                           rb_case_fragility *out, rb_diag *diag,
                           rb_design_progress_fn progress, void *ctx)
{
    rb_derived d;
    rb_status st = RB_OK;
    memset(out, 0, sizeof *out);
    if (c->model.bolt_model == RB_BOLT_NONE || c->n_motions == 0)
        return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, "anchorage",
                           "a fragility needs bolts and at least one motion");
    out->present = rb_run_fragility_present(c);
    out->judged = rb_run_fragility_judged(c);
    out->governing = -1;
    if ((st = rb_model_derive(&c->model, &d, diag)) != RB_OK)
        return st;
    out->motions = calloc(c->n_motions, sizeof *out->motions);
    if (!out->motions)
        return RB_ERR_NOMEM;
    out->n_motions = c->n_motions;
    out->g_mps2 = d.g;
    out->a_star_mps2 = d.a_star_mps2;
    out->level_mps2 = rb_motion_peak(&c->motions[0].motion);
    out->intensity = RB_IM_PFA;
    for (size_t m = 0; m < c->n_motions; m++) {
        out->motions[m].im_per_pfa = 1.0;
        out->motions[m].model_limit_mps2 = model_limit(c, m, d.g);
    }
    out->seed = seed;
    out->n_boot = n_boot;
    size_t total = rb_run_fragility_searches(c);
    job_ctx jc = {c, out, NULL, progress, ctx, 0, total, PTHREAD_MUTEX_INITIALIZER, NULL,
                  {0}, -1, NULL};
    for (int i = 0, j = 0; i < RB_N_LIMITS; i++)
        if ((out->present >> longest_first[i]) & 1u)
            jc.order[j++] = longest_first[i];
    jc.diags = calloc(total, sizeof *jc.diags);
    rb_status *sts = calloc(total, sizeof *sts);
    jc.runs = calloc(c->n_motions * RB_N_LIMITS, sizeof *jc.runs);
    jc.memo = rb_design_memo_new();
    if (!jc.diags || !sts || !jc.runs || !jc.memo) {
        free(jc.diags);
        free(sts);
        free(jc.runs);
        rb_design_memo_free(jc.memo);
        return RB_ERR_NOMEM;
    }
    st = searches(&jc, total, n_threads, sts, diag);
    /* Every capacity is first searched unconfirmed; then the governing
     * state's searches again with their confirmations (their scans and
     * bisections from the memo), until the state that governs is one
     * whose capacities are confirmed. A confirmation only lowers a
     * capacity, so the state that governed still does, as a rule; the loop
     * makes sure of it. */
    if (st == RB_OK)
        fit_all(out);
    while (st == RB_OK && out->governing >= 0
           && !((out->confirmed >> out->governing) & 1u)) {
        jc.confirming = out->governing;
        st = searches(&jc, c->n_motions, n_threads, sts, diag);
        out->confirmed |= 1u << jc.confirming;
        if (st == RB_OK)
            fit_all(out);
    }
    free(jc.diags);
    free(sts);
    out->solves = (long)rb_design_memo_runs(jc.memo);
    rb_design_memo_free(jc.memo);
    pthread_mutex_destroy(&jc.lock);
    for (size_t m = 0; st == RB_OK && m < c->n_motions; m++) {
        for (int k = 0; k < RB_N_LIMITS; k++)
            out->motions[m].runs += jc.runs[m * RB_N_LIMITS + (size_t)k];
        out->runs += out->motions[m].runs;
    }
    free(jc.runs);
    if (st != RB_OK)
        return st;
    if (progress)
        progress(ctx, total, total, NULL);
    return RB_OK;
}

/* Sa(f0) of a motion at its own level, 5 % damped (pseudo-acceleration). */
static rb_status motion_sa(const rb_motion *m, double f0, double xi, double *sa)
{
    rb_spectrum sp;
    rb_status st = rb_spectrum_alloc(&sp, &f0, 1, xi);
    if (st == RB_OK)
        st = rb_spectrum_of_motion(m, &sp);
    if (st == RB_OK)
        *sa = sp.psa_mps2[0];
    rb_spectrum_free(&sp);
    return st;
}

rb_status rb_run_fragility_intensity_ok(const rb_case *c, rb_fragility_intensity im,
                                        rb_diag *diag)
{
    if (im == RB_IM_SA && (c->model.rigid || !(c->model.freq_hz > 0)))
        return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, "equipment.frequency",
                           "spectral acceleration is taken at the cabinet's fixed-base "
                           "frequency, and a rigid cabinet has none");
    return RB_OK;
}

rb_status rb_run_fragility_intensity(const rb_case *c, rb_fragility_intensity im,
                                     rb_case_fragility *f, rb_diag *diag)
{
    if (im == f->intensity)
        return RB_OK;
    if (im != RB_IM_SA || f->intensity != RB_IM_PFA || f->n_motions != c->n_motions)
        return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, "intensity",
                           "a fragility in peak floor acceleration can be restated in "
                           "spectral acceleration only");
    rb_status st0 = rb_run_fragility_intensity_ok(c, im, diag);
    if (st0 != RB_OK)
        return st0;
    const double xi = 0.05;
    for (size_t m = 0; m < f->n_motions; m++) {
        const rb_motion *mo = &c->motions[m].motion;
        double sa = 0, peak = rb_motion_peak(mo);
        rb_status st = motion_sa(mo, c->model.freq_hz, xi, &sa);
        if (st != RB_OK || !(peak > 0))
            return rb_diag_set(diag, st != RB_OK ? st : RB_ERR_INVALID, NULL, 0, 0,
                               c->motions[m].name ? c->motions[m].name : "motion",
                               "no spectral acceleration for this motion");
        double r = sa / peak;
        f->motions[m].im_per_pfa = r;
        for (int k = 0; k < RB_N_LIMITS; k++)
            f->motions[m].capacity_mps2[k] *= r;
        f->motions[m].model_limit_mps2 *= r;
    }
    f->level_mps2 *= f->motions[0].im_per_pfa;
    f->intensity = RB_IM_SA;
    f->im_freq_hz = c->model.freq_hz;
    f->im_damping = xi;
    fit_all(f);
    return RB_OK;
}
