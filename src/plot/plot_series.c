/* Series as SVG paths. A 30 s record sampled at 5 ms has 6000 rows per
 * series, many more than the figure has pixel columns, so long series keep
 * only the extremes of each column: the drawn envelope is then the same as
 * with every point, at a fraction of the size. */
#include <math.h>
#include <stdio.h>
#include "plot_internal.h"

typedef struct {
    rb_strbuf *b;
    const rb_panel *p;
    int pen_down;        /* 0: the next point starts a subpath */
    size_t count;        /* points written */
} path_state;

/* Pairs after a moveto are implicit linetos, so only subpaths need a
 * command letter. A newline every few points keeps the file greppable. */
static void emit(path_state *s, double x, double y)
{
    double px = rb_panel_x(s->p, x), py = rb_panel_y(s->p, y);
    const char *sep = s->count == 0 ? "" : s->count % 12 == 0 ? "\n" : " ";
    rb_strbuf_printf(s->b, "%s%s%.1f,%.1f", sep, s->pen_down ? "" : "M", px, py);
    s->pen_down = 1;
    s->count++;
}

int rb_series_range(const double *y, size_t n, double scale, double *lo, double *hi)
{
    size_t i;
    int any = 0;
    for (i = 0; i < n; i++) {
        double v = scale * y[i];
        if (!isfinite(v))
            continue;
        if (!any || v < *lo)
            *lo = v;
        if (!any || v > *hi)
            *hi = v;
        any = 1;
    }
    return any;
}

/* Columns of half a pixel: two extremes per column keep the envelope. */
static size_t column_of(const rb_panel *p, double x, size_t n_cols)
{
    double f = rb_axis_frac(&p->xa, x);
    double c = floor(f * (double)n_cols);
    if (!(c >= 0))
        return 0;
    if (c >= (double)n_cols)
        return n_cols - 1;
    return (size_t)c;
}

void rb_series_path(rb_strbuf *b, const rb_panel *p, const double *x,
                    const double *y, size_t n, double scale,
                    const char *colour, const char *dash, const char *name)
{
    path_state s = { b, p, 0, 0 };
    size_t n_cols = (size_t)(p->w > 1 ? p->w : 1);
    size_t i = 0;
    rb_strbuf_puts(b, "<path class=\"series\" data-series=\"");
    rb_plot_escape(b, name);
    rb_strbuf_printf(b, "\" fill=\"none\" stroke=\"%s\" stroke-width=\"1.1\" "
                   "stroke-linejoin=\"round\"", colour);
    if (dash)
        rb_strbuf_printf(b, " stroke-dasharray=\"%s\"", dash);
    rb_strbuf_puts(b, " d=\"");
    if (n <= 2 * n_cols) {
        for (i = 0; i < n; i++) {
            double v = scale * y[i];
            if (isfinite(v) && isfinite(x[i]))
                emit(&s, x[i], v);
            else
                s.pen_down = 0;
        }
    }
    while (i < n) {
        /* one pixel column: its first point's column decides the extent */
        size_t col = column_of(p, x[i], n_cols), imin = i, imax = i, j = i;
        int finite = 1;
        for (; j < n && column_of(p, x[j], n_cols) == col; j++) {
            double v = scale * y[j];
            if (!isfinite(v) || !isfinite(x[j])) {
                finite = 0;
                break;
            }
            if (v < scale * y[imin])
                imin = j;
            if (v > scale * y[imax])
                imax = j;
        }
        if (j > i) {
            size_t a = imin < imax ? imin : imax, c = imin < imax ? imax : imin;
            emit(&s, x[a], scale * y[a]);
            if (c != a)
                emit(&s, x[c], scale * y[c]);
        }
        if (!finite) {
            s.pen_down = 0;
            j++;            /* skip the bad point */
        }
        i = j;
    }
    rb_strbuf_puts(b, "\"/>\n");
}
