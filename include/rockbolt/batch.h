/* Batch review: many cases, one summary (library rb_batch).
 *
 * A work list is built from case files, directories (their *.yaml files,
 * sorted), glob patterns and equipment lists (CSV files whose rows override
 * fields of a base case, one row per tag). rb_batch_run loads every item,
 * solves every case x motion combination on a pool of threads, judges each
 * run against the case's criteria and fills a summary: one entry per item,
 * with one run per motion. The summary depends only on the inputs: not on
 * the number of threads, nor on how the list was split into shards (see
 * rb_batch_merge). Renderers turn a summary into text, CSV, JSON and JUnit
 * XML; the JSON can be read back, which is how shards are merged. Nothing
 * here prints: progress goes to a callback. docs/batch.md has the formats. */
#ifndef ROCKBOLT_BATCH_H
#define ROCKBOLT_BATCH_H

#include <stdio.h>
#include <stddef.h>
#include <stdint.h>
#include "rockbolt/status.h"
#include "rockbolt/case_overrides.h"
#include "rockbolt/fragility.h"

/* Bumped when a field of the JSON summary is renamed, removed or changes
 * meaning, or when the reader needs one an older summary lacks: 2 added
 * each run's margin, governs and reason, and the fragility's anchorage
 * limit state and governing_limit_state; 3 each fragility limit state's
 * confirmed and model_limited (docs/report-format.md). */
#define RB_BATCH_FORMAT_VERSION 3

/* ---- Work list ----------------------------------------------------------- */

typedef struct {
    char *source;         /* owned: the case file, or the equipment list */
    int line;             /* equipment lists: line of the row; else 0 */
    int base_line, base_col; /* rows: line and column of the base's cell (a
                             multi-line cell before it puts it on a later
                             line than the row's); 0 for --base */
    char *tag;            /* owned: the row's tag; NULL for case files */
    char *base;           /* owned: rows: the base case, as resolved */
    rb_case_override *ov; /* owned, with owned key and value strings */
    size_t n_ov;
    int bad;              /* 1: the item cannot be run; error says why */
    rb_diag *error;       /* owned: set only when bad (a list of 100 000
                             rows would otherwise carry 100 MB of them) */
} rb_batch_item;

typedef struct {
    rb_batch_item *items; /* owned, in work order */
    size_t n, cap;
    const char *encoding; /* not owned: the equipment lists' character
                             encoding, an iconv name ("cp1252"); NULL: UTF-8.
                             Set it before adding lists. */
    const struct rb_sandbox *sandbox; /* not owned: the lists, and the cases
                             their items load, must lie in it
                             (rockbolt/sandbox.h); NULL: anywhere. Set it
                             before adding lists. */
} rb_batch_list;

/* Add what arg names, in this order of checks: a directory (its *.yaml
 * files, sorted by name; not recursive), a pattern with *, ? or [ (glob,
 * sorted), a file ending in .csv (an equipment list, rows in file order),
 * else a case file. default_base (may be NULL) is the base case for lists
 * without a base column, relative to the working directory. Names that
 * match nothing and lists that cannot be read become bad items, so the
 * batch still runs and reports them. Returns RB_ERR_NOMEM only. */
rb_status rb_batch_list_add(rb_batch_list *l, const char *arg, const char *default_base);

void rb_batch_list_free(rb_batch_list *l);

/* Parse an equipment list into l (called by rb_batch_list_add): UTF-8
 * (a byte-order mark allowed) unless l->encoding names another, comma- or
 * semicolon-separated as its header shows. */
rb_status rb_batch_list_read_csv(rb_batch_list *l, const char *path, const char *default_base);

/* ---- Summary --------------------------------------------------------------- */

typedef enum {
    RB_BATCH_PASS = 0,    /* every motion meets the criteria */
    RB_BATCH_FAIL,        /* a motion fails them */
    RB_BATCH_UNREADABLE,  /* the case could not be read (bad input) */
    RB_BATCH_ERROR        /* a solver run or a report failed (internal) */
} rb_batch_verdict;

/* The numbers of a run that every summary shows, at most this many
 * (src/batch/batch_columns.c holds the table of them). */
#define RB_BATCH_MAX_COLUMNS 16

