/* Blocks of markup laid out on pages and drawn: pango sets the text,
 * cairo's PDF surface takes it and the figures, librsvg draws the SVG
 * figures into it as vectors (docs/pdf.md says why these libraries).
 *
 * The document is laid out twice with the same code: the first pass only
 * counts the pages (to a PDF surface whose bytes are thrown away, so the
 * fonts measure the same), the second draws them with "Page n of m". */
#include <cairo-pdf.h>
#include <cairo.h>
#include <librsvg/rsvg.h>
#include <math.h>
#include <pango/pangocairo.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "pdf_internal.h"
#include "rockbolt/rockbolt.h"

/* Points (1/72 in). Letter for US customary cases, A4 for SI ones. */
#define MARGIN 54.0
#define FOOTER 24.0
#define CELL_PAD 3.0
#define BODY_PT 9.0

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
} pen;

/* The first error stands: its status, and msg and what after it. */
static void fail(pen *p, rb_status st, const char *msg, const char *what)
{
    if (p->st != RB_OK)
        return;
    p->st = st;
    if (p->diag)
        snprintf(p->diag->msg, sizeof p->diag->msg, "%s%s", msg, what ? what : "");
}

/* Set text in font over width (no wrap when width <= 0). */
static void set_text(pen *p, const PangoFontDescription *f, const char *text, double width,
                     PangoAlignment align)
{
    pango_layout_set_font_description(p->lay, f);
    pango_layout_set_width(p->lay, width > 0 ? (int)(width * PANGO_SCALE) : -1);
    pango_layout_set_wrap(p->lay, PANGO_WRAP_WORD_CHAR);
    pango_layout_set_alignment(p->lay, align);
    pango_layout_set_text(p->lay, text, -1);
}

static double text_height(pen *p)
{
    int w, h;
    pango_layout_get_size(p->lay, &w, &h);
    return (double)h / PANGO_SCALE;
}

static double text_width(pen *p)
{
    int w, h;
    pango_layout_get_size(p->lay, &w, &h);
    return (double)w / PANGO_SCALE;
}

static void show_layout_at(pen *p, PangoLayout *lay, double x, double y)
{
    if (!p->draw)
        return;
    cairo_move_to(p->cr, x, y);
    pango_cairo_show_layout(p->cr, lay);
}

static void show_at(pen *p, double x, double y)
{
    show_layout_at(p, p->lay, x, y);
}

/* The footer of the page being finished, then the next page. */
static void footer(pen *p)
{
    char right[64], left[512];
    const rb_pdf_cover *cv = p->cv;
    const rb_case_project *pr = cv->project;
    snprintf(right, sizeof right, "Page %d of %d", p->page, p->n_pages);
    snprintf(left, sizeof left, "%.200s%s%.200s  -  rockbolt %s",
             pr && pr->project ? pr->project : cv->case_name ? cv->case_name : cv->title,
             pr && pr->job_number ? ", job " : "", pr && pr->job_number ? pr->job_number : "",
             RB_VERSION_STRING);
    double y = p->ph - MARGIN + FOOTER / 2;
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

static void new_page(pen *p)
{
    footer(p);
    if (p->draw)
        cairo_show_page(p->cr);
    p->page++;
    p->y = MARGIN;
}

/* Room for h more points on this page, else the next page. */
static void need(pen *p, double h)
{
    if (p->y + h > p->ybot && p->y > MARGIN)
        new_page(p);
}

static void text_block(pen *p, const PangoFontDescription *f, const char *text, double indent,
                       double before, double after, double keep)
{
    set_text(p, f, text, p->width - indent, PANGO_ALIGN_LEFT);
    double h = text_height(p);
    p->y += before;
    need(p, h + keep);
    show_at(p, p->x0 + indent, p->y);
    p->y += h + after;
}

static void bullet(pen *p, const char *text)
{
    set_text(p, p->body, text, p->width - 14, PANGO_ALIGN_LEFT);
    double h = text_height(p);
    need(p, h);
    show_at(p, p->x0 + 14, p->y);
    set_text(p, p->body, "\xe2\x80\xa2", 0, PANGO_ALIGN_LEFT);
    show_at(p, p->x0 + 4, p->y);
    p->y += h + 1.5;
}

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
 * more than the page, the wide columns share what the narrow leave. */
static void column_widths(pen *p, const rb_pdf_block *t, double *w)
{
    size_t nc = t->n_cols, c, r;
    double total = 0, fixed = 0, wide = 0;
    for (c = 0; c < nc; c++)
        w[c] = 2 * CELL_PAD + 4;
    for (r = 0; r < t->n_rows; r++)
        for (c = 0; c < t->rows[r].n; c++) {
            set_text(p, t->rows[r].head ? p->bold : p->body, t->rows[r].cells[c], 0,
                     PANGO_ALIGN_LEFT);
            double x = text_width(p) + 2 * CELL_PAD + 1;
            if (x > w[c])
                w[c] = x;
        }
    for (c = 0; c < nc; c++)
        total += w[c];
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

static double row_height(pen *p, const rb_pdf_row *row, const double *w)
{
    double h = 0;
    for (size_t c = 0; c < row->n; c++) {
        set_text(p, row->head ? p->bold : p->body, row->cells[c], w[c] - 2 * CELL_PAD,
                 PANGO_ALIGN_LEFT);
        h = fmax(h, text_height(p));
    }
    return h + 2 * CELL_PAD;
}

static void draw_row(pen *p, const rb_pdf_row *row, const double *w, size_t nc, double h)
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
            set_text(p, row->head ? p->bold : p->body, s, w[c] - 2 * CELL_PAD,
                     !row->head && numeric(s) ? PANGO_ALIGN_RIGHT : PANGO_ALIGN_LEFT);
            show_at(p, x + CELL_PAD, p->y + CELL_PAD);
        }
        x += w[c];
    }
    p->y += h;
}

