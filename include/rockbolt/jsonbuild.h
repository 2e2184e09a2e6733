/* The one way JSON trees are built (library rb_report): the check report,
 * the design's sweeps, the batch summary and the fragility, spectra and
 * floor-motion files add their values through these,
 * and every number is printed by rb_json_number (rockbolt/jsonnum.h), so
 * the same double is the same text in all of them. The text is printed
 * by rb_json_print (rockbolt/jsonprint.h).
 *
 * The rb_j_* calls that take an rb_jctx are no-ops once a problem has been
 * met, so a builder need not check every call: the first problem
 * (allocation failure, or a non-finite number where one is not allowed,
 * with the key it was meant for) is kept in the context. */
#ifndef ROCKBOLT_JSONBUILD_H
#define ROCKBOLT_JSONBUILD_H

#include <stddef.h>
#include <cjson/cJSON.h>
#include "rockbolt/status.h"

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
/* A finite number; a non-finite one is an error (RB_ERR_NONFINITE, with
 * the key in cx->bad_key). */
void rb_j_num(rb_jctx *cx, cJSON *o, const char *key, double v);
/* A number, or null when it is not finite (rb_json_number_or_null). */
void rb_j_num_or_null(rb_jctx *cx, cJSON *o, const char *key, double v);
void rb_j_null(rb_jctx *cx, cJSON *o, const char *key);
void rb_j_opt(rb_jctx *cx, cJSON *o, const char *key, int have, double v);
void rb_j_norm(rb_jctx *cx, cJSON *o, const char *key, double v);
void rb_j_bool(rb_jctx *cx, cJSON *o, const char *key, int v);
void rb_j_str(rb_jctx *cx, cJSON *o, const char *key, const char *s);
/* Text from the inputs (a case's or a motion's name, a path): bytes that
 * are not UTF-8 written as \xHH (rb_utf8_fix), as every output shows them,
 * so that it reads back as it was. NULL is "". */
void rb_j_text(rb_jctx *cx, cJSON *o, const char *key, const char *s);
/* A count or seed, printed whole. */
void rb_j_int(rb_jctx *cx, cJSON *o, const char *key, long long v);
void rb_j_uint(rb_jctx *cx, cJSON *o, const char *key, unsigned long long v);
/* n numbers as an array, each null when it is not finite. */
void rb_j_nums(rb_jctx *cx, cJSON *o, const char *key, const double *v, size_t n);
/* Per-row values as {"left": .., "right": ..}. */
void rb_j_pair(rb_jctx *cx, cJSON *o, const char *key, const double v[2]);
void rb_j_pair_or_null(rb_jctx *cx, cJSON *o, const char *key, const double v[2]);
void rb_j_pair_norm(rb_jctx *cx, cJSON *o, const char *key, const double v[2]);
void rb_j_pair_bool(rb_jctx *cx, cJSON *o, const char *key, const int v[2]);
void rb_j_pair_when(rb_jctx *cx, cJSON *o, const char *key,
                    const int happened[2], const double t[2]);

/* rb_j_num_or_null for writers that chain their own checks (the batch
 * summary): nonzero when added, 0 when out of memory. */
int rb_j_add_num(cJSON *o, const char *key, double v);
/* rb_j_text for such writers: the member added, NULL when out of memory. */
cJSON *rb_j_add_text(cJSON *o, const char *key, const char *s);

#endif
