/* The verdict of one run (thesis sec. 6.6): either the bolts must stay
 * elastic, or they may yield but must keep their toughness usage below a
 * limit and the cabinet must not overturn; beside it, whether the model's
 * own assumptions held (docs/solver.md, Validity). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/interaction.h"
#include "rockbolt/jsonnum.h"
#include "rockbolt/criteria.h"
#include "rockbolt/names.h"

void rb_criteria_init(rb_criteria *c)
{
    /* every field a default, also those added later */
    memset(c, 0, sizeof *c);
    c->kind = RB_CRIT_NO_BREAK;
    c->usage_limit = 1.0;
    c->max_shear_over_w = 0;
    c->max_theta_over_alpha = 0;
    c->validity_mask = (1u << RB_N_CHECKS) - 1;
    c->friction_coefficient = 0;
    c->validity = RB_VALIDITY_WARN;
    c->confirm = RB_CONFIRM_MARGINAL;
    c->confirm_band = RB_CONFIRM_BAND_DEFAULT;
    c->units = RB_UNITS_SI;
}

const char *rb_check_name(rb_check k)
{
    switch (k) {
    case RB_CHECK_LIFT_OFF: return "lift-off";
    case RB_CHECK_SLIDING: return "sliding";
    case RB_CHECK_BOLT_IMPACT: return "bolt impact";
    case RB_CHECK_CONVERGENCE: return "convergence";
    case RB_N_CHECKS: break;
    }
    return "?";
}

const char *rb_check_key(rb_check k)
{
    switch (k) {
    case RB_CHECK_LIFT_OFF: return "lift_off";
    case RB_CHECK_SLIDING: return "sliding";
    case RB_CHECK_BOLT_IMPACT: return "bolt_impact";
    case RB_CHECK_CONVERGENCE: return "convergence";
    case RB_N_CHECKS: break;
    }
    return "?";
}

int rb_check_parse(const char *name, rb_check *k)
{
    for (int i = 0; i < RB_N_CHECKS; i++)
        if (strcmp(name, rb_check_name((rb_check)i)) == 0) {
            *k = (rb_check)i;
            return 1;
        }
    return 0;
}

const char *rb_check_status_str(rb_check_status s)
{
    switch (s) {
    case RB_CHECK_OK: return "ok";
    case RB_CHECK_WARNING: return "warning";
    case RB_CHECK_NOT_CHECKED: return "not-checked";
    }
    return "?";
}

int rb_warnings_count(unsigned warnings)
{
    int count = 0;
    for (int k = 0; k < RB_N_CHECKS; k++)
        count += (warnings >> k) & 1u;
    return count;
}

void rb_warnings_names(unsigned warnings, char *buf, size_t n)
{
    size_t len = 0;
    if (!n)
        return;
    buf[0] = '\0';
    for (int k = 0; k < RB_N_CHECKS && len < n; k++)
        if ((warnings >> k) & 1u)
            len += (size_t)snprintf(buf + len, n - len, "%s%s", len ? "; " : "",
                                    rb_check_name((rb_check)k));
}

void rb_warnings_str(unsigned warnings, char *buf, size_t n)
{
    int count = rb_warnings_count(warnings);
    size_t k;
    if (n)
        buf[0] = '\0';
    if (!count || !n)
        return;
    size_t len = (size_t)snprintf(buf, n, "%d validity warning%s:", count,
                                  count == 1 ? "" : "s");
    const char *sep = " ";
    for (k = 0; k < RB_N_CHECKS && len < n; k++)
        if ((warnings >> k) & 1u) {
            len += (size_t)snprintf(buf + len, n - len, "%s%s", sep, rb_check_name((rb_check)k));
            sep = ", ";
        }
}

static double larger(double a, double b)
{
    return a > b ? a : b;
}

