/* The renderers of a case's results (library rb_report): the check report
 * as JSON and text (through a template, rockbolt/template.h), the history
 * and sweep CSV, fragility, P-58 rows.
 *
 * The CLI solves every motion of a case, judges each result, and fills an
 * rb_report that only borrows what it points at. The renderers turn it into
 * a string the caller owns; nothing here prints or opens a file: the output
 * plan (rockbolt/outplan.h) writes them, whole or not at all. The JSON
 * layout is documented in docs/report-format.md and versioned by
 * RB_REPORT_FORMAT_VERSION. */
#ifndef ROCKBOLT_REPORT_H
#define ROCKBOLT_REPORT_H

#include <stddef.h>
#include <stdio.h>
#include "rockbolt/status.h"
#include "rockbolt/model.h"
#include "rockbolt/solve.h"
#include "rockbolt/criteria.h"
#include "rockbolt/case.h"
#include "rockbolt/design.h"
#include "rockbolt/fragility.h"

/* Bumped whenever a JSON field is renamed, removed or changes meaning;
 * adding a field does not bump it. */
#define RB_REPORT_FORMAT_VERSION 2

/* ---- What a report is made of ------------------------------------------ */

/* Room for "FAIL (4 validity warnings: lift-off, sliding, bolt impact,
 * convergence)". */
#define RB_HEADLINE_MAX 96

/* One motion of a case, solved and judged. */
typedef struct {
    const rb_case_motion *motion; /* borrowed: name, source, rb_motion */
    const rb_result *result;      /* borrowed: the solver's result */
    rb_verdict verdict;           /* rb_judge of the result, confirmed */
    /* the runs that confirmed a pass (rb_verdict_confirm); n_confirm 0
     * when the verdict was not confirmed */
    rb_confirm_run confirm[RB_CONFIRM_RUNS];
    size_t n_confirm;
} rb_report_motion;

typedef struct {
    const rb_case *kase;           /* borrowed: name, path, model, criteria */
    rb_derived derived;            /* rb_model_derive of kase->model */
    const rb_report_motion *motions; /* borrowed array of n_motions */
    size_t n_motions;
    int with_history;              /* JSON: include each motion's history */
    const rb_case_design *design;  /* borrowed; NULL for a check: the
                                      reports then have no design parts */
    int pass;                      /* 1 when every motion passes */
    unsigned warnings;             /* validity warnings of any motion */
    char headline[RB_HEADLINE_MAX]; /* "PASS", "FAIL", or either with its
                                      validity warnings in brackets */
    char reason[384];              /* one line: what governed the verdict */
} rb_report;

/* Set r->pass, r->warnings, r->headline and r->reason from the motions:
 * the first failing motion (and how many others fail) or, when all pass,
 * the criterion met. */
void rb_report_conclude(rb_report *r);

/* "PASS", "FAIL", or "PASS (2 validity warnings: lift-off, bolt impact)". */
void rb_report_headline(int pass, unsigned warnings, char *buf, size_t n);

/* Render the JSON report. *out is a NUL-terminated string the caller frees
 * with free(). Returns RB_ERR_NONFINITE (diag->key names the field) if any
 * number to be written is NaN or infinite, RB_ERR_NOMEM on allocation
 * failure; *out is NULL on error. */
rb_status rb_report_render_json(const rb_report *r, char **out, rb_diag *diag);

/* Render the text report through template text tmpl (see rb_template_*).
 * *out is owned by the caller (free()). Errors in the template come back as
 * RB_ERR_PARSE with the template line and column in diag. */
rb_status rb_report_render_text(const rb_report *r, const char *tmpl,
                                char **out, rb_diag *diag);

/* Write the time histories of the motions as CSV to fp: one header line,
 * then one line per history row, the motion's 1-based index first. Motions
 * without a history contribute no rows. Returns RB_ERR_IO if a write fails,
 * RB_ERR_NONFINITE for a NaN or infinite value. */
rb_status rb_history_write_csv(FILE *fp, const rb_report *r, rb_diag *diag);

/* ---- Sweeps --------------------------------------------------------------
 * A design sweep (rockbolt/design.h) written out: the searches keep no I/O. */

/* One row per point, with a header line, to an open stream (the JSON
 * report has the sweeps as objects). RB_ERR_IO on a write error. */
rb_status rb_sweep_write_csv(const rb_sweep *s, FILE *fp);

/* ---- Fragility (rb_run_fragility, rockbolt/run.h) ---------------------- */