/* A table, split between rows across pages, its heading rows repeated. */
static void table(pen *p, const rb_pdf_block *t)
{
    size_t nc = t->n_cols, r, n_head = 0;
    double *w = calloc(nc ? nc : 1, sizeof *w);
    if (!w) {
        fail(p, RB_ERR_NOMEM, "out of memory", NULL);
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
        if (p->y + h + keep > p->ybot && p->y > MARGIN) {
            new_page(p);
            if (r >= n_head)
                for (size_t k = 0; k < n_head; k++)
                    draw_row(p, &t->rows[k], w, nc, row_height(p, &t->rows[k], w));
        }
        draw_row(p, &t->rows[r], w, nc, h);
    }
    p->y += 6;
    free(w);
}

/* Text as printed: monospaced, made smaller (to 6 pt) until its widest
 * line fits the page, wrapped beyond that; split between lines. */
static void pre(pen *p, const char *text)
{
    PangoFontDescription *f = pango_font_description_copy(p->mono);
    double size = 8;
    for (;;) {
        pango_font_description_set_size(f, (int)(size * PANGO_SCALE));
        set_text(p, f, text, 0, PANGO_ALIGN_LEFT);
        if (text_width(p) <= p->width || size <= 6)
            break;
        size -= 0.5;
    }
    p->y += 2;
    for (const char *s = text; ; ) {
        size_t n = strcspn(s, "\n");
        char *line = malloc(n + 2);
        if (!line) {
            fail(p, RB_ERR_NOMEM, "out of memory", NULL);
            break;
        }
        memcpy(line, s, n);
        line[n] = '\0';
        if (n == 0)
            strcpy(line, " ");
        set_text(p, f, line, p->width, PANGO_ALIGN_LEFT);
        double h = text_height(p);
        need(p, h);
        show_at(p, p->x0, p->y);
        p->y += h;
        free(line);
        if (!s[n])
            break;
        s += n + 1;
    }
    p->y += 6;
    pango_font_description_free(f);
}

/* The height figure i takes on the page (with its caption): the width of
 * the page, or less where it would not fit on one. 0 when unreadable. */
static double figure_height(pen *p, size_t i)
{
    RsvgHandle *h = rsvg_handle_new_from_data((const guint8 *)p->svgs[i],
                                              strlen(p->svgs[i]), NULL);
    gdouble fw = 0, fh = 0;
    if (!h)
        return 0;
    if (!rsvg_handle_get_intrinsic_size_in_pixels(h, &fw, &fh) || !(fw > 0) || !(fh > 0))
        fw = 800, fh = 600;
    g_object_unref(h);
    double scale = p->width / fw, room = p->ybot - MARGIN - 16;
    return fmin(fh * scale, room) + 16;
}

/* Each figure the width of the page (smaller if it would not fit on one),
 * with its number under it. */