static void validity(const rb_criteria *c, const rb_result *r, rb_verdict *v)
{
    v->check[RB_CHECK_LIFT_OFF] = r->min_vertical_reaction_n <= 0 ? RB_CHECK_WARNING
                                                                 : RB_CHECK_OK;
    /* anchored, the horizontal reaction is the anchors' shear (17.7 with
     * concrete:), and friction is reported, not judged */
    if (!(c->friction_coefficient > 0) || r->fy_row_n > 0)
        v->check[RB_CHECK_SLIDING] = RB_CHECK_NOT_CHECKED;
    else
        v->check[RB_CHECK_SLIDING] = r->max_friction_demand > c->friction_coefficient
                                     ? RB_CHECK_WARNING : RB_CHECK_OK;
    /* only a rigid stop hides the impact; an elastic row resolves it */
    if (!r->rigid_bolts)
        v->check[RB_CHECK_BOLT_IMPACT] = RB_CHECK_NOT_CHECKED;
    else
        v->check[RB_CHECK_BOLT_IMPACT] = rb_bolt_impact_over_fy(r) > 0 ? RB_CHECK_WARNING
                                                                     : RB_CHECK_OK;
    /* one run cannot confirm itself: rb_verdict_confirm sets it */
    v->check[RB_CHECK_CONVERGENCE] = RB_CHECK_NOT_CHECKED;
    v->warnings = 0;
    for (int k = 0; k < RB_N_CHECKS; k++)
        if (v->check[k] == RB_CHECK_WARNING)
            v->warnings |= 1u << k;
}

/* v as text with enough digits that it reads back on the same side of
 * limit as v is: a passing 0.9999996 Fy must not print as "1". */
static const char *beside(double v, double limit, char *buf, size_t n)
{
    for (int prec = 6; prec <= 17; prec++) {
        snprintf(buf, n, "%.*g", prec, v);
        double back = strtod(buf, NULL);
        if ((back < limit) == (v < limit))
            break;
    }
    return buf;
}

/* A limit as the user wrote it: the shortest decimal that reads back to
 * the same double, so that 1.65 is not printed 1.6499999999999999. */
typedef struct { char s[RB_JSONNUM_MAX]; } limit_text;

static limit_text limit_str(double v)
{
    limit_text t;
    rb_json_number(v, t.s);
    return t;
}

/* A macro so that each message is a literal the compiler checks. */
#define SAY(v, pass_, ...) \
    ((void)snprintf((v)->reason, sizeof (v)->reason, __VA_ARGS__), (v)->criteria_pass = (pass_))

/* The conditions of 17.10.5.3(a) an anchorage misses, in words. */
static const char *not_ductile_why(unsigned why, char *buf, size_t n)
{
    static const struct {
        unsigned bit;
        const char *text;
    } conditions[] = {
        {RB_NOT_DUCTILE_CONCRETE, "the concrete lets go before the bolts yield"},
        {RB_NOT_DUCTILE_STRETCH, "the stretch length is below 8 da"},
        {RB_NOT_DUCTILE_THREADS, "f_uta / f_ya is below 1.3 with threads along part of "
                                 "the anchor, not upset"},
    };
    size_t len = 0;
    buf[0] = 0;
    for (size_t i = 0; i < sizeof conditions / sizeof conditions[0]; i++)
        if (why & conditions[i].bit && len < n)
            len += (size_t)snprintf(buf + len, n - len, "%s%s", len ? "; " : "",
                                    conditions[i].text);
    return buf;
}

rb_governing rb_result_governing(const rb_result *r)
{
    rb_governing g;
    g.usage = larger(r->usage[0], r->usage[1]);
    /* no rows, no ratio: a free-standing cabinet's is no number (NaN, null
     * in JSON, n/a in a table), not a zero that reads as a bolt unloaded */
    g.force_over_fy = r->fy_row_n > 0
                      ? larger(r->max_bolt_force_n[0], r->max_bolt_force_n[1]) / r->fy_row_n
                      : (double)NAN;
    g.shear_over_w = r->weight_n > 0 ? r->max_shear_elastic_n / r->weight_n : 0;
    return g;
}

/* The route of 17.10.5.3 the judge applies to a run (rb_criteria). */
static rb_route_applied route_applied(const rb_criteria *c, const rb_result *r)
{
    if (!c->concrete || !c->anchor_seismic)
        return RB_ROUTE_APPLIED_NONE;
    /* 17.10.5.2: only where the earthquake's share of the tension exceeds
     * 20 %: every newton of a rocking cabinet's bolt tension is seismic,
     * so the bolts need only have carried some */
    if (!(larger(r->max_bolt_force_n[0], r->max_bolt_force_n[1]) > 0))
        return RB_ROUTE_APPLIED_EXEMPT;
    if (r->yielded[0] || r->yielded[1] || c->anchor_route == RB_ROUTE_DUCTILE)
        return RB_ROUTE_APPLIED_DUCTILE;
    switch ((rb_seismic_route)c->anchor_route) {
    case RB_ROUTE_ATTACHMENT: return RB_ROUTE_APPLIED_ATTACHMENT;
    case RB_ROUTE_OMEGA: return RB_ROUTE_APPLIED_OMEGA;
    default: return RB_ROUTE_APPLIED_DYNAMIC;
    }
}

