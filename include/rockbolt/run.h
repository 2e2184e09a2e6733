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

#endif
