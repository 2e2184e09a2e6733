/* A run's peaks, as one table for both reports (report_peaks.c). Private
 * to src/report. */
#ifndef RB_REPORT_PEAKS_H
#define RB_REPORT_PEAKS_H

#include "report_internal.h"
#include "report_json_build.h"

/* Each peak in the JSON report's "peaks" object of a motion's result, in
 * the table's order. */
void rb_report_json_peaks(rb_jctx *cx, cJSON *o, const rb_result *r,
                          const rb_report_norms *n);

/* The peaks that the text templates name, each by its template name. */
void rb_report_text_peaks(rb_tvars *t, const rb_result *r, const rb_report_norms *n);

#endif
