/* Design checks (thesis sec. 6.6): the design factor, the recommended gap
 * ratio, frequency and amplitude sweeps, and the code-static comparison
 * (ASCE 7-16 / 7-22 component force against ACI 318-19 anchor steel).
 *
 * Every search is a set of independent solver runs. They run on n_threads
 * POSIX threads (n_threads <= 0: one per online processor), and the results
 * do not depend on n_threads: each grid point has its own slot, decisions
 * read the points in grid order, and runs made ahead of need by idle
 * threads are discarded and only counted in runs_speculative. The model
 * and the motion are read-only; levels are set on private copies. Levels
 * are in A* = (Fy_row l + W b) / (M h); for a model without bolts, Fy = 0
 * and A* is the uplift level W b / (M h). Library code: nothing here
 * prints. docs/design.md describes the algorithms. */
#ifndef ROCKBOLT_DESIGN_H
#define ROCKBOLT_DESIGN_H

#include <stddef.h>
#include "rockbolt/asce7.h"
#include "rockbolt/criteria.h"
#include "rockbolt/model.h"
#include "rockbolt/motion.h"
#include "rockbolt/solve.h"

/* The default largest gap the recommendation searches: 1/4 in, above
 * which ASCE 7 13.6.4 doubles the design force on snubbed equipment. */
#define RB_DESIGN_MAX_GAP_M 6.35e-3

/* Options for `rockbolt design` (issue: design checks). */
typedef struct {
    double scan_start;   /* in A*, default 0.05 */
    double scan_step;    /* in A*, default 0.05 */
    double scan_end;     /* in A*, default 1.5 */
    double resolution;   /* in A*, default 0.001 */
    double gap_ratio_min, gap_ratio_max, gap_ratio_step; /* defaults 0, 0.03, 0.0025 */
    /* the largest gap the recommendation searches, default 1/4 in =
     * 6.35 mm: above it ASCE 7 13.6.4 doubles the force on snubbed
     * equipment; <= 0: no bound but gap_ratio_max */
    double max_gap_m;
} rb_design_opts;

/* The sweeps a case asks `rockbolt design` for. */
typedef enum {
    RB_SWEEP_FREQUENCY = 0,  /* harmonic motion, x = excitation / fixed-base frequency */
    RB_SWEEP_AMPLITUDE       /* the given motion's shape, x = peak level in A* */
} rb_sweep_kind;

typedef struct {
    rb_sweep_kind kind;
    double from, to;          /* range of x */
    size_t n_points;          /* >= 1; equally spaced, from and to included */
    /* frequency sweeps only */
    double amplitude_astar;   /* peak floor acceleration in A* */
    double duration_s;        /* run length; <= 0 -> 8 s */
    double ramp_s;            /* linear ramp-up of the harmonic; 0 for none */
} rb_sweep_opts;

/* rb_design_opts (scan grid, resolution, gap grid) is declared in case.h
 * because case files carry it. Fills in the documented defaults: scan
 * 0.05 to 1.5 A* in steps of 0.05 A*, resolution 0.001 A*, gap ratios 0 to
 * 0.06 in steps of 0.0025. */
void rb_design_opts_defaults(rb_design_opts *o);

/* One run as every search makes it: the motion's shape at peak floor
 * acceleration level_mps2 (the motion itself at its own level), solved
 * without a history and judged by rb_judge_run, whose confirming runs go
 * to runs (room for RB_CONFIRM_RUNS) and their count to *n_runs. out is
 * overwritten and owns nothing. */
rb_status rb_design_run_at(const rb_model *model, const rb_motion *motion,
                           const rb_solve_opts *opts, const rb_criteria *criteria,
                           double level_mps2, rb_result *out, rb_verdict *verdict,
                           rb_confirm_run *runs, size_t *n_runs, rb_diag *diag);

/* Number of threads used for n_threads <= 0: the online processors (>= 1). */
int rb_design_threads_default(void);

/* Runs shared by the searches of one design. The design factors and an
 * amplitude sweep of one motion ask for many of the same levels; given one
 * memo, a run is solved once and its summary handed to every search that
 * asks for the same model, scaled motion and solver options (the bytes of
 * each). The results are those without a memo, bit for bit. Safe to share
 * between threads; it must not outlive the records of the motions it saw.
 * NULL everywhere a memo is taken: every run is solved. */
typedef struct rb_design_memo rb_design_memo;
rb_design_memo *rb_design_memo_new(void);   /* NULL when out of memory */
void rb_design_memo_free(rb_design_memo *m); /* accepts NULL */
size_t rb_design_memo_runs(rb_design_memo *m); /* runs held (0 for NULL) */
/* Keep a run solved outside the searches (`check`'s run of a motion at its
 * own level, which may carry a history): kept as the same run without a
 * history (opts with history_dt_s = 0, the options a search solves with),
 * since recording a history only reads the steps the solver takes
 * (tests/unit/test_design_memo_keep.c holds the two runs equal). The
 * result's history is not kept; r stays the caller's. */
