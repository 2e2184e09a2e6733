/* rb_batch_run: the work list through the thread pool, a chunk at a time.
 *
 * Each chunk of cases is loaded in parallel, then all its case x motion
 * runs go to the pool, so a case with many motions spreads over the
 * threads as well as many cases do. The last run of a case concludes it
 * and frees it, so memory is bounded by the chunk, not the list. Every
 * result goes to its own slot, so the summary does not depend on which
 * thread ran what. */
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "batch_engine.h"
#include "util/pool.h"

#define RB_BATCH_CHUNK 256

typedef struct {
    size_t slot, motion;
} run_ref;

typedef struct {
    const rb_batch_list *l;
    const rb_batch_opts *o;
    rb_batch_summary *out;
    rb_batch_case *cases;    /* the chunk's cases */
    rb_batch_slot *slots;    /* RB_BATCH_CHUNK */
    run_ref *runs;
    rb_record_cache *cache;  /* owned: records shared by the cases */
    int frag_threads;        /* of each fragility of the chunk */
    pthread_mutex_t lock;
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
static void progress(run_ctx *cx, const rb_batch_case *done_case, int run_done)
{
    pthread_mutex_lock(&cx->lock);
    cx->prog.runs_done += (size_t)run_done;
    if (done_case) {
        cx->prog.cases_done++;
        cx->prog.failed += done_case->verdict == RB_BATCH_FAIL;
        cx->prog.unreadable += done_case->verdict == RB_BATCH_UNREADABLE
                               || done_case->verdict == RB_BATCH_ERROR;
    }
    if (cx->o->progress)
        cx->o->progress(cx->o->progress_ctx, &cx->prog);
    pthread_mutex_unlock(&cx->lock);
}

static rb_status load_job(void *arg, size_t i)
{
    run_ctx *cx = arg;
    rb_batch_case *bc = &cx->cases[i];
    rb_batch_slot *s = &cx->slots[i];
    s->cache = cx->cache;
    rb_batch_case_load(s, &cx->l->items[bc->index], bc);
    if (!s->loaded || s->remaining == 0) {
        rb_batch_case_finish(s, bc, cx->o, cx->out->total);
        progress(cx, bc, 0);
    }
    return RB_OK;
}

/* The job that computes a case's fragility: its motion is this. */
#define FRAGILITY_JOB ((size_t)-1)

static rb_status run_job(void *arg, size_t k)
{
    run_ctx *cx = arg;
    const run_ref *r = &cx->runs[k];
    rb_batch_case *bc = &cx->cases[r->slot];
    rb_batch_slot *s = &cx->slots[r->slot];
    if (r->motion == FRAGILITY_JOB)
        rb_batch_case_fragility(s, bc, cx->frag_threads, cx->o);
    else
        rb_batch_case_solve(s, bc, r->motion, cx->o->design);
    pthread_mutex_lock(&cx->lock);
    int last = --s->remaining == 0;
    pthread_mutex_unlock(&cx->lock);
    if (last)
        rb_batch_case_finish(s, bc, cx->o, cx->out->total);
    progress(cx, last ? bc : NULL, r->motion != FRAGILITY_JOB);
    return RB_OK;
}

/* Threads for each fragility of a chunk: its searches share a pool of
 * their own, so a chunk of fewer cases than threads still uses them all
 * (the results do not depend on it). */
static int fragility_threads(const rb_batch_opts *o, size_t n_cases)
{
    int nt = o->n_threads > 0 ? o->n_threads : rb_pool_threads_default();
    size_t each = n_cases ? (size_t)nt / n_cases : 1;
    return each > 1 ? (int)each : 1;
}

static rb_status run_chunk(run_ctx *cx, size_t n)
{
    size_t n_runs = 0, n_frag = 0;
    rb_status st = rb_pool_map(n, cx->o->n_threads, load_job, cx, NULL);
    if (st != RB_OK)
        return st;
    for (size_t i = 0; i < n; i++)
        if (cx->slots[i].loaded) {
            n_runs += cx->slots[i].remaining;
            n_frag += cx->o->fragility != 0;
        }
    run_ref *runs = malloc((n_runs + n_frag ? n_runs + n_frag : 1) * sizeof *runs);
    if (!runs)
        return RB_ERR_NOMEM;
    /* the fragilities first: each is hundreds of solver runs, so that the
     * short motion runs fill the threads at the end */
    size_t k = 0;
    for (size_t i = 0; i < n && n_frag; i++)
        if (cx->slots[i].loaded) {
            runs[k].slot = i, runs[k++].motion = FRAGILITY_JOB;
        }
    for (size_t i = 0; i < n; i++)
        for (size_t m = 0; cx->slots[i].loaded && m < cx->slots[i].remaining; m++)
            runs[k].slot = i, runs[k++].motion = m;
    for (size_t i = 0; i < n && n_frag; i++)
        cx->slots[i].remaining += cx->slots[i].loaded;
    cx->runs = runs;
    cx->frag_threads = fragility_threads(cx->o, n_frag);
    st = rb_pool_map(k, cx->o->n_threads, run_job, cx, NULL);
    free(runs);
    cx->runs = NULL;
    return st;
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
        snprintf(diag->msg, sizeof diag->msg, "%s", bad);
    return RB_ERR_INVALID;
}

/* The summary's cases (this shard's items) from first on, n of them, with
 * what the list knows; *next is where the search for the next one starts. */
static rb_status select_cases(const rb_batch_list *l, const rb_batch_opts *o,
                              size_t *next, rb_batch_case *cases, size_t n)
{
    for (size_t k = 0; k < n; k++) {
        size_t i = *next;
        while (!rb_batch_in_shard(i, o->shard, o->n_shards))
            i++;
        *next = i + 1;
        rb_batch_case *bc = &cases[k];
        bc->index = i;
        bc->line = l->items[i].line;
        bc->source = rb_batch_strdup(l->items[i].source);
        bc->tag = rb_batch_default_tag(&l->items[i]);
        if (!bc->source || !bc->tag)
            return RB_ERR_NOMEM;
    }
    return RB_OK;
}

/* Hand a finished chunk to the sink and keep only its counts. */
static rb_status stream_chunk(const rb_batch_opts *o, rb_batch_summary *out,
                              size_t first, size_t n)
{
    rb_status st = o->sink(o->sink_ctx, out, out->cases, first, n);
    for (size_t i = 0; i < n; i++) {
        rb_batch_count_case(&out->counts, &out->cases[i]);
        rb_batch_case_free(&out->cases[i]);
    }
    return st;
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
    size_t n_cases = 0, next = 0;
    for (size_t i = 0; i < l->n; i++)
        n_cases += (size_t)rb_batch_in_shard(i, o->shard, o->n_shards);
    /* streamed: one chunk's cases at a time; else the whole summary */
    size_t held = out->streamed ? RB_BATCH_CHUNK : n_cases;
    out->cases = calloc(held ? held : 1, sizeof *out->cases);
    memset(&cx, 0, sizeof cx);
    cx.l = l;
    cx.o = o;
    cx.out = out;
    cx.prog.cases_total = n_cases;
    cx.slots = calloc(RB_BATCH_CHUNK, sizeof *cx.slots);
    /* an equipment list reads the same few records for every row */
    cx.cache = rb_record_cache_new(0);
    if (!out->cases || !cx.slots || !cx.cache || pthread_mutex_init(&cx.lock, NULL) != 0) {
        free(cx.slots);
        rb_record_cache_free(cx.cache);
        return RB_ERR_NOMEM;
    }
    for (size_t first = 0; first < n_cases && st == RB_OK; first += RB_BATCH_CHUNK) {
        size_t n = n_cases - first;
        if (n > RB_BATCH_CHUNK)
            n = RB_BATCH_CHUNK;
        cx.cases = out->streamed ? out->cases : out->cases + first;
        /* a case counts in the summary (and is freed with it) once selected */
        out->n_cases = out->streamed ? n : first + n;
        st = select_cases(l, o, &next, cx.cases, n);
        if (st == RB_OK)
            st = run_chunk(&cx, n);
        for (size_t i = 0; i < n; i++)
            rb_batch_slot_free(&cx.slots[i]);
        if (st == RB_OK && out->streamed)
            st = stream_chunk(o, out, first, n);
    }
    if (out->streamed) {
        for (size_t i = 0; i < out->n_cases; i++)
            rb_batch_case_free(&out->cases[i]);
        free(out->cases);
        out->cases = NULL;
        out->n_cases = out->counts.cases;
    }
    pthread_mutex_destroy(&cx.lock);
    free(cx.slots);
    rb_record_cache_free(cx.cache);
    return st;
}
