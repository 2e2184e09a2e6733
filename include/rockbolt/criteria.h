/* Acceptance criteria and the one verdict of a run (thesis sec. 6.6), with
 * the checks of the model's own assumptions (docs/solver.md, Validity). */
#ifndef ROCKBOLT_CRITERIA_H
#define ROCKBOLT_CRITERIA_H

#include <stddef.h>
#include "rockbolt/solve.h"
#include "rockbolt/units.h"
#include "rockbolt/names.h"

/* The conditions of 17.10.5.3(a) an anchorage can miss, as bits. */
enum {
    RB_NOT_DUCTILE_CONCRETE = 1u, /* concrete-governed strength below 1.2 steel */
    RB_NOT_DUCTILE_STRETCH = 2u,  /* stretch length below 8 da */
    RB_NOT_DUCTILE_THREADS = 4u   /* partial threads, not upset, f_uta / f_ya below 1.3 */
};

/* The route of 17.10.5.3 by which the anchorage meets the seismic
 * requirements where 17.10.5.2 asks for them (docs/code-check.md):
 *   AUTO        (a) where the run yields the bolts (they are the fuse),
 *               otherwise the run's own tension history stands for the
 *               amplified demand of (d);
 *   DUCTILE     (a): ductile steel governs (concrete over 1.2 steel,
 *               stretch length, threads);
 *   ATTACHMENT  (b)/(c): the concrete-governed design strengths at least
 *               the largest tension the bolts can pass on, 1.2 times the
 *               row's yield force;
 *   OMEGA       (d): the static check with Omega_0 (design.code). */
typedef enum {
    RB_ROUTE_AUTO = 0,
    RB_ROUTE_DUCTILE,
    RB_ROUTE_ATTACHMENT,
    RB_ROUTE_OMEGA
} rb_seismic_route;

/* What a judge made of 17.10 for one run (rb_verdict.anchor_route): the
 * route it applied, or why none was needed. */
typedef enum {
    RB_ROUTE_APPLIED_NONE = 0,  /* no concrete check, or 17.10 off (seismic: false) */
    RB_ROUTE_APPLIED_EXEMPT,    /* 17.10.5.2: the bolts carried no tension */
    RB_ROUTE_APPLIED_DUCTILE,   /* (a) */
    RB_ROUTE_APPLIED_ATTACHMENT,/* (b)/(c) */
    RB_ROUTE_APPLIED_OMEGA,     /* (d), static with Omega_0 */
    RB_ROUTE_APPLIED_DYNAMIC    /* auto, no yield: the run's tension for (d)'s demand */
} rb_route_applied;

extern const rb_enum_name rb_seismic_route_names[]; /* rb_seismic_route */
extern const rb_enum_name rb_route_applied_names[]; /* rb_route_applied */

typedef enum {
    RB_CRIT_NO_YIELD = 0,   /* bolts stay elastic */
    RB_CRIT_NO_BREAK,       /* bolts may yield; usage below usage_limit, no overturn */
    RB_N_CRITERIA           /* the design finds a factor for each kind above */
} rb_criterion_kind;
extern const rb_enum_name rb_criterion_names[];     /* rb_criterion_kind */
/* What each kind asks of the bolts, for people (the HTML summary's heads),
 * indexed by kind. */
extern const char *const rb_criterion_titles[RB_N_CRITERIA];

/* What a validity warning does to the verdict. */
typedef enum {
    RB_VALIDITY_WARN = 0,   /* reported beside the verdict */
    RB_VALIDITY_FAIL        /* fails the run */
} rb_validity_mode;
extern const rb_enum_name rb_validity_mode_names[]; /* rb_validity_mode */

/* When a passing verdict is confirmed by solving the motion again at
 * tighter tolerances (docs/report-format.md, "Confirmation"): near grazing the
 * response does not converge with the tolerance, and a pass the
 * tolerance can turn into a fail is no pass. */
typedef enum {
    RB_CONFIRM_MARGINAL = 0,   /* a pass within confirm_band of a limit */
    RB_CONFIRM_ALWAYS,         /* every pass */
    RB_CONFIRM_OFF
} rb_confirm_mode;
extern const rb_enum_name rb_confirm_mode_names[];  /* rb_confirm_mode */

/* The default band of a marginal pass: a governing number within this
 * fraction of its limit. A run that does not converge with the tolerance
 * moved its margin by up to 0.33 of the limit between tolerances and
 * integrators in 2 100 random passes (docs/report-format.md,
 * "Confirmation"); the band is half as wide again. */