void rb_design_memo_keep(rb_design_memo *m, const rb_model *model, const rb_motion *motion,
                         const rb_solve_opts *opts, rb_status status, const rb_result *r);

/* ---- Design factor ------------------------------------------------------ */

/* The largest peak floor acceleration of the motion's shape that meets the
 * criteria: scan upward from scan_start in steps of scan_step (in A*) to
 * scan_end, stop at the first failing level, bisect between the last passing
 * and that failing level until they are at most resolution apart. If
 * scan_start already fails the bisection starts from 0 (a motion of zero
 * amplitude is taken to pass without a run). The scan and bisection judge
 * by rb_judge; the pass they end on is then confirmed as rb_judge_run
 * does, and one that does not hold becomes the failing end of a new
 * bisection from the pass before it. */
typedef struct {
    double a_star_mps2;         /* A* of the model */
    double level_mps2;          /* largest passing peak floor acceleration found */
    double level_astar;         /* the same in A* */
    double factor;              /* A* / level; HUGE_VAL when level is 0 */
    double fail_mps2, fail_astar;   /* lowest failing level found (upper end of
                                       the final bracket); HUGE_VAL if none */
    double first_fail_astar;    /* first failing level on the scan grid;
                                   HUGE_VAL if none */
    double resolution_astar;    /* the resolution asked for */
    double scan_end_astar;      /* the top of the scan asked for */
    double bracket_astar;       /* fail - level reached (0 if no failure) */
    int no_failure;             /* 1: no failing level up to scan_end; level
                                   is then the last scan level and the factor
                                   only an upper bound */
    int fails_at_start;         /* 1: scan_start already fails */
    long runs;                  /* solver runs the search needed (the same
                                   for every thread count) */
    long scan_runs, bisect_runs;/* runs = scan_runs + bisect_runs */
    long runs_speculative;      /* runs made ahead by idle threads and not
                                   used; depends on n_threads */
    long confirm_fails;         /* ends of the search whose pass a
                                   confirmation turned into a fail, each
                                   followed by a new bisection below it */
    char pass_reason[256];      /* criteria verdict at level ("" if level 0) */
    char fail_reason[256];      /* verdict at fail ("" if no failure) */
} rb_design_factor_result;

/* motion gives the shape: sampled motions are rescaled through
 * motion->scale, closed forms through amplitude_mps2; polarity, duration
 * and everything else are kept. opts may be NULL (solver defaults); a time
 * history is never recorded. With criteria of kind RB_CRIT_NO_YIELD a run
 * also fails when a bolt row force reaches Fy without a yield being
 * recorded (non-yielding bolts). Errors: RB_ERR_INVALID (bad grid, model or
 * a motion of zero peak), RB_ERR_NOMEM, or the status of a solver run the
 * search needed, with the level named in diag->msg. */
rb_status rb_design_factor(const rb_model *model, const rb_motion *motion,
                           const rb_solve_opts *opts, const rb_criteria *criteria,
                           const rb_design_opts *design, int n_threads,
                           rb_design_memo *memo, rb_design_factor_result *out,
                           rb_diag *diag);

/* The least peak floor acceleration of the motion's shape at which the
 * base lifts off the floor (stage 1 -> 2), from one run of the model held
 * down by rigid bolts at no gap (src/design/uplift_level.c), through memo
 * (may be NULL). 0 when the motion has a vertical component (W b then
 * moves with the level), the model has no bolts, or the base does not
 * lift at the motion's own level. Errors: the held run's. */
rb_status rb_design_uplift_level(const rb_model *model, const rb_motion *motion,
                                 const rb_solve_opts *opts, rb_design_memo *memo,
                                 double *level_mps2, rb_diag *diag);

/* What a caller knows or asks of a search beyond rb_design_factor's:
 * near_astar (> 0, in A*): no level below it fails, and the failing
 * levels are expected to start near it; once the scan has its bracket,
 * near_astar - resolution / 2 is taken as a pass without a run, the levels
 * 1, 2, 4, ... resolutions above that are run until one fails, and the
 * bisection goes on from the bracket they leave (the result is the
 * search's own, a failing level at most resolution above a pass, provided
 * the caller's bound holds; where the failing levels do start there, it is
 * reached in one or two runs). 0: no such bound.
 * secant 1: before the bisection, where the criteria give a margin that is
 * continuous in the level (the usage of no-break with the bolts
 * stretching on; the largest row force over Fy of no-yield before a
 * yield), a run half a resolution either side of where the margin's
 * secant crosses 0: a bracket one resolution wide in two runs where the
 * margin is near linear; the bisection goes on from whatever bracket they
 * leave. The result is a failing level within the resolution above a
 * pass either way; it can differ from the bisection's by up to the
 * resolution, or more where the response crosses more than once inside
 * the scan's bracket. */
