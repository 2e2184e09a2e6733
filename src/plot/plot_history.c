/* The stacked time-history figure of one solved motion, after the thesis's
 * Figs. 5.13 to 6.18: six panels on one time axis, the stage shaded behind
 * them, and the first yield, breaks and overturn as vertical markers. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "rockbolt/names.h"
#include "plot_internal.h"

#define FIG_W 1000.0
#define LEFT 100.0
#define RIGHT 32.0
#define TITLE_H 72.0    /* title, verdict and levels */
#define MARK_ROW 13.0   /* one row of marker labels */
#define MAX_MARKERS 5
#define PANEL_H 135.0
#define PANEL_GAP 14.0
#define N_PANELS 6
#define MAX_COLS 1024

static const char *const stage_fill[6] = {
    "#ffffff", "#f2f2f2", "#dcebf7", "#fff2b3", "#e0f0da", "#f9d9d9"
};
static const char *const stage_name[6] = {
    "", "1 fixed base", "2 uplift, bolts slack", "3 impact on a bolt (instant)",
    "4 held by a bolt row", "5 bolt row yielding"
};

typedef struct {
    const double *y;
    double scale;
    const char *colour, *dash, *name, *label;
} series_spec;

typedef struct {
    const char *y_title;
    series_spec s[2];
    int n;
    double must_lo, must_hi;   /* inside the range when the data reach half
                                  way to them (a reference) */
    double ref[2];             /* dashed reference lines */
    int n_ref;
    const char *off_scale;     /* said in the panel when must_lo..must_hi is
                                  left out: the reference is off the axis */
} panel_spec;

/* Normalised when the normaliser exists, otherwise in engineering units:
 * a free-standing body has no Fy and no bolt capacity to divide by. */
static double norm_scale(double denom, double raw_scale, const char *norm_title,
                         const char *raw_title, const char **title)
{
    if (isfinite(denom) && denom > 0) {
        *title = norm_title;
        return 1 / denom;
    }
    *title = raw_title;
    return raw_scale;
}

static void set_series(series_spec *s, const double *y, double scale,
                       const char *colour, const char *name, const char *label)
{
    s->y = y;
    s->scale = scale;
    s->colour = colour;
    s->dash = NULL;
    s->name = name;
    s->label = label;
}

static void build_specs(const rb_report *rep, const rb_result *res,
                        panel_spec ps[N_PANELS])
{
    const rb_history *h = res->history;
    double g = rep->derived.g > 0 ? rep->derived.g : RB_G0, sc;
    int normed;
    /* raw panels (no normaliser) in the case's output units */
    const rb_out_units *ou = rb_out_units_of(rep->kase ? rep->kase->output_units
                                             : RB_UNITS_SI);
    int us = ou->system == RB_UNITS_US;
    memset(ps, 0, N_PANELS * sizeof *ps);

    set_series(&ps[0].s[0], h->accel, 1 / g, "#444444", "accel", "floor");
    ps[0].n = 1;
    ps[0].y_title = "floor accel. (g)";

    sc = norm_scale(res->alpha_rad, 1e3, "\xce\xb8 / \xce\xb1 (-)",
                    "\xce\xb8 (mrad)", &ps[1].y_title);
    set_series(&ps[1].s[0], h->theta, sc, "#1f77b4", "theta", "rotation");
    ps[1].n = 1;
    if (res->alpha_rad > 0 && res->theta0_rad > 0) {
        /* the initial contact angle: rocking beyond it loads a bolt row */
        ps[1].ref[0] = res->theta0_rad * sc;
        ps[1].ref[1] = -res->theta0_rad * sc;
        ps[1].n_ref = 2;
    }

    sc = norm_scale(res->u_static_m, 1 / ou->small_length_f, "U / U_static (-)",
                    us ? "U (in)" : "U (mm)", &ps[2].y_title);
    set_series(&ps[2].s[0], h->u, sc, "#2ca02c", "u", "frame deflection");
    ps[2].n = 1;

    normed = res->fy_row_n > 0;
    sc = norm_scale(res->fy_row_n, 1 / ou->force_f, "bolt force / Fy (-)",
                    us ? "bolt force (kip)" : "bolt force (kN)", &ps[3].y_title);
    set_series(&ps[3].s[0], h->bolt_force_left, -sc, "#1f77b4", "bolt_left",
               "left row (-)");
    set_series(&ps[3].s[1], h->bolt_force_right, sc, "#d62728", "bolt_right",
               "right row (+)");
    ps[3].n = 2;
    if (normed) {
        /* the yield lines at +-1 inside the frame, not on it */
        ps[3].must_lo = -1.1;
        ps[3].must_hi = 1.1;
        ps[3].ref[0] = -1;
        ps[3].ref[1] = 1;
        ps[3].n_ref = 2;
        ps[3].off_scale = "yield at \xc2\xb1" "1 Fy: off this scale";
    }

    sc = norm_scale(res->weight_n, 1 / ou->force_f, "base shear / W (-)",
                    us ? "base shear (kip)" : "base shear (kN)", &ps[4].y_title);
    set_series(&ps[4].s[0], h->shear_elastic, sc, "#9467bd", "shear_frame",
               "frame GA(\xcf\x80/4h)U");
    set_series(&ps[4].s[1], h->shear_total, sc, "#ff7f0e", "shear_total",
               "total floor reaction");
    ps[4].s[1].dash = "4 2";
    ps[4].n = 2;

    normed = res->capacity_j > 0;
    sc = norm_scale(res->capacity_j, 1 / ou->energy_f, "energy / capacity (-)",
                    us ? "absorbed energy (ft-lbf)" : "absorbed energy (J)",
                    &ps[5].y_title);
    set_series(&ps[5].s[0], h->energy_left, sc, "#1f77b4", "energy_left", "left row");
    set_series(&ps[5].s[1], h->energy_right, sc, "#d62728", "energy_right",
               "right row");
    ps[5].n = 2;
    if (normed) {
        ps[5].must_hi = 1.1;
        ps[5].ref[0] = 1;
        ps[5].n_ref = 1;
        ps[5].off_scale = "break at 1: off this scale";
    }
}

