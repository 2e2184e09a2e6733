/* Solver runs kept for the searches of one design (design.h). The two
 * design factors and an amplitude sweep of the same motion ask for many of
 * the same levels; a run is the same bits whoever asks, so it is solved
 * once. An entry is found by the exact bytes of the model, the scaled
 * motion and the solver options: bytes that differ (padding included) only
 * cost a second solve, never a wrong hit. The one exception is asked for:
 * a run to stop at a limit state's crossing (rb_solve_opts.stop_at) is
 * served by the same run made to the end, which decides that state
 * alike.
 *
 * Searches that run side by side may ask for one run at once: the first
 * to ask claims it (an entry not yet ready) and solves it, the others
 * wait for it instead of solving it again. A claim is always settled by
 * rb_design_memo_put, or given up by rb_design_memo_release. */
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include "design_internal.h"
#include "util/grow.h"

typedef struct {
    rb_model model;
    rb_motion motion;          /* its vertical pointer cleared: */
    rb_motion vertical;        /* the vertical's own bytes (zero for none),
                                  since a search scales it into a copy of
                                  its own wherever it runs a level */
    rb_solve_opts opts;
    rb_status status;
    rb_result r;
    int ready;                 /* 0: claimed, being solved */
} memo_entry;

struct rb_design_memo {
    pthread_mutex_t lock;
    pthread_cond_t settled;    /* a claim was put or released */
    memo_entry *e;
    size_t n, cap, n_ready;
};

rb_design_memo *rb_design_memo_new(void)
{
    rb_design_memo *m = calloc(1, sizeof *m);
    if (!m)
        return NULL;
    if (pthread_mutex_init(&m->lock, NULL) != 0) {
        free(m);
        return NULL;
    }
    if (pthread_cond_init(&m->settled, NULL) != 0) {
        pthread_mutex_destroy(&m->lock);
        free(m);
        return NULL;
    }
    return m;
}

void rb_design_memo_free(rb_design_memo *m)
{
    if (!m)
        return;
    pthread_cond_destroy(&m->settled);
    pthread_mutex_destroy(&m->lock);
    free(m->e);
    free(m);
}

size_t rb_design_memo_runs(rb_design_memo *m)
{
    size_t n = 0;
    if (m) {
        pthread_mutex_lock(&m->lock);
        n = m->n_ready;
        pthread_mutex_unlock(&m->lock);
    }
    return n;
}

/* A motion as the memo keeps it: the vertical's bytes beside it. */
static void key_of(const rb_motion *motion, rb_motion *flat, rb_motion *vertical)
{
    *flat = *motion;
    flat->vertical = NULL;
    memset(vertical, 0, sizeof *vertical);
    if (motion->vertical)
        *vertical = *motion->vertical;
}

/* The entry of a run, ready or claimed; NULL when none. */
static memo_entry *find(const rb_design_memo *m, const rb_model *model,
                        const rb_motion *motion_in, const rb_solve_opts *opts)
{
    rb_motion flat, vertical;
    const rb_motion *motion = &flat;
    key_of(motion_in, &flat, &vertical);
    for (size_t i = 0; i < m->n; i++) {
        memo_entry *e = &m->e[i];
        if (!memcmp(&e->motion, motion, sizeof *motion)
            && !memcmp(&e->vertical, &vertical, sizeof vertical)
            && !memcmp(&e->model, model, sizeof *model)
            && !memcmp(&e->opts, opts, sizeof *opts))
            return e;
    }
    return NULL;
}

/* A ready run: the run itself, or for a run to stop at a crossing, the
 * same run made to the end. Under m->lock. */
static const memo_entry *find_ready(const rb_design_memo *m, const rb_model *model,
                                    const rb_motion *motion, const rb_solve_opts *opts)
{
    const memo_entry *e = find(m, model, motion, opts);
    if ((!e || !e->ready) && opts->stop_at) {
        /* a run that goes to the end decides whatever a run stopped at a
         * crossing decides: the scan levels every limit state shares */
        rb_solve_opts full = *opts;
        full.stop_at = 0;
        const memo_entry *f = find(m, model, motion, &full);
        if (f && f->ready)
            return f;
    }
    return e && e->ready ? e : NULL;
}

