/* The concrete check in the text report: the anchorage's design strength
 * in each mode (list "concrete", with its list "modes"), and each motion's
 * demand on it at the instant of its largest 17.8 utilization. Forces in
 * the case's output units. */
#include <math.h>
#include <stdio.h>
#include "rockbolt/names.h"
#include "report_internal.h"

static const rb_out_units *units_of(const rb_report *r)
{
    return rb_out_units_of(r->kase->output_units);
}

static int modes_list(rb_txt_arena *a, const rb_report *r, rb_tlist *out)
{
    const rb_anchor_strength *s = &r->kase->anchor;
    const rb_out_units *u = units_of(r);
    rb_tscope *items = rb_txt_arena_alloc(a, RB_ANCHOR_N_MODES, sizeof *items);
    out->name = "modes";
    out->items = items;
    out->n = RB_ANCHOR_N_MODES;
    if (!items)
        return 0;
    for (int k = 0; k < RB_ANCHOR_N_MODES; k++) {
        const rb_anchor_mode_strength *m = &s->mode[k];
        rb_tvars t = {rb_txt_arena_alloc(a, RB_TXT_MAX_VARS, sizeof(rb_tvar)), 0};
        if (!t.v)
            return 0;
        rb_tv_str(&t, "mode", rb_enum_str(rb_anchor_mode_names, k));
        rb_tv_str(&t, "clause", rb_anchor_clause((rb_anchor_mode)k));
        rb_tv_str(&t, "equation", rb_anchor_equation((rb_anchor_mode)k));
        rb_tv_opt(&t, "nominal", m->applies, m->nominal_n / u->force_f);
        rb_tv_num(&t, "phi", m->phi);
        rb_tv_num(&t, "seismic", m->seismic);
        rb_tv_opt(&t, "design", m->applies, m->design_n / u->force_f);
        rb_tv_str(&t, "applies", !m->applies ? "does not apply"
                                 : rb_anchor_mode_is_steel((rb_anchor_mode)k)
                                 ? "static check; the run's steel: its criterion" : "");
        items[k].vars = t.v;
        items[k].n_vars = t.n;
    }
    return 1;
}

rb_status rb_report_text_concrete(const rb_report *r, rb_txt_arena *a, rb_tlist *out)
{
    out->name = "concrete";
    out->items = NULL;
    out->n = 0;
    if (!r->kase || !r->kase->has_concrete)
        return RB_OK;
    const rb_anchor_inputs *in = &r->kase->anchor_in;
    const rb_anchor_strength *s = &r->kase->anchor;
    const rb_out_units *u = units_of(r);
    rb_tscope *sc = rb_txt_arena_alloc(a, 1, sizeof *sc);
    rb_tlist *modes = rb_txt_arena_alloc(a, 1, sizeof *modes);
    rb_tvars t = {rb_txt_arena_alloc(a, RB_TXT_MAX_VARS, sizeof(rb_tvar)), 0};
    if (!sc || !modes || !t.v || !modes_list(a, r, modes))
        return RB_ERR_NOMEM;
    rb_tv_str(&t, "anchor_type", rb_enum_str(rb_anchor_type_names, (int)in->type));
    rb_tv_str(&t, "coefficients", rb_enum_str(rb_aci17_coef_names, (int)in->coef));
    rb_tv_num(&t, "fc", in->fc_pa / u->stress_f);
    rb_tv_str(&t, "cracked", in->cracked ? "cracked" : "uncracked");
    rb_tv_num(&t, "slab", in->thickness_m / u->small_length_f);
    /* no edge near: the slab's edge plays no part, and has no number */
    rb_tv_int(&t, "has_edge", isfinite(in->edge_m));
    rb_tv_opt(&t, "edge", isfinite(in->edge_m), in->edge_m / u->small_length_f);
    rb_tv_num(&t, "hef", in->hef_m / u->small_length_f);
    rb_tv_num(&t, "spacing", in->spacing_m / u->small_length_f);
    rb_tv_str(&t, "condition", in->condition_a ? "A" : "B");
    rb_tv_str(&t, "seismic_design", in->seismic ? "yes (17.10)" : "no");
    rb_tv_num(&t, "ase", s->ase_m2 / u->area_f);
    rb_tv_num(&t, "abrg", s->abrg_m2 / u->area_f);
    rb_tv_str(&t, "edge_reinforcement", rb_enum_str(rb_edge_reinforcement_names,
                                                    (int)in->edge_reinforcement));
    rb_tv_str(&t, "interaction", rb_enum_str(rb_interaction_names, (int)in->interaction));
    rb_tv_str(&t, "seismic_route", rb_enum_str(rb_seismic_route_names, (int)in->route));
    rb_tv_str(&t, "shear_case", s->shear_case == 3 ? "Case 3 of Fig. R17.7.2.1b (rows closer "
                                                     "than c_a1: the front row takes all)"
                                : s->shear_case ? "Cases 1 and 2 of Fig. R17.7.2.1b (front "
                                                  "row V/2, rear row V)"
                                : "no edge: breakout in shear does not apply");
    rb_tv_num(&t, "phi_nn", s->phi_nn_n / u->force_f);
    rb_tv_num(&t, "phi_vn", s->phi_vn_n / u->force_f);
    rb_tv_str(&t, "tension_governs", rb_enum_str(rb_anchor_mode_names, (int)s->tension_mode));
    rb_tv_str(&t, "shear_governs", rb_enum_str(rb_anchor_mode_names, (int)s->shear_mode));
    rb_tv_num(&t, "phi_nn_concrete", s->phi_nn_concrete_n / u->force_f);
    rb_tv_num(&t, "phi_vn_concrete", s->phi_vn_concrete_n / u->force_f);
    rb_tv_str(&t, "concrete_tension_governs",
              rb_enum_str(rb_anchor_mode_names, (int)s->concrete_tension_mode));
    rb_tv_str(&t, "concrete_shear_governs",
              rb_enum_str(rb_anchor_mode_names, (int)s->concrete_shear_mode));
    rb_tv_num(&t, "attachment_margin", s->attachment_margin);
    rb_tv_num(&t, "ductility_margin", s->ductility_margin);
    rb_tv_str(&t, "stretch_ok", s->stretch_ok ? "at least 8 da" : "below 8 da");
    rb_tv_num(&t, "futa_over_fya", s->futa_over_fya);
    rb_tv_str(&t, "threads", rb_enum_str(rb_anchor_threads_names, (int)in->threads));
    rb_tv_str(&t, "threads_ok", s->threads_ok ? "ok" : "below 1.3");
    rb_tv_str(&t, "ductile", s->ductile ? "ductile" : "NOT ductile");
    rb_tv_str(&t, "judged", r->kase->criteria.concrete ? "part of the verdict"
                                                        : "reported, not judged");
    sc->vars = t.v;
    sc->n_vars = t.n;
    sc->lists = modes;
    sc->n_lists = 1;
    out->items = sc;
    out->n = 1;
    return RB_OK;
}

