/* What the files that lay out and draw a PDF's pages share: the pen (the
 * page being filled, its fonts and layouts) and its primitives
 * (pdf_page.c), tables (pdf_table.c) and figures (pdf_figure.c). Private
 * to src/pdf. Lengths in points (1/72 in), y down from the page's top. */
#ifndef RB_PDF_PEN_H
#define RB_PDF_PEN_H

#include <cairo.h>
#include <pango/pangocairo.h>
#include "pdf_internal.h"

/* Letter for US customary cases, A4 for SI ones, with these margins. */
#define RB_PDF_MARGIN 54.0
#define RB_PDF_FOOTER 24.0
#define RB_PDF_CELL_PAD 3.0
#define RB_PDF_BODY_PT 9.0

typedef struct {
    cairo_t *cr;
    int draw;                 /* second pass */
    double pw, ph, x0, width, y, ybot;
    int page, n_pages;
    const rb_pdf_cover *cv;
    PangoLayout *lay;
    PangoLayout *foot;        /* the footer's own, so that a page break
                                 between measuring and drawing a block
                                 leaves the block's text in lay */
    PangoFontDescription *body, *bold, *title, *h1, *h2, *mono, *small;
    const char *const *svgs;
    size_t n_svgs;
    rb_status st;
    rb_diag *diag;
} rb_pdf_pen;

/* The first error stands: its status, and msg and what after it. */
void rb_pdf_fail(rb_pdf_pen *p, rb_status st, const char *msg, const char *what);
/* Set text in font f over width (no wrap when width <= 0) in p->lay. */
void rb_pdf_set_text(rb_pdf_pen *p, const PangoFontDescription *f, const char *text,
                     double width, PangoAlignment align);
double rb_pdf_text_height(rb_pdf_pen *p);
double rb_pdf_text_width(rb_pdf_pen *p);
/* Draw p->lay at x, y (second pass only). */
void rb_pdf_show_at(rb_pdf_pen *p, double x, double y);
/* The footer of the page being finished ("Page n of m"). */
void rb_pdf_footer(rb_pdf_pen *p);
/* Finish the page, start the next. */
void rb_pdf_new_page(rb_pdf_pen *p);
/* Room for h more points on this page, else the next page. */
void rb_pdf_need(rb_pdf_pen *p, double h);

/* A table, split between rows across pages, its heading rows repeated. */
void rb_pdf_table(rb_pdf_pen *p, const rb_pdf_block *t);
/* Every figure of p, one page wide, numbered. */
void rb_pdf_figures(rb_pdf_pen *p);
/* The height figure i takes (with its caption); 0 when unreadable. */
double rb_pdf_figure_height(rb_pdf_pen *p, size_t i);

#endif
