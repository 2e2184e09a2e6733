/* The fragility against the gap ratio: on top each limit state's
 * probability at the case's level, below its median on a log axis (the
 * states lie a few hundred times apart), the case's level dashed across
 * it. A state that could not be fitted at a ratio breaks its curves there. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "plot_internal.h"
#include "rockbolt/names.h"

#define FIG_W RB_STACK_FIG_W
#define LEFT RB_STACK_LEFT
#define PANEL_H RB_STACK_PANEL_H

/* Limit state k's probability at the level (median = 0) or its median in
 * g (median = 1) at each point; NaN where it is not fitted. */
static void column(const rb_fragility_sweep *s, int k, int median, double *y)
{
    for (size_t i = 0; i < s->n_points; i++) {
        const rb_case_fragility *f = &s->points[i];
        y[i] = !f->fitted[k] ? (double)NAN
               : median ? f->fit[k].median / f->g_mps2 : f->p_at_level[k];
    }
}

static void marks(rb_strbuf *b, const rb_panel *p, const double *x, const double *y,
                  size_t n, int k)
{
    for (size_t i = 0; i < n; i++)
        if (isfinite(y[i]))
            rb_strbuf_printf(b, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"3\" fill=\"%s\" "
                             "data-limit-state=\"%s\"/>\n", rb_panel_x(p, x[i]),
                             rb_panel_y(p, y[i]), rb_plot_limit_colours[k],
                             rb_enum_str(rb_limit_state_names, k));
}

rb_status rb_plot_fragility_sweep_svg(const rb_fragility_sweep *s, const char *title,
                                      char **out, rb_diag *diag)
{
    rb_strbuf b = {0};
    rb_panel p[2];
    rb_axis xa;
    char line[256];
    *out = NULL;
    if (!s || s->n_points == 0) {
        if (diag)
            rb_diag_set_msg(diag, "the sweep has no points to draw");
        return RB_ERR_INVALID;
    }
    size_t n = s->n_points;
    const rb_case_fragility *f0 = &s->points[0];
    double g = f0->g_mps2, level_g = f0->level_mps2 / g;
    double *y = malloc(n * sizeof *y);
    if (!y) {
        b.oom = 1;
        return rb_plot_finish(&b, out, diag);
    }
    double xlo = 0, xhi = 0, mlo = level_g, mhi = level_g;
    rb_series_range(s->gap_ratios, n, 1, &xlo, &xhi);
    rb_axis_nice(&xa, xlo, xhi, 10, 1);
    for (int k = 0; k < RB_N_LIMITS; k++) {
        double a, c;
        column(s, k, 1, y);
        if (rb_series_range(y, n, 1, &a, &c)) {
            mlo = fmin(mlo, a);
            mhi = fmax(mhi, c);
        }
    }
    rb_panel_stacked(&p[0], 0, &xa);
    rb_axis_nice(&p[0].ya, 0, 1, 5, 1);
    rb_panel_stacked(&p[1], 1, &xa);
    rb_axis_log(&p[1].ya, mlo, mhi);
    double bottom = p[1].y0 + PANEL_H;

    rb_svg_open(&b, FIG_W, bottom + 72);
    rb_strbuf_printf(&b, "<text x=\"%.1f\" y=\"24\" font-size=\"16\" font-weight=\"bold\">",
                     LEFT);
    rb_plot_escape(&b, title ? title : "Fragility against the gap ratio");
    rb_strbuf_puts(&b, "</text>\n");
    int sa = f0->intensity == RB_IM_SA;
    if (sa)
        snprintf(line, sizeof line, "lognormal fits to %zu motions at each gap ratio, in "
                 "the %g %% Sa at %.3g Hz; dashed: the case's level %.3g g", f0->n_motions,
                 100 * f0->im_damping, f0->im_freq_hz, level_g);
    else
        snprintf(line, sizeof line, "lognormal fits to %zu motions at each gap ratio; "
                 "dashed: the case's level %.3g g (%.3g A*)", f0->n_motions, level_g,
                 f0->level_mps2 / f0->a_star_mps2);
    rb_svg_text(&b, LEFT, 44, 11, "start", NULL, line);
    rb_panel_draw(&b, &p[0], "P at the case's level (-)", 0, NULL);
    rb_panel_draw(&b, &p[1], sa ? "median Sa(f0) (g), log scale" : "median (g), log scale",
                  1, "gap ratio g0 / l (-)");
    rb_panel_hline(&b, &p[1], level_g, "#555555");
    const char *names[RB_N_LIMITS], *cols[RB_N_LIMITS];
    int n_leg = 0;
    for (int k = 0; k < RB_N_LIMITS; k++) {
        char series[64];
        if (!rb_case_fragility_has(f0, k))
            continue;
        const char *name = rb_enum_str(rb_limit_state_names, k);
        int drawn = 0;
        for (int median = 0; median < 2; median++) {
            column(s, k, median, y);
            snprintf(series, sizeof series, "%s_%s", name, median ? "median" : "p");
            rb_series_path(&b, &p[median], s->gap_ratios, y, n, 1, rb_plot_limit_colours[k],
                           NULL, series);
            marks(&b, &p[median], s->gap_ratios, y, n, k);
            for (size_t i = 0; i < n; i++)
                drawn |= isfinite(y[i]);
        }
        if (drawn) {
            names[n_leg] = name;
            cols[n_leg++] = rb_plot_limit_colours[k];
        }
    }
    /* under the axis title: inside a panel it would hide a curve, whichever
     * corner it took */
    rb_panel key = p[1];
    key.y0 = bottom + 44;
    rb_panel_legend(&b, &key, names, cols, n_leg);
    rb_svg_close(&b);
    free(y);
    return rb_plot_finish(&b, out, diag);
}
