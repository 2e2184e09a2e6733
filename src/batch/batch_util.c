/* Small helpers of the batch code: strings, a growing buffer, and the
 * thread pool (the design searches' pool, which hands out jobs by a
 * shared counter; each job writes only its own slot). */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "batch_internal.h"
#include "../design/design_internal.h"

char *rb_batch_strdup(const char *s)
{
    size_t n = strlen(s) + 1;
    char *p = malloc(n);
    if (p)
        memcpy(p, s, n);
    return p;
}

void rb_bbuf_put(rb_bbuf *b, const char *s, size_t n)
{
    if (b->nomem)
        return;
    if (b->len + n + 1 > b->cap) {
        size_t cap = b->cap ? b->cap : 1024;
        while (cap < b->len + n + 1)
            cap *= 2;
        char *p = realloc(b->buf, cap);
        if (!p) {
            b->nomem = 1;
            return;
        }
        b->buf = p;
        b->cap = cap;
    }
    memcpy(b->buf + b->len, s, n);
    b->len += n;
    b->buf[b->len] = '\0';
}

void rb_bbuf_str(rb_bbuf *b, const char *s)
{
    rb_bbuf_put(b, s, strlen(s));
}

void rb_bbuf_printf(rb_bbuf *b, const char *fmt, ...)
{
    char small[512];
    va_list ap;
    va_start(ap, fmt);
    int n = vsnprintf(small, sizeof small, fmt, ap);
    va_end(ap);
    if (n < 0) {
        b->nomem = 1;
        return;
    }
    if ((size_t)n < sizeof small) {
        rb_bbuf_put(b, small, (size_t)n);
        return;
    }
    char *big = malloc((size_t)n + 1);
    if (!big) {
        b->nomem = 1;
        return;
    }
    va_start(ap, fmt);
    vsnprintf(big, (size_t)n + 1, fmt, ap);
    va_end(ap);
    rb_bbuf_put(b, big, (size_t)n);
    free(big);
}

char *rb_bbuf_take(rb_bbuf *b)
{
    char *p;
    if (b->nomem) {
        free(b->buf);
        p = NULL;
    } else {
        p = b->buf ? b->buf : rb_batch_strdup("");
    }
    memset(b, 0, sizeof *b);
    return p;
}

int rb_batch_threads_default(void)
{
    return rb_design_threads_default();
}

/* The design searches' pool runs the batch too: one work queue, the
 * caller's thread working, the same fallback when threads cannot start. */
typedef struct {
    rb_batch_job job;
    void *ctx;
} batch_job_ref;

static rb_status run_batch_job(void *ctx, size_t i)
{
    const batch_job_ref *ref = ctx;
    ref->job(ref->ctx, i);
    return RB_OK;
}

rb_status rb_batch_parallel(size_t n, int n_threads, rb_batch_job job, void *ctx)
{
    batch_job_ref ref = { job, ctx };
    return rb_design_parallel(n, n_threads, run_batch_job, &ref, NULL);
}