/* The y range is the data's (with zero), and takes in the reference range
 * must_lo..must_hi only when the data reach half way to it: a response of
 * 0.25 Fy fills its panel instead of lying flat under the yield lines.
 * Returns 1 when the reference range was left out. */
static int layout_panel(rb_panel *p, int k, double top, const panel_spec *ps,
                        const rb_history *h)
{
    double lo = 0, hi = 0, a, b, reach, must;
    int i, have = 0, left_out = 0;
    p->x0 = LEFT;
    p->w = FIG_W - LEFT - RIGHT;
    p->y0 = top + k * (PANEL_H + PANEL_GAP);
    p->h = PANEL_H;
    rb_axis_nice(&p->xa, h->t[0], h->t[h->n - 1], 10, 0);
    for (i = 0; i < ps->n; i++) {
        if (rb_series_range(ps->s[i].y, h->n, ps->s[i].scale, &a, &b)) {
            lo = fmin(lo, a);
            hi = fmax(hi, b);
            have = 1;
        }
    }
    reach = fmax(fabs(lo), fabs(hi));
    must = fmax(fabs(ps->must_lo), fabs(ps->must_hi));
    if (must > 0) {
        if (!have || reach >= 0.5 * must) {
            lo = fmin(lo, ps->must_lo);
            hi = fmax(hi, ps->must_hi);
        } else {
            left_out = 1;
        }
    }
    /* a little air so that a peak on a tick does not sit on the frame */
    a = 0.01 * (hi - lo);
    rb_axis_nice(&p->ya, lo < 0 ? lo - a : lo, hi > 0 ? hi + a : hi, 5, 1);
    return left_out;
}

/* The stage of each pixel column: the highest stage any sample interval
 * touching the column is in, so that a short yielding spell still shows. */
static void draw_stages(rb_strbuf *b, const rb_panel *top, double bottom,
                        const rb_history *h)
{
    int col[MAX_COLS];
    size_t n_cols = (size_t)top->w, i, c, start;
    double span = top->xa.hi - top->xa.lo;
    if (n_cols > MAX_COLS)
        n_cols = MAX_COLS;
    memset(col, 0, sizeof col);
    for (i = 0; i < h->n; i++) {
        double ta = h->t[i], tb = i + 1 < h->n ? h->t[i + 1] : h->t[i];
        double fa = floor((ta - top->xa.lo) / span * (double)n_cols);
        double fb = ceil((tb - top->xa.lo) / span * (double)n_cols);
        size_t c0, c1;
        int st = h->stage[i];
        if (!(fa >= 0))
            fa = 0;
        if (!(fb <= (double)n_cols))
            fb = (double)n_cols;
        if (!(fb > fa) || st < 1 || st > 5)
            continue;
        c0 = (size_t)fa;
        c1 = (size_t)fb;
        for (c = c0; c < c1; c++)
            if (st > col[c])
                col[c] = st;
    }
    rb_strbuf_puts(b, "<g class=\"stages\" stroke=\"none\">\n");
    for (start = 0; start < n_cols; start = c) {
        for (c = start; c < n_cols && col[c] == col[start]; c++)
            ;
        if (col[start] < 1)
            continue;
        rb_strbuf_printf(b, "<rect class=\"stage s%d\" x=\"%.1f\" y=\"%.1f\" "
                       "width=\"%.1f\" height=\"%.1f\" fill=\"%s\"/>\n", col[start],
                       top->x0 + top->w * (double)start / (double)n_cols, top->y0,
                       top->w * (double)(c - start) / (double)n_cols,
                       bottom - top->y0, stage_fill[col[start]]);
    }
    rb_strbuf_puts(b, "</g>\n");
}

