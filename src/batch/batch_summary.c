/* The batch summary: freeing, the governing motion, counts, and the
 * mean and maximum over a case's motions that every renderer shows. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "batch_summary.h"
#include "rockbolt/criteria.h"

const rb_diag *rb_batch_case_error(const rb_batch_case *c)
{
    static const rb_diag none;
    return c && c->error ? c->error : &none;
}

int rb_batch_case_set_error(rb_batch_case *c, const rb_diag *d)
{
    if (!c->error && !(c->error = malloc(sizeof *c->error)))
        return 0;
    *c->error = *d;
    return 1;
}

void rb_batch_case_free(rb_batch_case *c)
{
    free(c->source);
    free(c->tag);
    free(c->reason);
    free(c->error);
    for (size_t m = 0; c->runs && m < c->n_runs; m++) {
        free(c->runs[m].motion);
        free(c->runs[m].reason);
    }
    free(c->runs);
    if (c->fragility)
        free(c->fragility->error);
    free(c->fragility);
    memset(c, 0, sizeof *c);
}

void rb_batch_summary_free(rb_batch_summary *s)
{
    if (!s)
        return;
    for (size_t i = 0; s->cases && i < s->n_cases; i++)
        rb_batch_case_free(&s->cases[i]);
    free(s->cases);
    memset(s, 0, sizeof *s);
}

/* 1 if run a governs over an earlier run b: the judge's one rule,
 * rb_margin_governs on the margins the runs were judged with. */
static int governs(const rb_batch_result *a, const rb_batch_result *b)
{
    return rb_margin_governs(a->margin, b->margin);
}

size_t rb_batch_governing(const rb_batch_case *c)
{
    size_t g = 0;
    for (size_t m = 1; m < c->n_runs; m++)
        if (governs(&c->runs[m], &c->runs[g]))
            g = m;
    return g;
}

/* Runs count only for cases that were solved and judged. */
static int has_results(const rb_batch_case *c)
{
    return (c->verdict == RB_BATCH_PASS || c->verdict == RB_BATCH_FAIL) && c->n_runs > 0;
}

void rb_batch_count_case(rb_batch_counts *n, const rb_batch_case *c)
{
    n->cases++;
    n->passed += c->verdict == RB_BATCH_PASS;
    n->failed += c->verdict == RB_BATCH_FAIL;
    n->unreadable += c->verdict == RB_BATCH_UNREADABLE;
    n->errors += c->verdict == RB_BATCH_ERROR;
    if (has_results(c))
        n->runs += c->n_runs;
}

void rb_batch_count(const rb_batch_summary *s, rb_batch_counts *out)
{
    if (s->streamed) {
        *out = s->counts;
        return;
    }
    memset(out, 0, sizeof *out);
    for (size_t i = 0; i < s->n_cases; i++)
        rb_batch_count_case(out, &s->cases[i]);
}

const char *rb_batch_verdict_str(rb_batch_verdict v)
{
    switch (v) {
    case RB_BATCH_PASS: return "pass";
    case RB_BATCH_FAIL: return "fail";
    case RB_BATCH_UNREADABLE: return "unreadable";
    case RB_BATCH_ERROR: return "error";
    }
    return "error";
}

int rb_batch_verdict_parse(const char *s, rb_batch_verdict *v)
{
    static const rb_batch_verdict all[] = {RB_BATCH_PASS, RB_BATCH_FAIL,
                                           RB_BATCH_UNREADABLE, RB_BATCH_ERROR};
    for (size_t k = 0; k < 4; k++) {
        if (strcmp(s, rb_batch_verdict_str(all[k])) == 0) {
            *v = all[k];
            return 1;
        }
    }
    return 0;
}

/* A column's mean and its governing value over the runs; a run without
 * one (NaN) leaves the case without one: the design values are there only
 * when every run has one. */
void rb_batch_stats(const rb_batch_case *c, rb_batch_stat *mean, rb_batch_stat *max)
{
    memset(mean, 0, sizeof *mean);
    memset(max, 0, sizeof *max);
    if (!has_results(c))
        return;
    for (size_t k = 0; k < rb_batch_n_columns; k++) {
        int least = rb_batch_columns[k].agg == RB_BATCH_AGG_MIN;
        double sum = 0, top = c->runs[0].value[k];
        for (size_t m = 0; m < c->n_runs; m++) {
            double v = c->runs[m].value[k];
            sum += v;
            if (isnan(v) || isnan(top))
                top = (double)NAN;
            else if (m > 0)
                top = least ? fmin(top, v) : fmax(top, v);
        }
        mean->value[k] = sum / (double)c->n_runs;
        max->value[k] = top;
    }
}
