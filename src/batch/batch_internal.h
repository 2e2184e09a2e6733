/* What the batch_*.c files share; not part of the public API. */
#ifndef RB_BATCH_INTERNAL_H
#define RB_BATCH_INTERNAL_H

#include <stddef.h>
#include "rockbolt/batch.h"

/* The most bytes of an equipment list the reader takes (the digest reads
 * no more either). */
#define RB_CSV_MAX_BYTES (64u * 1024u * 1024u)

char *rb_batch_strdup(const char *s);

/* Free what a case owns and zero it. */
void rb_batch_case_free(rb_batch_case *c);

/* Append an item for source (copied); NULL on NOMEM. */
rb_batch_item *rb_batch_list_push(rb_batch_list *l, const char *source);

/* Mark an item bad, with the error at its source. */
void rb_batch_item_bad(rb_batch_item *it, int line, int col, const char *key,
                       const char *msg);

#include "util/strbuf.h"


#endif
