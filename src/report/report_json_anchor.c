/* The concrete check in the JSON report: under the root the anchorage's
 * inputs and its design strength in each mode of ACI 318-19 Chapter 17;
 * under each motion the demand it put on them. Written only for a case
 * with concrete:, so that other reports keep their bytes. SI throughout. */
#include <math.h>
#include "report_json_build.h"
#include "rockbolt/names.h"

static void add_inputs(rb_jctx *cx, cJSON *o, const rb_anchor_inputs *in)
{
    rb_j_str(cx, o, "type", rb_enum_str(rb_anchor_type_names, (int)in->type));
    rb_j_str(cx, o, "coefficients", rb_enum_str(rb_aci17_coef_names, (int)in->coef));
    rb_j_num(cx, o, "strength_pa", in->fc_pa);
    rb_j_bool(cx, o, "cracked", in->cracked);
    rb_j_num(cx, o, "lightweight", in->lambda_a);
    rb_j_num(cx, o, "thickness_m", in->thickness_m);
    rb_j_opt(cx, o, "edge_distance_m", isfinite(in->edge_m), in->edge_m);
    rb_j_str(cx, o, "reinforcement", in->condition_a ? "present" : "none");
    rb_j_bool(cx, o, "seismic", in->seismic);
    rb_j_num(cx, o, "embedment_m", in->hef_m);
    rb_j_num(cx, o, "spacing_m", in->spacing_m);
    rb_j_num(cx, o, "ultimate_stress_pa", in->futa_pa);
    rb_j_opt(cx, o, "tensile_area_m2", in->ase_m2 > 0, in->ase_m2);
    rb_j_bool(cx, o, "grout_pad", in->grout_pad);
    rb_j_str(cx, o, "threads", rb_enum_str(rb_anchor_threads_names, (int)in->threads));
    rb_j_str(cx, o, "edge_reinforcement", rb_enum_str(rb_edge_reinforcement_names,
                                                      (int)in->edge_reinforcement));
    rb_j_str(cx, o, "interaction", rb_enum_str(rb_interaction_names, (int)in->interaction));
    rb_j_str(cx, o, "seismic_route", rb_enum_str(rb_seismic_route_names, (int)in->route));
}