static void figures(pen *p)
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
            fail(p, RB_ERR_INVALID, "figure ", what);
            g_clear_error(&err);
            return;
        }
        if (!rsvg_handle_get_intrinsic_size_in_pixels(h, &fw, &fh) || !(fw > 0) || !(fh > 0))
            fw = 800, fh = 600;
        double scale = p->width / fw;
        double room = p->ybot - MARGIN - 16;
        if (fh * scale > room)
            scale = room / fh;
        double dw = fw * scale, dh = fh * scale;
        need(p, dh + 16);
        if (p->draw) {
            RsvgRectangle vp = {p->x0 + (p->width - dw) / 2, p->y, dw, dh};
            if (!rsvg_handle_render_document(h, p->cr, &vp, &err)) {
                char what[64];
                snprintf(what, sizeof what, "%zu cannot be drawn: %.40s", i + 1,
                         err ? err->message : "");
                fail(p, RB_ERR_INVALID, "figure ", what);
                g_clear_error(&err);
            }
        }
        g_object_unref(h);
        p->y += dh + 2;
        snprintf(cap, sizeof cap, "Figure %zu of %zu", i + 1, p->n_svgs);
        set_text(p, p->small, cap, p->width, PANGO_ALIGN_CENTER);
        show_at(p, p->x0, p->y);
        p->y += text_height(p) + 10;
    }
}

static void block(pen *p, const rb_pdf_block *b)
{
    switch (b->kind) {
    case RB_PDF_TITLE:
        text_block(p, p->title, b->text, 0, 0, 8, 20);
        break;
    case RB_PDF_H1:
        text_block(p, p->h1, b->text, 0, 10, 4, 48);
        break;
    case RB_PDF_H2:
        text_block(p, p->h2, b->text, 0, 6, 3, 36);
        break;
    case RB_PDF_H3:
        text_block(p, p->bold, b->text, 0, 5, 1, 24);
        break;
    case RB_PDF_EMPH:
        text_block(p, p->bold, b->text, 0, 3, 2, 12);
        break;
    case RB_PDF_PARA:
        text_block(p, p->body, b->text, 0, 0, 3, 0);
        break;
    case RB_PDF_BULLET:
        bullet(p, b->text);
        break;
    case RB_PDF_EQ:
        text_block(p, p->mono, b->text, 14, 0, 1.5, 0);
        break;
    case RB_PDF_TABLE:
        table(p, b);
        break;
    case RB_PDF_PRE:
        pre(p, b->text);
        break;
    case RB_PDF_FIGURES:
        figures(p);
        break;
    case RB_PDF_NEWPAGE:
        if (p->y > MARGIN)
            new_page(p);
        break;
    case RB_PDF_SPACE:
        p->y += 4;
        break;
    }
}

static PangoFontDescription *font(const char *family, double pt, int bold)
{
    PangoFontDescription *f = pango_font_description_new();
    pango_font_description_set_family(f, family);
    pango_font_description_set_size(f, (int)(pt * PANGO_SCALE));
    pango_font_description_set_weight(f, bold ? PANGO_WEIGHT_BOLD : PANGO_WEIGHT_NORMAL);
    return f;
}

/* One pass over the blocks on surface s; the page count in p->page. */
static void lay_out(pen *p, cairo_surface_t *s, const rb_pdf_blocks *bs)
{
    p->cr = cairo_create(s);
    p->lay = pango_cairo_create_layout(p->cr);
    /* the same metrics in both passes and on every machine's screen
     * settings: no hinting, no rounding to device pixels */
    cairo_font_options_t *fo = cairo_font_options_create();
    cairo_font_options_set_hint_style(fo, CAIRO_HINT_STYLE_NONE);
    cairo_font_options_set_hint_metrics(fo, CAIRO_HINT_METRICS_OFF);
    pango_cairo_context_set_font_options(pango_layout_get_context(p->lay), fo);
    cairo_font_options_destroy(fo);
    pango_layout_context_changed(p->lay);
    p->foot = pango_layout_new(pango_layout_get_context(p->lay));
    p->page = 1;
    p->y = MARGIN;
    for (size_t i = 0; i < bs->n && p->st == RB_OK; i++) {
        /* a heading over the figures goes to the page of the first */
        if (i + 1 < bs->n && bs->b[i + 1].kind == RB_PDF_FIGURES && p->n_svgs
            && bs->b[i].kind <= RB_PDF_H3)
            need(p, figure_height(p, 0) + 40);
        block(p, &bs->b[i]);
    }
    footer(p);
    if (p->draw)
        cairo_show_page(p->cr);
    g_object_unref(p->foot);
    g_object_unref(p->lay);
    p->foot = p->lay = NULL;
    if (cairo_status(p->cr) != CAIRO_STATUS_SUCCESS)
        fail(p, RB_ERR_IO, "cannot draw the document: ",
             cairo_status_to_string(cairo_status(p->cr)));
    cairo_destroy(p->cr);
    p->cr = NULL;
}

