/* The design a case asks for, in the order an engineer reads it: per
 * motion the design factors and the recommended gap, then the sweeps and
 * the code-static comparison. Each search already uses every thread it is
 * given, so the searches themselves run one after another. `design` runs
 * it all, `batch --design` the brief part of each motion: both through
 * design_motion, with the criteria of rb_run_design_criteria. */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/aci17.h"
#include "rockbolt/names.h"
#include "rockbolt/run.h"
#include "util/pool.h"

static rb_status fail_at(rb_diag *diag, const char *motion, const char *what,
                         rb_status st)
{
    char key[sizeof diag->key];
    if (!diag)
        return st;
    /* A long key is cut: the return value is read so that the cut is
     * deliberate, not a -Wformat-truncation warning in release builds. */
    if (snprintf(key, sizeof key, "motion '%.60s': %s", motion ? motion : "?", what) < 0)
        key[0] = '\0';
    return rb_diag_set(diag, st, diag->file, diag->line, diag->col, key, "%s",
                       diag->msg[0] ? diag->msg : rb_status_str(st));
}

/* The searches done and to do, told to a progress callback. */
typedef struct {
    rb_design_progress_fn fn;
    void *ctx;
    size_t done, total;
    pthread_mutex_t lock;   /* a motion's searches run side by side */
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
    pthread_mutex_lock(&p->lock);
    p->fn(p->ctx, p->done++, p->total, buf);
    pthread_mutex_unlock(&p->lock);
}

/* The searches of one motion, as jobs that may run at once: the design
 * factor of each criterion kind, the recommended gap and the amplitude
 * sweeps. They share one memo that waits for a run another search is
 * solving rather than solve it twice, so the factors run side by side
 * over the scan levels they share. Each writes its own fields of md and
 * its own diag; their results do not depend on which runs first. */
typedef struct {
    const rb_case *c;
    const rb_case_motion *cm;
    int full;
    int n_threads;              /* of each search */
    int sweep_threads;          /* of the amplitude sweeps */
    const rb_case_design *cd;
    rb_design_memo *memo;
    rb_motion_design *md;
    progress *pg;
    rb_diag diag[RB_N_CRITERIA + 2];
} searches;

/* jobs 0 to RB_N_CRITERIA - 1: the factor of that kind */
enum { JOB_GAP = RB_N_CRITERIA, JOB_SWEEPS, N_JOBS };

rb_design_hints rb_run_design_factor_hints(void)
{
    /* the bracket narrowed by the margin's secant where the criteria give
     * one: fewer runs where the margin is near linear, the level found
     * within the resolution of the bisection's */
    rb_design_hints hints = {0, 1};
    return hints;
}

/* The factor of criterion kind k (the case's own only, for the brief
 * design of a batch), under its kind's criteria. */
static rb_status factor(searches *s, int k, rb_diag *diag)
{
    const rb_case *c = s->c;
    char what[64], words[40];
    if (!s->full && (int)c->criteria.kind != k)
        return RB_OK;
    /* "design factor (no yield)": the kind's name in words */
    snprintf(what, sizeof what, "design factor (%s)",
             rb_enum_str_sep(rb_criterion_names, k, ' ', words, sizeof words));
    step(s->pg, s->cm->name, what);
    rb_design_hints hints = rb_run_design_factor_hints();
    rb_status st = rb_design_factor_near(&c->model, &s->cm->motion, &c->solve,
                                         &s->cd->factor_criteria[k], &c->design,
                                         s->n_threads, s->memo, &hints, &s->md->factor[k],
                                         diag);
    return st == RB_OK ? st : fail_at(diag, s->cm->name, what, st);
}

static rb_status gap(searches *s, rb_diag *diag)
{
    const rb_case *c = s->c;
    if (c->model.bolt_model == RB_BOLT_NONE)
        return RB_OK;
    step(s->pg, s->cm->name, "recommended gap");
    rb_status st = rb_gap_recommend_memo(&c->model, &s->cm->motion, &c->solve,
                                         &s->cd->gap_criteria, &c->design, s->n_threads,
                                         s->memo, &s->md->gap, diag);
    s->md->has_gap = st == RB_OK;
    return st == RB_OK ? st : fail_at(diag, s->cm->name, "recommended gap", st);
}

