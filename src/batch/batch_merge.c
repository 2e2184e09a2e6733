/* Merging the summaries of the shards of one work list. Cases move out of
 * the shard summaries' order into the list's order (by index); nothing is
 * recomputed from them except what every renderer derives anyway, so the
 * result renders exactly as one run over the whole list would. */
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
        snprintf(d->key, sizeof d->key, "merge");
        vsnprintf(d->msg, sizeof d->msg, fmt, ap);
        va_end(ap);
    }
    return RB_ERR_INVALID;
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

rb_status rb_batch_merge(const rb_batch_summary *shards, size_t n,
                         rb_batch_summary *out, rb_diag *diag)
{
    memset(out, 0, sizeof *out);
    if (n == 0)
        return fail(diag, "no summaries to merge");
    size_t total = shards[0].total;
    for (size_t k = 1; k < n; k++) {
        if (shards[k].total != total)
            return fail(diag, "the summaries come from different work lists "
                        "(%zu and %zu items)", total, shards[k].total);
        if (shards[k].design != shards[0].design)
            return fail(diag, "summary %zu and the first differ in --design", k + 1);
        if (shards[k].fragility != shards[0].fragility)
            return fail(diag, "summary %zu and the first differ in --fragility", k + 1);
        if (shards[k].intensity != shards[0].intensity)
            return fail(diag, "summary %zu and the first differ in --intensity", k + 1);
        if (shards[k].seed != shards[0].seed)
            return fail(diag, "summary %zu and the first differ in --seed (%llu and "
                        "%llu)", k + 1, (unsigned long long)shards[k].seed,
                        (unsigned long long)shards[0].seed);
    }
    for (size_t k = 1; k < n; k++)
        if (strcmp(shards[k].inputs_digest, shards[0].inputs_digest) != 0)
            return fail(diag, "summary %zu was run on other inputs than the first "
                        "(a different list, case or base: their inputs digests "
                        "differ)", k + 1);
    rb_batch_case **at = calloc(total ? total : 1, sizeof *at);
    if (!at)
        return RB_ERR_NOMEM;
    rb_status st = RB_OK;
    /* messages count cases from 1, as summaries and shards are counted and
     * as a reader counts a list's items (the JSON's index is from 0) */
    for (size_t k = 0; k < n && st == RB_OK; k++) {
        for (size_t i = 0; i < shards[k].n_cases && st == RB_OK; i++) {
            rb_batch_case *c = &shards[k].cases[i];
            if (c->index >= total)
                st = fail(diag, "case %zu is outside the work list of %zu",
                          c->index + 1, total);
            else if (at[c->index])
                st = fail(diag, "case %zu is in more than one summary (summary %zu)",
                          c->index + 1, k + 1);
            else
                at[c->index] = c;
        }
    }
    for (size_t i = 0; i < total && st == RB_OK; i++)
        if (!at[i])
            st = fail(diag, "case %zu of %zu is in no summary: a shard is missing",
                      i + 1, total);
    if (st == RB_OK && !(out->cases = calloc(total ? total : 1, sizeof *out->cases)))
        st = RB_ERR_NOMEM;
    out->design = shards[0].design;
    out->fragility = shards[0].fragility;
    out->seed = shards[0].seed;
    out->intensity = shards[0].intensity;
    memcpy(out->inputs_digest, shards[0].inputs_digest, sizeof out->inputs_digest);
    out->total = total;
    for (size_t i = 0; i < total && st == RB_OK; i++) {
        out->n_cases++;
        if (!copy_case(&out->cases[i], at[i]))
            st = RB_ERR_NOMEM;
    }
    free(at);
    if (st != RB_OK)
        rb_batch_summary_free(out);
    return st;
}
