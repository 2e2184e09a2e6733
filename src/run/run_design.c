/* The design a case asks for, in the order an engineer reads it: per
 * motion the design factors and the recommended gap, then the sweeps and
 * the code-static comparison. Each search already uses every thread it is
 * given, so the searches themselves run one after another. `design` runs
 * it all, `batch --design` the brief part of each motion: both through
 * design_motion, with the criteria of rb_run_design_criteria. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/aci17.h"
#include "rockbolt/run.h"

static rb_status fail_at(rb_diag *diag, const char *motion, const char *what,
                         rb_status st)
{
    char key[sizeof diag->key];
    if (!diag)
        return st;
    snprintf(key, sizeof key, "motion '%.60s': %s", motion ? motion : "?", what);
    return rb_diag_set(diag, st, diag->file, diag->line, diag->col, key, "%s",
                       diag->msg[0] ? diag->msg : rb_status_str(st));
}

/* The searches done and to do, told to a progress callback. */
typedef struct {
    rb_design_progress_fn fn;
    void *ctx;
    size_t done, total;
} progress;

static void step(progress *p, const char *motion, const char *what)
{
    char buf[200];
    if (!p->fn)
        return;
    if (motion)
        snprintf(buf, sizeof buf, "motion '%.100s': %s", motion, what);
    else
        snprintf(buf, sizeof buf, "%s", what);
    p->fn(p->ctx, p->done++, p->total, buf);
}

static rb_status design_searches(const rb_case *c, const rb_case_motion *cm,
                                 rb_run_design_scope scope, int n_threads,
                                 const rb_case_design *cd, rb_design_memo *memo,
                                 rb_motion_design *md, rb_diag *diag, progress *pg)
{
    const rb_motion *mo = &cm->motion;
    rb_status st;
    size_t i, n_amp = 0;
    int full = scope == RB_RUN_DESIGN_FULL;
    if (full || c->criteria.kind == RB_CRIT_NO_YIELD) {
        step(pg, cm->name, "design factor (no yield)");
        st = rb_design_factor(&c->model, mo, &c->solve, &cd->no_yield, &c->design,
                              n_threads, memo, &md->no_yield, diag);
        if (st != RB_OK)
            return fail_at(diag, cm->name, "design factor (no yield)", st);
    }
    if (full || c->criteria.kind == RB_CRIT_NO_BREAK) {
        step(pg, cm->name, "design factor (no break)");
        st = rb_design_factor(&c->model, mo, &c->solve, &cd->no_break, &c->design,
                              n_threads, memo, &md->no_break, diag);
        if (st != RB_OK)
            return fail_at(diag, cm->name, "design factor (no break)", st);
    }
    if (c->model.bolt_model != RB_BOLT_NONE) {
        step(pg, cm->name, "recommended gap");
        st = rb_gap_recommend(&c->model, mo, &c->solve, &cd->gap_criteria, &c->design,
                              n_threads, &md->gap, diag);
        md->has_gap = st == RB_OK;
        if (st != RB_OK)
            return fail_at(diag, cm->name, "recommended gap", st);
    }
    for (i = 0; full && i < c->n_sweeps; i++)
        n_amp += c->sweeps[i].kind == RB_SWEEP_AMPLITUDE;
    if (n_amp && !(md->sweeps = calloc(n_amp, sizeof *md->sweeps)))
        return RB_ERR_NOMEM;
    for (i = 0; n_amp && i < c->n_sweeps; i++) {
        if (c->sweeps[i].kind != RB_SWEEP_AMPLITUDE)
            continue;
        step(pg, cm->name, "amplitude sweep");
        st = rb_sweep_amplitude(&c->model, mo, &c->solve, &c->criteria, &c->sweeps[i],
                                n_threads, memo, &md->sweeps[md->n_sweeps++], diag);
        if (st != RB_OK)
            return fail_at(diag, cm->name, "amplitude sweep", st);
    }
    return RB_OK;
}

/* The searches of one motion share their runs: the factors' scans and an
 * amplitude sweep ask for many of the same levels. */
static rb_status design_motion(const rb_case *c, const rb_case_motion *cm,
                               rb_run_design_scope scope, int n_threads,
                               const rb_case_design *cd, rb_motion_design *md,
                               rb_diag *diag, progress *pg)
{
    rb_design_memo *memo = rb_design_memo_new();
    if (!memo)
        return RB_ERR_NOMEM;
    rb_status st = design_searches(c, cm, scope, n_threads, cd, memo, md, diag, pg);
    rb_design_memo_free(memo);
    return st;
}