static void draw_stage_legend(rb_strbuf *b, double y)
{
    double x = LEFT;
    int s;
    rb_svg_text(b, LEFT - 8, y + 10, 11, "end", NULL, "stage:");
    for (s = 1; s <= 5; s++) {
        rb_strbuf_printf(b, "<rect class=\"stage-key s%d\" x=\"%.1f\" y=\"%.1f\" "
                       "width=\"16\" height=\"12\" fill=\"%s\" stroke=\"#999999\" "
                       "stroke-width=\"0.6\"/>\n", s, x, y, stage_fill[s]);
        rb_svg_text(b, x + 21, y + 10, 11, "start", NULL, stage_name[s]);
        x += 34 + 5.6 * (double)strlen(stage_name[s]);
    }
}

typedef struct {
    double t;
    const char *kind;     /* class: yield, break, overturn */
    const char *label;
    const char *colour;
    double x;             /* in the figure */
    int row;              /* label row above the panels, 0 nearest */
    int right;            /* label to the right of the line (else left) */
} marker;

static int collect_markers(const rb_result *res, marker m[MAX_MARKERS])
{
    static const char *const yl[2] = { "yield L", "yield R" };
    static const char *const bl[2] = { "break L", "break R" };
    int n = 0, row, i, j;
    memset(m, 0, MAX_MARKERS * sizeof *m);
    for (row = 0; row < 2; row++) {
        if (res->yielded[row] && isfinite(res->first_yield_s[row])) {
            m[n].t = res->first_yield_s[row];
            m[n].kind = "yield";
            m[n].label = yl[row];
            m[n++].colour = "#c98a00";
        }
        if (res->broken[row] && isfinite(res->break_s[row])) {
            m[n].t = res->break_s[row];
            m[n].kind = "break";
            m[n].label = bl[row];
            m[n++].colour = "#b00000";
        }
    }
    if (res->overturned && isfinite(res->overturn_s)) {
        m[n].t = res->overturn_s;
        m[n].kind = "overturn";
        m[n].label = "overturn";
        m[n++].colour = "#000000";
    }
    for (i = 1; i < n; i++)          /* by time, for placing the labels */
        for (j = i; j > 0 && m[j].t < m[j - 1].t; j--) {
            marker t = m[j];
            m[j] = m[j - 1];
            m[j - 1] = t;
        }
    return n;
}

/* Labels are "yield R 2.545 s" beside their line; events close in time
 * (yield, break and overturn within a few tenths of a second) get rows of
 * their own instead of overprinting. Returns the number of rows used. */
static int place_markers(marker *m, int n, const rb_panel *p)
{
    double row_end[MAX_MARKERS];
    int i, r, rows = 0;
    for (r = 0; r < MAX_MARKERS; r++)
        row_end[r] = -1e9;
    for (i = 0; i < n; i++) {
        char lab[64];
        double w;
        m[i].x = rb_panel_x(p, m[i].t);
        snprintf(lab, sizeof lab, "%s %.3f s", m[i].label, m[i].t);
        w = 6.3 * (double)strlen(lab);
        m[i].right = m[i].x + 3 + w <= FIG_W - 2;
        for (r = 0; r < MAX_MARKERS - 1; r++)
            if (row_end[r] + 8 <= (m[i].right ? m[i].x + 3 : m[i].x - 3 - w))
                break;
        m[i].row = r;
        row_end[r] = m[i].right ? m[i].x + 3 + w : m[i].x - 3;
        if (r + 1 > rows)
            rows = r + 1;
    }
    return rows;
}

/* Lines first, then the labels with a white halo, so that a line never
 * runs through the label of an earlier event. */