/* One motion of a case, solved and judged. */
typedef struct {
    char *motion;         /* owned: the motion's name */
    int pass;
    unsigned warnings;    /* validity warnings (rb_verdict.warnings) */
    /* one number per column of the batch's table, in its order: the larger
     * toughness usage of the two rows, elastic frame shear / W, the larger
     * row force / Fy, theta / alpha and, with design, the design factor
     * (A* / largest passing level) and the recommended gap ratio; NaN
     * where the run has none (no bolts, no design, no factor found) */
    double value[RB_BATCH_MAX_COLUMNS];
    unsigned bounds;      /* bit k: value[k] is a bound (the design factor:
                             no failing level up to the scan's end) */
    /* the judge's one "governs" rule (rb_verdict_governing): the run's
     * margin (0 for a failing run) and the limit of it (rb_governs_limit) */
    double margin;
    int limit;
    char *reason;         /* owned: the run's verdict reason, one line */
    /* the concrete check (a case with concrete:): the largest 17.8
     * utilization and the mode that governs it (rb_anchor_mode: the
     * governing tension mode when tension's share is the larger, else the
     * governing shear mode); has_anchor 0 without one */
    int has_anchor;
    double anchor_utilization;
    int anchor_mode;
} rb_batch_result;

/* One limit state of a case's fragility (batch --fragility), as
 * rb_run_fragility gives it; the numbers are its own doubles. */
typedef struct {
    int present;          /* 0: the case has no such limit state (the
                             anchorage's without concrete:); the rest 0 */
    int fitted;           /* 0: fewer than two motions reached it */
    double median_mps2, beta;
    double median_lo_mps2, median_hi_mps2; /* 90 % bootstrap interval; NaN
                             when too few resamples could be fitted */
    double p_at_level;    /* at the case's own level */
    size_t reached;       /* motions that reached it within the scan */
    int confirmed;        /* its capacities confirmed at tighter tolerances
                             (the governing state's) */
    size_t model_limited; /* capacities that are the model's limit (the
                             vertical reaching -g), counted as reached */
} rb_batch_limit;

/* A case's fragility over its motions (rockbolt/fragility.h). */
typedef struct {
    char *error;          /* owned: why the case has none (it has no bolts);
                             NULL when it was computed */
    double g_mps2, level_mps2; /* the case's g and own level (motion 1's peak),
                             the level and medians in the summary's intensity */
    double im_freq_hz;    /* spectral acceleration: at this frequency (the
                             cabinet's f0); 0 for the peak floor acceleration */
    rb_batch_limit limits[RB_N_LIMITS];
    int governing;        /* the limit state that governs
                             (rb_fragility_governing), -1: none */
    double p58_weights[RB_P58_MAX_WEIGHTS]; /* the case's fragility:
                             damage_state_weights */
    size_t n_p58_weights; /* 0: FEMA P-58's */
} rb_batch_fragility;

typedef struct {
    size_t index;         /* position in the whole work list */
    char *source;         /* owned */
    int line;
    char *tag;            /* owned: row tag or case name (file stem if
                             unreadable) */
    rb_batch_verdict verdict;
    char *reason;         /* owned: one line */
    rb_diag *error;       /* owned: the first error (UNREADABLE, ERROR); NULL
                             when there is none, so that a summary row stays
                             a few hundred bytes (read it with
                             rb_batch_case_error) */
    size_t n_errors;      /* how many the load reported */
    rb_batch_result *runs;   /* owned, one per motion (none when unreadable) */
    size_t n_runs;
    rb_batch_fragility *fragility; /* owned: with --fragility, for a case
                             that was solved; else NULL */
    /* the code-static comparison of a solved case with design.code (as
     * `design` reports it): F_p and F_p / W_p, the static tension of the
     * far bolt row and its ratio to the row's phi N_sa, and the 17.8
     * utilization of that static demand (NaN without concrete:); has_code
     * 0 without design.code */
    int has_code;
    double code_fp_n, code_fp_over_wp, code_tension_n, code_steel_ratio,
           code_anchor_utilization;
} rb_batch_case;

/* "sha256:" and 64 hex digits, with the NUL. */
#define RB_BATCH_DIGEST_CHARS 72

/* Counts over the cases of a summary (rb_batch_count). */
typedef struct {
    size_t cases, passed, failed, unreadable, errors, runs;
} rb_batch_counts;

typedef struct {
    int design;           /* design factor and gap were asked for */
    int fragility;        /* each case's fragility was asked for */
    uint64_t seed;        /* of its bootstrap */
    rb_fragility_intensity intensity; /* its intensity measure */
    size_t total;         /* items in the whole work list */
    size_t shard, n_shards; /* 1-based shard; 0/0 for the whole list */
    rb_batch_case *cases; /* owned, by index */
    size_t n_cases;
    char inputs_digest[RB_BATCH_DIGEST_CHARS]; /* of the work list and the
                             files it names (rb_batch_list_digest); "" if
                             unknown */
    int streamed;         /* the cases went to rb_batch_opts.sink as they
                             were done and are gone: cases is NULL, n_cases
                             says how many there were, counts what they
                             were */
    rb_batch_counts counts; /* only when streamed */
    const char *name;     /* borrowed: the file a summary was read from (the
                             name given to rb_batch_reader_open), for merge's
                             messages; NULL or "" when unnamed */
} rb_batch_summary;

