/* Axes: tick values that a reader can add up in their head (1, 2 or 5
 * times a power of ten), linear or logarithmic, panels that map data onto
 * the figure, and their frames, grid, labels, reference lines and
 * legends. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "plot_internal.h"

static double nice_step(double span, int target)
{
    double raw = span / (target > 1 ? target : 1);
    double p = pow(10, floor(log10(raw)));
    double m = raw / p;
    if (m <= 1)
        return p;
    if (m <= 2)
        return 2 * p;
    if (m <= 5)
        return 5 * p;
    return 10 * p;
}

void rb_axis_nice(rb_axis *ax, double lo, double hi, int target, int round_out)
{
    double step, first, t;
    int k;
    if (!isfinite(lo))
        lo = 0;
    if (!isfinite(hi))
        hi = 0;
    if (!isfinite(hi - lo)) {   /* only a broken input gets here */
        lo = -1;
        hi = 1;
    }
    if (lo > hi) {
        t = lo;
        lo = hi;
        hi = t;
    }
    if (hi - lo <= 1e-12 * fmax(fabs(lo), fabs(hi))) {
        double w = lo != 0 ? 0.1 * fabs(lo) : 1;
        lo -= w;
        hi += w;
    }
    step = nice_step(hi - lo, target);
    /* a target too small for the span could still give many ticks */
    while ((hi - lo) / step > RB_PLOT_MAX_TICKS - 2)
        step *= 2;
    if (round_out) {
        lo = floor(lo / step + 1e-9) * step;
        hi = ceil(hi / step - 1e-9) * step;
    }
    ax->lo = lo;
    ax->hi = hi;
    ax->step = step;
    ax->log = 0;
    ax->n_ticks = 0;
    first = ceil(lo / step - 1e-9);
    for (k = 0; k < RB_PLOT_MAX_TICKS; k++) {
        t = (first + k) * step;
        if (t > hi + 1e-9 * step)
            break;
        if (fabs(t) < 1e-9 * step)
            t = 0;
        ax->ticks[ax->n_ticks++] = t;
    }
    ax->decimals = step >= 1 ? 0 : (int)ceil(-log10(step) - 1e-9);
    if (ax->decimals > 9)
        ax->decimals = 9;
}

/* The 1-2-5 value at or below v (down) or at or above it (up), v > 0. */
static double one_two_five(double v, int up)
{
    static const double m[4] = {1, 2, 5, 10};
    double p = pow(10, floor(log10(v)));
    if (up) {
        for (int i = 0; i < 4; i++)
            if (m[i] * p >= v * (1 - 1e-12))
                return m[i] * p;
        return 10 * p;
    }
    for (int i = 3; i >= 0; i--)
        if (m[i] * p <= v * (1 + 1e-12))
            return m[i] * p;
    return p;
}

void rb_axis_log(rb_axis *ax, double lo, double hi)
{
    int ok_lo = isfinite(lo) && lo > 0, ok_hi = isfinite(hi) && hi > 0;
    if (!ok_lo && !ok_hi)
        lo = hi = 1;
    else if (!ok_lo)
        lo = hi;
    else if (!ok_hi)
        hi = lo;
    if (lo > hi) {
        double t = lo;
        lo = hi;
        hi = t;
    }
    if (hi <= lo * (1 + 1e-12)) {
        lo /= 2;
        hi *= 2;
    }
    /* beyond the doubles' range a decade has no 1-2-5 values to round to */
    lo = fmax(lo, 1e-300);
    hi = fmin(hi, 1e300);
    memset(ax, 0, sizeof *ax);
    ax->log = 1;
    ax->lo = one_two_five(lo, 0);
    ax->hi = one_two_five(hi, 1);
    double decades = log10(ax->hi / ax->lo);
    /* 1, 2 and 5 in each decade while they fit, else every k-th power */
    int all = 3 * decades + 1 <= RB_PLOT_MAX_TICKS;
    int every = (int)ceil((decades + 1) / RB_PLOT_MAX_TICKS);
    static const double m[3] = {1, 2, 5};
    for (int e = (int)floor(log10(ax->lo)); e <= (int)ceil(log10(ax->hi)); e++) {
        if (!all && e % (every > 1 ? every : 1) != 0)
            continue;
        for (int i = 0; i < (all ? 3 : 1) && ax->n_ticks < RB_PLOT_MAX_TICKS; i++) {
            double t = m[i] * pow(10, e);
            if (t >= ax->lo * (1 - 1e-9) && t <= ax->hi * (1 + 1e-9))
                ax->ticks[ax->n_ticks++] = t;
        }
    }
}

