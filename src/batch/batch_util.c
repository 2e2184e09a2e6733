/* Small helpers of the batch code: strings, a growing buffer, and the
 * thread pool (the same shape as the design searches': a shared counter
 * hands out jobs, each job writes only its own slot). */
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "batch_internal.h"

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
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n >= 1 ? (n > 1024 ? 1024 : (int)n) : 1;
}

typedef struct {
    pthread_mutex_t lock;
    size_t next, n;
    rb_batch_job job;
    void *ctx;
} rb_bpool;

static void *bpool_worker(void *arg)
{
    rb_bpool *p = arg;
    for (;;) {
        pthread_mutex_lock(&p->lock);
        size_t i = p->next < p->n ? p->next++ : p->n;
        pthread_mutex_unlock(&p->lock);
        if (i >= p->n)
            return NULL;
        p->job(p->ctx, i);
    }
}

rb_status rb_batch_parallel(size_t n, int n_threads, rb_batch_job job, void *ctx)
{
    rb_bpool p = {.next = 0, .n = n, .job = job, .ctx = ctx};
    size_t nt = (size_t)(n_threads > 0 ? n_threads : rb_batch_threads_default());
    if (nt > n)
        nt = n;
    if (nt <= 1) {
        for (size_t i = 0; i < n; i++)
            job(ctx, i);
        return RB_OK;
    }
    pthread_t *tid = malloc(nt * sizeof *tid);
    if (!tid || pthread_mutex_init(&p.lock, NULL) != 0) {
        free(tid);
        return RB_ERR_NOMEM;
    }
    size_t started = 0;
    while (started < nt - 1 && pthread_create(&tid[started], NULL, bpool_worker, &p) == 0)
        started++;
    bpool_worker(&p);
    for (size_t k = 0; k < started; k++)
        pthread_join(tid[k], NULL);
    pthread_mutex_destroy(&p.lock);
    free(tid);
    return RB_OK;
}
