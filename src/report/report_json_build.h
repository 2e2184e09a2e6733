/* The JSON report's parts, shared by report_json*.c and sweep_write.c.
 * Private to src/report. */
#ifndef RB_REPORT_JSON_BUILD_H
#define RB_REPORT_JSON_BUILD_H

#include <cjson/cJSON.h>
#include "rockbolt/jsonbuild.h"
#include "rockbolt/report.h"

/* The report's own values (the generic builders are rockbolt/jsonbuild.h). */
void rb_j_theta0(rb_jctx *cx, cJSON *o, double v);

/* sweep_write.c: each sweep an object at the end of arr. */
void rb_report_json_sweep(rb_jctx *cx, cJSON *arr, const rb_sweep *s);

/* report_json_design.c: the design parts, written only when r->design is
 * set; the case's part under the root, a motion's under its object. */
void rb_report_json_case_design(rb_jctx *cx, cJSON *root, const rb_report *r);
void rb_report_json_motion_design(rb_jctx *cx, cJSON *motion_o, const rb_report *r,
                                  size_t i);

/* report_json_validity.c: a motion's validity block, and an array of the
 * names of the checks in a warnings mask. */
void rb_report_json_validity(rb_jctx *cx, cJSON *motion_o, const rb_report *r,
                             const rb_report_motion *m);
void rb_report_json_convergence(rb_jctx *cx, cJSON *validity_o, const rb_report *r,
                                const rb_report_motion *m);
void rb_j_warnings(rb_jctx *cx, cJSON *o, const char *key, unsigned warnings);

/* report_json_anchor.c: the concrete check, for a case with concrete:. */
void rb_report_json_anchorage(rb_jctx *cx, cJSON *root, const rb_report *r);
void rb_report_json_motion_anchorage(rb_jctx *cx, cJSON *motion_o, const rb_report *r,
                                     const rb_report_motion *m);

#endif
