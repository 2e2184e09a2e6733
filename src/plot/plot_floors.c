/* rockbolt motion's figure: for every component matched to a target, its
 * test response spectrum on the acceptance grid against the required one,
 * with the lower line and the guide line dashed between the cutoffs, one
 * panel each, stacked on one frequency axis. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "plot_internal.h"
#include "rockbolt/names.h"

#define TARGET_POINTS 200

int rb_plot_floors_has_figure(const rb_case_floors *f)
{
    for (size_t m = 0; m < f->n_motions; m++)
        for (int a = 0; a < RB_FLOOR_AXES; a++)
            if (f->motions[m].axis[a].target && f->motions[m].axis[a].trs.n >= 2)
                return 1;
    return 0;
}

/* y = scale x RRS(x) over [lo, hi] as one path */
static void rrs_path(rb_strbuf *b, const rb_panel *p, const rb_target *t, double lo,
                     double hi, double scale, double g, const char *dash, const char *name)
{
    double x[TARGET_POINTS], y[TARGET_POINTS];
    for (int i = 0; i < TARGET_POINTS; i++) {
        x[i] = lo * pow(hi / lo, (double)i / (TARGET_POINTS - 1));
        y[i] = rb_target_at(t, x[i]) / g;
    }
    rb_series_path(b, p, x, y, TARGET_POINTS, scale, dash ? "#555555" : "#000000", dash,
                   name);
}

static void panel(rb_strbuf *b, const rb_panel *p, const rb_floor_component *fc,
                  const char *label, double g, int last)
{
    const rb_spectrum *sp = &fc->trs;
    const rb_accept_rules *r = &fc->rules;
    const rb_accept_result *ac = &fc->sum.accept;
    char line[300];
    snprintf(line, sizeof line, "%s: TRS / RRS %.3f to %.3f, least margin %.3f at offset "
             "%u of %d: %s", label, ac->min_ratio, ac->max_ratio, ac->margin, ac->worst,
             RB_ACCEPT_OFFSETS, ac->pass ? "accepted at every offset"
                                         : "NOT accepted at every offset");
    rb_svg_text(b, p->x0, p->y0 - 6, 11, "start", "bold", line);
    rb_panel_draw(b, p, "spectral acceleration (g)", last,
                  last ? "frequency (Hz), log scale" : NULL);
    double lo = p->xa.lo, hi = p->xa.hi;
    rrs_path(b, p, fc->target, lo, hi, 1.0, g, NULL, "RRS");
    double a = fmax(lo, r->low_cutoff_hz), z = fmin(hi, r->high_cutoff_hz);
    if (z > a) {
        rrs_path(b, p, fc->target, a, z, r->lower, g, "5 3", "lower line");
        rrs_path(b, p, fc->target, a, z, r->guide, g, "5 3", "guide line");
    }
    rb_series_path(b, p, sp->freq_hz, sp->sa_mps2, sp->n, 1.0 / g, "#1f77b4", NULL, "TRS");
    static const char *const names[2] = {"TRS", "RRS"};
    static const char *const cols[2] = {"#1f77b4", "#000000"};
    rb_panel_legend(b, p, names, cols, 2);
}

rb_status rb_plot_floors_svg(const rb_case *c, const rb_case_floors *f, const char *title,
                             char **out, rb_diag *diag)
{
    rb_strbuf b = {0};
    double g = f->g_mps2, lo = INFINITY, hi = 0;
    int n = 0;
    *out = NULL;
    if (!rb_plot_floors_has_figure(f)) {
        if (diag)
            rb_diag_set_msg(diag, "no motion of the case has a target "
                            "spectrum to draw its TRS against");
        return RB_ERR_INVALID;
    }
    for (size_t m = 0; m < f->n_motions; m++)
        for (int a = 0; a < RB_FLOOR_AXES; a++) {
            const rb_spectrum *sp = &f->motions[m].axis[a].trs;
            if (!f->motions[m].axis[a].target || sp->n < 2)
                continue;
            lo = fmin(lo, sp->freq_hz[0]);
            hi = fmax(hi, sp->freq_hz[sp->n - 1]);
            n++;
        }
    rb_axis xa;
    rb_axis_log(&xa, lo, hi);
    rb_svg_open(&b, RB_STACK_FIG_W,
                RB_STACK_TOP + n * (RB_STACK_PANEL_H + RB_STACK_PANEL_GAP) + 60);
    rb_strbuf_printf(&b, "<text x=\"%.1f\" y=\"24\" font-size=\"16\" font-weight=\"bold\">",
                     RB_STACK_LEFT);
    rb_plot_escape(&b, title ? title : "Test response spectra");
    rb_strbuf_puts(&b, "</text>\n");
    rb_svg_text(&b, RB_STACK_LEFT, 44, 11, "start", NULL,
                "absolute acceleration at the target's damping on the 1/72-octave grid; "
                "dashed: the lower and guide lines between the cutoffs");
    int k = 0;
    for (size_t m = 0; m < f->n_motions; m++)
        for (int a = 0; a < RB_FLOOR_AXES; a++) {
            const rb_floor_component *fc = &f->motions[m].axis[a];
            if (!fc->target || fc->trs.n < 2)
                continue;
            rb_panel p;
            double top = 0;
            rb_panel_stacked(&p, k, &xa);
            for (size_t i = 0; i < fc->trs.n; i++)
                top = fmax(top, fc->trs.sa_mps2[i] / g);
            for (int i = 0; i < TARGET_POINTS; i++)
                top = fmax(top, fc->rules.guide
                                    * rb_target_at(fc->target,
                                                   lo * pow(hi / lo, (double)i
                                                            / (TARGET_POINTS - 1))) / g);
            rb_axis_nice(&p.ya, 0, top, 5, 1);
            char label[200];
            snprintf(label, sizeof label, "%.150s %s",
                     c->motions[m].name ? c->motions[m].name : "motion",
                     rb_enum_str(rb_floor_axis_names, a));
            panel(&b, &p, fc, label, g, k == n - 1);
            k++;
        }
    rb_svg_close(&b);
    return rb_plot_finish(&b, out, diag);
}
