/* Tables: columns as wide as their widest cell (the wide ones sharing
 * what the narrow leave when the page is too narrow), rows split across
 * pages with the heading rows repeated, numbers right-aligned. */
#include <cairo.h>
#include <math.h>
#include <pango/pangocairo.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "pdf_pen.h"

/* A number as a table shows it, right-aligned: "12.3", "-0.5", "n/a". */
static int numeric(const char *s)
{
    char *end;
    if (!*s)
        return 0;
    if (strcmp(s, "n/a") == 0)
        return 1;
    strtod(s, &end);
    return end != s && *end == '\0';
}

/* Column widths: each column its widest cell unwrapped, and where that is
 * more than the page, the wide columns share what the narrow leave. A
 * table whose first row ends in an empty cell (the cover, whose blanks a
 * hand fills in) is as wide as the page, its last column taking the rest. */
static void column_widths(rb_pdf_pen *p, const rb_pdf_block *t, double *w)
{
    size_t nc = t->n_cols, c, r;
    double total = 0, fixed = 0, wide = 0;
    for (c = 0; c < nc; c++)
        w[c] = 2 * RB_PDF_CELL_PAD + 4;
    for (r = 0; r < t->n_rows; r++)
        for (c = 0; c < t->rows[r].n; c++) {
            rb_pdf_set_text(p, t->rows[r].head ? p->bold : p->body, t->rows[r].cells[c], 0,
                            PANGO_ALIGN_LEFT);
            double x = rb_pdf_text_width(p) + 2 * RB_PDF_CELL_PAD + 1;
            if (x > w[c])
                w[c] = x;
        }
    for (c = 0; c < nc; c++)
        total += w[c];
    const rb_pdf_row *first = &t->rows[0];
    if (total < p->width && nc && first->n == nc && first->cells[nc - 1][0] == '\0')
        w[nc - 1] += p->width - total;
    if (total <= p->width)
        return;
    double share = p->width / (double)nc;
    for (c = 0; c < nc; c++) {
        if (w[c] <= share)
            fixed += w[c];
        else
            wide += w[c];
    }
    for (c = 0; c < nc; c++)
        if (w[c] > share)
            w[c] = (p->width - fixed) * w[c] / wide;
}

static double row_height(rb_pdf_pen *p, const rb_pdf_row *row, const double *w)
{
    double h = 0;
    for (size_t c = 0; c < row->n; c++) {
        rb_pdf_set_text(p, row->head ? p->bold : p->body, row->cells[c],
                        w[c] - 2 * RB_PDF_CELL_PAD, PANGO_ALIGN_LEFT);
        h = fmax(h, rb_pdf_text_height(p));
    }
    return h + 2 * RB_PDF_CELL_PAD;
}

static void draw_row(rb_pdf_pen *p, const rb_pdf_row *row, const double *w, size_t nc,
                     double h)
{
    double x = p->x0;
    for (size_t c = 0; c < nc; c++) {
        if (p->draw) {
            if (row->head) {
                cairo_set_source_rgb(p->cr, 0.93, 0.93, 0.93);
                cairo_rectangle(p->cr, x, p->y, w[c], h);
                cairo_fill(p->cr);
            }
            cairo_set_source_rgb(p->cr, 0.6, 0.6, 0.6);
            cairo_set_line_width(p->cr, 0.5);
            cairo_rectangle(p->cr, x, p->y, w[c], h);
            cairo_stroke(p->cr);
            cairo_set_source_rgb(p->cr, 0, 0, 0);
        }
        if (c < row->n) {
            const char *s = row->cells[c];
            rb_pdf_set_text(p, row->head ? p->bold : p->body, s, w[c] - 2 * RB_PDF_CELL_PAD,
                     !row->head && numeric(s) ? PANGO_ALIGN_RIGHT : PANGO_ALIGN_LEFT);
            rb_pdf_show_at(p, x + RB_PDF_CELL_PAD, p->y + RB_PDF_CELL_PAD);
        }
        x += w[c];
    }
    p->y += h;
}

/* A table, split between rows across pages, its heading rows repeated. */
void rb_pdf_table(rb_pdf_pen *p, const rb_pdf_block *t)
{
    size_t nc = t->n_cols, r, n_head = 0;
    double *w = calloc(nc ? nc : 1, sizeof *w);
    if (!w) {
        rb_pdf_fail(p, RB_ERR_NOMEM, "out of memory", NULL);
        return;
    }
    column_widths(p, t, w);
    while (n_head < t->n_rows && t->rows[n_head].head)
        n_head++;
    p->y += 2;
    for (r = 0; r < t->n_rows; r++) {
        double h = row_height(p, &t->rows[r], w);
        /* a heading row stays with the first row under it */
        double keep = r + 1 < t->n_rows && t->rows[r].head
                      ? row_height(p, &t->rows[r + 1], w) : 0;
        if (p->y + h + keep > p->ybot && p->y > RB_PDF_MARGIN) {
            rb_pdf_new_page(p);
            if (r >= n_head)
                for (size_t k = 0; k < n_head; k++)
                    draw_row(p, &t->rows[k], w, nc, row_height(p, &t->rows[k], w));
        }
        draw_row(p, &t->rows[r], w, nc, h);
    }
    p->y += 6;
    free(w);
}
