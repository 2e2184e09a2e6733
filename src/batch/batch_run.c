/* rb_batch_run: the work list as one pool of row jobs.
 *
 * Each job loads its own row, solves its motions, computes its fragility
 * and concludes it, then frees the loaded case, so at most one loaded case
 * per thread is alive and no barrier waits for the slowest row of a group.
 * Rows are handed out in list order: no cost estimate exists before a row
 * is loaded (its motions, their lengths and its fragility are the row's
 * case, read inside the job), and list order is what a streamed summary
 * needs. When streamed, a row is handed out only while it lies within
 * RB_BATCH_WINDOW rows of the first case not yet given to the sink, so
 * memory is bounded by the window, not the list; the thread that finishes
 * the first outstanding row hands the finished prefix to the sink. A list
 * with fewer rows than threads spreads each row's motions (and its
 * fragility's searches) over the threads left over. Every result goes to
 * its own slot, so the summary does not depend on which thread ran what. */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "batch_engine.h"
#include "util/pool.h"

#define RB_BATCH_WINDOW 256

typedef struct {
    const rb_batch_list *l;
    const rb_batch_opts *o;
    rb_batch_summary *out;
    unsigned char *done;     /* per held case: concluded, not yet streamed */
    size_t held;             /* cases out->cases holds */
    size_t emitted;          /* streamed: cases given to the sink */
    size_t n_cases;
    rb_record_cache *cache;  /* owned: records shared by the cases */
    int row_threads;         /* of each row's motions and fragility */
    rb_status stop;          /* the first failure; no new row starts */
    pthread_mutex_t lock;
    pthread_cond_t moved;    /* the streamed window moved, or stop */
    rb_batch_progress prog;
} run_ctx;

void rb_batch_opts_init(rb_batch_opts *o)
{
    memset(o, 0, sizeof *o);
}

int rb_batch_in_shard(size_t index, size_t shard, size_t n_shards)
{
    return n_shards == 0 || index % n_shards == shard - 1;
}

/* Count a finished run or case and tell the caller. */
static void progress_locked(run_ctx *cx, const rb_batch_case *done_case, int run_done)
{
    cx->prog.runs_done += (size_t)run_done;
    if (done_case) {
        cx->prog.cases_done++;
        cx->prog.failed += done_case->verdict == RB_BATCH_FAIL;
        cx->prog.unreadable += done_case->verdict == RB_BATCH_UNREADABLE
                               || done_case->verdict == RB_BATCH_ERROR;
    }
    if (cx->o->progress)
        cx->o->progress(cx->o->progress_ctx, &cx->prog);
}

static void progress(run_ctx *cx, const rb_batch_case *done_case, int run_done)
{
    pthread_mutex_lock(&cx->lock);
    progress_locked(cx, done_case, run_done);
    pthread_mutex_unlock(&cx->lock);
}

/* A row's motion runs, on the threads its row may use. */
typedef struct {
    run_ctx *cx;
    rb_batch_slot *s;
    rb_batch_case *bc;
} row_ctx;

static rb_status motion_job(void *arg, size_t m)
{
    row_ctx *r = arg;
    rb_batch_case_solve(r->s, r->bc, m, r->cx->o->design);
    progress(r->cx, NULL, 1);
    return RB_OK;
}

/* Threads for each row's motions and fragility: a list of fewer rows
 * than threads still uses them all (the results do not depend on it). */
static int row_threads(const rb_batch_opts *o, size_t n_cases)
{
    int nt = o->n_threads > 0 ? o->n_threads : rb_pool_threads_default();
    size_t each = n_cases ? (size_t)nt / n_cases : 1;
    return each > 1 ? (int)each : 1;
}

/* The list's index of the summary's case k (the k-th item of the shard). */
static size_t item_of(const rb_batch_opts *o, size_t k)
{
    return o->n_shards ? k * o->n_shards + (o->shard - 1) : k;
}

static rb_status select_case(const rb_batch_list *l, size_t i, rb_batch_case *bc)
{
    bc->index = i;
    bc->line = l->items[i].line;
    bc->source = rb_batch_strdup(l->items[i].source);
    bc->tag = rb_batch_default_tag(&l->items[i]);
    return bc->source && bc->tag ? RB_OK : RB_ERR_NOMEM;
}

/* Load, solve and conclude one row into bc. */
static rb_status run_row(run_ctx *cx, size_t i, rb_batch_case *bc)
{
    rb_status st = select_case(cx->l, i, bc);
    rb_batch_slot *s = calloc(1, sizeof *s);
    if (st != RB_OK || !s) {
        free(s);
        return RB_ERR_NOMEM;
    }
    s->cache = cx->cache;
    s->sandbox = cx->l->sandbox;
    rb_batch_case_load(s, &cx->l->items[i], bc);
    if (s->loaded && s->remaining > 0) {
        row_ctx r = {cx, s, bc};
        size_t n_motions = s->remaining;
        st = rb_pool_map(n_motions, cx->row_threads, motion_job, &r, NULL);
        if (st == RB_OK && cx->o->fragility)
            rb_batch_case_fragility(s, bc, cx->row_threads, cx->o);
        s->remaining = 0;
    }
    if (st == RB_OK)
        rb_batch_case_finish(s, bc, cx->o, cx->out->total);
    rb_batch_slot_free(s);
    free(s);
    return st;
}

