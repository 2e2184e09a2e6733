/* Merging the summaries of the shards of one work list. Cases move out of
 * the shard summaries' order into the list's order (by index); nothing is
 * recomputed from them except what every renderer derives anyway, so the
 * result renders exactly as one run over the whole list would. Each shard
 * holds its cases in the list's order (batch writes them so), so the merge
 * is a merge of sorted runs: one case per shard is held at a time, and the
 * memory does not grow with the list. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "batch_summary.h"

#if defined(__GNUC__)
__attribute__((format(printf, 2, 3)))
#endif
static rb_status fail(rb_diag *d, const char *fmt, ...)
{
    if (d) {
        va_list ap;
        va_start(ap, fmt);
        rb_diag_set_key(d, "merge");
        rb_diag_vset_msg(d, fmt, ap);
        va_end(ap);
    }
    return RB_ERR_INVALID;
}

/* How a message names summary k: its file where it was read from one,
 * else its place among the summaries given (counted from 1). */
typedef struct {
    char s[300];
} shard_label;

static shard_label label(const rb_batch_summary *heads, size_t k)
{
    shard_label l;
    if (heads[k].name && heads[k].name[0])
        snprintf(l.s, sizeof l.s, "'%s'", heads[k].name);
    else
        snprintf(l.s, sizeof l.s, "summary %zu", k + 1);
    return l;
}

static int copy_case(rb_batch_case *dst, const rb_batch_case *src)
{
    *dst = *src;
    dst->source = rb_batch_strdup(src->source);
    dst->tag = rb_batch_strdup(src->tag);
    dst->reason = rb_batch_strdup(src->reason ? src->reason : "");
    dst->error = NULL;
    int error_ok = !src->error || rb_batch_case_set_error(dst, src->error);
    dst->runs = src->n_runs ? calloc(src->n_runs, sizeof *dst->runs) : NULL;
    dst->fragility = NULL;
    int frag_ok = 1;
    if (src->fragility && (dst->fragility = malloc(sizeof *dst->fragility))) {
        *dst->fragility = *src->fragility;
        if (src->fragility->error)
            frag_ok = (dst->fragility->error = rb_batch_strdup(src->fragility->error)) != NULL;
    } else if (src->fragility) {
        frag_ok = 0;
    }
    if (!dst->source || !dst->tag || !dst->reason || !error_ok || !frag_ok
        || (src->n_runs && !dst->runs)) {
        dst->n_runs = 0;
        return 0;
    }
    for (size_t m = 0; m < src->n_runs; m++) {
        dst->runs[m] = src->runs[m];
        dst->runs[m].motion = rb_batch_strdup(src->runs[m].motion);
        dst->runs[m].reason = src->runs[m].reason ? rb_batch_strdup(src->runs[m].reason)
                                                  : NULL;
        if (!dst->runs[m].motion || (src->runs[m].reason && !dst->runs[m].reason)) {
            free(dst->runs[m].motion);
            free(dst->runs[m].reason);
            dst->n_runs = m;
            return 0;
        }
    }
    return 1;
}

/* The shards must be of one list, run with the same options. */
static rb_status check_heads(const rb_batch_summary *shards, size_t n, rb_diag *diag)
{
    if (n == 0)
        return fail(diag, "no summaries to merge");
    size_t total = shards[0].total;
    for (size_t k = 1; k < n; k++) {
        if (shards[k].total != total)
            return fail(diag, "the summaries come from different work lists "
                        "(%zu and %zu items)", total, shards[k].total);
        if (shards[k].design != shards[0].design)
            return fail(diag, "%s and %s differ in --design", label(shards, k).s,
                        label(shards, 0).s);
        if (shards[k].fragility != shards[0].fragility)
            return fail(diag, "%s and %s differ in --fragility", label(shards, k).s,
                        label(shards, 0).s);
        if (shards[k].intensity != shards[0].intensity)
            return fail(diag, "%s and %s differ in --intensity", label(shards, k).s,
                        label(shards, 0).s);
        if (shards[k].seed != shards[0].seed)
            return fail(diag, "%s and %s differ in --seed (%llu and %llu)",
                        label(shards, k).s, label(shards, 0).s,
                        (unsigned long long)shards[k].seed,
                        (unsigned long long)shards[0].seed);
    }
    for (size_t k = 1; k < n; k++)
        if (strcmp(shards[k].inputs_digest, shards[0].inputs_digest) != 0)
            return fail(diag, "%s was run on other inputs than %s (a different list, "
                        "case or base: their inputs digests differ)", label(shards, k).s,
                        label(shards, 0).s);
    return RB_OK;
}

typedef struct {
    rb_batch_case c;          /* the shard's next case, when has */
    int has;
    size_t last;              /* index of the case before it, + 1 (0: none) */
} pending;

/* Shard k's next case into p; its index within the list and after the one
 * before it. messages count cases from 1, as summaries and shards are
 * counted and as a reader counts a list's items (the JSON's index is from
 * 0). */
static rb_status advance(pending *p, const rb_batch_summary *heads, size_t k, size_t total,
                         rb_batch_next_fn next, void *ctx, rb_diag *diag)
{
    if (p->has)
        p->last = p->c.index + 1;
    rb_batch_case_free(&p->c);
    p->has = 0;
    rb_status st = next(ctx, k, &p->c, &p->has, diag);
    if (st != RB_OK || !p->has)
        return st;
    size_t i = p->c.index;
    if (i >= total)
        return fail(diag, "case %zu is outside the work list of %zu", i + 1, total);
    if (p->last && i + 1 == p->last)
        return fail(diag, "case %zu is in more than one summary (twice in %s)",
                    i + 1, label(heads, k).s);
    if (p->last && i + 1 < p->last)
        return fail(diag, "case %zu comes after case %zu in %s: merge reads "
                    "each summary's cases in the list's order, as batch writes them",
                    i + 1, p->last, label(heads, k).s);
    return RB_OK;
}

