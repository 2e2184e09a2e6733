/* The one judge (rb_judge) on results made by hand: the criteria in their
 * order, the validity checks and their mode, and messages that never
 * contradict their own numbers. */
#include <stdlib.h>
#include <string.h>
#include "harness.h"
#include "rockbolt/criteria.h"

static void base_result(rb_result *r)
{
    memset(r, 0, sizeof *r);
    r->weight_n = 1000;
    r->fy_row_n = 50000;
    r->min_vertical_reaction_n = 500;
    r->rigid_bolts = 1;
}

/* The number after "= " or "usage " in a reason. */
static double number_in(const char *reason, const char *after)
{
    const char *p = strstr(reason, after);
    return p ? strtod(p + strlen(after), NULL) : -1;
}

static void no_yield_whatever_the_model(void)
{
    rb_criteria c;
    rb_result r;
    rb_verdict v;
    rb_criteria_init(&c);
    c.kind = RB_CRIT_NO_YIELD;
    base_result(&r);
    /* non-yielding bolts record no yield; their force decides */
    r.max_bolt_force_n[1] = 1.392 * r.fy_row_n;
    rb_judge(&c, &r, &v);
    CHECK(!v.pass && !v.criteria_pass);
    CHECK(strstr(v.reason, "reaches Fy") != NULL);
    /* just below Fy passes, and says a number below 1 */
    r.max_bolt_force_n[1] = 0.9999996 * r.fy_row_n;
    rb_judge(&c, &r, &v);
    CHECK(v.pass);
    CHECK(number_in(v.reason, "Fy = ") < 1.0);
    /* a recorded yield fails even below Fy */
    r.yielded[0] = 1;
    rb_judge(&c, &r, &v);
    CHECK(!v.pass && strstr(v.reason, "yields") != NULL);
}

static void usage_beside_its_limit(void)
{
    rb_criteria c;
    rb_result r;
    rb_verdict v;
    rb_criteria_init(&c);
    base_result(&r);
    r.usage[0] = 0.9999996;
    rb_judge(&c, &r, &v);
    CHECK(v.pass && number_in(v.reason, "usage ") < 1.0);
    r.usage[0] = 1.0;
    rb_judge(&c, &r, &v);
    CHECK(!v.pass && number_in(v.reason, "usage ") >= 1.0);
    r.overturned = 1;
    rb_judge(&c, &r, &v);
    CHECK(!v.pass && strstr(v.reason, "overturns") != NULL);
}

static void validity(void)
{
    rb_criteria c;
    rb_result r;
    rb_verdict v;
    char s[128];
    rb_criteria_init(&c);
    base_result(&r);
    rb_judge(&c, &r, &v);
    CHECK(v.pass && v.warnings == 0);
    CHECK(v.check[RB_CHECK_LIFT_OFF] == RB_CHECK_OK);
    CHECK(v.check[RB_CHECK_SLIDING] == RB_CHECK_NOT_CHECKED);
    CHECK(v.check[RB_CHECK_BOLT_IMPACT] == RB_CHECK_OK);
    r.min_vertical_reaction_n = 0;           /* at zero the base leaves */
    r.max_bolt_impact_n = r.fy_row_n;        /* an impact of Fy yields a row */
    rb_judge(&c, &r, &v);
    CHECK(v.pass && v.criteria_pass);
    CHECK(v.warnings == ((1u << RB_CHECK_LIFT_OFF) | (1u << RB_CHECK_BOLT_IMPACT)));
    rb_warnings_str(v.warnings, s, sizeof s);
    CHECK(strcmp(s, "2 validity warnings: lift-off, bolt impact") == 0);
    c.validity = RB_VALIDITY_FAIL;
    rb_judge(&c, &r, &v);
    CHECK(!v.pass && v.criteria_pass && strstr(v.reason, "validity: fail") != NULL);
    /* sliding is a check only with a coefficient */
    c.validity = RB_VALIDITY_WARN;
    c.friction_coefficient = 0.5;
    r.max_friction_demand = 0.5;
    rb_judge(&c, &r, &v);
    CHECK(v.check[RB_CHECK_SLIDING] == RB_CHECK_OK);
    r.max_friction_demand = 0.51;
    rb_judge(&c, &r, &v);
    CHECK(v.check[RB_CHECK_SLIDING] == RB_CHECK_WARNING);
    /* elastic bolts resolve the impact themselves */
    r.rigid_bolts = 0;
    rb_judge(&c, &r, &v);
    CHECK(v.check[RB_CHECK_BOLT_IMPACT] == RB_CHECK_NOT_CHECKED);
    /* every name parses back */
    for (int k = 0; k < RB_N_CHECKS; k++) {
        rb_check back;
        CHECK(rb_check_parse(rb_check_name((rb_check)k), &back) && back == (rb_check)k);
    }
}

int main(void)
{
    no_yield_whatever_the_model();
    usage_beside_its_limit();
    validity();
    TEST_MAIN_END();
}