double rb_axis_frac(const rb_axis *ax, double v)
{
    if (ax->log)
        return log10(v / ax->lo) / log10(ax->hi / ax->lo);
    return (v - ax->lo) / (ax->hi - ax->lo);
}

void rb_axis_label(const rb_axis *ax, double v, char *buf, size_t n)
{
    if (ax->log) {
        snprintf(buf, n, "%g", v);
        return;
    }
    if (fabs(v) < 1e-9 * ax->step)
        v = 0;
    if (fabs(v) >= 1e6 || (v != 0 && ax->step < 1e-6))
        snprintf(buf, n, "%.3g", v);
    else
        snprintf(buf, n, "%.*f", ax->decimals, v);
}

/* Map onto the panel; anything non-finite lands on the axis so that no
 * "nan" can reach the SVG through a coordinate. */
double rb_panel_x(const rb_panel *p, double x)
{
    double v = p->x0 + rb_axis_frac(&p->xa, x) * p->w;
    return isfinite(v) ? v : p->x0;
}

double rb_panel_y(const rb_panel *p, double y)
{
    double v = p->y0 + p->h - rb_axis_frac(&p->ya, y) * p->h;
    return isfinite(v) ? v : p->y0 + p->h;
}

void rb_panel_stacked(rb_panel *p, int k, const rb_axis *xa)
{
    memset(p, 0, sizeof *p);
    p->x0 = RB_STACK_LEFT;
    p->w = RB_STACK_FIG_W - RB_STACK_LEFT - RB_STACK_RIGHT;
    p->y0 = RB_STACK_TOP + k * (RB_STACK_PANEL_H + RB_STACK_PANEL_GAP);
    p->h = RB_STACK_PANEL_H;
    p->xa = *xa;
}

void rb_panel_draw(rb_strbuf *b, const rb_panel *p, const char *y_title,
                   int x_labels, const char *x_title)
{
    char lab[64];
    int i;
    rb_strbuf_puts(b, "<g class=\"grid\" stroke=\"#dddddd\" stroke-width=\"0.6\">\n");
    for (i = 0; i < p->ya.n_ticks; i++) {
        double y = rb_panel_y(p, p->ya.ticks[i]);
        rb_strbuf_printf(b, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\"/>\n",
                       p->x0, y, p->x0 + p->w, y);
    }
    for (i = 0; i < p->xa.n_ticks; i++) {
        double x = rb_panel_x(p, p->xa.ticks[i]);
        rb_strbuf_printf(b, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\"/>\n",
                       x, p->y0, x, p->y0 + p->h);
    }
    rb_strbuf_puts(b, "</g>\n");
    /* zero line: signs matter in every panel */
    if (p->ya.lo < 0 && p->ya.hi > 0)
        rb_strbuf_printf(b, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" "
                       "stroke=\"#999999\" stroke-width=\"0.8\"/>\n",
                       p->x0, rb_panel_y(p, 0), p->x0 + p->w, rb_panel_y(p, 0));
    rb_strbuf_printf(b, "<rect class=\"frame\" x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" "
                   "height=\"%.1f\" fill=\"none\" stroke=\"#333333\" "
                   "stroke-width=\"0.8\"/>\n", p->x0, p->y0, p->w, p->h);
    for (i = 0; i < p->ya.n_ticks; i++) {
        rb_axis_label(&p->ya, p->ya.ticks[i], lab, sizeof lab);
        rb_svg_text(b, p->x0 - 5, rb_panel_y(p, p->ya.ticks[i]) + 4, 11, "end",
                    NULL, lab);
    }
    if (y_title) {
        double cx = p->x0 - 52, cy = p->y0 + p->h / 2;
        rb_strbuf_printf(b, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"12\" "
                       "text-anchor=\"middle\" transform=\"rotate(-90 %.1f %.1f)\">",
                       cx, cy, cx, cy);
        rb_plot_escape(b, y_title);
        rb_strbuf_puts(b, "</text>\n");
    }
    if (!x_labels)
        return;
    for (i = 0; i < p->xa.n_ticks; i++) {
        rb_axis_label(&p->xa, p->xa.ticks[i], lab, sizeof lab);
        rb_svg_text(b, rb_panel_x(p, p->xa.ticks[i]), p->y0 + p->h + 15, 11,
                    "middle", NULL, lab);
    }
    if (x_title)
        rb_svg_text(b, p->x0 + p->w / 2, p->y0 + p->h + 34, 12, "middle", NULL,
                    x_title);
}

