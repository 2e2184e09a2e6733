/* The fragility figure: for each limit state that could be fitted, the
 * lognormal curve P(limit state | peak floor acceleration) and the
 * motions' capacities at their empirical fractions (censored motions
 * count in the fractions but have no point); a dashed line at the case's
 * own level. The x axis is logarithmic unless asked otherwise: the base
 * lifts off at a hundredth of the level at which the bolts yield, which a
 * linear axis squeezes into its first pixels. */
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
#define PANEL_H 420.0
#define CURVE_POINTS 200

const char *const rb_plot_limit_colours[RB_N_LIMITS] = {"#ff7f0e", "#d62728", "#7f7f7f",
                                                       "#1f77b4", "#2ca02c"};

static int cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

const rb_enum_name rb_plot_scale_names[] = {
    {"log", RB_PLOT_SCALE_LOG}, {"linear", RB_PLOT_SCALE_LINEAR}, {NULL, 0}};

/* The intensities worth drawing, in g: the level, every capacity, and each
 * curve from 1 % to 99 %. */
static void x_range(const rb_case_fragility *f, double *lo, double *hi)
{
    *lo = *hi = f->level_mps2;
    for (size_t m = 0; m < f->n_motions; m++)
        for (int k = 0; k < RB_N_LIMITS; k++) {
            if (!rb_case_fragility_has(f, k))
                continue;
            *lo = fmin(*lo, f->motions[m].capacity_mps2[k]);
            *hi = fmax(*hi, f->motions[m].capacity_mps2[k]);
        }
    for (int k = 0; k < RB_N_LIMITS; k++)
        if (f->fitted[k] && rb_case_fragility_has(f, k)) {
            *lo = fmin(*lo, rb_fragility_quantile(&f->fit[k], 0.01));
            *hi = fmax(*hi, rb_fragility_quantile(&f->fit[k], 0.99));
        }
    *lo /= f->g_mps2;
    *hi /= f->g_mps2;
}

/* A motion's capacity in g and whether it is the model's limit. */
typedef struct {
    double g;
    int model_limited;
} capacity_point;

static int cmp_point(const void *a, const void *b)
{
    return cmp(&((const capacity_point *)a)->g, &((const capacity_point *)b)->g);
}

static void points(rb_strbuf *b, const rb_panel *p, const rb_case_fragility *f, int k,
                   capacity_point *cap)
{
    size_t n = 0;
    for (size_t m = 0; m < f->n_motions; m++)
        if (!f->motions[m].censored[k]) {
            cap[n].g = f->motions[m].capacity_mps2[k] / f->g_mps2;
            cap[n++].model_limited = f->motions[m].model_limited[k];
        }
    qsort(cap, n, sizeof *cap, cmp_point);
    for (size_t i = 0; i < n; i++) {
        /* a capacity that is the model's limit, not the bolts', is drawn
         * hollow: the bolts' own lies above it */
        int limited = cap[i].model_limited;
        rb_strbuf_printf(b, "<circle cx=\"%.2f\" cy=\"%.2f\" r=\"3.5\" fill=\"%s\" ",
                         rb_panel_x(p, cap[i].g), rb_panel_y(p, (i + 0.5) / (double)f->n_motions),
                         limited ? "#ffffff" : rb_plot_limit_colours[k]);
        if (limited)
            rb_strbuf_printf(b, "stroke=\"%s\" stroke-width=\"1.5\" data-model-limited=\"1\" ",
                             rb_plot_limit_colours[k]);
        rb_strbuf_printf(b, "data-limit-state=\"%s\"/>\n", rb_enum_str(rb_limit_state_names, k));
    }
}