void rb_report_json_anchorage(rb_jctx *cx, cJSON *root, const rb_report *r)
{
    const rb_case *c = r->kase;
    if (!c || !c->has_concrete || cx->st != RB_OK)
        return;
    const rb_anchor_strength *a = &c->anchor;
    cx->where = "anchorage_check";
    cJSON *o = rb_j_obj(cx, root, "anchorage_check");
    add_inputs(cx, rb_j_obj(cx, o, "inputs"), &c->anchor_in);
    rb_j_bool(cx, o, "judged", c->criteria.concrete);
    rb_j_num(cx, o, "anchor_diameter_m", a->da_m);
    rb_j_num(cx, o, "head_bearing_area_m2", a->abrg_m2);
    rb_j_num(cx, o, "tensile_area_m2", a->ase_m2);
    cJSON *modes = rb_j_arr(cx, o, "modes");
    for (int k = 0; k < RB_ANCHOR_N_MODES && cx->st == RB_OK; k++) {
        const rb_anchor_mode_strength *s = &a->mode[k];
        cJSON *m = rb_j_item(cx, modes);
        rb_j_str(cx, m, "mode", rb_enum_str(rb_anchor_mode_names, k));
        rb_j_str(cx, m, "clause", rb_anchor_clause((rb_anchor_mode)k));
        rb_j_bool(cx, m, "applies", s->applies);
        rb_j_opt(cx, m, "nominal_n", s->applies, s->nominal_n);
        rb_j_num(cx, m, "phi", s->phi);
        rb_j_num(cx, m, "seismic_factor", s->seismic);
        rb_j_opt(cx, m, "design_n", s->applies, s->design_n);
    }
    rb_j_num(cx, o, "phi_nn_row_n", a->phi_nn_n);
    rb_j_str(cx, o, "tension_governs", rb_enum_str(rb_anchor_mode_names, (int)a->tension_mode));
    rb_j_num(cx, o, "phi_vn_n", a->phi_vn_n);
    rb_j_str(cx, o, "shear_governs", rb_enum_str(rb_anchor_mode_names, (int)a->shear_mode));
    rb_j_num(cx, o, "phi_nn_concrete_row_n", a->phi_nn_concrete_n);
    rb_j_str(cx, o, "concrete_tension_governs",
             rb_enum_str(rb_anchor_mode_names, (int)a->concrete_tension_mode));
    rb_j_num(cx, o, "phi_vn_concrete_n", a->phi_vn_concrete_n);
    rb_j_str(cx, o, "concrete_shear_governs",
             rb_enum_str(rb_anchor_mode_names, (int)a->concrete_shear_mode));
    rb_j_opt(cx, o, "shear_case", a->shear_case != 0, a->shear_case);
    rb_j_opt(cx, o, "breakout_shear_front_row_n", a->shear_case != 0, a->vcbg_front_n);
    rb_j_opt(cx, o, "breakout_shear_rear_row_n", a->shear_case == 1, a->vcbg_rear_n);
    rb_j_num(cx, o, "ductility_margin", a->ductility_margin);
    rb_j_num(cx, o, "attachment_margin", a->attachment_margin);
    rb_j_opt(cx, o, "static_utilization", c->has_anchor_static, c->anchor_static_utilization);
    rb_j_bool(cx, o, "stretch_ok", a->stretch_ok);
    rb_j_num(cx, o, "futa_over_fya", a->futa_over_fya);
    rb_j_bool(cx, o, "threads_ok", a->threads_ok);
    rb_j_bool(cx, o, "ductile", a->ductile);
}

void rb_report_json_motion_anchorage(rb_jctx *cx, cJSON *motion_o, const rb_report *r,
                                     const rb_report_motion *m)
{
    const rb_result *res = m->result;
    if (!r->kase || !r->kase->has_concrete || !res || !res->anchor_checked)
        return;
    const rb_anchor_strength *a = &r->kase->anchor;
    cJSON *o = rb_j_obj(cx, motion_o, "anchorage");
    rb_j_num(cx, o, "utilization", res->anchor_max_ratio);
    rb_j_str(cx, o, "clause", rb_aci17_interaction_clause(res->anchor_clause));
    rb_j_num(cx, o, "time_s", res->anchor_max_s);
    rb_j_num(cx, o, "tension_n", res->anchor_tension_n);
    rb_j_num(cx, o, "shear_n", res->anchor_shear_n);
    rb_j_num(cx, o, "tension_ratio", res->anchor_tension_n / a->phi_nn_concrete_n);
    rb_j_num(cx, o, "shear_ratio", res->anchor_shear_n / a->phi_vn_concrete_n);
    rb_j_num(cx, o, "max_shear_n", res->max_shear_total_n);
    rb_j_str(cx, o, "governs", rb_enum_str(rb_anchor_mode_names,
                                           (int)rb_anchor_governing_mode(a, res->anchor_tension_n,
                                                                         res->anchor_shear_n)));
    rb_j_str(cx, o, "seismic_route", rb_enum_str(rb_route_applied_names, m->verdict.anchor_route));
    /* each mode's demand / design strength at that instant */
    cJSON *modes = rb_j_obj(cx, o, "mode_ratios");
    for (int k = 0; modes && k < RB_ANCHOR_N_MODES; k++) {
        const rb_anchor_mode_strength *s = &a->mode[k];
        double demand = rb_anchor_mode_in_tension((rb_anchor_mode)k) ? res->anchor_tension_n
                                                                       : res->anchor_shear_n;
        if (s->applies)
            rb_j_num(cx, modes, rb_enum_str(rb_anchor_mode_names, k), demand / s->design_n);
        else
            rb_j_null(cx, modes, rb_enum_str(rb_anchor_mode_names, k));
    }
}