void rb_batch_summary_free(rb_batch_summary *s);

/* The case's first error, or an empty diag when it has none; never NULL. */
const rb_diag *rb_batch_case_error(const rb_batch_case *c);
/* Set the case's error to a copy of d; 0 when memory runs out. */
int rb_batch_case_set_error(rb_batch_case *c, const rb_diag *d);

/* The governing motion of a case: the failing motion with the largest
 * usage if any fails, else the motion with the largest usage; ties go to
 * the larger force / Fy, then the earlier motion. 0 when there are none. */
size_t rb_batch_governing(const rb_batch_case *c);

/* Counts over a summary: its cases', or what they were when streamed. */
void rb_batch_count(const rb_batch_summary *s, rb_batch_counts *out);
/* Add one case to counts: the one rule both ways of counting use. */
void rb_batch_count_case(rb_batch_counts *n, const rb_batch_case *c);

/* ---- Running ---------------------------------------------------------- */

typedef struct {
    size_t cases_done, cases_total;   /* of this shard */
    size_t runs_done;
    size_t failed, unreadable;        /* so far */
} rb_batch_progress;

typedef struct {
    int n_threads;            /* <= 0: one per online processor */
    int design;               /* also the design factor and recommended gap */
    int fragility;            /* also each case's fragility (rb_run_fragility,
                                 RB_FRAGILITY_RESAMPLES resamples) */
    uint64_t seed;            /* of the fragility's bootstrap */
    rb_fragility_intensity intensity; /* the fragility's intensity: the peak
                                 floor acceleration (0, the default) or the
                                 5 % spectral acceleration at each
                                 cabinet's f0, as rb_run_fragility_intensity */
    const char *reports_dir;  /* NULL: no per-case reports; else one JSON
                                 and one text report per case */
    const char *report_template; /* text of report.txt; needed with reports */
    /* reports are staged here and renamed into place only by its
     * rb_outplan_write (all or none); NULL: each written at once */
    struct rb_outplan *report_stage;
    size_t shard, n_shards;   /* 1-based shard of n; 0/0: all */
    /* Called from worker threads, one call at a time, when a run or a
     * case is done. May be NULL. */
    void (*progress)(void *ctx, const rb_batch_progress *p);
    void *progress_ctx;
    /* When set, finished cases go here, in list order, one call at a
     * time (from the worker thread that finished the first outstanding
     * case), and are then freed: the summary keeps only
     * their counts (streamed), so that memory does not grow with them.
     * first is the position of cases[0] in the summary. A status other
     * than RB_OK stops the run with it. */
    rb_status (*sink)(void *ctx, const rb_batch_summary *s, const rb_batch_case *cases,
                      size_t first, size_t n);
    void *sink_ctx;
} rb_batch_opts;

void rb_batch_opts_init(rb_batch_opts *o);

/* The file name, without ".json" or ".txt", of the reports of the item at
 * index of a list of total items whose tag (row tag, else case name) is
 * tag: "<index>-<tag with unsafe bytes as _>", at most 120 bytes of tag. */
void rb_batch_report_stem(size_t index, const char *tag, size_t total, char *buf,
                          size_t n);

/* The items of shard k of n: those whose index i has i % n == k - 1. */
int rb_batch_in_shard(size_t index, size_t shard, size_t n_shards);

/* Run the list (or its shard) into out (owned by the caller, free with
 * rb_batch_summary_free, also after an error). Cases that cannot be read
 * or solved are verdicts, not errors: the call fails only for
 * RB_ERR_NOMEM or bad options (RB_ERR_INVALID, diag says which). */
/* The digest of a work list, alike in every shard: each item's source,
 * line, tag, base and overrides, then the bytes of every distinct case
 * file, list and base it names. RB_ERR_NOMEM, else RB_OK. */
rb_status rb_batch_list_digest(const rb_batch_list *l, char out[RB_BATCH_DIGEST_CHARS]);

rb_status rb_batch_run(const rb_batch_list *l, const rb_batch_opts *o,
                       rb_batch_summary *out, rb_diag *diag);