#define RB_CONFIRM_BAND_DEFAULT 0.5
/* How far apart the margins of a pass's runs may lie, as a fraction of the
 * limit, for the run to count as converged: a run that converges agrees
 * with itself to a few parts in a million. */
#define RB_CONFIRM_SPREAD 1e-3
/* The confirming runs of a pass: the run's own integrator at a tenth and
 * a hundredth of its tolerance, but no tighter than RB_CONFIRM_RTOL_MIN
 * (what double precision can meet); the last one also at a hundredth of
 * its rest_fraction (rb_solve_opts), which moves usage apart from the
 * tolerance: whether a small residual rocking is declared at rest decides
 * what the next strong pulse finds (docs/solver.md, "When rocking
 * stops"). */
#define RB_CONFIRM_RUNS 2
#define RB_CONFIRM_RTOL_MIN 1e-13

typedef struct {
    rb_criterion_kind kind;
    double usage_limit;            /* default 1.0 */
    double max_shear_over_w;       /* <= 0: no limit (elastic frame shear / W) */
    double max_theta_over_alpha;   /* <= 0: no limit */
    double friction_coefficient;   /* <= 0: sliding is not checked */
    rb_validity_mode validity;     /* default RB_VALIDITY_WARN */
    /* The concrete check (ACI 318-19 Chapter 17, rockbolt/anchor.h): set by
     * a case with concrete: (criteria: concrete: false clears it). A run
     * then fails when the 17.8 utilization of its concurrent tension and
     * shear on the concrete-governed strengths reaches 1, or, before that,
     * when the route of 17.10.5.3 it is judged by is not met (where 17.10
     * applies, anchor_seismic, and 17.10.5.2 does not exempt it: a run
     * whose bolts carry no tension is exempt):
     *   route (a), asked, or by auto or any route when the run yields
     *   the bolts: fails on anchor_not_ductile (RB_NOT_DUCTILE_*);
     *   route (b)/(c): fails where anchor_attachment_margin < 1;
     *   route (d): fails where anchor_static_utilization >= 1;
     *   auto without yield: the run's own demand is the check.
     * Default 0 throughout. */
    int concrete;
    int anchor_seismic;
    int anchor_route;                 /* rb_seismic_route */
    unsigned anchor_not_ductile;
    double anchor_attachment_margin;
    double anchor_static_utilization;
    /* the checks that validity: fail counts (bit 1 << rb_check); default
     * all. A fragility's lift-off limit state counts lift-off alone. */
    unsigned validity_mask;
    rb_confirm_mode confirm;       /* default RB_CONFIRM_MARGINAL */
    double confirm_band;           /* default RB_CONFIRM_BAND_DEFAULT */
    /* the units the verdict's reason prints its quantities in (the
     * case's output_units); default RB_UNITS_SI */
    rb_unit_system units;
} rb_criteria;

void rb_criteria_init(rb_criteria *c);

/* The model's assumptions, each checked on a result. */
typedef enum {
    RB_CHECK_LIFT_OFF = 0,  /* the base stays on the floor: reaction > 0 */
    RB_CHECK_SLIDING,       /* friction holds: demand <= friction_coefficient */
    RB_CHECK_BOLT_IMPACT,   /* a rigid stop is fair: elastic impact force < Fy */
    RB_CHECK_CONVERGENCE,   /* a confirmed pass held in every confirming run */
    RB_N_CHECKS
} rb_check;

typedef enum {
    RB_CHECK_OK = 0,
    RB_CHECK_WARNING,
    RB_CHECK_NOT_CHECKED    /* no friction coefficient; bolts that are not rigid;
                               a verdict not confirmed */
} rb_check_status;

typedef struct {
    int pass;                          /* the verdict */
    int criteria_pass;                 /* the acceptance criteria alone */
    rb_check_status check[RB_N_CHECKS];
    unsigned warnings;                 /* bit 1 << k for each check k that warns */
    char reason[256];                  /* one line saying what governed */
    int anchor_route;                  /* rb_route_applied: 17.10.5.3 as judged */
} rb_verdict;

/* The one judge of a run: every command and search gets its verdict here.
 * Overturning and a broken row always fail; no-yield fails when a row
 * yields or its force reaches Fy, whatever the bolt model; no-break when
 * the usage reaches its limit; then the optional limits; then, with
 * validity: fail, any validity warning. */
void rb_judge(const rb_criteria *c, const rb_result *r, rb_verdict *v);

