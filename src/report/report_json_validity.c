/* The JSON report's validity parts: per motion, whether the model's own
 * assumptions held (docs/report-format.md, "Validity"), and the names of
 * the checks that warn, which the verdicts carry. */
#include <math.h>
#include <stdio.h>
#include "rockbolt/version.h"
#include "rockbolt/names.h"
#include "report_internal.h"
#include "report_json_build.h"

void rb_j_warnings(rb_jctx *cx, cJSON *o, const char *key, unsigned warnings)
{
    cJSON *a = rb_j_arr(cx, o, key);
    for (int k = 0; k < RB_N_CHECKS && cx->st == RB_OK; k++)
        if ((warnings >> k) & 1u)
            rb_j_append(cx, a, cJSON_CreateString(rb_check_name((rb_check)k)));
}

static cJSON *check_obj(rb_jctx *cx, cJSON *parent, const rb_verdict *v, rb_check k)
{
    cJSON *o = rb_j_obj(cx, parent, rb_check_key(k));
    rb_j_str(cx, o, "status", rb_check_status_str(v->check[k]));
    return o;
}

void rb_report_json_validity(rb_jctx *cx, cJSON *motion_o, const rb_report *r,
                             const rb_report_motion *m)
{
    const rb_result *res = m->result;
    const rb_criteria *c = &r->kase->criteria;
    const rb_verdict *v = &m->verdict;
    double w = res->weight_n;
    cJSON *o = rb_j_obj(cx, motion_o, "validity"), *k;
    rb_j_str(cx, o, "mode", rb_enum_str(rb_validity_mode_names, (int)c->validity));
    k = check_obj(cx, o, v, RB_CHECK_LIFT_OFF);
    rb_j_num(cx, k, "min_vertical_reaction_n", res->min_vertical_reaction_n);
    rb_j_norm(cx, k, "min_vertical_reaction_over_w",
              rb_report_ratio(res->min_vertical_reaction_n, w));
    rb_j_opt(cx, k, "first_s", res->liftoff_first_s >= 0, res->liftoff_first_s);
    rb_j_num(cx, k, "time_s", res->liftoff_time_s);
    k = check_obj(cx, o, v, RB_CHECK_SLIDING);
    rb_j_opt(cx, k, "friction_coefficient", c->friction_coefficient > 0,
             c->friction_coefficient);
    rb_j_num(cx, k, "reaction_floor_over_w", RB_FRICTION_FLOOR);
    rb_j_num(cx, k, "max_friction_demand", res->max_friction_demand);
    rb_j_num(cx, k, "max_horizontal_reaction_n", res->max_shear_total_n);
    rb_j_norm(cx, k, "max_horizontal_reaction_over_w",
              rb_report_ratio(res->max_shear_total_n, w));
    k = check_obj(cx, o, v, RB_CHECK_BOLT_IMPACT);
    rb_j_opt(cx, k, "max_force_n", res->rigid_bolts, res->max_bolt_impact_n);
    rb_j_norm(cx, k, "max_force_over_fy", res->rigid_bolts
              ? rb_report_ratio(res->max_bolt_impact_n, res->fy_row_n) : (double)NAN);
    rb_j_opt(cx, k, "time_s", res->rigid_bolts && res->max_bolt_impact_n > 0,
             res->max_bolt_impact_s);
    rb_j_opt(cx, k, "row_stiffness_npm", res->rigid_bolts, r->derived.k_row_npm);
    rb_j_opt(cx, k, "effective_mass_kg", res->rigid_bolts,
             r->derived.Io / (r->kase->model.lever_arm_m * r->kase->model.lever_arm_m));
    rb_report_json_convergence(cx, o, r, m);
}

/* The confirmation of a pass (docs/report-format.md, "Confirmation"): how the
 * case asks for it, how far the run was from failing, and each
 * confirming run with its verdict. */
void rb_report_json_convergence(rb_jctx *cx, cJSON *validity_o, const rb_report *r,
                                const rb_report_motion *m)
{
    const rb_criteria *c = &r->kase->criteria;
    cJSON *o = check_obj(cx, validity_o, &m->verdict, RB_CHECK_CONVERGENCE);
    rb_j_str(cx, o, "confirm", rb_enum_str(rb_confirm_mode_names, (int)c->confirm));
    rb_j_num(cx, o, "band", rb_confirm_band(c, &m->motion->motion));
    rb_j_num(cx, o, "margin", rb_verdict_margin(c, m->result));
    cJSON *runs = rb_j_arr(cx, o, "runs");
    for (size_t i = 0; i < m->n_confirm && cx->st == RB_OK; i++) {
        const rb_confirm_run *cr = &m->confirm[i];
        cJSON *x = rb_j_item(cx, runs);
        rb_j_str(cx, x, "integrator", rb_enum_str(rb_integrator_names, cr->integrator));
        rb_j_num(cx, x, "tolerance", cr->rtol);
        rb_j_num(cx, x, "rest_fraction", cr->rest_fraction);
        rb_j_bool(cx, x, "solved", cr->solved);
        if (!cr->solved) {
            rb_j_str(cx, x, "error", rb_status_str((rb_status)cr->status));
            continue;
        }
        rb_j_bool(cx, x, "pass", cr->verdict.pass);
        rb_j_str(cx, x, "reason", cr->verdict.reason);
        rb_j_num(cx, x, "usage", cr->usage);
        rb_j_norm(cx, x, "max_bolt_force_over_fy", cr->max_bolt_force_over_fy);
        rb_j_num(cx, x, "max_theta_over_alpha", cr->max_theta_over_alpha);
        rb_j_num(cx, x, "margin", cr->margin);
    }
}
