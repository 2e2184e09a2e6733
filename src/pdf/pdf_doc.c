/* Blocks of markup laid out on pages and drawn: pango sets the text,
 * cairo's PDF surface takes it and the figures, librsvg draws the SVG
 * figures into it as vectors (docs/pdf.md says why these libraries).
 *
 * The document is laid out twice with the same code: the first pass only
 * counts the pages (to a PDF surface whose bytes are thrown away, so the
 * fonts measure the same), the second draws them with "Page n of m". */
#include <cairo-pdf.h>
#include <cairo.h>
#include <math.h>
#include <pango/pangocairo.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "pdf_pen.h"
#include "rockbolt/version.h"


static void text_block(rb_pdf_pen *p, const PangoFontDescription *f, const char *text,
                       double indent, double before, double after, double keep)
{
    rb_pdf_set_text(p, f, text, p->width - indent, PANGO_ALIGN_LEFT);
    double h = rb_pdf_text_height(p);
    p->y += before;
    rb_pdf_need(p, h + keep);
    rb_pdf_show_at(p, p->x0 + indent, p->y);
    p->y += h + after;
}

static void bullet(rb_pdf_pen *p, const char *text)
{
    rb_pdf_set_text(p, p->body, text, p->width - 14, PANGO_ALIGN_LEFT);
    double h = rb_pdf_text_height(p);
    rb_pdf_need(p, h);
    rb_pdf_show_at(p, p->x0 + 14, p->y);
    rb_pdf_set_text(p, p->body, "\xe2\x80\xa2", 0, PANGO_ALIGN_LEFT);
    rb_pdf_show_at(p, p->x0 + 4, p->y);
    p->y += h + 1.5;
}

/* Text as printed: monospaced, made smaller (to 6 pt) until its widest
 * line fits the page, wrapped beyond that; split between lines. */
static void pre(rb_pdf_pen *p, const char *text)
{
    PangoFontDescription *f = pango_font_description_copy(p->mono);
    double size = 8;
    for (;;) {
        pango_font_description_set_size(f, (int)(size * PANGO_SCALE));
        rb_pdf_set_text(p, f, text, 0, PANGO_ALIGN_LEFT);
        if (rb_pdf_text_width(p) <= p->width || size <= 6)
            break;
        size -= 0.5;
    }
    p->y += 2;
    for (const char *s = text; ; ) {
        size_t n = strcspn(s, "\n");
        char *line = malloc(n + 2);
        if (!line) {
            rb_pdf_fail(p, RB_ERR_NOMEM, "out of memory", NULL);
            break;
        }
        memcpy(line, s, n);
        line[n] = '\0';
        if (n == 0)
            strcpy(line, " ");
        rb_pdf_set_text(p, f, line, p->width, PANGO_ALIGN_LEFT);
        double h = rb_pdf_text_height(p);
        rb_pdf_need(p, h);
        rb_pdf_show_at(p, p->x0, p->y);
        p->y += h;
        free(line);
        if (!s[n])
            break;
        s += n + 1;
    }
    p->y += 6;
    pango_font_description_free(f);
}