static rb_status amplitude_sweeps(searches *s, rb_diag *diag)
{
    const rb_case *c = s->c;
    rb_motion_design *md = s->md;
    size_t i, n_amp = 0;
    for (i = 0; s->full && i < c->n_sweeps; i++)
        n_amp += c->sweeps[i].kind == RB_SWEEP_AMPLITUDE;
    if (n_amp && !(md->sweeps = calloc(n_amp, sizeof *md->sweeps)))
        return RB_ERR_NOMEM;
    for (i = 0; n_amp && i < c->n_sweeps; i++) {
        if (c->sweeps[i].kind != RB_SWEEP_AMPLITUDE)
            continue;
        step(s->pg, s->cm->name, "amplitude sweep");
        rb_status st = rb_sweep_amplitude(&c->model, &s->cm->motion, &c->solve,
                                          &c->criteria, &c->sweeps[i], s->sweep_threads,
                                          s->memo, &md->sweeps[md->n_sweeps++], diag);
        if (st != RB_OK)
            return fail_at(diag, s->cm->name, "amplitude sweep", st);
    }
    return RB_OK;
}

static rb_status search_job(void *v, size_t i)
{
    searches *s = v;
    rb_diag_clear(&s->diag[i]);
    if (i < JOB_GAP)
        return factor(s, (int)i, &s->diag[i]);
    return i == JOB_GAP ? gap(s, &s->diag[i]) : amplitude_sweeps(s, &s->diag[i]);
}

static rb_status design_searches(const rb_case *c, const rb_case_motion *cm,
                                 rb_run_design_scope scope, int n_threads,
                                 const rb_case_design *cd, rb_design_memo *memo,
                                 rb_motion_design *md, rb_diag *diag, progress *pg)
{
    searches s = {.c = c, .cm = cm, .full = scope == RB_RUN_DESIGN_FULL, .n_threads = 1,
                  .cd = cd, .memo = memo, .md = md, .pg = pg};
    rb_status sts[N_JOBS];
    int nt = n_threads > 0 ? n_threads : rb_pool_threads_default();
    /* the jobs side by side, their searches sharing out the threads: a
     * search's rounds wait for their slowest run, and the other jobs fill
     * the wait (rounding up oversubscribes a little rather than idle) */
    int outer = nt < N_JOBS ? nt : N_JOBS;
    s.n_threads = (nt + outer - 1) / outer;
    /* the sweeps start last, when one search is done; their points wait
     * on nothing, so they take every thread and fill the core the other
     * search leaves when it ends (a search given more threads would
     * evaluate levels it may not need) */
    s.sweep_threads = nt;
    rb_status st = rb_pool_map(N_JOBS, outer, search_job, &s, sts);
    for (int i = 0; i < N_JOBS && st == RB_OK; i++)
        if (sts[i] != RB_OK) {
            st = sts[i];
            if (diag)
                *diag = s.diag[i];
        }
    return st;
}

/* The searches of one motion share their runs: the factors' scans and an
 * amplitude sweep ask for many of the same levels, and the recommended
 * gap's run at the case's own gap is the motion's own run, which `check`
 * made before (checked, NULL when none). */
static rb_status design_motion(const rb_case *c, const rb_case_motion *cm,
                               const rb_result *checked, rb_run_design_scope scope,
                               int n_threads, const rb_case_design *cd,
                               rb_motion_design *md, rb_diag *diag, progress *pg)
{
    rb_design_memo *memo = rb_design_memo_new();
    if (!memo)
        return RB_ERR_NOMEM;
    if (checked)
        rb_design_memo_keep(memo, &c->model, &cm->motion, &c->solve, RB_OK, checked);
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
            rb_diag_set_key(diag, "design.sweeps[%zu]", i + 1);
            return st;
        }
    }
    return RB_OK;
}

void rb_run_design_criteria(const rb_case *c, rb_case_design *out)
{
    for (int k = 0; k < RB_N_CRITERIA; k++) {
        out->factor_criteria[k] = c->criteria;
        out->factor_criteria[k].kind = (rb_criterion_kind)k;
    }
    /* a case judged on "no yield" still has a no-break factor: at the
     * default usage limit, not whatever the no-yield case left there */
    if (c->criteria.kind != RB_CRIT_NO_BREAK) {
        rb_criteria def;
        rb_criteria_init(&def);
        out->factor_criteria[RB_CRIT_NO_BREAK].usage_limit = def.usage_limit;
    }
    out->gap_criteria = c->criteria;
}