/* Whether the route applied fails the run: a route with a yes-or-no
 * answer fails on the same test in the verdict and in its margin */
static int route_fails(const rb_criteria *c, rb_route_applied route)
{
    switch (route) {
    case RB_ROUTE_APPLIED_DUCTILE: return c->anchor_not_ductile != 0;
    case RB_ROUTE_APPLIED_ATTACHMENT: return !(c->anchor_attachment_margin >= 1);
    case RB_ROUTE_APPLIED_OMEGA: return !(c->anchor_static_utilization < 1);
    default: return 0;
    }
}

static void route_reason(const rb_criteria *c, const rb_result *r, rb_route_applied route,
                         rb_verdict *v)
{
    /* the three conditions together are 157 characters; the reason's 256
     * hold them after the longest prefix (95) */
    char why[160];
    int yielded = r->yielded[0] || r->yielded[1];
    if (route == RB_ROUTE_APPLIED_DUCTILE)
        SAY(v, 0, "the anchorage is not ductile (ACI 318-19 17.10.5.3(a)%s): %s",
            yielded && c->anchor_route != RB_ROUTE_DUCTILE
                ? ", the route of a run whose bolts yield" : "",
            not_ductile_why(c->anchor_not_ductile, why, sizeof why));
    else if (route == RB_ROUTE_APPLIED_ATTACHMENT)
        SAY(v, 0, "the anchorage fails 17.10.5.3(c): its concrete-governed design tension "
            "strength is %.3f of 1.2 times the row's yield force", c->anchor_attachment_margin);
    else
        SAY(v, 0, "the anchorage fails 17.10.5.3(d): the static check with Omega_0 has "
            "17.8 utilization %.3f", c->anchor_static_utilization);
}

/* A free-standing base (no rows) is held by friction alone, which the
 * model assumes holds: a demand above the coefficient fails the run. */
static int free_standing_judged(const rb_criteria *c, const rb_result *r)
{
    return !(r->fy_row_n > 0) && c->friction_coefficient > 0;
}

static int slides(const rb_criteria *c, const rb_result *r)
{
    return free_standing_judged(c, r) && r->max_friction_demand > c->friction_coefficient;
}

static void criteria(const rb_criteria *c, const rb_result *r, rb_verdict *v)
{
    rb_route_applied route = route_applied(c, r);
    v->anchor_route = (int)route;
    char num[32];
    rb_governing g = rb_result_governing(r);
    double usage = g.usage, shear = g.shear_over_w, force = g.force_over_fy;
    if (r->overturned)
        SAY(v, 0, "the cabinet overturns at t = %.3f s", r->overturn_s);
    else if (r->broken[0] || r->broken[1])
        SAY(v, 0, "a bolt row breaks at t = %.3f s",
            r->broken[0] ? r->break_s[0] : r->break_s[1]);
    else if (c->kind == RB_CRIT_NO_YIELD && (r->yielded[0] || r->yielded[1]))
        SAY(v, 0, "a bolt row yields at t = %.3f s (criterion: no yield)",
            r->yielded[0] ? r->first_yield_s[0] : r->first_yield_s[1]);
    else if (c->kind == RB_CRIT_NO_YIELD && force >= 1.0)
        /* rows that never yield in the model still must not reach Fy */
        SAY(v, 0, "a bolt row force reaches Fy (max force / Fy = %s; criterion: no yield)",
            beside(force, 1.0, num, sizeof num));
    else if (c->kind == RB_CRIT_NO_BREAK && usage >= c->usage_limit)
        SAY(v, 0, "bolt toughness usage %s reaches the limit %s",
            beside(usage, c->usage_limit, num, sizeof num), limit_str(c->usage_limit).s);
    else if (c->max_shear_over_w > 0 && shear > c->max_shear_over_w)
        SAY(v, 0, "base shear / W = %s exceeds its limit %s",
            beside(shear, c->max_shear_over_w, num, sizeof num), limit_str(c->max_shear_over_w).s);
    else if (c->max_theta_over_alpha > 0 && r->max_theta_over_alpha > c->max_theta_over_alpha)
        SAY(v, 0, "rotation / alpha = %s exceeds its limit %s",
            beside(r->max_theta_over_alpha, c->max_theta_over_alpha, num, sizeof num),
            limit_str(c->max_theta_over_alpha).s);
    else if (slides(c, r))
        SAY(v, 0, "the base slides: friction demand %s exceeds the friction coefficient "
            "%s (free-standing: the model assumes the base does not slide)",
            beside(r->max_friction_demand, c->friction_coefficient, num, sizeof num),
            limit_str(c->friction_coefficient).s);
    else if (route_fails(c, route))
        route_reason(c, r, route, v);
    else if (c->concrete && r->anchor_checked && r->anchor_max_ratio >= 1.0)
        SAY(v, 0, "the anchorage reaches its concrete design strength: %s utilization %s at "
            "t = %.3f s (tension %s, shear %s)",
            rb_aci17_interaction_clause(r->anchor_clause),
            beside(r->anchor_max_ratio, 1.0, num, sizeof num), r->anchor_max_s,
            rb_qty_str(c->units, RB_Q_FORCE, r->anchor_tension_n, 4).s,
            rb_qty_str(c->units, RB_Q_FORCE, r->anchor_shear_n, 4).s);
    else if (c->kind == RB_CRIT_NO_YIELD && isnan(force))
        SAY(v, 1, "no bolts to yield; the cabinet stands (max rotation / alpha = %s)",
            beside(r->max_theta_over_alpha, 1.0, num, sizeof num));
    else if (c->kind == RB_CRIT_NO_YIELD)
        SAY(v, 1, "bolts stay elastic (max force / Fy = %s)", beside(force, 1.0, num, sizeof num));
    else
        SAY(v, 1, "bolt toughness usage %s is below the limit %s",
            beside(usage, c->usage_limit, num, sizeof num), limit_str(c->usage_limit).s);
}