/* Give the sink the finished cases from the first outstanding one on, in
 * list order, and keep only their counts. Under cx->lock. */
static void stream_ready(run_ctx *cx)
{
    rb_batch_summary *out = cx->out;
    while (cx->stop == RB_OK && cx->emitted < cx->n_cases && cx->done[cx->emitted % cx->held]) {
        size_t at = cx->emitted % cx->held, n = 0;
        while (at + n < cx->held && cx->emitted + n < cx->n_cases && cx->done[at + n])
            n++;
        rb_status st = cx->o->sink(cx->o->sink_ctx, out, out->cases + at, cx->emitted, n);
        for (size_t k = at; k < at + n; k++) {
            rb_batch_count_case(&out->counts, &out->cases[k]);
            rb_batch_case_free(&out->cases[k]);
            cx->done[k] = 0;
        }
        cx->emitted += n;
        if (st != RB_OK)
            cx->stop = st;
    }
    pthread_cond_broadcast(&cx->moved);
}

static rb_status row_job(void *arg, size_t k)
{
    run_ctx *cx = arg;
    int streamed = cx->out->streamed;
    pthread_mutex_lock(&cx->lock);
    /* rows are handed out in order, so the first outstanding row is
     * always running on another thread: this wait ends */
    while (streamed && cx->stop == RB_OK && k >= cx->emitted + cx->held)
        pthread_cond_wait(&cx->moved, &cx->lock);
    int stopped = cx->stop != RB_OK;
    pthread_mutex_unlock(&cx->lock);
    if (stopped)
        return RB_OK;
    rb_batch_case *bc = &cx->out->cases[k % cx->held];
    rb_status st = run_row(cx, item_of(cx->o, k), bc);
    pthread_mutex_lock(&cx->lock);
    if (st != RB_OK && cx->stop == RB_OK)
        cx->stop = st;
    cx->done[k % cx->held] = 1;
    if (st == RB_OK)
        progress_locked(cx, bc, 0);
    if (streamed)
        stream_ready(cx);
    pthread_mutex_unlock(&cx->lock);
    return RB_OK;
}

static rb_status check_opts(const rb_batch_opts *o, rb_diag *diag)
{
    const char *bad = NULL;
    if ((o->n_shards == 0) != (o->shard == 0) || o->shard > o->n_shards)
        bad = "the shard must be i/n with 1 <= i <= n";
    else if (o->reports_dir && !o->report_template)
        bad = "reports need the report template";
    if (!bad)
        return RB_OK;
    if (diag)
        rb_diag_set_msg(diag, "%s", bad);
    return RB_ERR_INVALID;
}

rb_status rb_batch_run(const rb_batch_list *l, const rb_batch_opts *o,
                       rb_batch_summary *out, rb_diag *diag)
{
    run_ctx cx;
    memset(out, 0, sizeof *out);
    rb_status st = check_opts(o, diag);
    if (st != RB_OK)
        return st;
    out->design = o->design;
    out->fragility = o->fragility;
    out->seed = o->seed;
    out->intensity = o->intensity;
    out->total = l->n;
    out->shard = o->shard;
    out->n_shards = o->n_shards;
    out->streamed = o->sink != NULL;
    if ((st = rb_batch_list_digest(l, out->inputs_digest)) != RB_OK)
        return st;
    size_t n_cases = 0;
    for (size_t i = 0; i < l->n; i++)
        n_cases += (size_t)rb_batch_in_shard(i, o->shard, o->n_shards);
    memset(&cx, 0, sizeof cx);
    /* streamed: a window of cases at a time; else the whole summary */
    cx.held = out->streamed && n_cases > RB_BATCH_WINDOW ? RB_BATCH_WINDOW : n_cases;
    if (cx.held == 0)
        cx.held = 1;
    out->cases = calloc(cx.held, sizeof *out->cases);
    cx.done = calloc(cx.held, 1);
    cx.l = l;
    cx.o = o;
    cx.out = out;
    cx.n_cases = n_cases;
    cx.prog.cases_total = n_cases;
    cx.row_threads = row_threads(o, n_cases);
    /* an equipment list reads the same few records for every row */
    cx.cache = rb_record_cache_new(0);
    int locks = 0;
    if (out->cases && cx.done && cx.cache && pthread_mutex_init(&cx.lock, NULL) == 0) {
        locks = 1;
        if (pthread_cond_init(&cx.moved, NULL) == 0)
            locks = 2;
    }
    if (locks < 2) {
        if (locks)
            pthread_mutex_destroy(&cx.lock);
        free(cx.done);
        free(out->cases);
        out->cases = NULL;
        rb_record_cache_free(cx.cache);
        return RB_ERR_NOMEM;
    }
    /* a case counts in the summary (and is freed with it) once held */
    out->n_cases = cx.held;
    st = rb_pool_map(n_cases, o->n_threads, row_job, &cx, NULL);
    if (st == RB_OK)
        st = cx.stop;
    if (out->streamed) {
        for (size_t i = 0; i < cx.held; i++)
            rb_batch_case_free(&out->cases[i]);
        free(out->cases);
        out->cases = NULL;
        out->n_cases = out->counts.cases;
    } else {
        out->n_cases = n_cases;
    }
    pthread_cond_destroy(&cx.moved);
    pthread_mutex_destroy(&cx.lock);
    free(cx.done);
    rb_record_cache_free(cx.cache);
    return st;
}