static void draw_markers(rb_strbuf *b, const marker *m, int n, const rb_panel *top,
                         double bottom)
{
    int i;
    for (i = 0; i < n; i++) {
        if (m[i].t < top->xa.lo || m[i].t > top->xa.hi)
            continue;
        rb_strbuf_printf(b, "<line class=\"marker %s\" x1=\"%.1f\" y1=\"%.1f\" "
                       "x2=\"%.1f\" y2=\"%.1f\" stroke=\"%s\" stroke-width=\"1.2\" "
                       "stroke-dasharray=\"6 3\"/>\n", m[i].kind, m[i].x,
                       top->y0 - 14 - MARK_ROW * m[i].row, m[i].x, bottom, m[i].colour);
    }
    for (i = 0; i < n; i++) {
        char lab[64];
        if (m[i].t < top->xa.lo || m[i].t > top->xa.hi)
            continue;
        snprintf(lab, sizeof lab, "%s %.3f s", m[i].label, m[i].t);
        rb_strbuf_printf(b, "<text class=\"marker-label\" x=\"%.1f\" y=\"%.1f\" "
                       "font-size=\"11\" text-anchor=\"%s\" fill=\"%s\" "
                       "stroke=\"#ffffff\" stroke-width=\"3\" paint-order=\"stroke\">",
                       m[i].right ? m[i].x + 3 : m[i].x - 3,
                       top->y0 - 5 - MARK_ROW * m[i].row, m[i].right ? "start" : "end",
                       m[i].colour);
        rb_plot_escape(b, lab);
        rb_strbuf_puts(b, "</text>\n");
    }
}

/* A synthetic motion's description ("synthetic: AC156 (2010) S_DS ..., z/h
 * 1, seed 1, motion 1"), whose "/" are not directories; only a table's file
 * loses its directory. */
static const char *synthetic_what(const char *src, char *buf, size_t n)
{
    static const char table[] = "synthetic: table ";
    const char *file = src + sizeof table - 1, *end, *slash;
    if (strncmp(src, table, sizeof table - 1) != 0 || !(end = strstr(file, ", seed ")))
        return src;
    slash = NULL;
    for (const char *q = file; q < end; q++)
        if (*q == '/')
            slash = q;
    if (!slash)
        return src;
    snprintf(buf, n, "%.*s%s", (int)(sizeof table - 1), src, slash + 1);
    return buf;
}

/* What the motion is, for the title: the record's file name, a synthetic
 * motion's target and seed, or the closed form with its frequency or
 * duration. */
static const char *motion_what(const rb_report_motion *rm, char *buf, size_t n)
{
    const rb_case_motion *cm = rm->motion;
    const char *src, *slash;
    if (!cm)
        return "floor motion";
    switch (cm->motion.kind) {
    case RB_MOTION_HARMONIC:
        snprintf(buf, n, "harmonic, %.4g Hz", cm->motion.freq_hz);
        return buf;
    case RB_MOTION_SAMPLED:
        src = cm->source ? cm->source : "record";
        if (strncmp(src, "synthetic:", 10) == 0)
            return synthetic_what(src, buf, n);
        slash = strrchr(src, '/');
        snprintf(buf, n, "record %s", slash ? slash + 1 : src);
        return buf;
    case RB_MOTION_PULSE:
        snprintf(buf, n, "%s pulse, %.4g s",
                 rb_enum_str(rb_pulse_shape_names, (int)cm->motion.pulse),
                 cm->motion.pulse_s);
        return buf;
    default:
        return "critical alternating pulses";
    }
}