double rb_bolt_impact_over_fy(const rb_result *r)
{
    if (!r->rigid_bolts || !(r->fy_row_n > 0) || !(r->max_bolt_impact_n >= r->fy_row_n))
        return 0;
    return r->max_bolt_impact_n / r->fy_row_n;
}

int rb_bolt_impact_note(const rb_result *r, char *buf, size_t n)
{
    double x = rb_bolt_impact_over_fy(r);
    if (n)
        buf[0] = '\0';
    if (!(x > 0) || !n)
        return 0;
    snprintf(buf, n, "rigid bolts: an elastic bolt would load the row to %.3g Fy", x);
    return 1;
}

void rb_judge(const rb_criteria *c, const rb_result *r, rb_verdict *v)
{
    memset(v, 0, sizeof *v);
    criteria(c, r, v);
    validity(c, r, v);
    v->pass = v->criteria_pass;
    if (v->pass && (v->warnings & c->validity_mask) && c->validity == RB_VALIDITY_FAIL) {
        char w[128];
        rb_warnings_str(v->warnings & c->validity_mask, w, sizeof w);
        snprintf(v->reason, sizeof v->reason, "%s (criteria: validity: fail)", w);
        v->pass = 0;
    }
    /* a verdict on rigid stops that hid an impact says what they hid, so
     * that a pass is not read as the bolts' own (docs/solver.md, Bolt impact) */
    char note[96];
    size_t len = strlen(v->reason);
    if (rb_bolt_impact_note(r, note, sizeof note) && len < sizeof v->reason)
        snprintf(v->reason + len, sizeof v->reason - len, "; %s", note);
}

/* How far value is below limit, as a fraction of the limit. */
static double below(double value, double limit)
{
    return 1 - value / limit;
}

const char *rb_governs_name(rb_governs_limit k)
{
    switch (k) {
    case RB_GOVERNS_OVERTURN: return "overturning";
    case RB_GOVERNS_BREAK: return "bolt break";
    case RB_GOVERNS_YIELD: return "bolt yield";
    case RB_GOVERNS_USAGE: return "toughness usage";
    case RB_GOVERNS_SHEAR: return "base shear";
    case RB_GOVERNS_ROTATION: return "rotation";
    case RB_GOVERNS_SLIDING: return "sliding";
    case RB_GOVERNS_ROUTE: return "anchorage route";
    case RB_GOVERNS_ANCHORAGE: return "anchorage utilization";
    case RB_GOVERNS_VALIDITY: return "validity";
    case RB_GOVERNS_CONFIRMATION: return "convergence";
    case RB_N_GOVERNS: break;
    }
    return "?";
}