typedef struct {
    double near_astar;
    int secant;
} rb_design_hints;

/* rb_design_factor with hints (NULL: none, rb_design_factor itself). */
rb_status rb_design_factor_near(const rb_model *model, const rb_motion *motion,
                                const rb_solve_opts *opts, const rb_criteria *criteria,
                                const rb_design_opts *design, int n_threads,
                                rb_design_memo *memo, const rb_design_hints *hints,
                                rb_design_factor_result *out, rb_diag *diag);

/* One English sentence for reports, e.g. "design factor 4.13: meets the
 * criteria up to 0.2422 A* (27.81 m/s^2); fails at 0.2430 A* (first failing
 * scan level 0.25 A*); resolution 0.001 A*; 11 runs", or, when nothing
 * fails, one that says "no failing level up to scan_end (1.5 A*)". */
void rb_design_factor_describe(const rb_design_factor_result *f, const rb_out_units *u,
                               double g_mps2, char *buf, size_t n);

/* ---- Recommended gap ratio ---------------------------------------------- */

/* What bounds the searched range from above. */
typedef enum {
    RB_GAP_BOUND_RATIO = 0,   /* design.gap_ratio_max */
    RB_GAP_BOUND_MAX_GAP      /* design.max_gap over the lever arm */
} rb_gap_bound;

typedef struct {
    double gap_ratio;           /* g0 / l of this grid point */
    int evaluated;              /* 0: below the highest failing gap, not run
                                   (the rest of the point is then zero) */
    int meets;                  /* 1 if the run meets the criteria */
    double max_force_over_fy;   /* larger of the two rows */
    double max_u_over_ustatic;
    double max_theta_over_alpha;
    double usage_max;           /* larger toughness usage of the two rows */
    char reason[256];           /* criteria verdict */
} rb_gap_point;

typedef struct {
    int found;                  /* 0: no gap in the range works */
    double gap_ratio;           /* recommended: smallest grid gap from which
                                   every larger grid gap meets the criteria */
    double gap_m;               /* gap_ratio x lever arm */
    rb_gap_point *points;       /* owned; the grid, ascending */
    size_t n_points;
    long fail_index;            /* highest failing grid point, -1 if none */
    long runs;                  /* grid runs the search needed, plus 1 for
                                   the yielding run (same for any n_threads) */
    long runs_speculative;      /* grid runs made ahead and discarded */
    /* The thesis's reading (sec. 6.6): a run with yielding bolts (stretching
     * past failure) at the case's own gap; its final gaps tell how large a
     * gap the motion opens. yield_run = 0 for a model without bolts. */
    int yield_run;
    double yield_initial_gap_ratio;
    double yield_final_gap_ratio[2];   /* [RB_LEFT], [RB_RIGHT] */
    double yield_final_gap_ratio_max;
    double yield_usage[2];
    /* The range searched and what bounds it: [points[0], range_max] by
     * bound; the case's own gap ratio is always a point of the grid, and
     * own_meets its verdict. own_only: the recommendation is the case's
     * own gap because a larger grid gap (fail_index's) fails. */
    double range_max;
    int bound;                  /* rb_gap_bound */
    int own_above;              /* the case's own gap lies above the bound: the
                                   grid runs up to it */
    double max_gap_m;           /* design.max_gap as used (0: none) */
    double own_gap_ratio;
    int own_meets;
    int own_only;
} rb_gap_result;

/* Run the model, with its gap set to the grid ratios of [gap_ratio_min,
 * gap_ratio_max] (step gap_ratio_step) from the largest down to the first
 * that fails, under the motion as given, and recommend the smallest ratio g
 * such that g and every larger grid ratio meet the criteria. Errors as for
 * rb_design_factor. out is owned by the caller: rb_gap_result_free. */
rb_status rb_gap_recommend(const rb_model *model, const rb_motion *motion,
                           const rb_solve_opts *opts, const rb_criteria *criteria,
                           const rb_design_opts *design, int n_threads,
                           rb_gap_result *out, rb_diag *diag);
/* The same through memo (NULL: every run solved), shared with the design
 * factors of the same motion; the result is the same bit for bit. */
