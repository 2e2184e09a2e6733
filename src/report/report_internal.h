/* What the JSON and text reports share: the normalised forms of a result
 * and the names of enum values, computed in one place so the two reports
 * cannot disagree. Private to src/report. */
#ifndef RB_REPORT_INTERNAL_H
#define RB_REPORT_INTERNAL_H

#include "rockbolt/report.h"
#include "rockbolt/template.h"

/* Normalised forms of one result. A ratio whose denominator is zero or not
 * positive (no motion, no bolts) is NAN here and "no value" in a report. */
typedef struct {
    double v0_n;                 /* V0 = M a, a = peak floor acceleration */
    double peak_g;               /* a / g */
    double peak_over_a_star;     /* a / A* */
    double shear_elastic_over_w, shear_elastic_over_v0;
    double shear_total_over_w, shear_total_over_v0;
    double min_vertical_over_w;  /* least vertical floor reaction / W */
    double force_over_fy[2];     /* max bolt force / Fy_row */
    double final_gap_ratio[2];   /* final gap / l */
} rb_report_norms;

void rb_report_norms_compute(const rb_report *r, const rb_report_motion *m,
                             rb_report_norms *n);

/* Ratio a / b, or NAN when b is not positive or either is not finite. */
double rb_report_ratio(double a, double b);

/* Fixed names of enum values, as written in the reports; never NULL. */
const char *rb_report_side_str(int side); /* RB_LEFT, RB_RIGHT */

/* ---- report_suite.c: a case's motions taken together -------------------- */
#define RB_SUITE_N 6
/* Names of the suite values, as written in the reports: usage (larger
 * row), bolt_force_over_fy (larger row), shear_elastic_over_w,
 * shear_total_over_w, u_over_ustatic, theta_over_alpha. */
extern const char *const rb_suite_names[RB_SUITE_N];
typedef struct {
    size_t governing;            /* index of the governing motion */
    double margin;               /* its margin (rb_verdict_governing) */
    int limit;                   /* and the limit of it (rb_governs_limit) */
    double mean[RB_SUITE_N];     /* NAN when no motion has the value */
    double max[RB_SUITE_N];
} rb_report_suite;
void rb_report_suite_compute(const rb_report *r, rb_report_suite *s);
/* The governing motion of a report's motions by the judge's one rule
 * (rb_verdict_governing), with its margin and limit (rb_governs_limit;
 * either may be NULL); 0 for a report without motions. */
size_t rb_report_governing(const rb_report *r, double *margin, int *limit);

/* ---- report_text_vars.c: template variable tables ---------------------- */
#define RB_TXT_MAX_VARS 160 /* per scope; an assert guards it */

/* A table being filled; holds at most RB_TXT_MAX_VARS (asserted). */
typedef struct {
    rb_tvar *v;
    size_t n;
} rb_tvars;
rb_tvar *rb_tv_add(rb_tvars *t, const char *name, rb_tval_kind kind);
/* A number; NAN (a ratio without a denominator) renders as "n/a". */
void rb_tv_num(rb_tvars *t, const char *name, double x);
/* x when have, else "n/a". */
void rb_tv_opt(rb_tvars *t, const char *name, int have, double x);
void rb_tv_int(rb_tvars *t, const char *name, long x);
/* A string; NULL renders as "n/a" and is false in a section. */
void rb_tv_str(rb_tvars *t, const char *name, const char *s);
const char *rb_yes_no(int b);

/* ---- report_text_design.c: the design lists of the text report ---------- */
typedef struct rb_txt_arena rb_txt_arena;
rb_txt_arena *rb_txt_arena_new(void);        /* NULL when out of memory */
void rb_txt_arena_free(rb_txt_arena *a);     /* accepts NULL */
/* The top-level list "design" and a motion's list "motion_design": one item
 * when r->design is set, none otherwise. Tables live in a. */
rb_status rb_report_text_case_design(const rb_report *r, rb_txt_arena *a,
                                     rb_tlist *out);
rb_status rb_report_text_motion_design(const rb_report *r, size_t i, rb_txt_arena *a,
                                       rb_tlist *out);
/* n zeroed items of size bytes that live as long as a; NULL when out of
 * memory (and every later call then fails too). */
void *rb_txt_arena_alloc(rb_txt_arena *a, size_t n, size_t size);

/* What bounds the code-static F_p, in words (rb_code_result.bound). */
const char *rb_report_code_bound_str(int bound);
/* Whether the code-static check passes: the steel (T / phi N_sa at most
 * 1), and the anchorage in concrete (its 17.8 utilization below 1). */
int rb_report_code_steel_pass(const rb_code_result *k);
int rb_report_code_concrete_pass(const rb_code_result *k);

/* ---- report_text_anchor.c: the concrete check of the text report ------- */
/* The top-level list "concrete" (one item for a case with concrete:, none
 * otherwise) with its list "modes"; and a motion's variables has_anchorage
 * and anchor_*. */
rb_status rb_report_text_concrete(const rb_report *r, rb_txt_arena *a, rb_tlist *out);
void rb_report_text_motion_anchorage(rb_tvars *t, const rb_report *r,
                                     const rb_report_motion *m);
/* A motion's list "anchor_modes": each mode's demand and demand / design
 * strength at the instant of its largest utilization (none without). */
rb_status rb_report_text_motion_anchor_modes(const rb_report *r, const rb_report_motion *m,
                                             rb_txt_arena *a, rb_tlist *out);

/* ---- the fragility's, its sweep's, the spectra's and the floor motions'
 * JSON: trees built by rb_j_* (rockbolt/jsonbuild.h), laid out by
 * rb_json_print_layout ---------------------------------------------------- */
#include "rockbolt/jsonbuild.h"
#include "rockbolt/jsonprint.h"
/* fragility_write.c: the root of such a file, with its format, the format's
 * version (1) and the case's name; NULL (and cx->st set) when out of memory. */
cJSON *rb_report_file_json(rb_jctx *cx, const char *format, const rb_case *c);
/* The file's text laid out by layout, root freed; NULL after any problem. */
char *rb_report_file_print(rb_jctx *cx, cJSON *root, const rb_json_layout *layout);
/* Limit state k of f as an object at the end of arr: its fit, whether its
 * capacities are confirmed, how many are the model's limit. */
void rb_report_fragility_limit_json(rb_jctx *cx, cJSON *arr, const rb_case_fragility *f,
                                    int k);
/* "judged_limit_states": [...] and "governing_limit_state": its name or
 * null (rb_fragility_governing). */
void rb_report_fragility_governing_json(rb_jctx *cx, cJSON *o, const rb_case_fragility *f);
/* The root with the head a fragility and its sweep share: format, its
 * version, case, intensity (its frequency and damping for a spectral one), g, A* and the
 * case's level, from f0 (NULL: a sweep without points). */
cJSON *rb_report_fragility_head_json(rb_jctx *cx, const char *format, const rb_case *c,
                                     const rb_case_fragility *f0);
/* "bootstrap": {resamples, seed, interval}. */
void rb_report_fragility_bootstrap_json(rb_jctx *cx, cJSON *root,
                                        const rb_case_fragility *f0);
/* spectrum_write.c: "target": {type, its levels, damping, check range and
 * band}, for every JSON output that compares a motion with one. */
void rb_report_target_json(rb_jctx *cx, cJSON *o, const rb_target *t);
/* "acceptance": {...}: a laboratory's acceptance of a motion
 * (rockbolt/accept.h), every offset's outcome with it. */
void rb_report_accept_json(rb_jctx *cx, cJSON *o, const rb_accept_result *ac);

#endif
