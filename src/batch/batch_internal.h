/* What the batch_*.c files share; not part of the public API. */
#ifndef RB_BATCH_INTERNAL_H
#define RB_BATCH_INTERNAL_H

#include <stddef.h>
#include "rockbolt/batch.h"

char *rb_batch_strdup(const char *s);

/* Append an item for source (copied); NULL on NOMEM. */
rb_batch_item *rb_batch_list_push(rb_batch_list *l, const char *source);

/* Mark an item bad, with the error at its source. */
void rb_batch_item_bad(rb_batch_item *it, int line, int col, const char *key,
                       const char *msg);

/* A growing string; nomem is sticky, so callers check once at the end. */
typedef struct {
    char *buf;
    size_t len, cap;
    int nomem;
} rb_bbuf;

void rb_bbuf_put(rb_bbuf *b, const char *s, size_t n);
void rb_bbuf_str(rb_bbuf *b, const char *s);
void rb_bbuf_printf(rb_bbuf *b, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* The buffer's string (never NULL unless nomem), handed to the caller. */
char *rb_bbuf_take(rb_bbuf *b);

/* job(ctx, i) for i in [0, n) on up to n_threads threads, the caller's
 * included; every job runs. RB_ERR_NOMEM if no thread table. */
typedef void (*rb_batch_job)(void *ctx, size_t i);
rb_status rb_batch_parallel(size_t n, int n_threads, rb_batch_job job, void *ctx);
int rb_batch_threads_default(void);

/* One case of the work list, loaded, solved, judged and reported. */
typedef struct rb_batch_ctx rb_batch_ctx;

#endif