void rb_panel_hline(rb_strbuf *b, const rb_panel *p, double y, const char *colour)
{
    double py;
    if (!isfinite(y) || y < p->ya.lo || y > p->ya.hi)
        return;
    py = rb_panel_y(p, y);
    rb_strbuf_printf(b, "<line class=\"ref\" x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" "
                   "y2=\"%.1f\" stroke=\"%s\" stroke-width=\"0.8\" "
                   "stroke-dasharray=\"5 3\"/>\n", p->x0, py, p->x0 + p->w, py, colour);
}

void rb_panel_legend(rb_strbuf *b, const rb_panel *p, const char *const *names,
                     const char *const *colours, int n)
{
    /* right-aligned entries, measured with an average glyph width */
    double x = p->x0 + p->w - 6, y = p->y0 + 13;
    int i;
    for (i = n - 1; i >= 0; i--) {
        double text_w = 6.0 * (double)strlen(names[i]);
        double x_line = x - text_w - 26;
        rb_strbuf_printf(b, "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"14\" "
                       "fill=\"#ffffff\" fill-opacity=\"0.8\"/>\n",
                       x_line - 2, y - 10, text_w + 30);
        rb_strbuf_printf(b, "<line x1=\"%.1f\" y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\" "
                       "stroke=\"%s\" stroke-width=\"2\"/>\n",
                       x_line, y - 4, x_line + 20, y - 4, colours[i]);
        rb_svg_text(b, x_line + 24, y, 11, "start", NULL, names[i]);
        x = x_line - 10;
    }
}

void rb_svg_open(rb_strbuf *b, double width, double height)
{
    rb_strbuf_printf(b, "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" "
                   "width=\"%.0f\" height=\"%.0f\" viewBox=\"0 0 %.0f %.0f\" "
                   "font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n",
                   width, height, width, height);
    rb_strbuf_printf(b, "<rect x=\"0\" y=\"0\" width=\"%.0f\" height=\"%.0f\" "
                   "fill=\"#ffffff\"/>\n", width, height);
}

void rb_svg_close(rb_strbuf *b)
{
    rb_strbuf_puts(b, "</svg>\n");
}

void rb_svg_text(rb_strbuf *b, double x, double y, double size, const char *anchor,
                 const char *weight, const char *s)
{
    rb_strbuf_printf(b, "<text x=\"%.1f\" y=\"%.1f\" font-size=\"%.0f\" "
                   "text-anchor=\"%s\"", x, y, size, anchor);
    if (weight)
        rb_strbuf_printf(b, " font-weight=\"%s\"", weight);
    rb_strbuf_puts(b, ">");
    rb_plot_escape(b, s);
    rb_strbuf_puts(b, "</text>\n");
}