/* ---- Output ------------------------------------------------------------- */

typedef enum {
    RB_BATCH_TEXT,        /* the table for the terminal */
    RB_BATCH_CSV,         /* one row per case and motion */
    RB_BATCH_JSON,        /* what merge reads back */
    RB_BATCH_JUNIT,       /* one testcase per case */
    RB_BATCH_P58,         /* FEMA P-58 fragility rows, one per case
                             (with --fragility) */
    RB_BATCH_N_FORMATS
} rb_batch_format;

/* Each renderer returns a NUL-terminated string the caller frees, or NULL
 * when memory runs out. rb_batch_render is the whole summary; it is the
 * head, each case at its position pos (0, 1, ...) and the tail, in that
 * order, which can also be rendered apart: a streamed summary's cases
 * are rendered as they come and its head, which holds the counts, at the
 * end (n from rb_batch_count). */
char *rb_batch_render(rb_batch_format f, const rb_batch_summary *s);
char *rb_batch_render_head(rb_batch_format f, const rb_batch_summary *s,
                           const rb_batch_counts *n);
char *rb_batch_render_case(rb_batch_format f, const rb_batch_summary *s,
                           const rb_batch_case *c, size_t pos);
char *rb_batch_render_tail(rb_batch_format f, const rb_batch_summary *s,
                           const rb_batch_counts *n);

/* Reading a JSON summary as batch --json writes it, one case at a time,
 * so that memory does not grow with the summary (docs/robustness.md): the
 * head (every member before "cases", which must come last, as batch writes
 * it) into head, then rb_batch_reader_next for each case in the file's
 * order. Each piece has a limit, a summary none; a piece over its limit is
 * RB_ERR_LIMIT, text that is not a summary RB_ERR_PARSE, a read error
 * RB_ERR_IO, each with the file, line, column, field and reason in diag. */
#define RB_BATCH_READ_HEAD_MAX (64u * 1024u)       /* the head's values */
#define RB_BATCH_READ_CASE_MAX (4u * 1024u * 1024u) /* one case's text: 1000
                             motions of a case take about 0.7 MB */
#define RB_BATCH_READ_KEY_MAX 256                   /* a key of the head */
#define RB_BATCH_READ_DEPTH 32                      /* nesting in a value */
#define RB_BATCH_READ_KEEP (1024u * 1024u)          /* a buffer grown past
                             this for one long case is not kept */
typedef struct rb_batch_reader rb_batch_reader;
/* name: the file's name in diagnostics. fp stays the caller's. */
rb_status rb_batch_reader_open(FILE *fp, const char *name, rb_batch_summary *head,
                               rb_batch_reader **out, rb_diag *diag);
/* The next case into c (owned by the caller then), *got 1; *got 0 at the
 * end of the list, once the rest of the file is checked. */
rb_status rb_batch_reader_next(rb_batch_reader *r, rb_batch_case *c, int *got,
                               rb_diag *diag);
void rb_batch_reader_close(rb_batch_reader *r);

/* A whole summary in text, read with the reader above (no file name in
 * its diagnostics). */
rb_status rb_batch_summary_parse(const char *text, rb_batch_summary *out,
                                 rb_diag *diag);

/* Merge the summaries of the shards of one work list into out, which then
 * renders byte for byte as a single run's. Every shard must come from the
 * same list (same total, design and fragility flags and seed) and
 * together they must hold each index once, each summary in the list's
 * order. RB_ERR_INVALID with the reason in diag otherwise. */
rb_status rb_batch_merge(const rb_batch_summary *shards, size_t n,
                         rb_batch_summary *out, rb_diag *diag);

/* The same, streamed: heads are the n shards' heads (rb_batch_reader_open),
 * next gives shard k's next case (*got 0 at its end; the case is then the
 * merge's) and each merged case goes to sink, in the list's order, and is
 * freed; out gets the head and counts (streamed). Each shard's cases must
 * come in the list's order, as batch writes them: the merge holds one case
 * per shard at a time. */
typedef rb_status (*rb_batch_next_fn)(void *ctx, size_t k, rb_batch_case *c, int *got,
                                      rb_diag *diag);
rb_status rb_batch_merge_stream(const rb_batch_summary *heads, size_t n,
                                rb_batch_next_fn next, void *next_ctx,
                                rb_status (*sink)(void *ctx, const rb_batch_summary *s,
                                                  const rb_batch_case *cases,
                                                  size_t first, size_t n),
                                void *sink_ctx, rb_batch_summary *out, rb_diag *diag);

#endif
