/* Hysteresis figure of one solved motion: each bolt row's force against its
 * elongation, and the bolts' overturning moment about the pivot against the
 * base rotation, drawn from the time history. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "plot_internal.h"

#define FIG_W 1000.0
#define LEFT 100.0
#define TOP 64.0
#define PANEL_W 370.0
#define PANEL_H 300.0
#define PANEL_GAP 110.0
#define MAX_POINTS 6000   /* per curve; longer histories are strided */

/* Vertical travel of the plate at a bolt row, and the row's lever arm, at
 * rotation th (> 0 loads that row): as the solver takes them. */
static double chord(int small, double l, double th)
{
    return small ? l * th : 2 * l * sin(th / 2);
}

static double lever(int small, double l, double th)
{
    return small ? l : l * cos(th / 2);
}

/* One <path> of the points (x[i], y[i]) of panel p, every stride-th row,
 * broken at non-finite points. Not decimated by columns: a loop's x goes
 * back and forth. */
static void curve(rb_strbuf *b, const rb_panel *p, const double *x, const double *y,
                  size_t n, const char *colour, const char *dash, const char *name)
{
    size_t stride = n > MAX_POINTS ? (n + MAX_POINTS - 1) / MAX_POINTS : 1, i;
    int pen = 0;
    rb_strbuf_printf(b, "<path data-series=\"%s\" fill=\"none\" stroke=\"%s\" "
                   "stroke-width=\"1.1\"%s%s%s d=\"", name, colour,
                   dash ? " stroke-dasharray=\"" : "", dash ? dash : "", dash ? "\"" : "");
    for (i = 0; i < n; i += stride) {
        if (!isfinite(x[i]) || !isfinite(y[i])) {
            pen = 0;
            continue;
        }
        rb_strbuf_printf(b, "%s%.1f,%.1f", pen ? " L" : (i ? " M" : "M"),
                         rb_panel_x(p, x[i]), rb_panel_y(p, y[i]));
        pen = 1;
    }
    rb_strbuf_puts(b, "\"/>\n");
}

static void range2(const double *a, const double *c, size_t n, double *lo, double *hi)
{
    double l1, h1, l2, h2;
    int ha = rb_series_range(a, n, 1, &l1, &h1), hc = c && rb_series_range(c, n, 1, &l2, &h2);
    *lo = 0;
    *hi = 0;
    if (ha) {
        *lo = fmin(*lo, l1);
        *hi = fmax(*hi, h1);
    }
    if (hc) {
        *lo = fmin(*lo, l2);
        *hi = fmax(*hi, h2);
    }
}

static void set_panel(rb_panel *p, int k, double xlo, double xhi, double ylo, double yhi)
{
    p->x0 = LEFT + k * (PANEL_W + PANEL_GAP);
    p->y0 = TOP;
    p->w = PANEL_W;
    p->h = PANEL_H;
    rb_axis_nice(&p->xa, xlo - 0.01 * (xhi - xlo), xhi + 0.01 * (xhi - xlo), 6, 1);
    rb_axis_nice(&p->ya, ylo - 0.01 * (yhi - ylo), yhi + 0.01 * (yhi - ylo), 6, 1);
}