static rb_status design_sweeps(const rb_case *c, int n_threads, rb_case_design *out,
                               rb_diag *diag, progress *pg)
{
    size_t i, n = 0;
    for (i = 0; i < c->n_sweeps; i++)
        n += c->sweeps[i].kind == RB_SWEEP_FREQUENCY;
    if (!n)
        return RB_OK;
    if (!(out->sweeps = calloc(n, sizeof *out->sweeps)))
        return RB_ERR_NOMEM;
    for (i = 0; i < c->n_sweeps; i++) {
        rb_status st;
        if (c->sweeps[i].kind != RB_SWEEP_FREQUENCY)
            continue;
        step(pg, NULL, "frequency sweep");
        st = rb_sweep_frequency(&c->model, &c->solve, &c->criteria, &c->sweeps[i],
                                n_threads, &out->sweeps[out->n_sweeps++], diag);
        if (st != RB_OK) {
            snprintf(diag->key, sizeof diag->key, "design.sweeps[%zu]", i + 1);
            return st;
        }
    }
    return RB_OK;
}

void rb_run_design_criteria(const rb_case *c, rb_case_design *out)
{
    out->no_yield = c->criteria;
    out->no_yield.kind = RB_CRIT_NO_YIELD;
    out->no_break = c->criteria;
    out->no_break.kind = RB_CRIT_NO_BREAK;
    /* a case judged on "no yield" still has a no-break factor: at the
     * default usage limit, not whatever the no-yield case left there */
    if (c->criteria.kind != RB_CRIT_NO_BREAK) {
        rb_criteria def;
        rb_criteria_init(&def);
        out->no_break.usage_limit = def.usage_limit;
    }
    out->gap_criteria = c->criteria;
}

rb_status rb_run_motion_design(const rb_case *c, size_t m, rb_run_design_scope scope,
                               int n_threads, const rb_case_design *cd,
                               rb_motion_design *md, rb_diag *diag)
{
    progress none = {0};
    memset(md, 0, sizeof *md);
    return design_motion(c, &c->motions[m], scope, n_threads, cd, md, diag, &none);
}

const rb_design_factor_result *rb_run_own_factor(const rb_case *c,
                                                 const rb_motion_design *md)
{
    return c->criteria.kind == RB_CRIT_NO_YIELD ? &md->no_yield : &md->no_break;
}

rb_status rb_run_design(const rb_case *c, int n_threads, rb_case_design *out,
                        rb_diag *diag, rb_design_progress_fn fn, void *ctx)
{
    rb_status st = RB_OK;
    size_t i, n_amp = 0, n_freq = 0;
    progress pg = {fn, ctx, 0, 0};
    for (i = 0; i < c->n_sweeps; i++) {
        n_amp += c->sweeps[i].kind == RB_SWEEP_AMPLITUDE;
        n_freq += c->sweeps[i].kind == RB_SWEEP_FREQUENCY;
    }
    pg.total = c->n_motions * (2 + (c->model.bolt_model != RB_BOLT_NONE) + n_amp)
        + n_freq + (c->has_code != 0);
    memset(out, 0, sizeof *out);
    rb_run_design_criteria(c, out);
    if (!(out->motions = calloc(c->n_motions ? c->n_motions : 1, sizeof *out->motions)))
        return RB_ERR_NOMEM;
    out->n_motions = c->n_motions;
    for (i = 0; i < c->n_motions && st == RB_OK; i++)
        st = design_motion(c, &c->motions[i], RB_RUN_DESIGN_FULL, n_threads, out,
                           &out->motions[i], diag, &pg);
    if (st == RB_OK)
        st = design_sweeps(c, n_threads, out, diag, &pg);
    if (st == RB_OK && c->has_code) {
        step(&pg, NULL, "code-static comparison");
        st = rb_code_static(&c->model, &c->code, &out->code, diag);
        if (st == RB_OK && c->has_concrete) {
            /* the static demand on the anchorage: T of a row, and all of
             * the anchor design force in shear (no friction counted) */
            rb_code_result *k = &out->code;
            k->has_concrete = 1;
            k->concrete_utilization = rb_aci17_interaction(k->tension_n, c->anchor.phi_nn_n,
                                                           k->fp_anchor_n, c->anchor.phi_vn_n,
                                                           &k->concrete_clause);
        }
        if (st != RB_OK) {
            char key[sizeof diag->key];
            snprintf(key, sizeof key, "design.code.%.100s", diag->key);
            snprintf(diag->key, sizeof diag->key, "%s", key);
        }
        out->has_code = st == RB_OK;
    }
    if (st == RB_OK && fn)
        fn(ctx, pg.total, pg.total, NULL);
    return st;
}