int rb_design_memo_get(rb_design_memo *m, const rb_model *model, const rb_motion *motion,
                       const rb_solve_opts *opts, rb_status *status, rb_result *r)
{
    int hit = 0;
    if (!m)
        return 0;
    pthread_mutex_lock(&m->lock);
    const memo_entry *e = find_ready(m, model, motion, opts);
    if (e) {
        *status = e->status;
        *r = e->r;
        hit = 1;
    }
    pthread_mutex_unlock(&m->lock);
    return hit;
}

/* A new entry, not ready; NULL when the memo cannot grow. Under m->lock. */
static memo_entry *add(rb_design_memo *m, const rb_model *model, const rb_motion *motion,
                       const rb_solve_opts *opts)
{
    if (m->n == m->cap) {
        memo_entry *e = rb_grow(m->e, &m->cap, sizeof *e, 64);
        if (!e)
            return NULL;
        m->e = e;
    }
    memo_entry *e = &m->e[m->n++];
    memset(e, 0, sizeof *e);
    e->model = *model;
    key_of(motion, &e->motion, &e->vertical);
    e->opts = *opts;
    return e;
}

rb_design_memo_claim rb_design_memo_take(rb_design_memo *m, const rb_model *model,
                                         const rb_motion *motion, const rb_solve_opts *opts,
                                         rb_status *status, rb_result *r)
{
    rb_design_memo_claim got = RB_MEMO_SOLVE;
    if (!m)
        return got;
    pthread_mutex_lock(&m->lock);
    for (;;) {
        const memo_entry *e = find_ready(m, model, motion, opts);
        if (e) {
            *status = e->status;
            *r = e->r;
            got = RB_MEMO_HIT;
            break;
        }
        if (!find(m, model, motion, opts)) {
            /* nobody has it: solve it here (or, if the memo cannot grow,
             * solve it unclaimed: the run stands, the memo only forgets) */
            got = add(m, model, motion, opts) ? RB_MEMO_CLAIMED : RB_MEMO_SOLVE;
            break;
        }
        /* another search is solving it: its result is this run's, bit
         * for bit */
        pthread_cond_wait(&m->settled, &m->lock);
    }
    pthread_mutex_unlock(&m->lock);
    return got;
}

void rb_design_memo_release(rb_design_memo *m, const rb_model *model,
                            const rb_motion *motion, const rb_solve_opts *opts)
{
    if (!m)
        return;
    pthread_mutex_lock(&m->lock);
    memo_entry *e = find(m, model, motion, opts);
    if (e && !e->ready) {
        /* the last entry takes its place; no pointer into e is held */
        *e = m->e[--m->n];
    }
    pthread_cond_broadcast(&m->settled);
    pthread_mutex_unlock(&m->lock);
}

void rb_design_memo_put(rb_design_memo *m, const rb_model *model, const rb_motion *motion,
                        const rb_solve_opts *opts, rb_status status, const rb_result *r)
{
    if (!m)
        return;
    if (r->history) {
        /* not kept, but a claim on it is settled */
        rb_design_memo_release(m, model, motion, opts);
        return;
    }
    pthread_mutex_lock(&m->lock);
    memo_entry *e = find(m, model, motion, opts);
    /* two threads may have solved the same run at once: keep one */
    if (!e)
        e = add(m, model, motion, opts);
    /* a memo that cannot grow only forgets: the run stands */
    if (e && !e->ready) {
        e->status = status;
        e->r = *r;
        e->ready = 1;
        m->n_ready++;
    }
    pthread_cond_broadcast(&m->settled);
    pthread_mutex_unlock(&m->lock);
}

void rb_design_memo_keep(rb_design_memo *m, const rb_model *model, const rb_motion *motion,
                         const rb_solve_opts *opts, rb_status status, const rb_result *r)
{
    rb_solve_opts o = *opts;
    rb_result summary = *r;
    /* the searches solve without a history: the same steps, read less */
    o.history_dt_s = 0;
    summary.history = NULL;
    rb_design_memo_put(m, model, motion, &o, status, &summary);
}
