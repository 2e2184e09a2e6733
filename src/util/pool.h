/* A parallel map: n independent jobs on a few POSIX threads, the caller's
 * included. Jobs are handed out through a shared counter, so a slow job
 * does not hold up the others; each job writes only its own slot, so the
 * outcome does not depend on which thread ran what. Internal to the
 * libraries (src/util). */
#ifndef RB_UTIL_POOL_H
#define RB_UTIL_POOL_H

#include <stddef.h>
#include "rockbolt/status.h"

/* One job: fills slot i of whatever ctx points to, returns its status. */
typedef rb_status (*rb_pool_job)(void *ctx, size_t i);

/* The online processors, 1 to 1024. */
int rb_pool_threads_default(void);

/* Run job(ctx, i) for i in [0, n) on up to n_threads threads (<= 0: all
 * processors). Every job runs, whatever the others return; the statuses go
 * to status[i] (may be NULL). If threads cannot be created the calling
 * thread runs the rest. RB_ERR_NOMEM when the thread table cannot be
 * allocated (no job has run then). */
rb_status rb_pool_map(size_t n, int n_threads, rb_pool_job job, void *ctx,
                      rb_status *status);

#endif