rb_status rb_report_text_motion_anchor_modes(const rb_report *r, const rb_report_motion *m,
                                             rb_txt_arena *a, rb_tlist *out)
{
    const rb_result *res = m->result;
    out->name = "anchor_modes";
    out->items = NULL;
    out->n = 0;
    if (!r->kase || !r->kase->has_concrete || !res || !res->anchor_checked)
        return RB_OK;
    const rb_anchor_strength *s = &r->kase->anchor;
    const rb_out_units *u = units_of(r);
    rb_tscope *items = rb_txt_arena_alloc(a, RB_ANCHOR_N_MODES, sizeof *items);
    if (!items)
        return RB_ERR_NOMEM;
    for (int k = 0; k < RB_ANCHOR_N_MODES; k++) {
        const rb_anchor_mode_strength *md = &s->mode[k];
        double demand = rb_anchor_mode_in_tension((rb_anchor_mode)k) ? res->anchor_tension_n
                                                                       : res->anchor_shear_n;
        rb_tvars t = {rb_txt_arena_alloc(a, RB_TXT_MAX_VARS, sizeof(rb_tvar)), 0};
        if (!t.v)
            return RB_ERR_NOMEM;
        rb_tv_str(&t, "mode", rb_enum_str(rb_anchor_mode_names, k));
        rb_tv_str(&t, "clause", rb_anchor_clause((rb_anchor_mode)k));
        rb_tv_num(&t, "demand", demand / u->force_f);
        rb_tv_opt(&t, "design", md->applies, md->design_n / u->force_f);
        rb_tv_opt(&t, "ratio", md->applies, demand / md->design_n);
        items[k].vars = t.v;
        items[k].n_vars = t.n;
    }
    out->items = items;
    out->n = RB_ANCHOR_N_MODES;
    return RB_OK;
}

void rb_report_text_motion_anchorage(rb_tvars *t, const rb_report *r,
                                     const rb_report_motion *m)
{
    const rb_result *res = m->result;
    int have = r->kase && r->kase->has_concrete && res && res->anchor_checked;
    const rb_out_units *u = units_of(r);
    rb_tv_int(t, "has_anchorage", have);
    if (!have)
        return;
    const rb_anchor_strength *s = &r->kase->anchor;
    rb_tv_num(t, "anchor_utilization", res->anchor_max_ratio);
    rb_tv_str(t, "anchor_clause", rb_aci17_interaction_clause(res->anchor_clause));
    rb_tv_num(t, "anchor_s", res->anchor_max_s);
    rb_tv_num(t, "anchor_tension", res->anchor_tension_n / u->force_f);
    rb_tv_num(t, "anchor_tension_ratio", res->anchor_tension_n / s->phi_nn_concrete_n);
    rb_tv_num(t, "anchor_shear", res->anchor_shear_n / u->force_f);
    rb_tv_num(t, "anchor_shear_ratio", res->anchor_shear_n / s->phi_vn_concrete_n);
    /* the largest shear of the run, which the instant of the largest
     * utilization need not hold (17.8.1 counts tension alone) */
    rb_tv_num(t, "anchor_shear_max", res->max_shear_total_n / u->force_f);
    rb_tv_num(t, "anchor_shear_max_ratio", res->max_shear_total_n / s->phi_vn_concrete_n);
    rb_tv_str(t, "anchor_route", rb_enum_str(rb_route_applied_names, m->verdict.anchor_route));
    rb_tv_str(t, "anchor_mode", rb_enum_str(rb_anchor_mode_names,
                                            (int)rb_anchor_governing_mode(
                                                s, res->anchor_tension_n, res->anchor_shear_n)));
}
