/* The validation program: runs the thesis cases of cases/thesis/ through
 * the library and compares each quantity with the value the thesis prints.
 *
 * The expected values live in cases/thesis/expected.csv (one row per
 * quantity, with its source, tolerance and the reason for that tolerance);
 * vd_table.c reads it, vd_eval.c computes rockbolt's value of each row,
 * vd_report.c writes docs/validation.md. */
#ifndef RB_VD_H
#define RB_VD_H

#include <stddef.h>
#include <stdio.h>

/* Size of every error message buffer: room for a loader diagnostic (file,
 * key and message of an rb_diag) with a prefix. */
#define VD_ERR 1400

/* ---- The table of thesis values ---------------------------------------- */

typedef enum {
    VD_TOL_ABS = 0,   /* |rockbolt - thesis| <= tol */
    VD_TOL_REL,       /* |rockbolt - thesis| <= tol |thesis| */
    VD_TOL_RANGE,     /* lo <= rockbolt <= hi: the interval a thesis value
                         read off a coarse grid stands for */
    VD_TOL_EXACT      /* words (yes/no, Break, ...): must be equal */
} vd_tol_kind;

typedef struct {
    int line;             /* line in the CSV, for messages */
    char *section;        /* heading of the section the row belongs to */
    char *kase;           /* case file name inside cases/thesis/ */
    int motion;           /* 1-based motion index (1 when empty) */
    char *quantity;       /* evaluator name, optionally ":arg" and "@-1" */
    char *label;          /* what the row is, in words */
    char *thesis;         /* the thesis's value as printed */
    char *source;         /* table / figure / page */
    vd_tol_kind tol_kind;
    double tol;
    double lo, hi;        /* VD_TOL_RANGE; -/+HUGE_VAL when open */
    char *tol_text;       /* as written, for the report */
    int differs_note;     /* 0: must agree; N: known to differ, see note N */
    char *reason;         /* why this tolerance */
} vd_row;

typedef struct {
    vd_row *rows;         /* owned */
    size_t n, cap;
} vd_table;

/* Read the table; on error print "file:line: message" to stderr, return 0. */
int vd_table_read(const char *path, vd_table *t);
void vd_table_free(vd_table *t);

/* ---- Evaluation --------------------------------------------------------- */

typedef enum {
    VD_AGREES = 0,        /* within the tolerance */
    VD_OUT,               /* outside the tolerance of a row that must agree */
    VD_DIFFERS,           /* outside, and known to differ (see the note) */
    VD_AGREES_UNEXPECTED, /* within, though a difference was expected */
    VD_ERROR              /* could not be computed */
} vd_verdict;

typedef struct {
    int numeric;          /* 1: value holds the number; 0: word holds a word */
    double value;
    char word[32];
    char diff[48];        /* difference as printed ("" for words) */
    vd_verdict verdict;
    char error[VD_ERR];   /* why VD_ERROR */
} vd_outcome;

typedef struct vd_ctx vd_ctx;

/* root: directory holding cases/thesis (the source root). n_threads for
 * the design searches (<= 0: all processors). */
vd_ctx *vd_ctx_new(const char *root, int n_threads);
void vd_ctx_free(vd_ctx *c);

/* Compute rockbolt's value of row r and judge it. */
void vd_evaluate(vd_ctx *c, const vd_row *r, vd_outcome *out);

/* Number of solver runs and searches done so far (for the timing line). */
long vd_ctx_runs(const vd_ctx *c);

/* ---- Figures ----------------------------------------------------------- */

/* A case whose time history the thesis shows as a figure. */
typedef struct {
    const char *kase;     /* case file inside cases/thesis/ */
    const char *figure;   /* the thesis's figure number(s) */
} vd_figure_spec;

/* The figure cases, ended by a {NULL, NULL} entry. */
extern const vd_figure_spec vd_figures[];

/* Make directory dir if it does not exist; 0 (reason on stderr) on failure. */
int vd_figure_dir(const char *dir);

/* Solve motion 1 of case kase with a time history and write its figure to
 * svg_path. Returns 0 (reason on stderr) if the case or the run fails. */
int vd_figure_write(const char *root, const char *kase, const char *svg_path);

/* ---- Report ------------------------------------------------------------- */

typedef struct {
    const char *command;     /* the command that regenerates the file */
    const char *notes_path;  /* hand-written notes appended verbatim */
    const char *const *figure_svgs; /* per vd_figures entry, its SVG path
                                       relative to the report, or NULL when
                                       not drawn; NULL: no figures at all */
    const char *root;        /* source root: the validity section runs the
                                cases under it; NULL: no such section */
} vd_report_opts;

/* vd_validity.c: the validity section (every thesis case, each check's
 * status). Returns 0 on a write error. */
int vd_validity_write(FILE *fp, const char *root);

/* Write the Markdown report of every row to fp. Returns 0 on a write or
 * read error. */
int vd_report_write(FILE *fp, const vd_table *t, const vd_outcome *o,
                    const vd_report_opts *opts);

#endif
