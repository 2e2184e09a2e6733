/* Acceptance criteria and the one verdict of a run (thesis sec. 6.6), with
 * the checks of the model's own assumptions (docs/solver.md, Validity). */
#ifndef ROCKBOLT_CRITERIA_H
#define ROCKBOLT_CRITERIA_H

#include <stddef.h>
#include "rockbolt/solve.h"

typedef enum {
    RB_CRIT_NO_YIELD = 0,   /* bolts stay elastic */
    RB_CRIT_NO_BREAK        /* bolts may yield; usage below usage_limit, no overturn */
} rb_criterion_kind;

/* What a validity warning does to the verdict. */
typedef enum {
    RB_VALIDITY_WARN = 0,   /* reported beside the verdict */
    RB_VALIDITY_FAIL        /* fails the run */
} rb_validity_mode;

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
     * shear reaches 1, or, before that, when the anchorage is not ductile
     * where 17.10 asks it to be (anchor_ductile 0). Default 0 and 1. */
    int concrete;
    int anchor_ductile;
    /* the checks that validity: fail counts (bit 1 << rb_check); default
     * all. A fragility's lift-off limit state counts lift-off alone. */
    unsigned validity_mask;
} rb_criteria;

void rb_criteria_init(rb_criteria *c);

/* The model's assumptions, each checked on a result. */
typedef enum {
    RB_CHECK_LIFT_OFF = 0,  /* the base stays on the floor: reaction > 0 */
    RB_CHECK_SLIDING,       /* friction holds: demand <= friction_coefficient */
    RB_CHECK_BOLT_IMPACT,   /* a rigid stop is fair: elastic impact force < Fy */
    RB_N_CHECKS
} rb_check;

typedef enum {
    RB_CHECK_OK = 0,
    RB_CHECK_WARNING,
    RB_CHECK_NOT_CHECKED    /* no friction coefficient; bolts that are not rigid */
} rb_check_status;

typedef struct {
    int pass;                          /* the verdict */
    int criteria_pass;                 /* the acceptance criteria alone */
    rb_check_status check[RB_N_CHECKS];
    unsigned warnings;                 /* bit 1 << k for each check k that warns */
    char reason[256];                  /* one line saying what governed */
} rb_verdict;

/* The one judge of a run: every command and search gets its verdict here.
 * Overturning and a broken row always fail; no-yield fails when a row
 * yields or its force reaches Fy, whatever the bolt model; no-break when
 * the usage reaches its limit; then the optional limits; then, with
 * validity: fail, any validity warning. */
void rb_judge(const rb_criteria *c, const rb_result *r, rb_verdict *v);

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
