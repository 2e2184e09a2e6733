/* The body's light markup (docs/pdf.md) parsed into blocks: one line a
 * block, but for tables (consecutive "|" lines) and text as printed
 * (between "```" lines). */
#include <stdlib.h>
#include <string.h>
#include "pdf_internal.h"
#include "util/grow.h"

static char *dup_n(const char *s, size_t n)
{
    char *p = malloc(n + 1);
    if (p) {
        memcpy(p, s, n);
        p[n] = '\0';
    }
    return p;
}

static char *dup_trim(const char *s, size_t n)
{
    while (n && (*s == ' ' || *s == '\t'))
        s++, n--;
    while (n && (s[n - 1] == ' ' || s[n - 1] == '\t' || s[n - 1] == '\r'))
        n--;
    return dup_n(s, n);
}

static rb_pdf_block *add_block(rb_pdf_blocks *bs, rb_pdf_kind kind)
{
    if (bs->n == bs->cap) {
        rb_pdf_block *nb = rb_grow(bs->b, &bs->cap, sizeof *nb, 32);
        if (!nb)
            return NULL;
        bs->b = nb;
    }
    rb_pdf_block *b = &bs->b[bs->n++];
    memset(b, 0, sizeof *b);
    b->kind = kind;
    return b;
}

/* One "|" line of a table: its cells, the extra ones joined into the last. */
static int add_row(rb_pdf_block *t, const char *line, size_t len)
{
    int head = len > 1 && line[1] == '=';
    const char *p = line + 1 + head, *end = line + len;
    size_t n = 1, k = 0;
    for (const char *q = p; q < end; q++)
        n += *q == '|';
    if (t->n_rows == t->cap_rows) {
        rb_pdf_row *nr = rb_grow(t->rows, &t->cap_rows, sizeof *nr, 8);
        if (!nr)
            return 0;
        t->rows = nr;
    }
    if (t->n_rows == 0)
        t->n_cols = n;
    size_t keep = n < t->n_cols ? n : t->n_cols;
    rb_pdf_row *r = &t->rows[t->n_rows];
    r->head = head;
    r->n = 0;
    if (!(r->cells = calloc(keep ? keep : 1, sizeof *r->cells)))
        return 0;
    t->n_rows++;
    while (k < keep) {
        const char *bar = k + 1 < keep ? memchr(p, '|', (size_t)(end - p)) : NULL;
        const char *stop = bar ? bar : end;
        if (!(r->cells[k] = dup_trim(p, (size_t)(stop - p))))
            return 0;
        r->n = ++k;
        p = bar ? bar + 1 : end;
    }
    return 1;
}

static const struct {
    const char *prefix;
    rb_pdf_kind kind;
} prefixes[] = {
    {"= ", RB_PDF_TITLE}, {"## ", RB_PDF_H2}, {"# ", RB_PDF_H1}, {"!! ", RB_PDF_H3},
    {"! ", RB_PDF_EMPH}, {"- ", RB_PDF_BULLET}, {"> ", RB_PDF_EQ},
};

rb_status rb_pdf_parse(const char *markup, rb_pdf_blocks *out)
{
    const char *s = markup;
    rb_pdf_block *table = NULL, *pre = NULL;
    rb_strbuf pb = {0};
    memset(out, 0, sizeof *out);
    while (*s) {
        size_t len = strcspn(s, "\n");
        const char *line = s;
        s += len + (s[len] == '\n');
        if (len && line[len - 1] == '\r')
            len--;
        if (len >= 3 && strncmp(line, "```", 3) == 0) {
            if (pre) {
                pre->text = rb_strbuf_take(&pb);
                if (!pre->text && !(pre->text = dup_n("", 0)))
                    goto nomem;
                pre = NULL;
            } else if (!(pre = add_block(out, RB_PDF_PRE))) {
                goto nomem;
            }
            table = NULL;
            continue;
        }
        if (pre) {
            if (pb.n)
                rb_strbuf_puts(&pb, "\n");
            rb_strbuf_putn(&pb, line, len);
            if (pb.oom)
                goto nomem;
            continue;
        }
        if (len && line[0] == '|') {
            if (!table && !(table = add_block(out, RB_PDF_TABLE)))
                goto nomem;
            if (!add_row(table, line, len))
                goto nomem;
            continue;
        }
        table = NULL;
        rb_pdf_kind kind = RB_PDF_PARA;
        size_t skip = 0;
        if (len == 0 || strspn(line, " \t") == len) {
            kind = RB_PDF_SPACE;
            skip = len;
        } else if (len == 8 && strncmp(line, "@figures", 8) == 0) {
            kind = RB_PDF_FIGURES;
            skip = len;
        } else if (len == 8 && strncmp(line, "@newpage", 8) == 0) {
            kind = RB_PDF_NEWPAGE;
            skip = len;
        } else {
            for (size_t k = 0; k < sizeof prefixes / sizeof prefixes[0]; k++) {
                size_t pl = strlen(prefixes[k].prefix);
                if (len >= pl && strncmp(line, prefixes[k].prefix, pl) == 0) {
                    kind = prefixes[k].kind;
                    skip = pl;
                    break;
                }
            }
        }
        rb_pdf_block *b = add_block(out, kind);
        if (!b || !(b->text = dup_trim(line + skip, len - skip)))
            goto nomem;
    }
    if (pre) {
        /* an unclosed block runs to the end */
        pre->text = rb_strbuf_take(&pb);
        if (!pre->text && !(pre->text = dup_n("", 0)))
            goto nomem;
    }
    return RB_OK;
nomem:
    rb_strbuf_free(&pb);
    rb_pdf_blocks_free(out);
    return RB_ERR_NOMEM;
}

void rb_pdf_blocks_free(rb_pdf_blocks *bs)
{
    for (size_t i = 0; i < bs->n; i++) {
        rb_pdf_block *b = &bs->b[i];
        free(b->text);
        for (size_t r = 0; r < b->n_rows; r++) {
            for (size_t c = 0; c < b->rows[r].n; c++)
                free(b->rows[r].cells[c]);
            free(b->rows[r].cells);
        }
        free(b->rows);
    }
    free(bs->b);
    memset(bs, 0, sizeof *bs);
}
