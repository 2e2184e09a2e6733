/* Helpers the summary renderers and the reader share. */
#ifndef RB_BATCH_SUMMARY_H
#define RB_BATCH_SUMMARY_H

#include <cjson/cJSON.h>
#include "batch_internal.h"

const char *rb_batch_verdict_str(rb_batch_verdict v);
int rb_batch_verdict_parse(const char *s, rb_batch_verdict *v);

/* Mean or maximum of each result over a case's runs; for the design
 * factor, whose smallest value governs, the "maximum" holds the minimum.
 * The design values are there (has_*) only when every run has one. */
typedef struct {
    double usage, shear_over_w, force_over_fy, theta_over_alpha;
    int has_factor, has_gap;
    double design_factor, gap_ratio;
} rb_batch_stat;

/* Zero when the case has no results (unreadable, error). */
void rb_batch_stats(const rb_batch_case *c, rb_batch_stat *mean, rb_batch_stat *max);

/* Each output format in three pieces (batch_render.c puts them together):
 * the head, which holds the counts, each case at its position in the
 * output, and the tail. */
#define RB_BATCH_PIECES(fmt)                                                       \
    void rb_batch_##fmt##_head(rb_strbuf *b, const rb_batch_summary *s,             \
                               const rb_batch_counts *n);                           \
    void rb_batch_##fmt##_case(rb_strbuf *b, const rb_batch_summary *s,             \
                               const rb_batch_case *c, size_t pos);                 \
    void rb_batch_##fmt##_tail(rb_strbuf *b, const rb_batch_summary *s,             \
                               const rb_batch_counts *n);
RB_BATCH_PIECES(text)
RB_BATCH_PIECES(csv)
RB_BATCH_PIECES(json)
RB_BATCH_PIECES(junit)
RB_BATCH_PIECES(p58)

/* "sha256:" and the hex SHA-256 of text (batch_digest.c). */
void rb_batch_digest_text(const char *text, char out[RB_BATCH_DIGEST_CHARS]);

/* Reading a summary back (batch_json.c), a piece at a time for
 * batch_read.c: the head's members (all but "cases") from root, and one
 * element of "cases", which must match its digest. RB_ERR_PARSE with the
 * field in diag->key and the reason in diag->msg, no place. */
rb_status rb_batch_json_read_head(const cJSON *root, rb_batch_summary *out, rb_diag *diag);
rb_status rb_batch_json_read_case(const cJSON *o, const rb_batch_summary *s,
                                  rb_batch_case *c, rb_diag *diag);

#endif