rb_status rb_plot_fragility_svg(const rb_case_fragility *f, const char *title,
                                rb_plot_scale x_scale, char **out, rb_diag *diag)
{
    rb_strbuf b = {0};
    rb_panel p;
    memset(&p, 0, sizeof p);
    p.x0 = LEFT, p.y0 = TOP, p.w = FIG_W - LEFT - RIGHT, p.h = PANEL_H;
    double x[CURVE_POINTS], y[CURVE_POINTS];
    capacity_point *cap = malloc((f->n_motions ? f->n_motions : 1) * sizeof *cap);
    const char *names[RB_N_LIMITS];
    char label[RB_N_LIMITS][64];
    const char *cols[RB_N_LIMITS];
    char line[256];
    int n_leg = 0;
    *out = NULL;
    if (!cap || f->n_motions == 0) {
        free(cap);
        if (diag)
            rb_diag_set_msg(diag, "no motions to draw");
        return cap ? RB_ERR_INVALID : RB_ERR_NOMEM;
    }
    double lo, hi;
    x_range(f, &lo, &hi);
    if (x_scale == RB_PLOT_SCALE_LINEAR)
        rb_axis_nice(&p.xa, 0, hi, 10, 1);
    else
        rb_axis_log(&p.xa, lo, hi);
    rb_axis_nice(&p.ya, 0, 1, 5, 1);
    rb_svg_open(&b, FIG_W, TOP + PANEL_H + 80);
    rb_strbuf_printf(&b, "<text x=\"%.1f\" y=\"24\" font-size=\"16\" font-weight=\"bold\">",
                     LEFT);
    rb_plot_escape(&b, title ? title : "Fragility");
    rb_strbuf_puts(&b, "</text>\n");
    snprintf(line, sizeof line, "lognormal fits to %zu motions; points: capacities at "
             "their fractions; dashed: the case's level %.3g g (A* = %.3g g); governs: %s",
             f->n_motions, f->level_mps2 / f->g_mps2, f->a_star_mps2 / f->g_mps2,
             f->governing >= 0 ? rb_enum_str(rb_limit_state_names, f->governing) : "none");
    rb_svg_text(&b, LEFT, 44, 11, "start", NULL, line);
    unsigned limited = 0;
    for (int k = 0; k < RB_N_LIMITS; k++)
        if (f->fitted[k] && rb_case_fragility_model_limited(f, k))
            limited |= 1u << k;
    if (limited) {
        char states[96];
        rb_limit_states_str(limited, states, sizeof states);
        snprintf(line, sizeof line, "hollow: the model's limit (the vertical reaches -g), "
                 "not the bolts', counted as reached: %s are lower bounds", states);
        rb_svg_text(&b, LEFT, 58, 11, "start", NULL, line);
    }
    char im[96], x_title[140];
    rb_fragility_intensity_describe(f, im, sizeof im);
    snprintf(x_title, sizeof x_title, "%s (g)%s", im, p.xa.log ? ", log scale" : "");
    rb_panel_draw(&b, &p, "probability of reaching the limit state (-)", 1, x_title);
    double lx = rb_panel_x(&p, f->level_mps2 / f->g_mps2);
    rb_strbuf_printf(&b, "<line x1=\"%.2f\" y1=\"%.2f\" x2=\"%.2f\" y2=\"%.2f\" "
                     "stroke=\"#555555\" stroke-dasharray=\"4 3\"/>\n", lx, p.y0, lx,
                     p.y0 + p.h);
    for (int k = 0; k < RB_N_LIMITS; k++) {
        if (!f->fitted[k] || !rb_case_fragility_has(f, k))
            continue;
        for (int i = 0; i < CURVE_POINTS; i++) {
            /* evenly spaced along the axis, whichever its scale */
            x[i] = p.xa.log ? p.xa.lo * pow(p.xa.hi / p.xa.lo, i / (CURVE_POINTS - 1.0))
                            : p.xa.hi * (i + 1) / CURVE_POINTS;
            y[i] = rb_fragility_prob(&f->fit[k], x[i] * f->g_mps2);
        }
        rb_series_path(&b, &p, x, y, CURVE_POINTS, 1, rb_plot_limit_colours[k], NULL,
                       rb_enum_str(rb_limit_state_names, k));
        points(&b, &p, f, k, cap);
        names[n_leg] = rb_enum_str(rb_limit_state_names, k);
        if (k == f->governing || (limited >> k) & 1u) {
            snprintf(label[k], sizeof label[k], "%s (%s%s%s)", names[n_leg],
                     k == f->governing ? "governs" : "", k == f->governing
                     && (limited >> k) & 1u ? ", " : "", (limited >> k) & 1u
                     ? "model's limit" : "");
            names[n_leg] = label[k];
        }
        cols[n_leg++] = rb_plot_limit_colours[k];
    }
    rb_panel_legend(&b, &p, names, cols, n_leg);
    rb_svg_close(&b);
    free(cap);
    return rb_plot_finish(&b, out, diag);
}