/* Text for the terminal, JSON (SI, every capacity) and CSV (one row per
 * motion and limit state, in g and A*). Each returns a string the caller
 * frees, or NULL when memory runs out. */
char *rb_fragility_render_text(const rb_case *c, const rb_case_fragility *f);
/* The intensity a fragility is in, in words ("peak floor acceleration",
 * "5 % spectral acceleration at 5 Hz"). */
void rb_fragility_intensity_describe(const rb_case_fragility *f, char *buf, size_t n);
char *rb_fragility_render_json(const rb_case *c, const rb_case_fragility *f);
char *rb_fragility_render_csv(const rb_case *c, const rb_case_fragility *f);

/* ---- FEMA P-58 fragility rows (docs/fragility.md, "FEMA P-58") ---------- */

/* The limit states of a row, in the sequence a loss tool evaluates them:
 * LS1 the anchorage fails, with the damage states FEMA P-58 splits it
 * into; LS2 the cabinet overturns. */
#define RB_P58_N_LS 2
/* The limit state of the fragility that row limit state ls (0: LS1, 1:
 * LS2) is, for a fragility with the limit states present (bit 1 << k),
 * their fits and medians: LS1 the anchorage's failure by whichever way
 * comes first, of the bolts' toughness used up (usage) and, where the
 * case has concrete:, the concrete check (anchorage), by
 * rb_fragility_governing over the two (the usage when neither is
 * fitted); LS2 the overturn state. */
rb_limit_state rb_p58_limit(int ls, unsigned present, const int fitted[RB_N_LIMITS],
                            const double median[RB_N_LIMITS]);
/* FEMA P-58's weights of LS1's damage states: anchorage failure, and
 * anchorage failure with the equipment lost. */
#define RB_P58_DEFAULT_W1 0.7
#define RB_P58_DEFAULT_W2 0.3

/* One row: a lognormal per limit state in peak floor acceleration (g). */
typedef struct {
    const char *id;           /* the component's ID */
    int fitted[RB_P58_N_LS];  /* 0: the limit state could not be fitted */
    double median_g[RB_P58_N_LS];
    double beta[RB_P58_N_LS];
    /* beyond P-58's columns: whether the limit state's capacities were
     * confirmed at tighter tolerances (the governing state's), and how
     * many of them are the model's limit (a lower bound), as the
     * fragility's JSON says */
    int confirmed[RB_P58_N_LS];
    size_t model_limited[RB_P58_N_LS];
    const double *weights;    /* LS1's damage-state weights */
    size_t n_weights;         /* 0: the P-58 defaults */
} rb_p58_row;

/* The header line and one row of the SimCenter / pelicun fragility CSV
 * (ID, Incomplete, Demand-Type, ..., LS2-DamageStateWeights, then
 * LS1-Confirmed, LS1-ModelLimited, LS2-Confirmed, LS2-ModelLimited after
 * P-58's own columns). New strings,
 * NULL when memory runs out. Numbers are the shortest that read back to
 * the same double. */
char *rb_p58_render_head(void);
char *rb_p58_render_row(const rb_p58_row *r);
/* `fragility --p58`: the header and the row of a fragility in peak floor
 * acceleration, its ID the case's fragility.p58_id or else its name. */
char *rb_fragility_render_p58(const rb_case *c, const rb_case_fragility *f);

/* ---- Response spectra (rb_run_spectra, rockbolt/run.h) ------------------- */

/* Text for the terminal (each motion's peak, strong-motion duration and
 * fit to its target, then the spectra in g), JSON (SI, every ordinate)
 * and CSV (one row per motion and frequency). Each returns a string the
 * caller frees, or NULL when memory runs out. */
char *rb_spectra_render_text(const rb_case *c, const rb_case_spectra *s);
char *rb_spectra_render_json(const rb_case *c, const rb_case_spectra *s);
char *rb_spectra_render_csv(const rb_case *c, const rb_case_spectra *s);
/* The same for a sweep over gap ratios (rb_run_fragility_gap_sweep): text
 * (a line per gap ratio: each limit state's median in g, beta and
 * probability at the case's level), JSON (each point's limit states as
 * the fragility's JSON has them) and CSV (a row per gap ratio and limit
 * state). */
char *rb_fragility_sweep_render_text(const rb_case *c, const rb_fragility_sweep *s);
char *rb_fragility_sweep_render_json(const rb_case *c, const rb_fragility_sweep *s);
char *rb_fragility_sweep_render_csv(const rb_fragility_sweep *s);

#endif