static void block(rb_pdf_pen *p, const rb_pdf_block *b)
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
        rb_pdf_table(p, b);
        break;
    case RB_PDF_PRE:
        pre(p, b->text);
        break;
    case RB_PDF_FIGURES:
        rb_pdf_figures(p);
        break;
    case RB_PDF_NEWPAGE:
        if (p->y > RB_PDF_MARGIN)
            rb_pdf_new_page(p);
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
static void lay_out(rb_pdf_pen *p, cairo_surface_t *s, const rb_pdf_blocks *bs)
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
    p->y = RB_PDF_MARGIN;
    for (size_t i = 0; i < bs->n && p->st == RB_OK; i++) {
        /* a heading over the figures goes to the page of the first */
        if (i + 1 < bs->n && bs->b[i + 1].kind == RB_PDF_FIGURES && p->n_svgs
            && bs->b[i].kind <= RB_PDF_H3)
            rb_pdf_need(p, rb_pdf_figure_height(p, 0) + 40);
        block(p, &bs->b[i]);
    }
    rb_pdf_footer(p);
    if (p->draw)
        cairo_show_page(p->cr);
    g_object_unref(p->foot);
    g_object_unref(p->lay);
    p->foot = p->lay = NULL;
    if (cairo_status(p->cr) != CAIRO_STATUS_SUCCESS)
        rb_pdf_fail(p, RB_ERR_IO, "cannot draw the document: ",
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

static cairo_surface_t *surface(rb_pdf_pen *p, cairo_write_func_t write, void *closure)
{
    cairo_surface_t *s = cairo_pdf_surface_create_for_stream(write, closure, p->pw, p->ph);
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS)
        return s;
    /* 1.4: no compressed object streams (newer cairo writes them for 1.5),
     * so that the page objects stay plain for any reader */
    cairo_pdf_surface_restrict_to_version(s, CAIRO_PDF_VERSION_1_4);
    char creator[64];
    snprintf(creator, sizeof creator, "rockbolt %s", RB_VERSION_STRING);
    cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_CREATOR, creator);
    cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_TITLE, p->cv->title);
    if (p->cv->project && p->cv->project->engineer)
        cairo_pdf_surface_set_metadata(s, CAIRO_PDF_METADATA_AUTHOR,
                                       p->cv->project->engineer);
    return s;
}

rb_status rb_pdf_render(const rb_pdf_cover *cv, const char *body,
                        const char *const *svgs, size_t n_svgs,
                        char **out, size_t *len, rb_diag *diag)
{
    rb_strbuf mk = {0}, doc = {0};
    rb_pdf_blocks bs;
    rb_pdf_pen p;
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
    p.x0 = RB_PDF_MARGIN;
    p.width = p.pw - 2 * RB_PDF_MARGIN;
    p.ybot = p.ph - RB_PDF_MARGIN - RB_PDF_FOOTER;
    p.body = font("DejaVu Sans", RB_PDF_BODY_PT, 0);
    p.bold = font("DejaVu Sans", RB_PDF_BODY_PT, 1);
    p.title = font("DejaVu Sans", 16, 1);
    p.h1 = font("DejaVu Sans", 13, 1);
    p.h2 = font("DejaVu Sans", 10.5, 1);
    p.mono = font("DejaVu Sans Mono", 8, 0);
    p.small = font("DejaVu Sans", 7.5, 0);
    /* pass 1: count the pages */
    cairo_surface_t *s = surface(&p, discard, NULL);
    if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS)
        rb_pdf_fail(&p, RB_ERR_IO, "cannot make a PDF surface", NULL);
    else
        lay_out(&p, s, &bs);
    cairo_surface_destroy(s);
    /* pass 2: draw them, numbered */
    if (p.st == RB_OK) {
        p.n_pages = p.page;
        p.draw = 1;
        s = surface(&p, collect, &doc);
        if (cairo_surface_status(s) != CAIRO_STATUS_SUCCESS)
            rb_pdf_fail(&p, RB_ERR_IO, "cannot make a PDF surface", NULL);
        else
            lay_out(&p, s, &bs);
        cairo_surface_finish(s);
        if (p.st == RB_OK && cairo_surface_status(s) != CAIRO_STATUS_SUCCESS)
            rb_pdf_fail(&p, doc.oom ? RB_ERR_NOMEM : RB_ERR_IO, "cannot write the document: ",
                 cairo_status_to_string(cairo_surface_status(s)));
        cairo_surface_destroy(s);
        if (p.st == RB_OK && p.page != p.n_pages)
            rb_pdf_fail(&p, RB_ERR_INVALID,
                        "the pages were laid out twice differently (a bug)", NULL);
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