rb_status rb_gap_recommend_memo(const rb_model *model, const rb_motion *motion,
                                const rb_solve_opts *opts, const rb_criteria *criteria,
                                const rb_design_opts *design, int n_threads,
                                rb_design_memo *memo, rb_gap_result *out, rb_diag *diag);

/* One English sentence: the recommended gap ratio and the range it holds
 * over, or "no gap ratio in [min, max] meets the criteria". */
void rb_gap_describe(const rb_gap_result *g, const rb_out_units *u, char *buf, size_t n);

/* Free what a gap result owns; accepts NULL. */
void rb_gap_result_free(rb_gap_result *r);

/* ---- Sweeps --------------------------------------------------------------- */



void rb_sweep_opts_init(rb_sweep_opts *o, rb_sweep_kind kind);

typedef struct {
    double x;                   /* frequency ratio, or level in A* */
    double freq_hz;             /* excitation frequency (0 for amplitude sweeps
                                   of non-harmonic motions) */
    double peak_mps2;           /* peak floor acceleration of the run */
    double level_astar;         /* peak_mps2 / A* */
    double max_u_over_ustatic;
    double max_force_over_fy[2];/* [RB_LEFT], [RB_RIGHT] */
    double max_theta_over_alpha;
    double usage[2];
    int yielded[2], broken[2], overturned;
    int meets;                  /* criteria verdict; -1 when none were given */
    rb_status status;           /* solver status of this point (RB_OK, or why
                                   the point has no numbers) */
} rb_sweep_point;

typedef struct {
    rb_sweep_kind kind;
    double a_star_mps2;
    double fixed_base_hz;       /* the model's fixed-base frequency */
    double amplitude_astar;     /* frequency sweeps: the level used */
    rb_sweep_point *points;     /* owned; n_points */
    size_t n_points;
} rb_sweep;

/* Frequency response: the model under a harmonic floor motion of peak
 * amplitude_astar A*, at each frequency ratio of the range. A point whose
 * run fails keeps its status and zero numbers; the sweep still returns
 * RB_OK. criteria may be NULL. Returns RB_ERR_INVALID for a bad range, a
 * rigid model (no fixed-base frequency) or a bad model; RB_ERR_NOMEM. */
rb_status rb_sweep_frequency(const rb_model *model, const rb_solve_opts *opts,
                             const rb_criteria *criteria, const rb_sweep_opts *sw,
                             int n_threads, rb_sweep *out, rb_diag *diag);

/* Amplitude sweep: the motion's shape at each level of the range (in A*). */
rb_status rb_sweep_amplitude(const rb_model *model, const rb_motion *motion,
                             const rb_solve_opts *opts, const rb_criteria *criteria,
                             const rb_sweep_opts *sw, int n_threads,
                             rb_design_memo *memo, rb_sweep *out, rb_diag *diag);

/* Free what a sweep owns; accepts NULL. */
void rb_sweep_free(rb_sweep *s);


/* ---- Everything a case asks for -------------------------------------------- */

/* The design of one motion of a case. */
typedef struct {
    /* one per criterion kind (rb_criterion_kind), under the case's
     * design.factor_criteria of that kind: no yield, bolts stay elastic;
     * no break, bolts may yield, usage below the case's limit (1.0
     * unless the case sets one for no-break) */
    rb_design_factor_result factor[RB_N_CRITERIA];
    int has_gap;                       /* 0 for a model without bolts */
    rb_gap_result gap;                 /* against the case's own criteria */
    rb_sweep *sweeps;                  /* owned: the case's amplitude sweeps
                                          of this motion, n_sweeps of them */
    size_t n_sweeps;
} rb_motion_design;

typedef struct {
    rb_criteria factor_criteria[RB_N_CRITERIA]; /* as judged, by kind */
    rb_criteria gap_criteria;          /* as judged */
    rb_motion_design *motions;         /* owned, one per motion of the case */
    size_t n_motions;
    rb_sweep *sweeps;                  /* owned: the frequency sweeps */
    size_t n_sweeps;
    int has_code;                      /* the case gave design.code */
    rb_code_result code;
} rb_case_design;

/* Progress of a case design (rb_run_design, rockbolt/run.h): called
 * before each search with the number of searches done, their total and
 * what comes next ("motion 'elcentro': recommended gap", text of the case,
 * not escaped), and once at the end with done == total and what NULL.
 * From the calling thread only. */
typedef void (*rb_design_progress_fn)(void *ctx, size_t done, size_t total,
                                      const char *what);

/* Free what a motion's design owns and zero it; accepts NULL. */
void rb_motion_design_free(rb_motion_design *md);

/* Free what a case design owns; accepts NULL and a zeroed design. */
void rb_case_design_free(rb_case_design *d);

#endif