/* m and *lim take x and k where x is the nearer to failing: a tie keeps
 * the earlier limit, and every limit reached is at 0, so that of several
 * the judge's first (the verdict's reason) governs; a NaN (a number that
 * does not apply) gives way to any number, as fmin does. */
static void nearer(double *m, rb_governs_limit *lim, double x, rb_governs_limit k)
{
    if (x < 0)
        x = 0;
    if (x < *m || (isnan(*m) && !isnan(x))) {
        *m = x;
        *lim = k;
    }
}

/* x at or below 0 is a limit reached: 0 (a NaN stays: no number). */
static double reached_at_0(double x)
{
    return x < 0 ? 0 : x;
}

void rb_verdict_margins(const rb_criteria *c, const rb_result *r, double m[RB_N_GOVERNS])
{
    rb_governing g = rb_result_governing(r);
    for (int k = 0; k < RB_N_GOVERNS; k++)
        m[k] = NAN;
    if (r->overturned || r->broken[0] || r->broken[1]) {
        m[r->overturned ? RB_GOVERNS_OVERTURN : RB_GOVERNS_BREAK] = 0;
        return;
    }
    /* overturning is a limit of every criterion */
    m[RB_GOVERNS_OVERTURN] = reached_at_0(below(r->max_theta_over_alpha, 1));
    if (c->kind == RB_CRIT_NO_YIELD)
        m[RB_GOVERNS_YIELD] = reached_at_0(r->yielded[0] || r->yielded[1]
                                           ? 0 : below(g.force_over_fy, 1));
    else
        m[RB_GOVERNS_USAGE] = reached_at_0(below(g.usage, c->usage_limit));
    if (c->max_shear_over_w > 0)
        m[RB_GOVERNS_SHEAR] = reached_at_0(below(g.shear_over_w, c->max_shear_over_w));
    if (c->max_theta_over_alpha > 0)
        m[RB_GOVERNS_ROTATION] = reached_at_0(below(r->max_theta_over_alpha,
                                                    c->max_theta_over_alpha));
    if (free_standing_judged(c, r))
        m[RB_GOVERNS_SLIDING] = reached_at_0(below(r->max_friction_demand,
                                                   c->friction_coefficient));
    if (route_fails(c, route_applied(c, r)))
        m[RB_GOVERNS_ROUTE] = 0;
    if (c->concrete && r->anchor_checked)
        m[RB_GOVERNS_ANCHORAGE] = reached_at_0(below(r->anchor_max_ratio, 1));
    if (c->validity == RB_VALIDITY_FAIL) {
        unsigned mask = c->validity_mask;
        rb_governs_limit unused;
        if ((mask >> RB_CHECK_LIFT_OFF) & 1u && r->weight_n > 0)
            nearer(&m[RB_GOVERNS_VALIDITY], &unused, r->min_vertical_reaction_n / r->weight_n,
                   RB_GOVERNS_VALIDITY);
        if ((mask >> RB_CHECK_BOLT_IMPACT) & 1u && r->rigid_bolts && r->fy_row_n > 0)
            nearer(&m[RB_GOVERNS_VALIDITY], &unused, below(r->max_bolt_impact_n, r->fy_row_n),
                   RB_GOVERNS_VALIDITY);
    }
}

double rb_verdict_margin_of(const rb_criteria *c, const rb_result *r, rb_governs_limit *limit)
{
    double each[RB_N_GOVERNS];
    rb_governs_limit lim = RB_GOVERNS_OVERTURN, dummy;
    if (!limit)
        limit = &dummy;
    rb_verdict_margins(c, r, each);
    if (r->overturned || r->broken[0] || r->broken[1]) {
        *limit = r->overturned ? RB_GOVERNS_OVERTURN : RB_GOVERNS_BREAK;
        return 0;
    }
    /* the judge's order: of two limits at one margin the first governs; a
     * limit that does not apply is a NaN, which gives way to any number */
    double m = each[RB_GOVERNS_OVERTURN];
    for (int k = RB_GOVERNS_OVERTURN + 1; k < RB_GOVERNS_CONFIRMATION; k++)
        nearer(&m, &lim, each[k], (rb_governs_limit)k);
    *limit = lim;
    /* a NaN (no number to judge by) is as marginal as can be */
    return m > 0 ? m : 0;
}

