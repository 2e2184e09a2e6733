/* Verdict of one run against the acceptance criteria (thesis sec. 6.6):
 * either the bolts must stay elastic, or they may yield but must keep their
 * toughness usage below a limit and the cabinet must not overturn. */
#include <stdio.h>
#include "rockbolt/criteria.h"

void rb_criteria_init(rb_criteria *c)
{
    c->kind = RB_CRIT_NO_BREAK;
    c->usage_limit = 1.0;
    c->max_shear_over_w = 0;
    c->max_theta_over_alpha = 0;
}

/* A macro so that each message is a literal the compiler checks. */
#define say(reason, n, pass, fmt, v) \
    ((reason) && (n) ? (void)snprintf(reason, n, fmt, v) : (void)0, (pass))

int rb_criteria_judge(const rb_criteria *c, const rb_result *r, char *reason, size_t n)
{
    double usage = r->usage[0] > r->usage[1] ? r->usage[0] : r->usage[1];
    double shear = r->weight_n > 0 ? r->max_shear_elastic_n / r->weight_n : 0;
    if (r->overturned)
        return say(reason, n, 0, "the cabinet overturns at t = %.3f s", r->overturn_s);
    if (r->broken[0] || r->broken[1])
        return say(reason, n, 0, "a bolt row breaks at t = %.3f s",
                   r->broken[0] ? r->break_s[0] : r->break_s[1]);
    if (c->kind == RB_CRIT_NO_YIELD && (r->yielded[0] || r->yielded[1]))
        return say(reason, n, 0, "a bolt row yields at t = %.3f s (criterion: no yield)",
                   r->yielded[0] ? r->first_yield_s[0] : r->first_yield_s[1]);
    if (c->kind == RB_CRIT_NO_BREAK && usage >= c->usage_limit)
        return say(reason, n, 0, "bolt toughness usage %.3f reaches the limit", usage);
    if (c->max_shear_over_w > 0 && shear > c->max_shear_over_w)
        return say(reason, n, 0, "base shear / W = %.3f exceeds its limit", shear);
    if (c->max_theta_over_alpha > 0 && r->max_theta_over_alpha > c->max_theta_over_alpha)
        return say(reason, n, 0, "rotation / alpha = %.4f exceeds its limit",
                   r->max_theta_over_alpha);
    if (c->kind == RB_CRIT_NO_YIELD) {
        double f = r->fy_row_n > 0 ? (r->max_bolt_force_n[0] > r->max_bolt_force_n[1]
                   ? r->max_bolt_force_n[0] : r->max_bolt_force_n[1]) / r->fy_row_n : 0;
        return say(reason, n, 1, "bolts stay elastic (max force / Fy = %.3f)", f);
    }
    return say(reason, n, 1, "bolt toughness usage %.3f is below the limit", usage);
}