static cairo_status_t discard(void *closure, const unsigned char *data, unsigned int n)
{
    (void)closure;
    (void)data;
    (void)n;
    return CAIRO_STATUS_SUCCESS;
}

static cairo_status_t collect(void *closure, const unsigned char *data, unsigned int n)
{
    rb_strbuf *b = closure;
    rb_strbuf_putn(b, (const char *)data, n);
    return b->oom ? CAIRO_STATUS_NO_MEMORY : CAIRO_STATUS_SUCCESS;
}

static cairo_surface_t *surface(pen *p, cairo_write_func_t write, void *closure)
{
    cairo_surface_t *s = cairo_pdf_surface_create_for_stream(write, closure, p->pw, p->ph);
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS)
        return s;
    cairo_pdf_surface_restrict_to_version(s, CAIRO_PDF_VERSION_1_5);
    char creator[64];
    snprintf(creator, sizeof creator, "rockbolt %s", RB_VERSION_STRING);
    cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_CREATOR, creator);
    cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_TITLE, p->cv->title);
    if (p->cv->project && p->cv->project->engineer)
        cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_AUTHOR, p->cv->project->engineer);
    return s;
}

rb_status rb_pdf_render(const rb_pdf_cover *cv, const char *body,
                        const char *const *svgs, size_t n_svgs,
                        char **out, size_t *len, rb_diag *diag)
{
    rb_strbuf mk = {0}, doc = {0};
    rb_pdf_blocks bs;
    pen p;
    *out = NULL;
    *len = 0;
    rb_pdf_cover_markup(&mk, cv);
    rb_strbuf_puts(&mk, body ? body : "");
    rb_strbuf_puts(&mk, "\n");
    rb_pdf_limits_markup(&mk);
    if (mk.oom) {
        rb_strbuf_free(&mk);
        return RB_ERR_NOMEM;
    }
    rb_status st = rb_pdf_parse(mk.p, &bs);
    rb_strbuf_free(&mk);
    if (st != RB_OK)
        return st;
    memset(&p, 0, sizeof p);
    p.cv = cv;
    p.svgs = svgs;
    p.n_svgs = n_svgs;
    p.diag = diag;
    p.st = RB_OK;
    int letter = cv->units == RB_UNITS_US;
    p.pw = letter ? 612 : 595.276;
    p.ph = letter ? 792 : 841.89;
    p.x0 = MARGIN;
    p.width = p.pw - 2 * MARGIN;
    p.ybot = p.ph - MARGIN - FOOTER;
    p.body = font("DejaVu Sans", BODY_PT, 0);
    p.bold = font("DejaVu Sans", BODY_PT, 1);
    p.title = font("DejaVu Sans", 16, 1);
    p.h1 = font("DejaVu Sans", 13, 1);
    p.h2 = font("DejaVu Sans", 10.5, 1);
    p.mono = font("DejaVu Sans Mono", 8, 0);
    p.small = font("DejaVu Sans", 7.5, 0);
    /* pass 1: count the pages */
    cairo_surface_t *s = surface(&p, discard, NULL);
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS)
        fail(&p, RB_ERR_IO, "cannot make a PDF surface", NULL);
    else
        lay_out(&p, s, &bs);
    cairo_surface_destroy(s);
    /* pass 2: draw them, numbered */
    if (p.st == RB_OK) {
        p.n_pages = p.page;
        p.draw = 1;
        s = surface(&p, collect, &doc);
        if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS)
            fail(&p, RB_ERR_IO, "cannot make a PDF surface", NULL);
        else
            lay_out(&p, s, &bs);
        cairo_surface_finish(s);
        if (p.st == RB_OK && cairo_surface_status(s) != CAIRO_STATUS_SUCCESS)
            fail(&p, doc.oom ? RB_ERR_NOMEM : RB_ERR_IO, "cannot write the document: ",
                 cairo_status_to_string(cairo_surface_status(s)));
        cairo_surface_destroy(s);
        if (p.st == RB_OK && p.page != p.n_pages)
            fail(&p, RB_ERR_INVALID, "the pages were laid out twice differently (a bug)", NULL);
    }
    PangoFontDescription *fonts[] = {p.body, p.bold, p.title, p.h1, p.h2, p.mono, p.small};
    for (size_t k = 0; k < sizeof fonts / sizeof fonts[0]; k++)
        pango_font_description_free(fonts[k]);
    rb_pdf_blocks_free(&bs);
    if (p.st == RB_OK && doc.oom)
        p.st = RB_ERR_NOMEM;
    if (p.st != RB_OK) {
        rb_strbuf_free(&doc);
        return p.st;
    }
    *len = doc.n;
    *out = doc.p;
    return RB_OK;
}
