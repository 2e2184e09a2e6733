/* Solver runs kept for the searches of one design (design.h). The two
 * design factors and an amplitude sweep of the same motion ask for many of
 * the same levels; a run is the same bits whoever asks, so it is solved
 * once. An entry is found by the exact bytes of the model, the scaled
 * motion and the solver options: bytes that differ (padding included) only
 * cost a second solve, never a wrong hit. The one exception is asked for:
 * a run to stop at a limit state's crossing (rb_solve_opts.stop_at) is
 * served by the same run made to the end, which decides that state
 * alike. */
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
} memo_entry;

struct rb_design_memo {
    pthread_mutex_t lock;
    memo_entry *e;
    size_t n, cap;
};

rb_design_memo *rb_design_memo_new(void)
{
    rb_design_memo *m = calloc(1, sizeof *m);
    if (m && pthread_mutex_init(&m->lock, NULL) != 0) {
        free(m);
        return NULL;
    }
    return m;
}

void rb_design_memo_free(rb_design_memo *m)
{
    if (!m)
        return;
    pthread_mutex_destroy(&m->lock);
    free(m->e);
    free(m);
}

size_t rb_design_memo_runs(rb_design_memo *m)
{
    size_t n = 0;
    if (m) {
        pthread_mutex_lock(&m->lock);
        n = m->n;
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

static const memo_entry *find(const rb_design_memo *m, const rb_model *model,
                              const rb_motion *motion_in, const rb_solve_opts *opts)
{
    rb_motion flat, vertical;
    const rb_motion *motion = &flat;
    key_of(motion_in, &flat, &vertical);
    for (size_t i = 0; i < m->n; i++) {
        const memo_entry *e = &m->e[i];
        if (!memcmp(&e->motion, motion, sizeof *motion)
            && !memcmp(&e->vertical, &vertical, sizeof vertical)
            && !memcmp(&e->model, model, sizeof *model)
            && !memcmp(&e->opts, opts, sizeof *opts))
            return e;
    }
    return NULL;
}

int rb_design_memo_get(rb_design_memo *m, const rb_model *model, const rb_motion *motion,
                       const rb_solve_opts *opts, rb_status *status, rb_result *r)
{
    int hit = 0;
    if (!m)
        return 0;
    pthread_mutex_lock(&m->lock);
    const memo_entry *e = find(m, model, motion, opts);
    if (!e && opts->stop_at) {
        /* a run that goes to the end decides whatever a run stopped at a
         * crossing decides: the scan levels every limit state shares */
        rb_solve_opts full = *opts;
        full.stop_at = 0;
        e = find(m, model, motion, &full);
    }
    if (e) {
        *status = e->status;
        *r = e->r;
        hit = 1;
    }
    pthread_mutex_unlock(&m->lock);
    return hit;
}

void rb_design_memo_put(rb_design_memo *m, const rb_model *model, const rb_motion *motion,
                        const rb_solve_opts *opts, rb_status status, const rb_result *r)
{
    if (!m || r->history)
        return;
    pthread_mutex_lock(&m->lock);
    /* two threads may have solved the same run at once: keep one */
    if (!find(m, model, motion, opts)) {
        if (m->n == m->cap) {
            memo_entry *e = rb_grow(m->e, &m->cap, sizeof *e, 64);
            if (!e) {
                /* a memo that cannot grow only forgets: the run stands */
                pthread_mutex_unlock(&m->lock);
                return;
            }
            m->e = e;
        }
        memo_entry *e = &m->e[m->n++];
        e->model = *model;
        key_of(motion, &e->motion, &e->vertical);
        e->opts = *opts;
        e->status = status;
        e->r = *r;
    }
    pthread_mutex_unlock(&m->lock);
}
