/* The page being filled: text set by pango and drawn by cairo, the
 * footer of each page, and the breaks between pages. */
#include <cairo.h>
#include <math.h>
#include <pango/pangocairo.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "pdf_pen.h"
#include "rockbolt/version.h"

/* The first error stands: its status, and msg and what after it. */
void rb_pdf_fail(rb_pdf_pen *p, rb_status st, const char *msg, const char *what)
{
    if (p->st != RB_OK)
        return;
    p->st = st;
    if (p->diag)
        rb_diag_set_msg(p->diag, "%s%s", msg, what ? what : "");
}

/* Set text in font over width (no wrap when width <= 0). */
void rb_pdf_set_text(rb_pdf_pen *p, const PangoFontDescription *f, const char *text,
                     double width, PangoAlignment align)
{
    pango_layout_set_font_description(p->lay, f);
    pango_layout_set_width(p->lay, width > 0 ? (int)(width * PANGO_SCALE) : -1);
    pango_layout_set_wrap(p->lay, PANGO_WRAP_WORD_CHAR);
    pango_layout_set_alignment(p->lay, align);
    pango_layout_set_text(p->lay, text, -1);
}

double rb_pdf_text_height(rb_pdf_pen *p)
{
    int w, h;
    pango_layout_get_size(p->lay, &w, &h);
    return (double)h / PANGO_SCALE;
}

double rb_pdf_text_width(rb_pdf_pen *p)
{
    int w, h;
    pango_layout_get_size(p->lay, &w, &h);
    return (double)w / PANGO_SCALE;
}

static void show_layout_at(rb_pdf_pen *p, PangoLayout *lay, double x, double y)
{
    if (!p->draw)
        return;
    cairo_move_to(p->cr, x, y);
    pango_cairo_show_layout(p->cr, lay);
}

void rb_pdf_show_at(rb_pdf_pen *p, double x, double y)
{
    show_layout_at(p, p->lay, x, y);
}

/* The footer of the page being finished, then the next page. */
void rb_pdf_footer(rb_pdf_pen *p)
{
    char right[64], left[512];
    const rb_pdf_cover *cv = p->cv;
    const rb_case_project *pr = cv->project;
    snprintf(right, sizeof right, "Page %d of %d", p->page, p->n_pages);
    snprintf(left, sizeof left, "%.200s%s%.200s  -  rockbolt %s",
             pr && pr->project ? pr->project : cv->case_name ? cv->case_name : cv->title,
             pr && pr->job_number ? ", job " : "", pr && pr->job_number ? pr->job_number : "",
             RB_VERSION_STRING);
    double y = p->ph - RB_PDF_MARGIN + RB_PDF_FOOTER / 2;
    if (p->draw) {
        cairo_set_source_rgb(p->cr, 0.6, 0.6, 0.6);
        cairo_set_line_width(p->cr, 0.5);
        cairo_move_to(p->cr, p->x0, y - 4);
        cairo_line_to(p->cr, p->x0 + p->width, y - 4);
        cairo_stroke(p->cr);
        cairo_set_source_rgb(p->cr, 0.25, 0.25, 0.25);
    }
    PangoLayout *f = p->foot;
    pango_layout_set_font_description(f, p->small);
    pango_layout_set_width(f, (int)(p->width * 0.75 * PANGO_SCALE));
    pango_layout_set_ellipsize(f, PANGO_ELLIPSIZE_END);
    pango_layout_set_alignment(f, PANGO_ALIGN_LEFT);
    pango_layout_set_text(f, left, -1);
    show_layout_at(p, f, p->x0, y);
    pango_layout_set_ellipsize(f, PANGO_ELLIPSIZE_NONE);
    pango_layout_set_width(f, (int)(p->width * PANGO_SCALE));
    pango_layout_set_alignment(f, PANGO_ALIGN_RIGHT);
    pango_layout_set_text(f, right, -1);
    show_layout_at(p, f, p->x0, y);
    if (p->draw)
        cairo_set_source_rgb(p->cr, 0, 0, 0);
}

void rb_pdf_new_page(rb_pdf_pen *p)
{
    rb_pdf_footer(p);
    if (p->draw)
        cairo_show_page(p->cr);
    p->page++;
    p->y = RB_PDF_MARGIN;
}

/* Room for h more points on this page, else the next page. */
void rb_pdf_need(rb_pdf_pen *p, double h)
{
    if (p->y + h > p->ybot && p->y > RB_PDF_MARGIN)
        rb_pdf_new_page(p);
}
