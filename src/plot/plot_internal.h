/* What the figure renderers share: a growing text buffer that remembers an
 * allocation failure instead of reporting each one, XML escaping, nice
 * axis ticks, panels with their axes, and decimated series. Private to
 * src/report. */
#ifndef RB_PLOT_INTERNAL_H
#define RB_PLOT_INTERNAL_H

#include <stddef.h>
#include "rockbolt/plot.h"

/* ---- Text buffer ---------------------------------------------------------- */

#include "util/strbuf.h"

/* Append s shown as every output for people shows user text
 * (rb_text_escape_lines: controls other than tab and newline, format
 * characters, U+FFFE and U+FFFF and bytes that are not UTF-8 written as
 * \x1b, \u202e, \xff), then & < > " ' escaped, so that the result is
 * always well-formed XML text or attribute content. NULL appends
 * nothing. */
void rb_plot_escape(rb_strbuf *b, const char *s);
/* Hand the text over: *out gets it (RB_OK) or NULL (RB_ERR_NOMEM, with
 * diag->msg set). The buffer is empty afterwards either way. */
rb_status rb_plot_finish(rb_strbuf *b, char **out, rb_diag *diag);
/* The HTML page's summary tables of rep (plot_summary.c); nothing for NULL. */
void rb_plot_summary_tables(rb_strbuf *b, const rb_report *rep);

/* ---- Axes ------------------------------------------------------------------ */

#define RB_PLOT_MAX_TICKS 16

/* An axis range rounded out to nice ticks (1, 2 or 5 times a power of 10),
 * linear or logarithmic. */
typedef struct {
    double lo, hi;                  /* range drawn; both > 0 when log */
    double step;                    /* linear: between ticks */
    double ticks[RB_PLOT_MAX_TICKS];
    int n_ticks;
    int decimals;                   /* for the tick labels */
    int log;                        /* 1: positions by log10 */
} rb_axis;

/* Ticks for data in [lo, hi] (any order, non-finite ends taken as 0), about
 * target ticks. With round_out the range grows to the outer ticks;
 * otherwise it stays [lo, hi] and only ticks inside are kept. A zero-width
 * range is widened around its value. */
void rb_axis_nice(rb_axis *ax, double lo, double hi, int target, int round_out);

/* A logarithmic axis for data in [lo, hi], both > 0 (a non-positive or
 * non-finite end is taken from the other, a zero-width range widened to a
 * factor of 2 each way): the range rounded out to 1, 2 or 5 times a power
 * of 10, ticks at those values inside it, or at the powers of 10 alone
 * when they would be too many. */
void rb_axis_log(rb_axis *ax, double lo, double hi);

/* Where v lies along ax, 0 at lo and 1 at hi (outside for v outside; not
 * finite for v <= 0 on a log axis). */
double rb_axis_frac(const rb_axis *ax, double v);

/* Format v as a tick label of ax (no "-0"). */
void rb_axis_label(const rb_axis *ax, double v, char *buf, size_t n);

/* A rectangle of the figure with an x and a y axis mapped onto it. */
typedef struct {
    double x0, y0, w, h;            /* SVG user units, y0 is the top */
    rb_axis xa, ya;
} rb_panel;

/* The sweep figures' layout (a design sweep, a fragility against the gap
 * ratio): panels of one x axis stacked in a column. */
#define RB_STACK_FIG_W 900.0
#define RB_STACK_LEFT 100.0
#define RB_STACK_RIGHT 32.0
#define RB_STACK_TOP 70.0
#define RB_STACK_PANEL_H 240.0
#define RB_STACK_PANEL_GAP 24.0
/* Panel k (0 at the top) of that column, with x axis xa; its y axis is the
 * caller's to set. */
void rb_panel_stacked(rb_panel *p, int k, const rb_axis *xa);

double rb_panel_x(const rb_panel *p, double x);
double rb_panel_y(const rb_panel *p, double y);

/* Frame, grid lines and y tick labels of p, and the y axis title (rotated,
 * left of the labels). With x_labels the x tick labels and x_title go
 * below the panel. */
void rb_panel_draw(rb_strbuf *b, const rb_panel *p, const char *y_title,
                   int x_labels, const char *x_title);

/* A dashed horizontal reference line at y, if y is inside the panel. */
void rb_panel_hline(rb_strbuf *b, const rb_panel *p, double y, const char *colour);

/* Legend entries in the panel's top right corner: a short line of each
 * colour and its name. Drawn with <line> and <text>, never <path>. */
void rb_panel_legend(rb_strbuf *b, const rb_panel *p, const char *const *names,
                     const char *const *colours, int n);

/* ---- Series ---------------------------------------------------------------- */

/* One <path> for the points (x[i], scale * y[i]), i < n, in panel p. When
 * there are more than two points per pixel column, each column keeps its
 * minimum and maximum, in the order they occur. A non-finite point ends
 * the current subpath. Always exactly one <path> element, even when no
 * point is finite (its d is then empty). dash may be NULL; name goes
 * into the path's data-series attribute. */
void rb_series_path(rb_strbuf *b, const rb_panel *p, const double *x,
                    const double *y, size_t n, double scale,
                    const char *colour, const char *dash, const char *name);

/* Smallest and largest finite value of scale * y[i]; returns 0 if none. */
int rb_series_range(const double *y, size_t n, double scale, double *lo,
                    double *hi);

/* ---- Fragility figures ----------------------------------------------------- */

/* The colour of each limit state (rb_limit_state), the same in every figure. */
extern const char *const rb_plot_limit_colours[RB_N_LIMITS];

/* ---- Common SVG pieces ---------------------------------------------------- */

/* <svg ...> with its size and the shared font, and a white background. */
void rb_svg_open(rb_strbuf *b, double width, double height);
void rb_svg_close(rb_strbuf *b);
/* A text element; s is escaped. anchor is "start", "middle" or "end". */
void rb_svg_text(rb_strbuf *b, double x, double y, double size, const char *anchor,
                 const char *weight, const char *s);

#endif