double rb_verdict_margin(const rb_criteria *c, const rb_result *r)
{
    return rb_verdict_margin_of(c, r, NULL);
}

double rb_verdict_governing(const rb_criteria *c, const rb_result *r, const rb_verdict *v,
                            rb_governs_limit *limit)
{
    rb_governs_limit lim;
    double m = rb_verdict_margin_of(c, r, &lim);
    if (!v->pass && m > 0) {
        /* the run held its limits; its confirming runs did not */
        lim = RB_GOVERNS_CONFIRMATION;
        m = 0;
    }
    if (limit)
        *limit = lim;
    return v->pass ? m : 0;
}

int rb_margin_governs(double a, double b)
{
    /* no number to judge by is as marginal as can be (rb_verdict_margin) */
    a = a == a ? a : 0;
    b = b == b ? b : 0;
    /* a failing run (0) governs every pass, however near its margin is to 0;
     * passes tie within RB_MARGIN_TIE, so that two motions whose margins
     * are one number reached by two roundings name the first motion on
     * every build, not the one whose last bit came out lower */
    if (a == 0)
        return b > 0;
    return a < b - RB_MARGIN_TIE;
}

/* A plate that rocked near the bolt heads and never met them leaves every
 * limit of the rows untouched, yet the response jumps where it would meet
 * them: a touch loads a row, which can reach Fy at once. Under no-yield
 * such a near miss is as marginal as a force near Fy (docs/report-format.md,
 * "Confirmation"); under no-break a touch starts a usage at zero, which
 * the margin already measures. */
int rb_result_near_contact(const rb_result *r, double band)
{
    return r->theta0_rad > 0 && r->bolt_impacts == 0 && r->max_bolt_force_n[0] == 0
           && r->max_bolt_force_n[1] == 0 && r->max_theta_rad > (1 - band) * r->theta0_rad;
}

double rb_confirm_band(const rb_criteria *c, const rb_motion *motion)
{
    return motion && motion->kind == RB_MOTION_HARMONIC ? 1 : c->confirm_band;
}

int rb_verdict_wants_confirm(const rb_criteria *c, double band, const rb_result *r,
                             const rb_verdict *v)
{
    if (!v->pass || c->confirm == RB_CONFIRM_OFF)
        return 0;
    return c->confirm == RB_CONFIRM_ALWAYS || rb_verdict_margin(c, r) < band
           || (c->kind == RB_CRIT_NO_YIELD && rb_result_near_contact(r, band));
}

/* Where a run was solved, for a reason: its tolerance, and its rest
 * fraction where it is not the first confirming run's (the run confirmed
 * has that one); cr NULL is the run confirmed, at rtol. */
static const char *run_where(char *buf, size_t n, const rb_confirm_run *runs,
                             const rb_confirm_run *cr, double rtol)
{
    int len = snprintf(buf, n, "%.3g", cr ? cr->rtol : rtol);
    if (cr && cr->rest_fraction != runs[0].rest_fraction && len > 0 && (size_t)len < n)
        snprintf(buf + len, n - (size_t)len, " and rest fraction %.3g", cr->rest_fraction);
    return buf;
}

/* One margin's range over the run confirmed (first) and its confirming
 * runs: the least margin's (k == RB_N_GOVERNS) or limit k's own. A run
 * with a number replaces a NaN, so that a limit no run reaches stays NaN
 * while one that some run reaches is judged by those runs. */
typedef struct {
    double lo, hi;
    const rb_confirm_run *run_lo, *run_hi;   /* NULL: the run confirmed */
} margin_range;

static margin_range range_over(double first, int k, const rb_confirm_run *runs, size_t n)
{
    margin_range r = {first, first, NULL, NULL};
    for (size_t i = 0; i < n; i++) {
        double x = k == RB_N_GOVERNS ? runs[i].margin : runs[i].limit_margins[k];
        if (x < r.lo || (isnan(r.lo) && !isnan(x))) {
            r.lo = x;
            r.run_lo = &runs[i];
        }
        if (x > r.hi || (isnan(r.hi) && !isnan(x))) {
            r.hi = x;
            r.run_hi = &runs[i];
        }
    }
    return r;
}

/* Converged: the runs agree within RB_CONFIRM_SPREAD, or every run keeps
 * the band to spare and more than the scatter seen. NaN is not converged. */
