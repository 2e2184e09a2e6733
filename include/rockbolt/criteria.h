/* Acceptance criteria and the verdict of a run (thesis sec. 6.6). */
#ifndef ROCKBOLT_CRITERIA_H
#define ROCKBOLT_CRITERIA_H

#include <stddef.h>
#include "rockbolt/solve.h"

typedef enum {
    RB_CRIT_NO_YIELD = 0,   /* bolts stay elastic */
    RB_CRIT_NO_BREAK        /* bolts may yield; usage below usage_limit, no overturn */
} rb_criterion_kind;

typedef struct {
    rb_criterion_kind kind;
    double usage_limit;            /* default 1.0 */
    double max_shear_over_w;       /* <= 0: no limit (elastic frame shear / W) */
    double max_theta_over_alpha;   /* <= 0: no limit */
} rb_criteria;

void rb_criteria_init(rb_criteria *c);

/* 1 if the result meets the criteria, 0 if not; reason (may be NULL) gets
 * one line saying what governed. */
int rb_criteria_judge(const rb_criteria *c, const rb_result *r,
                      char *reason, size_t reason_size);

#endif