/* What a rigid stop hid (docs/solver.md, Bolt impact): the elastic impact
 * force over Fy of a run whose rigid rows the bolt-impact check warns of
 * (at or above Fy), else 0; and the note the verdict line carries for it
 * ("rigid bolts: an elastic bolt would load the row to x Fy"), 0 and ""
 * when there is none. */
double rb_bolt_impact_over_fy(const rb_result *r);
int rb_bolt_impact_note(const rb_result *r, char *buf, size_t n);

/* The numbers of a run the criteria read, worked out once for the judge,
 * the margin and the confirming runs: the larger row's usage, the larger
 * row force over Fy (0 without rows), the elastic frame shear over W. */
typedef struct {
    double usage, force_over_fy, shear_over_w;
} rb_governing;
rb_governing rb_result_governing(const rb_result *r);

/* The limit a run's margin is measured against (rb_verdict_margin_of),
 * in the judge's order: of two limits at one margin the first governs. */
typedef enum {
    RB_GOVERNS_OVERTURN = 0,  /* rotation towards alpha */
    RB_GOVERNS_BREAK,         /* a broken row */
    RB_GOVERNS_YIELD,         /* no-yield: a row's force towards Fy */
    RB_GOVERNS_USAGE,         /* no-break: the toughness usage towards its limit */
    RB_GOVERNS_SHEAR,         /* max_shear_over_w */
    RB_GOVERNS_ROTATION,      /* max_theta_over_alpha */
    RB_GOVERNS_SLIDING,       /* a free-standing base's friction demand */
    RB_GOVERNS_ROUTE,         /* the 17.10.5.3 route the judge applies */
    RB_GOVERNS_ANCHORAGE,     /* the 17.8 utilization */
    RB_GOVERNS_VALIDITY,      /* validity: fail, a check it counts */
    RB_GOVERNS_CONFIRMATION,  /* a pass its confirming runs did not hold */
    RB_N_GOVERNS
} rb_governs_limit;

/* A limit's name for people and reports ("anchorage utilization"). */
const char *rb_governs_name(rb_governs_limit k);

/* rb_verdict_margin, and which limit gives it (limit may be NULL). */
double rb_verdict_margin_of(const rb_criteria *c, const rb_result *r, rb_governs_limit *limit);

/* Each limit's own margin in r under c, in rb_governs_limit's order: as
 * rb_verdict_margin measures it (0 once reached), NaN for a limit that
 * does not apply; rb_verdict_margin is the least of them. A run that
 * overturned or broke a row has 0 at that limit and NaN elsewhere. */
void rb_verdict_margins(const rb_criteria *c, const rb_result *r, double m[RB_N_GOVERNS]);

/* The one "governs" rule of every command and report: a run's margin is
 * rb_verdict_margin_of r under c, and 0 for a run whose verdict v fails
 * (then with the limit that failed it); the motion that governs a case is
 * the one with the least margin over all the verdict's criteria, the
 * anchorage's utilization among them, and of motions at one margin (all
 * failing ones among them) the first in the case's order, which is the
 * motion a failing case's verdict line names. Passing margins within
 * RB_MARGIN_TIE of each other are one margin: a margin is a relative
 * distance to a limit, and two motions at one physical limit (a row
 * capped at Fy, say) reach it by different roundings, whose last bit
 * would otherwise pick the motion. rb_margin_governs(a, b): 1 if a run of
 * margin a governs over an earlier one of margin b (a failing run's 0
 * over every pass). */
#define RB_MARGIN_TIE 1e-9
double rb_verdict_governing(const rb_criteria *c, const rb_result *r, const rb_verdict *v,
                            rb_governs_limit *limit);
int rb_margin_governs(double a, double b);

/* How far a run is from failing: the smallest relative distance of its
 * governing numbers from their limits (usage or bolt force, rotation
 * towards overturning, the optional limits, the concrete's utilization,
 * and with validity: fail the checks it counts), 0 for a run that fails.
 * A pass within c->confirm_band of it is marginal. */
double rb_verdict_margin(const rb_criteria *c, const rb_result *r);

/* The band within which a pass under motion is confirmed: the criteria's
 * confirm_band, or the whole range (1) under a harmonic. A steady
 * harmonic keeps a chaotic rocking response going to its end, and another
 * tolerance took a harmonic's margin further than any band: among 1 362
 * random harmonic passes under no-break, by up to 0.71 of the limit in
 * runs that held and from 0.97 to a broken row in one that did not
 * (docs/report-format.md, "Confirmation"). With a band of 1 every
 * harmonic pass that moved is confirmed, and stands only where its runs
 * converge. */
