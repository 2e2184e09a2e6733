/* The case pipeline: what every command does with a case, written once.
 *
 * A motion of a case is solved with the case's own solver settings and
 * judged by rb_judge; the runs of a case are then concluded into one
 * rb_report. `check`, `design` and `batch` all go through these calls, so
 * a case gets the same verdict and the same numbers whichever command runs
 * it (tests/verdicts proves it over random cases). The motions of a case
 * are independent: a caller may solve them in any order, on any thread,
 * and conclude once all are done. No I/O. */
#ifndef ROCKBOLT_RUN_H
#define ROCKBOLT_RUN_H

#include "rockbolt/case.h"
#include "rockbolt/design.h"
#include "rockbolt/floors.h"
#include "rockbolt/fragility.h"
#include "rockbolt/report.h"

/* Interval of a time history when the case names none. */
#define RB_HISTORY_DT_DEFAULT_S 0.01

/* Solve motion i of c and judge it. A time history is kept when the case
 * asks for one (analysis.history) or want_history is set (figures, the
 * history CSV), at the case's output_interval or RB_HISTORY_DT_DEFAULT_S;
 * it does not change the results. r is overwritten (free with
 * rb_result_free); rm borrows c's motion and r. On a solver error diag
 * names the time and stage and rm is not filled. */
rb_status rb_run_motion(const rb_case *c, size_t i, int want_history, rb_result *r,
                        rb_report_motion *rm, rb_diag *diag);

/* The report of c from its judged motions (n = c->n_motions): derived
 * constants, verdict, headline and reason. rep borrows c and rms. */
void rb_run_conclude(const rb_case *c, const rb_report_motion *rms, rb_report *rep);

/* ---- Design searches ------------------------------------------------------ */

typedef enum {
    RB_RUN_DESIGN_FULL,   /* both design factors, the recommended gap and the
                             amplitude sweeps (`design`) */
    RB_RUN_DESIGN_BRIEF   /* the design factor for the case's own criteria
                             and the recommended gap (`batch --design`) */
} rb_run_design_scope;

/* The criteria a case's design judges by: no yield, no break (at the
 * case's usage limit when it is judged on no break, else the default) and
 * the case's own for the gap. Sets only those three fields of out. */
void rb_run_design_criteria(const rb_case *c, rb_case_design *out);
/* What the design command's factor searches ask of rb_design_factor_near:
 * the margin's secant before the bisection (docs/design.md, "Design
 * factor"), so that a probe of its brackets searches as it does. */
rb_design_hints rb_run_design_factor_hints(void);

/* The design of motion m of c, the part scope names, against the criteria
 * in cd (rb_run_design_criteria). checked is the motion's own run made
 * before (rb_run_motion's result), which the searches are given instead of
 * solving it again, or NULL. md is overwritten; free it with
 * rb_motion_design_free (also after an error).
 * Errors as for rb_design_factor; diag->key then names the motion and the
 * search. */
rb_status rb_run_motion_design(const rb_case *c, size_t m, const rb_result *checked,
                               rb_run_design_scope scope, int n_threads,
                               const rb_case_design *cd, rb_motion_design *md,
                               rb_diag *diag);

/* The design factor against the case's own criteria, out of md. */
const rb_design_factor_result *rb_run_own_factor(const rb_case *c,
                                                 const rb_motion_design *md);

/* The whole design of a case: for every motion the full scope; once for
 * the case the frequency sweeps and the code-static comparison. out is
 * owned by the caller (rb_case_design_free, also after an error). The
 * progress callback may be NULL; the results do not depend on it. */
rb_status rb_run_design(const rb_case *c, int n_threads, rb_case_design *out,
                        rb_diag *diag, rb_design_progress_fn progress, void *ctx);
/* The same after `check`: checked[i] is motion i's run at its own level
 * (rb_run_motion's result, history or not), which every search of motion
 * i that asks for that run is given instead of solving it again (the
 * recommended gap's run at the case's own gap, the factors' where a scan
 * level is the motion's own). checked NULL: as rb_run_design. */
rb_status rb_run_design_checked(const rb_case *c, const rb_result *checked, int n_threads,
                                rb_case_design *out, rb_diag *diag,
                                rb_design_progress_fn progress, void *ctx);

/* ---- Fragility ------------------------------------------------------------ */

/* The fragility of c over its motions: every motion x limit state search
 * (on n_threads), then the fits and their bootstrap intervals (n_boot
 * resamples from seed). progress as for rb_run_design (one step per
 * search). out is owned by the caller (rb_case_fragility_free, also after
 * an error). RB_ERR_INVALID for a case without bolts; else as
 * rb_design_factor, diag->key naming the motion and limit state. */
