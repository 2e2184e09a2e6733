/* The figures: the commands' own SVG documents drawn by librsvg into the
 * page as vectors, a page wide or smaller where one would not fit. */
#include <librsvg/rsvg.h>
#include <cairo.h>
#include <math.h>
#include <pango/pangocairo.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "pdf_pen.h"

/* The height figure i takes on the page (with its caption): the width of
 * the page, or less where it would not fit on one. 0 when unreadable. */
double rb_pdf_figure_height(rb_pdf_pen *p, size_t i)
{
    RsvgHandle *h = rsvg_handle_new_from_data((const guint8 *)p->svgs[i],
                                              strlen(p->svgs[i]), NULL);
    gdouble fw = 0, fh = 0;
    if (!h)
        return 0;
    if (!rsvg_handle_get_intrinsic_size_in_pixels(h, &fw, &fh) || !(fw > 0) || !(fh > 0))
        fw = 800, fh = 600;
    g_object_unref(h);
    double scale = p->width / fw, room = p->ybot - RB_PDF_MARGIN - 16;
    return fmin(fh * scale, room) + 16;
}

/* Each figure the width of the page (smaller if it would not fit on one),
 * with its number under it. */
void rb_pdf_figures(rb_pdf_pen *p)
{
    for (size_t i = 0; i < p->n_svgs && p->st == RB_OK; i++) {
        GError *err = NULL;
        const char *svg = p->svgs[i];
        RsvgHandle *h = rsvg_handle_new_from_data((const guint8 *)svg, strlen(svg), &err);
        gdouble fw = 0, fh = 0;
        char cap[64];
        if (!h) {
            char what[64];
            snprintf(what, sizeof what, "%zu is not an SVG document librsvg reads", i + 1);
            rb_pdf_fail(p, RB_ERR_INVALID, "figure ", what);
            g_clear_error(&err);
            return;
        }
        if (!rsvg_handle_get_intrinsic_size_in_pixels(h, &fw, &fh) || !(fw > 0) || !(fh > 0))
            fw = 800, fh = 600;
        double scale = p->width / fw;
        double room = p->ybot - RB_PDF_MARGIN - 16;
        if (fh * scale > room)
            scale = room / fh;
        double dw = fw * scale, dh = fh * scale;
        rb_pdf_need(p, dh + 16);
        if (p->draw) {
            RsvgRectangle vp = {p->x0 + (p->width - dw) / 2, p->y, dw, dh};
            if (!rsvg_handle_render_document(h, p->cr, &vp, &err)) {
                /* room for the longest index and the whole of the cut message */
                char what[96];
                snprintf(what, sizeof what, "%zu cannot be drawn: %.40s", i + 1,
                         err ? err->message : "");
                rb_pdf_fail(p, RB_ERR_INVALID, "figure ", what);
                g_clear_error(&err);
            }
        }
        g_object_unref(h);
        p->y += dh + 2;
        snprintf(cap, sizeof cap, "Figure %zu of %zu", i + 1, p->n_svgs);
        rb_pdf_set_text(p, p->small, cap, p->width, PANGO_ALIGN_CENTER);
        rb_pdf_show_at(p, p->x0, p->y);
        p->y += rb_pdf_text_height(p) + 10;
    }
}
