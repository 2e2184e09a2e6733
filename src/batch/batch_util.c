/* Small helpers of the batch code: strings, and the work list's items,
 * which the list's readers (batch_list.c, batch_list_csv.c) fill (the
 * growing string and the thread pool are src/util's). */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "batch_internal.h"
#include "util/grow.h"

char *rb_batch_strdup(const char *s)
{
    size_t n = strlen(s) + 1;
    char *p = malloc(n);
    if (p)
        memcpy(p, s, n);
    return p;
}

rb_batch_item *rb_batch_list_push(rb_batch_list *l, const char *source)
{
    if (l->n == l->cap) {
        rb_batch_item *p = rb_grow(l->items, &l->cap, sizeof *p, 16);
        if (!p)
            return NULL;
        l->items = p;
    }
    rb_batch_item *it = &l->items[l->n];
    memset(it, 0, sizeof *it);
    if (!(it->source = rb_batch_strdup(source)))
        return NULL;
    l->n++;
    return it;
}

void rb_batch_item_bad(rb_batch_item *it, int line, int col, const char *key,
                       const char *msg)
{
    it->bad = 1;
    if (!it->error && !(it->error = calloc(1, sizeof *it->error)))
        return;     /* the case loader reports it without the details */
    rb_diag_set(it->error, RB_ERR_INVALID, it->source, line, col, key, "%s", msg);
}

static void item_free(rb_batch_item *it)
{
    free(it->source);
    free(it->tag);
    free(it->base);
    for (size_t k = 0; k < it->n_ov; k++) {
        free((char *)it->ov[k].key);
        free((char *)it->ov[k].value);
    }
    free(it->ov);
    free(it->error);
}

void rb_batch_list_free(rb_batch_list *l)
{
    if (!l)
        return;
    for (size_t i = 0; i < l->n; i++)
        item_free(&l->items[i]);
    free(l->items);
    memset(l, 0, sizeof *l);
}