rb_status rb_run_fragility(const rb_case *c, int n_threads, uint64_t seed, unsigned n_boot,
                           rb_case_fragility *out, rb_diag *diag,
                           rb_design_progress_fn progress, void *ctx);

/* The limit states c's fragility has (bit 1 << k of rb_limit_state): all
 * but RB_LIMIT_ANCHORAGE, which a case has with concrete: (whether or not
 * its criteria judge it). */
unsigned rb_run_fragility_present(const rb_case *c);
/* Of those, the ones c's own verdict fails on: overturning always;
 * first-yield under no-yield, usage under no-break; lift-off where
 * validity: fail counts it; the anchorage where the criteria judge the
 * concrete. rb_fragility_governing picks among these. */
unsigned rb_run_fragility_judged(const rb_case *c);
/* The searches of c's fragility: motions x limit states it has. */
size_t rb_run_fragility_searches(const rb_case *c);

/* ---- Response spectra ---------------------------------------------------- */

/* The response spectra of every motion of c (after building filter and
 * scaling: the floor the solver sees), on o's grid, and, for a motion with
 * a target, its fit on the target's check grid. out is owned by the
 * caller (rb_case_spectra_free, also after an error). RB_ERR_INVALID for
 * a bad grid (diag->key "spectrum") or a motion without a spectrum (the
 * critical excitation). */
rb_status rb_run_spectra(const rb_case *c, const rb_spectrum_opts *o, rb_case_spectra *out,
                         rb_diag *diag);
/* ---- Floor accelerations for a table ------------------------------------ */

/* Every motion of c as the cabinet feels it (rockbolt/floors.h): H1, and
 * V where the motion has a vertical, sampled from t = 0 to the end of its
 * run, polarity and scale applied; each with its peak, Arias intensity
 * and, for a component matched to a target, its fit at the target's
 * check points. out is owned by the caller (rb_case_floors_free, also
 * after an error). RB_ERR_INVALID (diag->key the motion's name) for the
 * critical excitation, which has no acceleration of its own, and a
 * series whose first sample is off its own step from 0; RB_ERR_LIMIT for
 * a component over RB_FLOOR_MAX_SAMPLES. */
rb_status rb_run_floors(const rb_case *c, rb_case_floors *out, rb_diag *diag);

/* Restate a fragility of c (from rb_run_fragility, in peak floor
 * acceleration) in another intensity: RB_IM_SA, the 5 % pseudo-spectral
 * acceleration at the cabinet's fixed-base frequency. A motion's Sa is
 * linear in its level, so each capacity is its peak times the motion's
 * Sa(f0) / peak (im_per_pfa); the case's level likewise, and every limit
 * state is fitted again with the same bootstrap seed. The searches are not
 * run again. RB_ERR_INVALID (diag->key "equipment.frequency") for a rigid
 * cabinet, which has no fixed-base frequency. */
rb_status rb_run_fragility_intensity(const rb_case *c, rb_fragility_intensity im,
                                     rb_case_fragility *f, rb_diag *diag);
/* Whether c's fragility can be stated in im, before any search:
 * RB_ERR_INVALID as above otherwise. */
rb_status rb_run_fragility_intensity_ok(const rb_case *c, rb_fragility_intensity im,
                                        rb_diag *diag);

/* The most gap ratios a sweep takes: each is a whole fragility. */
#define RB_FRAGILITY_SWEEP_MAX_POINTS 100

/* The fragility of c with its gap set to each of the n gap ratios (of the
 * lever arm, as the case's gap_ratio: key sets it), one rb_run_fragility
 * after the other; everything else, the level included, is the case's.
 * Every ratio is checked first, as the case loader checks a gap: 0 or at
 * least 1e-9, and one the plate can rotate through (rb_model_derive);
 * RB_ERR_INVALID with diag->key "gap_ratio" and the ratio in the message
 * otherwise, and for n = 0 or n > RB_FRAGILITY_SWEEP_MAX_POINTS. progress
 * counts the searches of all the points. out is owned by the caller
 * (rb_fragility_sweep_free, also after an error); other errors as
 * rb_run_fragility. */
rb_status rb_run_fragility_gap_sweep(const rb_case *c, const double *gap_ratios, size_t n,
                                     int n_threads, uint64_t seed, unsigned n_boot,
                                     rb_fragility_sweep *out, rb_diag *diag,
                                     rb_design_progress_fn progress, void *ctx);

/* Every point of a sweep restated in intensity im, as
 * rb_run_fragility_intensity (the ratio of a motion's Sa(f0) to its peak
 * does not depend on the gap). Errors as that function. */
rb_status rb_run_fragility_sweep_intensity(const rb_case *c, rb_fragility_intensity im,
                                           rb_fragility_sweep *s, rb_diag *diag);

#endif