static int range_converged(margin_range r, double band)
{
    return r.hi - r.lo <= RB_CONFIRM_SPREAD || (r.lo >= band && r.hi - r.lo < r.lo);
}

void rb_verdict_confirm(rb_verdict *v, double margin, const double *limit_margins, double band,
                        double rtol, const rb_confirm_run *runs, size_t n)
{
    if (!n)
        return;
    v->check[RB_CHECK_CONVERGENCE] = RB_CHECK_OK;
    for (size_t i = 0; i < n; i++) {
        const rb_confirm_run *cr = &runs[i];
        if (cr->solved && cr->verdict.pass)
            continue;
        v->check[RB_CHECK_CONVERGENCE] = RB_CHECK_WARNING;
        v->warnings |= 1u << RB_CHECK_CONVERGENCE;
        if (!v->pass)
            continue;
        /* the first run that fails says why; the others only warn */
        const char *how = rb_enum_str(rb_integrator_names, cr->integrator);
        char at[40];
        run_where(at, sizeof at, runs, cr, rtol);
        if (cr->solved)
            snprintf(v->reason, sizeof v->reason, "not confirmed: at tolerance %s (%s), %.180s",
                     at, how, cr->verdict.reason);
        else
            snprintf(v->reason, sizeof v->reason, "not confirmed: the run at tolerance "
                     "%s (%s) stopped: %s", at, how,
                     rb_status_str((rb_status)cr->status));
        v->pass = 0;
    }
    if (!v->pass)
        return;
    /* Every run passes. A response that converges gives them all one
     * margin; one that does not (near grazing, a yielding row's usage under
     * a long excitation) scatters, and a next tolerance is another draw
     * from that scatter, which three draws do not bound: passes whose runs
     * agreed within a twentieth of the limit broke a row in one of six
     * more. A pass whose runs agree within RB_CONFIRM_SPREAD has
     * converged; one whose runs do not stands only where every run keeps
     * the band to spare, and more than the scatter seen. */
    margin_range r = range_over(margin, RB_N_GOVERNS, runs, n);
    char at_lo[40], at_hi[40];
    /* a NaN least margin signs nothing, whatever the other runs give */
    if (isnan(margin) || !range_converged(r, band)) {
        v->check[RB_CHECK_CONVERGENCE] = RB_CHECK_WARNING;
        v->warnings |= 1u << RB_CHECK_CONVERGENCE;
        snprintf(v->reason, sizeof v->reason, "not confirmed: %.3g to spare of the nearest "
                 "limit at tolerance %s but %.3g at %s (%s); the run does not converge, and "
                 "a further one can take more than that", r.lo,
                 run_where(at_lo, sizeof at_lo, runs, r.run_lo, rtol), r.hi,
                 run_where(at_hi, sizeof at_hi, runs, r.run_hi, rtol),
                 rb_enum_str(rb_integrator_names, runs[0].integrator));
        v->pass = 0;
        return;
    }
    /* The least margin converging is not the response converging: a
     * harmonic's rotation can agree to the thousandth over three runs
     * while the usage they give moves from 0.026 to 0.054, and the run
     * that broke the row was one draw further. Whether the least margin
     * agreed can turn on the last bit of a run (a change of the series'
     * rounding alone turned tests/verdicts/cases/harmonic-chaos-pass.yaml
     * into a pass), so every limit's own margin is held to the same rule. */
    if (!limit_margins)
        return;
    /* a limit no run reaches (NaN in every run) does not scatter */
    int k = 0;
    for (; k < RB_N_GOVERNS; k++) {
        r = range_over(limit_margins[k], k, runs, n);
        if (!isnan(r.hi - r.lo) && !range_converged(r, band))
            break;
    }
    if (k == RB_N_GOVERNS)
        return;
    v->check[RB_CHECK_CONVERGENCE] = RB_CHECK_WARNING;
    v->warnings |= 1u << RB_CHECK_CONVERGENCE;
    snprintf(v->reason, sizeof v->reason, "not confirmed: %.3g to spare of the %s at "
             "tolerance %s but %.3g at %s (%s); the run does not converge, and a further "
             "one can take more than that", r.lo, rb_governs_name((rb_governs_limit)k),
             run_where(at_lo, sizeof at_lo, runs, r.run_lo, rtol), r.hi,
             run_where(at_hi, sizeof at_hi, runs, r.run_hi, rtol),
             rb_enum_str(rb_integrator_names, runs[0].integrator));
    v->pass = 0;
}