double rb_confirm_band(const rb_criteria *c, const rb_motion *motion);

/* Whether r's plate came within the fraction band of the contact angle of
 * rows it never met (their limits untouched, but a touch would load them). */
int rb_result_near_contact(const rb_result *r, double band);

/* Whether v, rb_judge's verdict of r, is to be confirmed by reruns
 * (rb_confirm_mode): only a pass is, since a confirmation can only turn a
 * pass into a fail; with marginal, a pass within band (rb_confirm_band)
 * of a limit or, under no-yield, near the bolt heads it never met
 * (rb_result_near_contact). */
int rb_verdict_wants_confirm(const rb_criteria *c, double band, const rb_result *r,
                             const rb_verdict *v);

/* One confirming run: how it was solved and rb_judge's verdict of it. */
typedef struct {
    int integrator;        /* rb_integrator */
    double rtol;
    double rest_fraction;  /* rb_solve_opts.rest_fraction of the run */
    int solved;            /* 0: the solver stopped (status) */
    int status;            /* rb_status when not solved */
    rb_verdict verdict;    /* when solved */
    double usage;          /* the larger row's */
    double max_bolt_force_over_fy, max_theta_over_alpha;
    double margin;         /* rb_verdict_margin of the run */
    double limit_margins[RB_N_GOVERNS];  /* rb_verdict_margins of the run */
} rb_confirm_run;

/* How a confirmation solves a run: rb_solve_run, or a caller's cache of
 * it (the design searches' memo). 0 in diag's stead: no diagnostics. */
typedef rb_status (*rb_solve_fn)(void *ctx, const rb_model *model, const rb_motion *motion,
                                 const rb_solve_opts *opts, rb_result *out);

/* The one verdict of a run, for every command and search: rb_judge of r
 * (model under motion, solved with opts), and for a pass that wants it
 * (rb_verdict_wants_confirm) the confirming runs, solved by solve (NULL:
 * rb_solve_run) without a history and folded in by rb_verdict_confirm.
 * runs has room for RB_CONFIRM_RUNS; *n_runs is how many were made. */
void rb_judge_run(const rb_criteria *c, const rb_model *model, const rb_motion *motion,
                  const rb_solve_opts *opts, const rb_result *r, rb_solve_fn solve,
                  void *ctx, rb_verdict *v, rb_confirm_run *runs, size_t *n_runs);
/* rb_judge_run's pass and reason alone, for a search that keeps no
 * confirming run: a confirming run that fails decides the fail, and the
 * runs after it are not made (the warnings of the verdict may then name
 * fewer runs than rb_judge_run's). */
void rb_judge_decide(const rb_criteria *c, const rb_model *model, const rb_motion *motion,
                     const rb_solve_opts *opts, const rb_result *r, rb_solve_fn solve,
                     void *ctx, rb_verdict *v);

/* Fold the confirming runs into v (a pass of rb_judge of a run whose
 * rb_verdict_margin is margin and rb_verdict_margins limit_margins,
 * solved at tolerance rtol, judged with the confirm band band): the
 * convergence check is ok when every run passes too and the runs agree,
 * else a warning, and the verdict fails with the first failing run's
 * reason (a run the solver could not finish fails as well). Runs that all
 * pass but whose margins lie more than RB_CONFIRM_SPREAD apart have not
 * converged, and the next tolerance is another draw from their scatter:
 * the verdict fails too unless every run has at least band to spare and
 * more than the spread. The same holds for each limit's own margin
 * (runs' limit_margins), not only the least: limit_margins NULL checks
 * the least alone. n = 0 leaves v as it is, with the check not checked. */
void rb_verdict_confirm(rb_verdict *v, double margin, const double *limit_margins, double band,
                        double rtol, const rb_confirm_run *runs, size_t n);

/* A check's name for people ("lift-off") and its JSON key ("lift_off"). */
const char *rb_check_name(rb_check k);
const char *rb_check_key(rb_check k);
/* The check a name of rb_check_name stands for; 0 if none. */
int rb_check_parse(const char *name, rb_check *k);
const char *rb_check_status_str(rb_check_status s);

/* How many checks a warnings mask names. */
int rb_warnings_count(unsigned warnings);
/* "name; name" for a warnings mask (one CSV field); "" for none. */
void rb_warnings_names(unsigned warnings, char *buf, size_t n);
/* "N validity warning(s): name, name" for a warnings mask; "" for none. */
void rb_warnings_str(unsigned warnings, char *buf, size_t n);

#endif
