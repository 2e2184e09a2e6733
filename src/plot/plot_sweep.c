/* The response curve of a sweep, after the thesis's Figs. 5.23 to 6.4:
 * peak frame deflection and peak bolt force against the frequency ratio or
 * the level, yield marked o and failure x at each point. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "plot_internal.h"

#define FIG_W RB_STACK_FIG_W
#define LEFT RB_STACK_LEFT
#define PANEL_H RB_STACK_PANEL_H

/* The y values of one series, NaN where the point has no result, so that
 * rb_series_path breaks the curve there. */
static double *column(const rb_sweep *s, int which)
{
    double *v = malloc(s->n_points * sizeof *v);
    size_t i;
    if (!v)
        return NULL;
    for (i = 0; i < s->n_points; i++) {
        const rb_sweep_point *p = &s->points[i];
        double y = which < 0 ? p->max_u_over_ustatic : p->max_force_over_fy[which];
        v[i] = p->status == RB_OK ? y : nan("");
    }
    return v;
}

/* row < 0: either row (the deflection curve); else that row's curve. */
static int yielded(const rb_sweep_point *p, int row)
{
    return row < 0 ? p->yielded[RB_LEFT] || p->yielded[RB_RIGHT] : p->yielded[row];
}

static int failed(const rb_sweep_point *p, int row)
{
    if (p->overturned)
        return 1;
    return row < 0 ? p->broken[RB_LEFT] || p->broken[RB_RIGHT] : p->broken[row];
}

/* A mark at every point with a result: x where it failed (it also yielded,
 * and the x says more), o where it yielded, a dot otherwise. */
static void draw_marks(rb_strbuf *b, const rb_panel *p, const rb_sweep *s,
                       const double *x, const double *y, int row)
{
    size_t i;
    for (i = 0; i < s->n_points; i++) {
        const rb_sweep_point *pt = &s->points[i];
        double px, py;
        if (pt->status != RB_OK || !isfinite(y[i]) || !isfinite(x[i]))
            continue;
        px = rb_panel_x(p, x[i]);
        py = rb_panel_y(p, y[i]);
        if (failed(pt, row))
            rb_strbuf_printf(b, "<g class=\"mark-fail\" stroke=\"#b00000\" "
                           "stroke-width=\"1.6\"><line x1=\"%.1f\" y1=\"%.1f\" "
                           "x2=\"%.1f\" y2=\"%.1f\"/><line x1=\"%.1f\" y1=\"%.1f\" "
                           "x2=\"%.1f\" y2=\"%.1f\"/></g>\n", px - 4, py - 4, px + 4,
                           py + 4, px - 4, py + 4, px + 4, py - 4);
        else if (yielded(pt, row))
            rb_strbuf_printf(b, "<circle class=\"mark-yield\" cx=\"%.1f\" cy=\"%.1f\" "
                           "r=\"4\" fill=\"none\" stroke=\"#c98a00\" "
                           "stroke-width=\"1.6\"/>\n", px, py);
        else
            rb_strbuf_printf(b, "<circle class=\"mark-point\" cx=\"%.1f\" cy=\"%.1f\" "
                           "r=\"1.8\" fill=\"#333333\"/>\n", px, py);
    }
}

static void layout(rb_panel *p, int k, const rb_axis *xa, const double *const *ys,
                   int n_ys, size_t n, double must_hi)
{
    double lo = 0, hi = must_hi, a, c;
    int i;
    rb_panel_stacked(p, k, xa);
    for (i = 0; i < n_ys; i++)
        if (rb_series_range(ys[i], n, 1, &a, &c)) {
            lo = fmin(lo, a);
            hi = fmax(hi, c);
        }
    rb_axis_nice(&p->ya, lo, hi + 0.01 * (hi - lo), 5, 1);
}

/* An amplitude sweep's levels in g as well as A*: the ticks of the level
 * axis labelled in g along the top of the upper panel. */
static void draw_g_axis(rb_strbuf *b, const rb_panel *p, double a_star_mps2)
{
    double f = a_star_mps2 / RB_G0;
    char lab[64];
    int i;
    if (!(f > 0) || !isfinite(f))
        return;
    rb_svg_text(b, p->x0 - 16, p->y0 - 6, 11, "end", NULL, "a (g)");
    for (i = 0; i < p->xa.n_ticks; i++) {
        double g = p->xa.ticks[i] * f;
        snprintf(lab, sizeof lab, "%.3g", fabs(g) < 1e-12 ? 0.0 : g);
        rb_strbuf_printf(b, "<text class=\"g-tick\" x=\"%.1f\" y=\"%.1f\" "
                       "font-size=\"11\" text-anchor=\"middle\">%s</text>\n",
                       rb_panel_x(p, p->xa.ticks[i]), p->y0 - 6, lab);
    }
}

static void draw_key(rb_strbuf *b, double y)
{
    rb_strbuf_printf(b, "<circle cx=\"%.1f\" cy=\"%.1f\" r=\"4\" fill=\"none\" "
                   "stroke=\"#c98a00\" stroke-width=\"1.6\"/>\n", LEFT + 4, y - 4);
    rb_svg_text(b, LEFT + 14, y, 11, "start", NULL, "a bolt row yielded");
    rb_strbuf_printf(b, "<g stroke=\"#b00000\" stroke-width=\"1.6\"><line x1=\"%.1f\" "
                   "y1=\"%.1f\" x2=\"%.1f\" y2=\"%.1f\"/><line x1=\"%.1f\" y1=\"%.1f\" "
                   "x2=\"%.1f\" y2=\"%.1f\"/></g>\n", LEFT + 140, y - 8, LEFT + 148,
                   y, LEFT + 140, y, LEFT + 148, y - 8);
    rb_svg_text(b, LEFT + 156, y, 11, "start", NULL,
                "failed: a bolt row broke or the body overturned");
}

