/* The parallel map of src/util/pool.h. */
#include <pthread.h>
#include <stdlib.h>
#include <unistd.h>
#include "pool.h"

typedef struct {
    pthread_mutex_t lock;
    size_t next, n;
    rb_pool_job job;
    void *ctx;
    rb_status *status;
} rb_pool_state;

int rb_pool_threads_default(void)
{
    long n = sysconf(_SC_NPROCESSORS_ONLN);
    return n >= 1 ? (n > 1024 ? 1024 : (int)n) : 1;
}

static void *pool_worker(void *arg)
{
    rb_pool_state *p = arg;
    for (;;) {
        pthread_mutex_lock(&p->lock);
        size_t i = p->next < p->n ? p->next++ : p->n;
        pthread_mutex_unlock(&p->lock);
        if (i >= p->n)
            return NULL;
        rb_status st = p->job(p->ctx, i);
        if (p->status)
            p->status[i] = st;
    }
}

rb_status rb_pool_map(size_t n, int n_threads, rb_pool_job job, void *ctx,
                             rb_status *status)
{
    rb_pool_state p = {.next = 0, .n = n, .job = job, .ctx = ctx, .status = status};
    size_t nt = (size_t)(n_threads > 0 ? n_threads : rb_pool_threads_default());
    if (nt > n)
        nt = n;
    if (nt <= 1) {
        /* no thread for a single job: the caller's thread is enough */
        for (size_t i = 0; i < n; i++) {
            rb_status st = job(ctx, i);
            if (status)
                status[i] = st;
        }
        return RB_OK;
    }
    pthread_t *tid = malloc(nt * sizeof *tid);
    if (!tid || pthread_mutex_init(&p.lock, NULL) != 0) {
        free(tid);
        return RB_ERR_NOMEM;
    }
    /* the caller's thread works too, so nt - 1 helpers */
    size_t started = 0;
    while (started < nt - 1 && pthread_create(&tid[started], NULL, pool_worker, &p) == 0)
        started++;
    pool_worker(&p);
    for (size_t k = 0; k < started; k++)
        pthread_join(tid[k], NULL);
    pthread_mutex_destroy(&p.lock);
    free(tid);
    return RB_OK;
}
