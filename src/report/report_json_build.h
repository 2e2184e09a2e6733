/* The JSON report's tree builders, shared by report_json*.c. Private to
 * src/report. */
#ifndef RB_REPORT_JSON_BUILD_H
#define RB_REPORT_JSON_BUILD_H

#include <cjson/cJSON.h>
#include "rockbolt/report.h"

/* Builder state: the first problem met is kept, later calls are no-ops. */
typedef struct {
    rb_status st;
    const char *where;     /* section being written, for diagnostics */
    char where_buf[64];    /* "motions[i]" */
    char bad_key[128];
} rb_jctx;

void rb_j_oom(rb_jctx *cx, const void *added);
cJSON *rb_j_obj(rb_jctx *cx, cJSON *parent, const char *key);
/* An array under key; NULL (and cx->st set) when out of memory. */
cJSON *rb_j_arr(rb_jctx *cx, cJSON *parent, const char *key);
/* item at the end of arr, which takes it; an item NULL, or one that cannot
 * be added, is out of memory (the item is then freed). Nothing after an
 * earlier error. */
void rb_j_append(rb_jctx *cx, cJSON *arr, cJSON *item);
/* A new object at the end of arr; NULL after an error. */
cJSON *rb_j_item(rb_jctx *cx, cJSON *arr);
void rb_j_num(rb_jctx *cx, cJSON *o, const char *key, double v);
void rb_j_null(rb_jctx *cx, cJSON *o, const char *key);
void rb_j_opt(rb_jctx *cx, cJSON *o, const char *key, int have, double v);
void rb_j_norm(rb_jctx *cx, cJSON *o, const char *key, double v);
void rb_j_theta0(rb_jctx *cx, cJSON *o, double v);
void rb_j_bool(rb_jctx *cx, cJSON *o, const char *key, int v);
void rb_j_str(rb_jctx *cx, cJSON *o, const char *key, const char *s);
void rb_j_pair(rb_jctx *cx, cJSON *o, const char *key, const double v[2]);
void rb_j_pair_norm(rb_jctx *cx, cJSON *o, const char *key, const double v[2]);
void rb_j_pair_bool(rb_jctx *cx, cJSON *o, const char *key, const int v[2]);
void rb_j_pair_when(rb_jctx *cx, cJSON *o, const char *key,
                    const int happened[2], const double t[2]);

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
