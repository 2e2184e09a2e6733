/* The case loader's error context: the diagnostics every stage adds
 * (rb_cctx_error*, at most RB_CASE_MAX_DIAGS a load, in reading order),
 * the files a load read, and the dotted key paths the messages name. The
 * stages of case_internal.h call it; it calls none of them. */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "case_internal.h"
#include "util/grow.h"

void rb_diag_list_free(rb_diag_list *l)
{
    if (!l)
        return;
    free(l->items);
    l->items = NULL;
    l->n = l->cap = 0;
}

rb_diag *rb_diag_list_add(rb_diag_list *l)
{
    if (l->n == l->cap) {
        rb_diag *p = rb_grow(l->items, &l->cap, sizeof *p, 8);
        if (!p)
            return NULL;
        l->items = p;
    }
    rb_diag *d = &l->items[l->n++];
    memset(d, 0, sizeof *d);
    return d;
}

static rb_diag *cctx_push(rb_cctx *c)
{
    rb_diag *d = rb_diag_list_add(c->diags);
    if (!d)
        c->nomem = 1;
    return d;
}

/* RB_ERR_NOMEM outranks everything; otherwise the first error's status
 * stays, except that a plain PARSE is upgraded to the more specific IO or
 * LIMIT. */
static void cctx_status(rb_cctx *c, rb_status st)
{
    if (c->status == RB_OK || st == RB_ERR_NOMEM
        || (c->status == RB_ERR_PARSE && (st == RB_ERR_IO || st == RB_ERR_LIMIT)))
        c->status = st;
}

static void cctx_vadd(rb_cctx *c, rb_status st, const char *file, int line,
                         int col, const char *key, const char *fmt, va_list ap)
#if defined(__GNUC__)
    __attribute__((format(printf, 7, 0)))
#endif
    ;

static void cctx_vadd(rb_cctx *c, rb_status st, const char *file, int line,
                         int col, const char *key, const char *fmt, va_list ap)
{
    c->n_errors++;
    cctx_status(c, st);
    rb_diag *d;
    if (c->diags->n - c->first_diag >= RB_CASE_MAX_DIAGS) {
        if (c->n_dropped++ > 0)
            return;
        d = &c->dropped;
        memset(d, 0, sizeof *d);
    } else if (!(d = cctx_push(c))) {
        return;
    }
    rb_diag_vset(d, st, file, line, col, key, fmt, ap);
}

void rb_cctx_error_at(rb_cctx *c, rb_status st, const char *file, int line,
                      int col, const char *key, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    cctx_vadd(c, st, file, line, col, key, fmt, ap);
    va_end(ap);
}

void rb_cctx_error(rb_cctx *c, const rb_ynode *n, const char *key,
                   const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    cctx_vadd(c, RB_ERR_INVALID, n ? n->file : NULL, n ? n->line : 0,
                 n ? n->col : 0, key, fmt, ap);
    va_end(ap);
}

const char *rb_cctx_file(rb_cctx *c, const char *name)
{
    for (size_t i = 0; i < c->n_files; i++)
        if (strcmp(c->files[i], name) == 0)
            return c->files[i];
    if (c->n_files == RB_CASE_MAX_FILES)
        return NULL;
    size_t len = strlen(name) + 1;
    char *copy = malloc(len);
    if (!copy) {
        c->nomem = 1;
        return NULL;
    }
    memcpy(copy, name, len);
    c->files[c->n_files++] = copy;
    return copy;
}

void rb_case_keypath(char *dst, const char *path, const char *key)
{
    if (path && path[0])
        snprintf(dst, RB_CASE_KEY_MAX, "%s.%s", path, key);
    else
        snprintf(dst, RB_CASE_KEY_MAX, "%s", key);
}

static size_t file_rank(const rb_cctx *c, const char *file)
{
    for (size_t i = 0; i < c->n_files; i++)
        if (strcmp(c->files[i], file) == 0)
            return i;
    return c->n_files;
}

/* Put this load's diagnostics (from index first on) in reading order: the
 * case file before its bases, then by line and column. Insertion sort keeps
 * equal positions in the order they were found; lists are short (at most
 * RB_CASE_MAX_DIAGS). */
static void cctx_sort(const rb_cctx *c, size_t first)
{
    rb_diag *d = c->diags->items;
    for (size_t i = first + 1; i < c->diags->n; i++) {
        rb_diag tmp = d[i];
        size_t r = file_rank(c, tmp.file), j = i;
        while (j > first) {
            const rb_diag *p = &d[j - 1];
            size_t rp = file_rank(c, p->file);
            if (rp < r || (rp == r && (p->line < tmp.line
                || (p->line == tmp.line && p->col <= tmp.col))))
                break;
            d[j] = d[j - 1];
            j--;
        }
        d[j] = tmp;
    }
}

void rb_cctx_finish(rb_cctx *c, size_t first)
{
    cctx_sort(c, first);
    if (c->n_dropped > 0) {
        /* After the sort, so that the count comes last. */
        rb_diag *d = cctx_push(c);
        if (d) {
            *d = c->dropped;
            rb_diag_set_msg(d, "too many errors: %zu more not shown (at most %d are "
                            "listed); the first of them: %.400s", c->n_dropped,
                            RB_CASE_MAX_DIAGS, c->dropped.msg);
        }
    }
}