rb_status rb_batch_merge_stream(const rb_batch_summary *heads, size_t n,
                                rb_batch_next_fn next, void *next_ctx,
                                rb_status (*sink)(void *ctx, const rb_batch_summary *s,
                                                  const rb_batch_case *cases,
                                                  size_t first, size_t n),
                                void *sink_ctx, rb_batch_summary *out, rb_diag *diag)
{
    memset(out, 0, sizeof *out);
    rb_status st = check_heads(heads, n, diag);
    if (st != RB_OK)
        return st;
    size_t total = heads[0].total;
    out->design = heads[0].design;
    out->fragility = heads[0].fragility;
    out->seed = heads[0].seed;
    out->intensity = heads[0].intensity;
    memcpy(out->inputs_digest, heads[0].inputs_digest, sizeof out->inputs_digest);
    out->total = total;
    out->streamed = 1;
    pending *p = calloc(n, sizeof *p);
    if (!p)
        return RB_ERR_NOMEM;
    for (size_t k = 0; k < n && st == RB_OK; k++)
        st = advance(&p[k], heads, k, total, next, next_ctx, diag);
    for (size_t i = 0; i < total && st == RB_OK; i++) {
        size_t g = n;           /* the shard whose next case comes first */
        for (size_t k = 0; k < n; k++)
            if (p[k].has && (g == n || p[k].c.index < p[g].c.index))
                g = k;
        if (g == n) {
            st = fail(diag, "case %zu of %zu is in no summary: a shard is missing",
                      i + 1, total);
        } else if (p[g].c.index > i) {
            /* a summary out of order looks the same from here */
            st = fail(diag, "case %zu of %zu is in no summary: a shard is missing, or a "
                      "summary's cases are not in the list's order (the next case of "
                      "%s is case %zu)", i + 1, total, label(heads, g).s, p[g].c.index + 1);
        } else if (p[g].c.index < i) {
            st = fail(diag, "case %zu is in more than one summary (%s)",
                      p[g].c.index + 1, label(heads, g).s);
        } else if ((st = sink(sink_ctx, out, &p[g].c, i, 1)) == RB_OK) {
            rb_batch_count_case(&out->counts, &p[g].c);
            out->n_cases++;
            st = advance(&p[g], heads, g, total, next, next_ctx, diag);
        }
    }
    /* a case left over was merged already from another summary */
    for (size_t k = 0; k < n && st == RB_OK; k++)
        if (p[k].has)
            st = fail(diag, "case %zu is in more than one summary (%s)",
                      p[k].c.index + 1, label(heads, k).s);
    for (size_t k = 0; k < n; k++)
        rb_batch_case_free(&p[k].c);
    free(p);
    return st;
}

/* The in-memory form on top of the stream: next walks the summaries'
 * arrays, the sink copies each case into out. */
typedef struct {
    const rb_batch_summary *shards;
    size_t *at;
    rb_batch_case *cases;     /* merged so far, grown as they come: a
                                 summary's total is not trusted for a size */
    size_t n, cap;
} mem_ctx;

static rb_status mem_next(void *ctx, size_t k, rb_batch_case *c, int *got, rb_diag *diag)
{
    mem_ctx *m = ctx;
    (void)diag;
    *got = 0;
    if (m->at[k] >= m->shards[k].n_cases)
        return RB_OK;
    if (!copy_case(c, &m->shards[k].cases[m->at[k]++])) {
        rb_batch_case_free(c);
        return RB_ERR_NOMEM;
    }
    *got = 1;
    return RB_OK;
}

static rb_status mem_sink(void *ctx, const rb_batch_summary *s, const rb_batch_case *cases,
                          size_t first, size_t n)
{
    mem_ctx *m = ctx;
    (void)s, (void)first;
    for (size_t i = 0; i < n; i++) {
        if (m->n == m->cap) {
            size_t cap = m->cap ? 2 * m->cap : 16;
            rb_batch_case *p = realloc(m->cases, cap * sizeof *p);
            if (!p)
                return RB_ERR_NOMEM;
            m->cases = p;
            m->cap = cap;
        }
        if (!copy_case(&m->cases[m->n], &cases[i])) {
            rb_batch_case_free(&m->cases[m->n]);
            return RB_ERR_NOMEM;
        }
        m->n++;
    }
    return RB_OK;
}

rb_status rb_batch_merge(const rb_batch_summary *shards, size_t n,
                         rb_batch_summary *out, rb_diag *diag)
{
    memset(out, 0, sizeof *out);
    mem_ctx m = {shards, calloc(n ? n : 1, sizeof *m.at), NULL, 0, 0};
    if (!m.at)
        return RB_ERR_NOMEM;
    rb_status st = rb_batch_merge_stream(shards, n, mem_next, &m, mem_sink, &m, out, diag);
    free(m.at);
    out->cases = m.cases;
    out->n_cases = m.n;
    out->streamed = 0;
    memset(&out->counts, 0, sizeof out->counts);
    if (st != RB_OK)
        rb_batch_summary_free(out);
    return st;
}