rb_status rb_run_motion_design(const rb_case *c, size_t m, const rb_result *checked,
                               rb_run_design_scope scope, int n_threads,
                               const rb_case_design *cd, rb_motion_design *md,
                               rb_diag *diag)
{
    progress none = {NULL, NULL, 0, 0, PTHREAD_MUTEX_INITIALIZER};
    memset(md, 0, sizeof *md);
    return design_motion(c, &c->motions[m], checked, scope, n_threads, cd, md, diag, &none);
}

const rb_design_factor_result *rb_run_own_factor(const rb_case *c,
                                                 const rb_motion_design *md)
{
    return &md->factor[c->criteria.kind];
}

/* The design's two independent parts: every motion's searches, and the
 * frequency sweeps (which use no motion), each with its own diag. */
typedef struct {
    const rb_case *c;
    const rb_result *checked;   /* check's run of each motion, or NULL */
    int n_threads;
    rb_case_design *out;
    progress *pg;
    rb_diag diag[2];
} design_parts;

static rb_status part_job(void *v, size_t i)
{
    design_parts *d = v;
    rb_status st = RB_OK;
    rb_diag_clear(&d->diag[i]);
    if (i == 1)
        return design_sweeps(d->c, d->n_threads, d->out, &d->diag[i], d->pg);
    for (size_t m = 0; m < d->c->n_motions && st == RB_OK; m++)
        st = design_motion(d->c, &d->c->motions[m], d->checked ? &d->checked[m] : NULL,
                           RB_RUN_DESIGN_FULL, d->n_threads, d->out, &d->out->motions[m],
                           &d->diag[i], d->pg);
    return st;
}

rb_status rb_run_design(const rb_case *c, int n_threads, rb_case_design *out,
                        rb_diag *diag, rb_design_progress_fn fn, void *ctx)
{
    return rb_run_design_checked(c, NULL, n_threads, out, diag, fn, ctx);
}

rb_status rb_run_design_checked(const rb_case *c, const rb_result *checked, int n_threads,
                                rb_case_design *out, rb_diag *diag,
                                rb_design_progress_fn fn, void *ctx)
{
    rb_status st = RB_OK;
    size_t i, n_amp = 0, n_freq = 0;
    progress pg = {fn, ctx, 0, 0, PTHREAD_MUTEX_INITIALIZER};
    for (i = 0; i < c->n_sweeps; i++) {
        n_amp += c->sweeps[i].kind == RB_SWEEP_AMPLITUDE;
        n_freq += c->sweeps[i].kind == RB_SWEEP_FREQUENCY;
    }
    pg.total = c->n_motions * (RB_N_CRITERIA + (c->model.bolt_model != RB_BOLT_NONE) + n_amp)
        + n_freq + (c->has_code != 0);
    memset(out, 0, sizeof *out);
    rb_run_design_criteria(c, out);
    if (!(out->motions = calloc(c->n_motions ? c->n_motions : 1, sizeof *out->motions)))
        return RB_ERR_NOMEM;
    out->n_motions = c->n_motions;
    /* the frequency sweeps side by side with the motions' searches: a
     * search's bisection is a chain of runs, one after another, and the
     * sweep's independent points fill the cores it leaves idle (each
     * part is given every thread; with one, they run in this order) */
    int nt = n_threads > 0 ? n_threads : rb_pool_threads_default();
    design_parts parts = {.c = c, .checked = checked, .n_threads = n_threads, .out = out,
                          .pg = &pg};
    rb_status sts[2];
    st = rb_pool_map(n_freq ? 2 : 1, nt > 1 ? 2 : 1, part_job, &parts, sts);
    for (i = 0; i < (n_freq ? 2u : 1u) && st == RB_OK; i++)
        if (sts[i] != RB_OK) {
            st = sts[i];
            if (diag)
                *diag = parts.diag[i];
        }
    if (st == RB_OK && c->has_code) {
        step(&pg, NULL, "code-static comparison");
        st = rb_code_static(&c->model, &c->code, &out->code, diag);
        if (st == RB_OK && c->has_anchor_static) {
            /* the static demand on the anchorage, worked out with the case */
            rb_code_result *k = &out->code;
            k->has_concrete = 1;
            k->concrete_utilization = c->anchor_static_utilization;
            k->concrete_clause = c->anchor_static_clause;
        }
        if (st != RB_OK)
            rb_diag_set_key(diag, "design.code.%.100s", diag->key);
        out->has_code = st == RB_OK;
    }
    if (st == RB_OK && fn)
        fn(ctx, pg.total, pg.total, NULL);
    return st;
}
