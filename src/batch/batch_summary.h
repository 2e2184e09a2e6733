/* Helpers the summary renderers and the reader share. */
#ifndef RB_BATCH_SUMMARY_H
#define RB_BATCH_SUMMARY_H

#include <cjson/cJSON.h>
#include "batch_internal.h"
#include "rockbolt/design.h"
#include "rockbolt/solve.h"

const char *rb_batch_verdict_str(rb_batch_verdict v);
int rb_batch_verdict_parse(const char *s, rb_batch_verdict *v);

/* ---- The columns (batch_columns.c) ------------------------------------------
 *
 * One table of the numbers a run shows, in the order every output shows
 * them: the text table, the CSV, the JSON (written and read back), the
 * mean and the maximum of a case and JUnit's failure lines all loop over
 * it. A new number is one line of the table (and its accessor). */

/* What a column's number is taken from when a run is solved. */
typedef struct {
    const rb_result *result;
    const rb_design_factor_result *factor; /* the case's own design factor;
                                              NULL without design */
    const rb_motion_design *design;        /* NULL without design */
} rb_batch_source;

typedef enum {
    RB_BATCH_AGG_MAX,     /* the largest value governs */
    RB_BATCH_AGG_MIN      /* the smallest does (a design factor) */
} rb_batch_agg;

typedef struct {
    const char *name;     /* JSON key and CSV column */
    const char *label;    /* the text table's column head */
    const char *junit;    /* in JUnit's failure lines; NULL: not there */
    int design;           /* 1: only in summaries with design */
    int width, precision; /* in the text table */
    const char *none_text, *none_csv; /* where the run has none (NaN) */
    rb_batch_agg agg;
    const char *agg_name; /* the key of the aggregate in "max" */
    /* the run's value (NaN: none); design columns are asked only when the
     * run's design search succeeded */
    double (*of)(const rb_batch_source *src);
    /* NULL, or 1 when the value is a bound: text marks it ">", the CSV
     * and the JSON add a NAME_bound column */
    int (*bound_of)(const rb_batch_source *src);
} rb_batch_column;

extern const rb_batch_column rb_batch_columns[];
extern const size_t rb_batch_n_columns;

/* Whether column k is in a summary whose design flag is design. */
int rb_batch_column_shown(size_t k, int design);

/* Fill the columns of run from src: design 0 the run's own, 1 the design's. */
void rb_batch_columns_fill(rb_batch_result *run, const rb_batch_source *src, int design);

/* Mean or maximum (the minimum for a column whose smallest value governs)
 * of each column over a case's runs; NaN where a run has none. */
typedef struct {
    double value[RB_BATCH_MAX_COLUMNS];
} rb_batch_stat;

/* Zero when the case has no results (unreadable, error). */
void rb_batch_stats(const rb_batch_case *c, rb_batch_stat *mean, rb_batch_stat *max);

/* Each output format in three pieces (batch_render.c puts them together):
 * the head, which holds the counts, each case at its position in the
 * output, and the tail. */
#define RB_BATCH_PIECES(fmt)                                                       \
    void rb_batch_render_##fmt##_head(rb_strbuf *b, const rb_batch_summary *s,    \
                                      const rb_batch_counts *n);                  \
    void rb_batch_render_##fmt##_case(rb_strbuf *b, const rb_batch_summary *s,    \
                                      const rb_batch_case *c, size_t pos);        \
    void rb_batch_render_##fmt##_tail(rb_strbuf *b, const rb_batch_summary *s,    \
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
rb_status rb_batch_read_json_head(const cJSON *root, rb_batch_summary *out, rb_diag *diag);
rb_status rb_batch_read_json_case(const cJSON *o, const rb_batch_summary *s,
                                  rb_batch_case *c, rb_diag *diag);

#endif
