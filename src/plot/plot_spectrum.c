/* The response spectra figure: each motion's absolute acceleration
 * spectrum against frequency on a logarithmic axis, with each target drawn
 * over them, and its band (lower and upper multiples) dashed over the
 * frequencies where a motion must stay within it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "plot_internal.h"
#include "rockbolt/names.h"

#define FIG_W 900.0
#define LEFT 100.0
#define RIGHT 32.0
#define TOP 70.0
#define PANEL_H 440.0
#define TARGET_POINTS 200
#define MAX_LEGEND 8

static const char *const palette[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728",
                                      "#9467bd", "#8c564b", "#e377c2", "#7f7f7f",
                                      "#bcbd22", "#17becf"};
#define N_PALETTE (sizeof palette / sizeof palette[0])

/* The distinct targets of the case's motions, at most n. */
static size_t targets_of(const rb_case *c, const rb_case_spectra *s, const rb_target **t,
                         size_t n)
{
    size_t k = 0;
    for (size_t m = 0; m < s->n_motions; m++) {
        const rb_target *x = s->motions[m].has_target ? c->motions[m].target : NULL;
        size_t j = 0;
        while (x && j < k && t[j] != x)
            j++;
        if (x && j == k && k < n)
            t[k++] = x;
    }
    return k;
}

static void draw_target(rb_strbuf *b, const rb_panel *p, const rb_target *t, double g,
                        double f_lo, double f_hi)
{
    double x[TARGET_POINTS], y[TARGET_POINTS];
    for (int i = 0; i < TARGET_POINTS; i++) {
        x[i] = f_lo * pow(f_hi / f_lo, (double)i / (TARGET_POINTS - 1));
        y[i] = rb_target_at(t, x[i]) / g;
    }
    rb_series_path(b, p, x, y, TARGET_POINTS, 1, "#000000", NULL, "target");
    double a = fmax(f_lo, t->check_from_hz), z = fmin(f_hi, t->check_to_hz);
    if (!(z > a))
        return;
    for (int i = 0; i < TARGET_POINTS; i++) {
        x[i] = a * pow(z / a, (double)i / (TARGET_POINTS - 1));
        y[i] = rb_target_at(t, x[i]) / g;
    }
    rb_series_path(b, p, x, y, TARGET_POINTS, t->band_lower, "#555555", "5 3",
                   "band lower");
    rb_series_path(b, p, x, y, TARGET_POINTS, t->band_upper, "#555555", "5 3",
                   "band upper");
}

rb_status rb_plot_spectra_svg(const rb_case *c, const rb_case_spectra *s, const char *title,
                              char **out, rb_diag *diag)
{
    rb_strbuf b = {0};
    rb_panel p;
    const rb_target *targets[8];
    char line[256];
    *out = NULL;
    if (s->n_motions == 0 || s->motions[0].sp.n < 2) {
        if (diag)
            rb_diag_set_msg(diag, "no spectra to draw");
        return RB_ERR_INVALID;
    }
    const rb_spectrum *sp0 = &s->motions[0].sp;
    double f_lo = sp0->freq_hz[0], f_hi = sp0->freq_hz[sp0->n - 1], g = s->g_mps2;
    size_t nt = targets_of(c, s, targets, 8);
    double top = 0;
    for (size_t m = 0; m < s->n_motions; m++)
        for (size_t i = 0; i < s->motions[m].sp.n; i++)
            top = fmax(top, s->motions[m].sp.sa_mps2[i] / g);
    for (size_t k = 0; k < nt; k++)
        for (int i = 0; i < TARGET_POINTS; i++)
            top = fmax(top, targets[k]->band_upper
                                * rb_target_at(targets[k], f_lo * pow(f_hi / f_lo,
                                               (double)i / (TARGET_POINTS - 1))) / g);
    memset(&p, 0, sizeof p);
    p.x0 = LEFT, p.y0 = TOP, p.w = FIG_W - LEFT - RIGHT, p.h = PANEL_H;
    rb_axis_log(&p.xa, f_lo, f_hi);
    rb_axis_nice(&p.ya, 0, top, 8, 1);
    rb_svg_open(&b, FIG_W, TOP + PANEL_H + 80);
    rb_strbuf_printf(&b, "<text x=\"%.1f\" y=\"24\" font-size=\"16\" font-weight=\"bold\">",
                     LEFT);
    rb_plot_escape(&b, title ? title : "Response spectra");
    rb_strbuf_puts(&b, "</text>\n");
    snprintf(line, sizeof line, "absolute acceleration, %g %% damping, %zu motion%s%s",
             100 * s->opts.damping, s->n_motions, s->n_motions == 1 ? "" : "s",
             nt ? "; black: target, dashed: its band where it is checked" : "");
    rb_svg_text(&b, LEFT, 44, 11, "start", NULL, line);
    rb_panel_draw(&b, &p, "spectral acceleration (g)", 1, "frequency (Hz), log scale");
    const char *names[MAX_LEGEND + 1], *cols[MAX_LEGEND + 1];
    int n_leg = 0;
    for (size_t m = 0; m < s->n_motions; m++) {
        const rb_spectrum *sp = &s->motions[m].sp;
        const char *col = palette[m % N_PALETTE];
        rb_series_path(&b, &p, sp->freq_hz, sp->sa_mps2, sp->n, 1.0 / g,
                       col, NULL, c->motions[m].name ? c->motions[m].name : "motion");
        if (n_leg < MAX_LEGEND && s->n_motions <= MAX_LEGEND) {
            names[n_leg] = c->motions[m].name ? c->motions[m].name : "motion";
            cols[n_leg++] = col;
        }
    }
    for (size_t k = 0; k < nt; k++)
        draw_target(&b, &p, targets[k], g, f_lo, f_hi);
    if (nt && n_leg < MAX_LEGEND + 1) {
        names[n_leg] = "target";
        cols[n_leg++] = "#000000";
    }
    rb_panel_legend(&b, &p, names, cols, n_leg);
    rb_svg_close(&b);
    return rb_plot_finish(&b, out, diag);
}