rb_status rb_plot_hysteresis_svg(const rb_report *rep, size_t motion_index,
                                 char **out, rb_diag *diag)
{
    const rb_report_motion *rm;
    const rb_history *h;
    const rb_model *m;
    const rb_out_units *u;
    rb_strbuf b = {0};
    rb_panel p[2];
    double *el[2] = {NULL, NULL}, *fr[2] = {NULL, NULL}, *mom = NULL, *rot = NULL;
    double lo, hi, ylo, yhi;
    size_t i, n;
    int small, s;
    char title[320], xt[64], yt[64];
    *out = NULL;
    if (!rep || !rep->kase || motion_index >= rep->n_motions
        || !rep->motions[motion_index].result
        || !(h = rep->motions[motion_index].result->history) || h->n < 2) {
        if (diag)
            rb_diag_set_msg(diag, "motion %zu: no time history of two "
                            "rows or more to draw", motion_index + 1);
        return RB_ERR_INVALID;
    }
    rm = &rep->motions[motion_index];
    m = &rep->kase->model;
    u = rb_out_units_of(rep->kase->output_units);
    small = rep->kase->solve.formulation == RB_FORM_SMALL;
    n = h->n;
    for (s = 0; s < 2; s++) {
        el[s] = malloc(n * sizeof *el[s]);
        fr[s] = malloc(n * sizeof *fr[s]);
    }
    mom = malloc(n * sizeof *mom);
    rot = malloc(n * sizeof *rot);
    if (!el[0] || !el[1] || !fr[0] || !fr[1] || !mom || !rot) {
        b.oom = 1;
        goto done;
    }
    for (i = 0; i < n; i++) {
        double th = h->theta[i], fl = h->bolt_force_left[i], fR = h->bolt_force_right[i];
        /* theta > 0 lifts the right row, theta < 0 the left one; the
         * elongation is the plate's travel at the row past the initial gap
         * (negative, down to -gap on the floor: the bolt is slack) */
        el[RB_RIGHT][i] = (fmax(chord(small, m->lever_arm_m, th), 0) - m->gap_m)
                          / u->small_length_f;
        el[RB_LEFT][i] = (fmax(chord(small, m->lever_arm_m, -th), 0) - m->gap_m)
                         / u->small_length_f;
        fr[RB_LEFT][i] = fl / u->force_f;
        fr[RB_RIGHT][i] = fR / u->force_f;
        /* the bolts' moment about the pivot, positive against theta > 0 */
        mom[i] = (fR * lever(small, m->lever_arm_m, fabs(th)) * (th > 0)
                  - fl * lever(small, m->lever_arm_m, fabs(th)) * (th < 0))
                 / (u->force_f * u->length_f);
        rot[i] = th * 1e3;
    }
    range2(el[0], el[1], n, &lo, &hi);
    range2(fr[0], fr[1], n, &ylo, &yhi);
    set_panel(&p[0], 0, lo, hi, ylo, yhi);
    range2(rot, NULL, n, &lo, &hi);
    range2(mom, NULL, n, &ylo, &yhi);
    set_panel(&p[1], 1, lo, hi, ylo, yhi);

    rb_svg_open(&b, FIG_W, TOP + PANEL_H + 70);
    snprintf(title, sizeof title, "%.120s \xe2\x80\x94 %.120s: hysteresis",
             rep->kase->name ? rep->kase->name : "case",
             rm->motion && rm->motion->name ? rm->motion->name : "motion");
    rb_svg_text(&b, LEFT, 24, 16, "start", "bold", title);
    rb_svg_text(&b, LEFT, 44, 11, "start", NULL,
                "bolt row force against elongation (plate travel at the row past "
                "the initial gap); bolts' moment about the pivot against rotation");
    snprintf(xt, sizeof xt, "elongation (%s)", u->small_length);
    snprintf(yt, sizeof yt, "bolt row force (%s)", u->force);
    rb_panel_draw(&b, &p[0], yt, 1, xt);
    curve(&b, &p[0], el[RB_LEFT], fr[RB_LEFT], n, "#1f77b4", NULL, "force_left");
    curve(&b, &p[0], el[RB_RIGHT], fr[RB_RIGHT], n, "#d62728", "5 3", "force_right");
    {
        static const char *const names[2] = { "left row", "right row" };
        static const char *const colours[2] = { "#1f77b4", "#d62728" };
        rb_panel_legend(&b, &p[0], names, colours, 2);
    }
    snprintf(yt, sizeof yt, "overturning moment of the bolts (%s-%s)", u->force, u->length);
    rb_panel_draw(&b, &p[1], yt, 1, "rotation \xce\xb8 (mrad)");
    curve(&b, &p[1], rot, mom, n, "#9467bd", NULL, "moment");
    rb_svg_close(&b);
done:
    for (s = 0; s < 2; s++) {
        free(el[s]);
        free(fr[s]);
    }
    free(mom);
    free(rot);
    return rb_plot_finish(&b, out, diag);
}