static void draw_titles(rb_strbuf *b, const rb_report *rep, const rb_report_motion *rm)
{
    const rb_result *res = rm->result;
    const char *case_name = rep->kase && rep->kase->name ? rep->kase->name : "case";
    const char *motion_name = rm->motion && rm->motion->name ? rm->motion->name : "motion";
    char line[512];
    rb_strbuf_printf(b, "<text x=\"%.1f\" y=\"24\" font-size=\"16\" font-weight=\"bold\">",
                   LEFT);
    rb_plot_escape(b, case_name);
    rb_strbuf_puts(b, " \xe2\x80\x94 ");
    rb_plot_escape(b, motion_name);
    rb_strbuf_puts(b, " (");
    rb_plot_escape(b, motion_what(rm, line, sizeof line));
    rb_strbuf_puts(b, ")</text>\n");
    char head[RB_HEADLINE_MAX];
    rb_report_headline(rm->verdict.pass, rm->verdict.warnings, head, sizeof head);
    rb_strbuf_printf(b, "<text x=\"%.1f\" y=\"44\" font-size=\"12\">%s: ", LEFT, head);
    rb_plot_escape(b, rm->verdict.reason);
    rb_strbuf_puts(b, "</text>\n");
    if (res->a_star_mps2 > 0 && rep->derived.g > 0 && isfinite(res->a_star_mps2)
        && isfinite(res->peak_floor_mps2)) {
        double l = rep->kase ? rep->kase->model.lever_arm_m : 0;
        int n = snprintf(line, sizeof line,
                         "peak floor %.3f A* = %.3f g; A* = %.2f g",
                         res->peak_floor_mps2 / res->a_star_mps2,
                         res->peak_floor_mps2 / rep->derived.g,
                         res->a_star_mps2 / rep->derived.g);
        if (l > 0 && isfinite(rep->kase->model.gap_m / l) && n > 0
            && (size_t)n < sizeof line)
            snprintf(line + n, sizeof line - (size_t)n, "; gap ratio %.4g",
                     rep->kase->model.gap_m / l);
        rb_svg_text(b, LEFT, 60, 11, "start", NULL, line);
    }
}

static rb_status check_motion(const rb_report *rep, size_t k, rb_diag *diag)
{
    const rb_history *h;
    const char *why = NULL;
    if (!rep || k >= rep->n_motions || !rep->motions[k].result)
        why = "no such motion in the report";
    else if (!(h = rep->motions[k].result->history) || h->n < 2)
        why = "the motion has no time history of two rows or more "
              "(solve with a history interval)";
    else if (!(h->t[h->n - 1] > h->t[0]))
        why = "the time history does not advance in time";
    if (!why)
        return RB_OK;
    if (diag)
        rb_diag_set_msg(diag, "motion %zu: %s", k + 1, why);
    return RB_ERR_INVALID;
}

rb_status rb_plot_history_svg(const rb_report *rep, size_t motion_index,
                              char **out, rb_diag *diag)
{
    const rb_report_motion *rm;
    const rb_history *h;
    panel_spec ps[N_PANELS];
    rb_panel p[N_PANELS];
    marker marks[MAX_MARKERS];
    rb_strbuf b = {0};
    double bottom, height, top;
    int k, i, n_marks, rows;
    rb_status st = check_motion(rep, motion_index, diag);
    *out = NULL;
    if (st != RB_OK)
        return st;
    rm = &rep->motions[motion_index];
    h = rm->result->history;
    build_specs(rep, rm->result, ps);
    /* the time axis first: marker labels decide how high the panels start */
    layout_panel(&p[0], 0, 0, &ps[0], h);
    n_marks = collect_markers(rm->result, marks);
    rows = place_markers(marks, n_marks, &p[0]);
    top = TITLE_H + MARK_ROW * (rows > 1 ? rows : 1) + 12;
    int off[N_PANELS];
    for (k = 0; k < N_PANELS; k++)
        off[k] = layout_panel(&p[k], k, top, &ps[k], h);
    bottom = p[N_PANELS - 1].y0 + PANEL_H;
    height = bottom + 80;

    rb_svg_open(&b, FIG_W, height);
    draw_titles(&b, rep, rm);
    draw_stages(&b, &p[0], bottom, h);
    for (k = 0; k < N_PANELS; k++) {
        const char *names[2], *colours[2];
        rb_panel_draw(&b, &p[k], ps[k].y_title, k == N_PANELS - 1, "time (s)");
        for (i = 0; i < ps[k].n_ref; i++)
            rb_panel_hline(&b, &p[k], ps[k].ref[i], "#777777");
        for (i = 0; i < ps[k].n; i++) {
            const series_spec *s = &ps[k].s[i];
            rb_series_path(&b, &p[k], h->t, s->y, h->n, s->scale, s->colour, s->dash,
                           s->name);
            names[i] = s->label;
            colours[i] = s->colour;
        }
        if (ps[k].n > 1)
            rb_panel_legend(&b, &p[k], names, colours, ps[k].n);
        if (off[k] && ps[k].off_scale)
            rb_svg_text(&b, p[k].x0 + 6, p[k].y0 + 13, 11, "start", NULL,
                        ps[k].off_scale);
    }
    draw_markers(&b, marks, n_marks, &p[0], bottom);
    draw_stage_legend(&b, bottom + 50);
    rb_svg_close(&b);
    return rb_plot_finish(&b, out, diag);
}