rb_status rb_plot_sweep_svg(const rb_sweep *s, const char *title, char **out,
                            rb_diag *diag)
{
    rb_strbuf b = {0};
    double *x = NULL, *u = NULL, *fl = NULL, *fr = NULL, bottom;
    rb_axis xa;
    rb_panel p[2];
    size_t i, missing = 0;
    char line[256];
    rb_status st;
    *out = NULL;
    if (!s || s->n_points == 0 || !s->points) {
        if (diag)
            rb_diag_set_msg(diag, "the sweep has no points to draw");
        return RB_ERR_INVALID;
    }
    x = malloc(s->n_points * sizeof *x);
    u = column(s, -1);
    fl = column(s, RB_LEFT);
    fr = column(s, RB_RIGHT);
    if (!x || !u || !fl || !fr) {
        b.oom = 1;
        goto done;
    }
    for (i = 0; i < s->n_points; i++) {
        x[i] = s->points[i].x;
        missing += s->points[i].status != RB_OK;
    }
    {
        double lo = 0, hi = 0;
        if (!rb_series_range(x, s->n_points, 1, &lo, &hi))
            lo = hi = 0;
        rb_axis_nice(&xa, lo, hi, 10, 1);
    }
    {
        const double *ys_u[1] = { u }, *ys_f[2] = { fl, fr };
        layout(&p[0], 0, &xa, ys_u, 1, s->n_points, 1);
        layout(&p[1], 1, &xa, ys_f, 2, s->n_points, 1.1);
    }
    bottom = p[1].y0 + PANEL_H;

    rb_svg_open(&b, FIG_W, bottom + 90);
    rb_strbuf_printf(&b, "<text x=\"%.1f\" y=\"24\" font-size=\"16\" "
                   "font-weight=\"bold\">", LEFT);
    rb_plot_escape(&b, title ? title : s->kind == RB_SWEEP_FREQUENCY
                   ? "Frequency response" : "Amplitude response");
    rb_strbuf_puts(&b, "</text>\n");
    /* an upstream NaN must not reach the text as "nan" */
    if (!isfinite(s->amplitude_astar) || !isfinite(s->fixed_base_hz)
        || !isfinite(s->a_star_mps2))
        snprintf(line, sizeof line, "%s", s->kind == RB_SWEEP_FREQUENCY
                 ? "harmonic floor motion" : "the motion's shape scaled to each level");
    else if (s->kind == RB_SWEEP_FREQUENCY)
        snprintf(line, sizeof line, "harmonic floor motion of peak %.3g A*; "
                 "fixed-base frequency f0 = %.3g Hz; A* = %.3g g",
                 s->amplitude_astar, s->fixed_base_hz, s->a_star_mps2 / RB_G0);
    else
        snprintf(line, sizeof line, "the motion's shape scaled to each level; "
                 "A* = %.3g g", s->a_star_mps2 / RB_G0);
    rb_svg_text(&b, LEFT, 44, 11, "start", NULL, line);

    rb_panel_draw(&b, &p[0], "peak U / U_static (-)", 0, NULL);
    if (s->kind == RB_SWEEP_AMPLITUDE)
        draw_g_axis(&b, &p[0], s->a_star_mps2);
    rb_series_path(&b, &p[0], x, u, s->n_points, 1, "#2ca02c", NULL, "u_over_ustatic");
    draw_marks(&b, &p[0], s, x, u, -1);

    rb_panel_draw(&b, &p[1], "peak bolt force / Fy (-)", 1,
                  s->kind == RB_SWEEP_FREQUENCY
                  ? "excitation frequency / fixed-base frequency, f / f0 (-)"
                  : "peak floor acceleration a / A* (-); in g along the top");
    rb_panel_hline(&b, &p[1], 1, "#777777");
    rb_series_path(&b, &p[1], x, fl, s->n_points, 1, "#1f77b4", NULL, "force_left");
    rb_series_path(&b, &p[1], x, fr, s->n_points, 1, "#d62728", "5 3", "force_right");
    draw_marks(&b, &p[1], s, x, fl, RB_LEFT);
    draw_marks(&b, &p[1], s, x, fr, RB_RIGHT);
    {
        static const char *const names[2] = { "left row", "right row" };
        static const char *const colours[2] = { "#1f77b4", "#d62728" };
        rb_panel_legend(&b, &p[1], names, colours, 2);
    }
    draw_key(&b, bottom + 58);
    if (missing) {
        snprintf(line, sizeof line, "%zu of %zu points have no result (solver "
                 "error); the curves are broken there", missing, s->n_points);
        rb_svg_text(&b, LEFT, bottom + 78, 11, "start", NULL, line);
    }
    rb_svg_close(&b);
done:
    free(x);
    free(u);
    free(fl);
    free(fr);
    st = rb_plot_finish(&b, out, diag);
    return st;
}
