/* Figures of a check, written as SVG and HTML text (library rb_report).
 *
 * The figures follow the thesis's stacked time-history plots (Figs. 5.13 to
 * 6.18) and its response curves (Figs. 5.23 to 6.4). The module draws them
 * itself, with no plotting library, and does no file I/O: every renderer
 * returns a malloc'd NUL-terminated string that the caller owns and frees
 * with free(); on error *out is NULL. Nothing here prints.
 *
 * The SVG is standalone (xmlns set, no XML declaration, no ids, no
 * scripts, no external references), so the same string can be saved as a
 * .svg file or pasted verbatim into an HTML page. Every text taken from the
 * input (case, motion, title, report) is escaped, and bytes that are not
 * valid UTF-8 or not allowed in XML are replaced, so the output always
 * parses as XML. Non-finite numbers are never written: a NaN or infinite
 * sample breaks its line. Each plotted series is exactly one <path>
 * element; nothing else is drawn with <path>. docs/plots.md describes the
 * figures and their conventions. */
#ifndef ROCKBOLT_PLOT_H
#define ROCKBOLT_PLOT_H

#include <stddef.h>
#include "rockbolt/status.h"
#include "rockbolt/report.h"
#include "rockbolt/fragility.h"
#include "rockbolt/design.h"
#include "rockbolt/names.h"

/* Series of the time-history figure, top panel to bottom, in the order
 * their <path> elements appear: floor acceleration; theta; U; left and
 * right bolt row force; elastic (frame) and total base shear; energy
 * absorbed by the left and right row. */
#define RB_PLOT_HISTORY_SERIES 9

/* Stacked time-history figure of motion motion_index of rep. The motion's
 * result must carry a history (solve with rb_solve_opts.history_dt_s > 0;
 * the CLI's 0.01 s is fine, 0.005 s is smoother). Panels, sharing the time
 * axis in s: floor acceleration / g; theta / alpha; U / U_static; bolt row
 * force / Fy (left row drawn negative, right row positive); base shear / W
 * (frame and total); absorbed energy / capacity per row. A panel whose
 * normaliser is zero (no bolts, no motion) is drawn in engineering units
 * instead. The stage of each sample is shaded behind the panels, and the
 * first yield of each row, each break and the overturn are vertical
 * markers. Histories longer than two samples per pixel column are reduced
 * to the minimum and maximum of each column. Returns RB_ERR_INVALID (diag
 * says why) for a motion index out of range or a motion without a history
 * of at least two rows, RB_ERR_NOMEM. */
rb_status rb_plot_history_svg(const rb_report *rep, size_t motion_index,
                              char **out, rb_diag *diag);

/* Hysteresis of motion motion_index of rep, from its history: each bolt
 * row's force against its elongation (the plate's travel at the row past
 * the initial gap; negative while the bolt is slack), and the bolts'
 * moment about the pivot against the rotation in mrad, in the case's
 * output units (rb_case.output_units). Series, in <path> order:
 * force_left, force_right, moment. Errors as rb_plot_history_svg. */
rb_status rb_plot_hysteresis_svg(const rb_report *rep, size_t motion_index,
                                 char **out, rb_diag *diag);

/* Response curve of a sweep: peak U / U_static (top) and peak bolt row
 * force / Fy per row (bottom) against x, the excitation frequency over the
 * fixed-base frequency (frequency sweeps) or the peak floor level in A*
 * (amplitude sweeps). Points where a bolt row yielded are marked o, points
 * that failed (a row broke or the body overturned) x, as in the thesis.
 * Points without a result (status not RB_OK) break the curves and are
 * counted in a note under the figure. title (may be NULL) heads the
 * figure. RB_ERR_INVALID for a sweep without points, RB_ERR_NOMEM. */
rb_status rb_plot_sweep_svg(const rb_sweep *s, const char *title, char **out,
                            rb_diag *diag);

/* A self-contained page: title as <title> and heading; with rep (may be
 * NULL) the summary of a calculation package: the verdict and its reason,
 * a table of each motion's verdict and validity checks, one of its peaks
 * and one of the cabinet and anchorage, in the case's output units; then
 * each of the n_svgs figures inline, in order; then text_report (may be
 * NULL) escaped in a <pre>. Readable on a phone, and printed the summary
 * is the first page. The page is XHTML-compatible (it parses as XML as well as HTML)
 * and refers to nothing outside itself. Each svgs[i] must be an <svg>
 * element as the renderers above produce; a leading XML declaration is
 * dropped. RB_ERR_INVALID if one is NULL or does not start with <svg,
 * RB_ERR_NOMEM. */
rb_status rb_plot_html_page(const rb_report *rep, const char *title,
                            const char *text_report, const char *const *svgs,
                            size_t n_svgs, char **out, rb_diag *diag);

/* The page of a whole check: the text report and the time-history figure of
 * every motion that has a history, titled after the case and its verdict.
 * Motions without a history are skipped. Errors as for the two calls it
 * makes. */
rb_status rb_plot_report_html(const rb_report *rep, const char *text_report,
                              char **out, rb_diag *diag);

/* The scale of an axis that a caller may choose. */
typedef enum {
    RB_PLOT_SCALE_LOG = 0,
    RB_PLOT_SCALE_LINEAR
} rb_plot_scale;

/* "log", "linear": the one name table of rb_plot_scale (--x-scale). */
extern const rb_enum_name rb_plot_scale_names[];

/* The fragility figure of a case: each fitted limit state's lognormal
 * curve against the peak floor acceleration in g on an x axis of the
 * given scale (on a log axis a lognormal curve is a symmetric S, and
 * states a hundred times apart are all readable), the motions'
 * capacities as points at their empirical fractions, the case's level
 * dashed. title (may be NULL) heads it. RB_ERR_INVALID without motions,
 * RB_ERR_NOMEM. */
rb_status rb_plot_fragility_svg(const rb_case_fragility *f, const char *title,
                                rb_plot_scale x_scale, char **out, rb_diag *diag);

/* The fragility against the gap ratio (rb_run_fragility_gap_sweep): each
 * fitted limit state's probability at the case's level (top) and its
 * median in g on a log axis (bottom, the case's level dashed) at each gap
 * ratio, a point at each; a state not fitted at a ratio breaks its curves.
 * title (may be NULL) heads it. RB_ERR_INVALID without points,
 * RB_ERR_NOMEM. */
rb_status rb_plot_fragility_sweep_svg(const rb_fragility_sweep *s, const char *title,
                                      char **out, rb_diag *diag);

/* The response spectra of a case's motions (rb_run_spectra): absolute
 * acceleration in g against frequency on a logarithmic axis, each target
 * over them with its band dashed where it is checked. RB_ERR_INVALID
 * without spectra, RB_ERR_NOMEM. */
rb_status rb_plot_spectra_svg(const rb_case *c, const rb_case_spectra *s, const char *title,
                              char **out, rb_diag *diag);

/* rockbolt motion's figure (rb_run_floors): for every component matched
 * to a target, a panel of its TRS in g on the acceptance grid against the
 * RRS, the lower line (0.9) and the guide (1.3) dashed between the
 * cutoffs, titled with the acceptance's verdict. RB_ERR_INVALID when no
 * component has a target, RB_ERR_NOMEM. */
#include "rockbolt/floors.h"
int rb_plot_floors_has_figure(const rb_case_floors *f);
rb_status rb_plot_floors_svg(const rb_case *c, const rb_case_floors *f, const char *title,
                             char **out, rb_diag *diag);

#endif
