/* The text report: the variables a template sees, and the rendering.
 *
 * The layout lives in templates/report.txt (and its compiled-in copy);
 * this file only names the values, in engineering units (mm, kN, MPa) next
 * to their normalised forms, so the layout can change without touching C.
 * Each dimensional value has two names: one with its SI unit in the name
 * (gap_mm), and a unit-neutral one (gap) in the case's output units
 * (rb_case.output_units: SI or US customary) with the unit's name beside
 * it (gap_unit), which the shipped template uses.
 * The normalised forms come from report_common.c, as in the JSON report,
 * so the two agree digit for digit at the precision shown. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/version.h"
#include "rockbolt/names.h"
#include "report_internal.h"
#include "report_peaks.h"

/* The report's output units (rb_case.output_units). */
static const rb_out_units *out_units(const rb_report *r)
{
    return rb_out_units_of(r->kase->output_units);
}

/* The unit-neutral names: each value in the case's output units, with the
 * units' names, so that one template serves SI and US customary cases. */
static void case_unit_vars(rb_tvars *t, const rb_report *r)
{
    const rb_out_units *u = out_units(r);
    const rb_model *m = &r->kase->model;
    const rb_derived *d = &r->derived;
    static const char *const heads[2][4] = {
        { "max force (kN)", "absorbed (J)", "final gap (mm)", "energy (J)" },
        { "max force (kip)", "absorbed (ft-lbf)", "final gap (in)", "energy (ft-lbf)" } };
    int us = u->system == RB_UNITS_US;
    rb_tv_int(t, "si", !us);
    rb_tv_int(t, "us", us);
    rb_tv_str(t, "output_units", us ? "us" : "si");
    rb_tv_str(t, "mass_unit", u->mass);
    rb_tv_str(t, "force_unit", u->force);
    rb_tv_str(t, "length_unit", u->length);
    rb_tv_str(t, "gap_unit", u->small_length);
    rb_tv_str(t, "area_unit", u->area);
    rb_tv_str(t, "stress_unit", u->stress);
    rb_tv_str(t, "energy_unit", u->energy);
    rb_tv_str(t, "stiffness_unit", u->stiffness);
    rb_tv_str(t, "force_head", heads[us][0]);
    rb_tv_str(t, "absorbed_head", heads[us][1]);
    rb_tv_str(t, "final_gap_head", heads[us][2]);
    rb_tv_str(t, "energy_head", heads[us][3]);
    rb_tv_num(t, "mass", m->mass_kg / u->mass_f);
    rb_tv_num(t, "h", m->cm_height_m / u->length_f);
    rb_tv_num(t, "height", 2 * m->cm_height_m / u->length_f);
    rb_tv_num(t, "width", 2 * m->half_width_m / u->length_f);
    rb_tv_num(t, "bolt_area", m->bolt_area_m2 / u->area_f);
    rb_tv_num(t, "yield_stress", m->yield_stress_pa / u->stress_f);
    rb_tv_num(t, "lever_arm", m->lever_arm_m / u->length_f);
    rb_tv_num(t, "gap", m->gap_m / u->small_length_f);
    rb_tv_num(t, "fy_row", d->fy_row_n / u->force_f);
    rb_tv_num(t, "capacity", d->capacity_j / u->energy_f);
    rb_tv_num(t, "weight", d->W / u->force_f);
}

static void case_vars(rb_tvars *t, const rb_report *r)
{
    const rb_model *m = &r->kase->model;
    const rb_derived *d = &r->derived;
    size_t i, failed = 0;
    for (i = 0; i < r->n_motions; i++)
        failed += !r->motions[i].verdict.pass;
    rb_tv_str(t, "verdict", r->pass ? "PASS" : "FAIL");
    rb_tv_str(t, "headline", r->headline);
    rb_tv_int(t, "n_validity_warnings", (long)rb_warnings_count(r->warnings));
    rb_tv_str(t, "reason", r->reason);
    rb_tv_str(t, "version", RB_VERSION_STRING);
    rb_tv_str(t, "case_name", r->kase->name);
    rb_tv_str(t, "case_path", r->kase->path);
    rb_tv_str(t, "description", r->kase->description);
    rb_tv_str(t, "criterion", rb_enum_str(rb_criterion_names, (int)r->kase->criteria.kind));
    rb_tv_num(t, "usage_limit", r->kase->criteria.usage_limit);
    rb_tv_str(t, "confirm", rb_enum_str(rb_confirm_mode_names, (int)r->kase->criteria.confirm));
    rb_tv_num(t, "confirm_band", r->kase->criteria.confirm_band);
    /* the judge's band of a motion (rb_confirm_band) can be wider than the
     * case's, under a harmonic: the header says so */
    int wider = 0;
    for (i = 0; i < r->n_motions; i++)
        wider |= rb_confirm_band(&r->kase->criteria, &r->motions[i].motion->motion)
                 > r->kase->criteria.confirm_band;
    rb_tv_int(t, "has_harmonic", wider);
    rb_tv_str(t, "formulation", rb_enum_str(rb_formulation_names, (int)r->kase->solve.formulation));
    rb_tv_str(t, "integrator", rb_enum_str(rb_integrator_names, (int)r->kase->solve.integrator));
    rb_tv_int(t, "n_motions", (long)r->n_motions);
    rb_tv_int(t, "n_failed", (long)failed);
    rb_tv_num(t, "mass_kg", m->mass_kg);
    rb_tv_num(t, "h_m", m->cm_height_m);
    rb_tv_num(t, "height_m", 2 * m->cm_height_m);
    rb_tv_num(t, "width_m", 2 * m->half_width_m);
    rb_tv_str(t, "rigid", rb_yes_no(m->rigid));
    rb_tv_num(t, "freq_hz", m->freq_hz);
    rb_tv_num(t, "damping", m->damping);
    rb_tv_str(t, "bolt_model", rb_enum_str(rb_bolt_model_names, (int)m->bolt_model));
    rb_tv_int(t, "has_bolts", m->bolt_model != RB_BOLT_NONE);
    rb_tv_int(t, "bolts_per_row", m->bolts_per_row);
    rb_tv_num(t, "bolt_area_mm2", m->bolt_area_m2 * 1e6);
    rb_tv_num(t, "yield_stress_mpa", m->yield_stress_pa * 1e-6);
    rb_tv_num(t, "lever_arm_m", m->lever_arm_m);
    rb_tv_num(t, "gap_mm", m->gap_m * 1e3);
    rb_tv_num(t, "gap_ratio", rb_report_ratio(m->gap_m, m->lever_arm_m));
    rb_tv_num(t, "fy_row_kn", d->fy_row_n * 1e-3);
    rb_tv_num(t, "capacity_j", d->capacity_j);
    rb_tv_num(t, "weight_kn", d->W * 1e-3);
    rb_tv_num(t, "a_star_mps2", d->a_star_mps2);
    rb_tv_num(t, "a_star_g", rb_report_ratio(d->a_star_mps2, d->g));
    rb_tv_num(t, "a_uplift_g", rb_report_ratio(d->a_uplift_mps2, d->g));
    rb_tv_num(t, "alpha_rad", d->alpha);
    rb_tv_num(t, "theta0_rad", d->theta0_rad);
    rb_tv_num(t, "delta", d->delta);
    case_unit_vars(t, r);
}

/* The suite: governing motion and mean / max, for cases of several
 * motions (the template shows it when n_motions > 1). */
static void suite_vars(rb_tvars *t, const rb_report *r)
{
    static const char *const mean_names[RB_SUITE_N] = {
        "mean_usage", "mean_force_over_fy", "mean_shear_elastic_over_w",
        "mean_shear_total_over_w", "mean_u_over_ustatic", "mean_theta_over_alpha" };
    static const char *const max_names[RB_SUITE_N] = {
        "max_usage", "max_force_over_fy", "max_shear_elastic_over_w",
        "max_shear_total_over_w", "max_u_over_ustatic_all", "max_theta_over_alpha_all" };
    rb_report_suite su;
    size_t k;
    if (r->n_motions == 0) {
        rb_tv_int(t, "suite", 0);
        return;
    }
    rb_report_suite_compute(r, &su);
    rb_tv_int(t, "suite", r->n_motions > 1);
    rb_tv_int(t, "governing_index", (long)(su.governing + 1));
    rb_tv_str(t, "governing_name", r->motions[su.governing].motion->name);
    rb_tv_str(t, "governing_limit", rb_governs_name((rb_governs_limit)su.limit));
    rb_tv_num(t, "governing_margin", su.margin);
    for (k = 0; k < RB_SUITE_N; k++) {
        rb_tv_num(t, mean_names[k], su.mean[k]);
        rb_tv_num(t, max_names[k], su.max[k]);
    }
}

static void motion_head_vars(rb_tvars *t, const rb_report *r, size_t i,
                             const rb_report_norms *n, char *rm_headline, size_t hn)
{
    const rb_report_motion *rm = &r->motions[i];
    const rb_result *res = rm->result;
    rb_tv_int(t, "index", (long)(i + 1));
    rb_tv_str(t, "name", rm->motion->name);
    rb_tv_str(t, "source", rm->motion->source);
    rb_report_headline(rm->verdict.pass, rm->verdict.warnings, rm_headline, hn);
    rb_tv_str(t, "motion_verdict", rm->verdict.pass ? "PASS" : "FAIL");
    rb_tv_str(t, "motion_headline", rm_headline);
    rb_tv_str(t, "motion_reason", rm->verdict.reason);
    rb_tv_str(t, "kind", rb_enum_str(rb_case_motion_type_names, (int)rm->motion->type));
    rb_tv_num(t, "peak_mps2", res->peak_floor_mps2);
    rb_tv_num(t, "peak_g", n->peak_g);
    rb_tv_num(t, "peak_over_a_star", n->peak_over_a_star);
    rb_tv_num(t, "duration_s", rm->motion->motion.duration_s);
    rb_tv_num(t, "t_end_s", res->t_end_s);
    rb_tv_num(t, "max_u_mm", res->max_u_m * 1e3);
    rb_tv_num(t, "u_static_mm", res->u_static_m * 1e3);
    rb_tv_num(t, "shear_elastic_kn", res->max_shear_elastic_n * 1e-3);
    rb_tv_num(t, "shear_total_kn", res->max_shear_total_n * 1e-3);
    rb_tv_num(t, "v0_kn", n->v0_n * 1e-3);
    rb_report_text_peaks(t, res, n);
    const rb_out_units *u = out_units(r);
    rb_tv_num(t, "max_u", res->max_u_m / u->small_length_f);
    rb_tv_num(t, "u_static", res->u_static_m / u->small_length_f);
    rb_tv_num(t, "shear_elastic", res->max_shear_elastic_n / u->force_f);
    rb_tv_num(t, "shear_total", res->max_shear_total_n / u->force_f);
    rb_tv_num(t, "v0", n->v0_n / u->force_f);
}

/* Per-row values as name_left / name_right. */
static void motion_row_vars(rb_tvars *t, const rb_result *res, const rb_report_norms *n,
                            const rb_out_units *u)
{
    static const char *const neutral[2][3] = {
        { "force_left", "absorbed_left", "final_gap_left" },
        { "force_right", "absorbed_right", "final_gap_right" } };
    static const char *const names[2][10] = {
        { "force_left_kn", "force_left_over_fy", "usage_left", "absorbed_left_j",
          "yielded_left", "first_yield_left_s", "broken_left", "break_left_s",
          "final_gap_left_mm", "final_gap_ratio_left" },
        { "force_right_kn", "force_right_over_fy", "usage_right", "absorbed_right_j",
          "yielded_right", "first_yield_right_s", "broken_right", "break_right_s",
          "final_gap_right_mm", "final_gap_ratio_right" }
    };
    int s;
    for (s = 0; s < 2; s++) {
        const char *const *nm = names[s];
        rb_tv_num(t, nm[0], res->max_bolt_force_n[s] * 1e-3);
        rb_tv_num(t, nm[1], n->force_over_fy[s]);
        rb_tv_num(t, nm[2], res->usage[s]);
        rb_tv_num(t, nm[3], res->absorbed_j[s]);
        rb_tv_str(t, nm[4], rb_yes_no(res->yielded[s]));
        rb_tv_opt(t, nm[5], res->yielded[s], res->first_yield_s[s]);
        rb_tv_str(t, nm[6], rb_yes_no(res->broken[s]));
        rb_tv_opt(t, nm[7], res->broken[s], res->break_s[s]);
        rb_tv_num(t, nm[8], res->final_gap_m[s] * 1e3);
        rb_tv_num(t, nm[9], n->final_gap_ratio[s]);
        rb_tv_num(t, neutral[s][0], res->max_bolt_force_n[s] / u->force_f);
        rb_tv_num(t, neutral[s][1], res->absorbed_j[s] / u->energy_f);
        rb_tv_num(t, neutral[s][2], res->final_gap_m[s] / u->small_length_f);
    }
}

static void motion_outcome_vars(rb_tvars *t, const rb_result *res,
                                const rb_out_units *u)
{
    rb_tv_num(t, "t_fixed_s", res->stage_time_s[RB_STAGE_FIXED]);
    rb_tv_num(t, "t_uplift_s", res->stage_time_s[RB_STAGE_UPLIFT]);
    rb_tv_num(t, "t_held_s", res->stage_time_s[RB_STAGE_HELD]);
    rb_tv_num(t, "t_yield_s", res->stage_time_s[RB_STAGE_YIELD]);
    rb_tv_int(t, "floor_impacts", res->floor_impacts);
    rb_tv_int(t, "bolt_impacts", res->bolt_impacts);
    rb_tv_int(t, "uplifts", res->uplifts);
    rb_tv_str(t, "overturned", rb_yes_no(res->overturned));
    rb_tv_opt(t, "overturn_s", res->overturned, res->overturn_s);
    rb_tv_str(t, "overturn_side", res->overturned
           ? rb_report_side_str(res->overturn_side) : NULL);
    rb_tv_num(t, "e_input_j", res->e_input);
    rb_tv_num(t, "e_damping_j", res->e_damping);
    rb_tv_num(t, "e_impact_j", res->e_impact);
    rb_tv_num(t, "e_plastic_j", res->e_plastic);
    rb_tv_num(t, "e_input", res->e_input / u->energy_f);
    rb_tv_num(t, "e_damping", res->e_damping / u->energy_f);
    rb_tv_num(t, "e_impact", res->e_impact / u->energy_f);
    rb_tv_num(t, "e_plastic", res->e_plastic / u->energy_f);
    rb_tv_int(t, "steps", res->steps);
    rb_tv_int(t, "events", res->events);
}

/* What confirmed a pass, in one line: the runs and their governing
 * numbers, or why there were none (docs/report-format.md, "Confirmation"). */
static void convergence_text(const rb_criteria *c, const rb_report_motion *rm, char *buf,
                             size_t n)
{
    size_t len = 0;
    if (rm->n_confirm == 0) {
        if (c->confirm == RB_CONFIRM_OFF)
            snprintf(buf, n, "not confirmed (confirm: off)");
        else if (!rm->verdict.pass)
            snprintf(buf, n, "a failing run is not confirmed");
        else
            snprintf(buf, n, "not needed: %.3f of the nearest limit to spare (band %.3g)",
                     rb_verdict_margin(c, rm->result),
                     rb_confirm_band(c, &rm->motion->motion));
        return;
    }
    buf[0] = '\0';
    for (size_t i = 0; i < rm->n_confirm && len < n; i++) {
        const rb_confirm_run *cr = &rm->confirm[i];
        const char *how = rb_enum_str(rb_integrator_names, cr->integrator);
        char at[64];
        /* the run that also tightens the rest fraction says so (the
         * first keeps the case's) */
        if (cr->rest_fraction != rm->confirm[0].rest_fraction)
            snprintf(at, sizeof at, "%.3g, rest fraction %.3g", cr->rtol, cr->rest_fraction);
        else
            snprintf(at, sizeof at, "%.3g", cr->rtol);
        if (!cr->solved)
            len += (size_t)snprintf(buf + len, n - len, "%s%s at %s: stopped (%s)",
                                    i ? "; " : "", how, at,
                                    rb_status_str((rb_status)cr->status));
        else {
            char ff[32] = "n/a";   /* no bolts (rb_result_governing) */
            if (!isnan(cr->max_bolt_force_over_fy))
                snprintf(ff, sizeof ff, "%.4f", cr->max_bolt_force_over_fy);
            len += (size_t)snprintf(buf + len, n - len, "%s%s at %s: %s, usage %.4f, "
                                    "force %s Fy, rotation %.4f alpha, %.3f to spare",
                                    i ? "; " : "", how, at,
                                    cr->verdict.pass ? "pass" : "fail", cr->usage,
                                    ff, cr->max_theta_over_alpha, cr->margin);
        }
    }
}

/* The checks of the model's assumptions (docs/report-format.md, Validity). */
static rb_status motion_validity_vars(rb_tvars *t, const rb_report *r,
                                      const rb_report_motion *rm, rb_txt_arena *arena)
{
    const rb_result *res = rm->result;
    const rb_criteria *c = &r->kase->criteria;
    const rb_verdict *v = &rm->verdict;
    rb_tv_str(t, "validity_mode", rb_enum_str(rb_validity_mode_names, (int)c->validity));
    rb_tv_str(t, "lift_off_status", rb_check_status_str(v->check[RB_CHECK_LIFT_OFF]));
    rb_tv_opt(t, "liftoff_first_s", res->liftoff_first_s >= 0, res->liftoff_first_s);
    rb_tv_num(t, "liftoff_time_s", res->liftoff_time_s);
    rb_tv_str(t, "sliding_status", rb_check_status_str(v->check[RB_CHECK_SLIDING]));
    rb_tv_str(t, "sliding_judged", !(c->friction_coefficient > 0) ? "no friction coefficient"
              : res->fy_row_n > 0 ? "anchored: reported, not judged; the anchors carry "
                                    "the horizontal reaction"
              : "free-standing: a demand above the coefficient fails the run");
    rb_tv_opt(t, "friction_coefficient", c->friction_coefficient > 0,
              c->friction_coefficient);
    rb_tv_num(t, "friction_floor_over_w", RB_FRICTION_FLOOR);
    rb_tv_str(t, "bolt_impact_status", rb_check_status_str(v->check[RB_CHECK_BOLT_IMPACT]));
    rb_tv_opt(t, "impact_force_kn", res->rigid_bolts, res->max_bolt_impact_n * 1e-3);
    rb_tv_opt(t, "impact_over_fy", res->rigid_bolts,
              rb_report_ratio(res->max_bolt_impact_n, res->fy_row_n));
    rb_tv_opt(t, "impact_s", res->rigid_bolts && res->max_bolt_impact_n > 0,
              res->max_bolt_impact_s);
    rb_tv_opt(t, "k_row_mn_per_m", res->rigid_bolts, r->derived.k_row_npm * 1e-6);
    const rb_out_units *u = out_units(r);
    rb_tv_opt(t, "impact_force", res->rigid_bolts, res->max_bolt_impact_n / u->force_f);
    rb_tv_opt(t, "k_row", res->rigid_bolts, r->derived.k_row_npm / u->stiffness_f);
    /* the variables borrow their text until the template is rendered */
    enum { CONV_MAX = 320 };
    char *conv = rb_txt_arena_alloc(arena, CONV_MAX, 1);
    if (!conv)
        return RB_ERR_NOMEM;
    convergence_text(c, rm, conv, CONV_MAX);
    rb_tv_str(t, "convergence_status", rb_check_status_str(v->check[RB_CHECK_CONVERGENCE]));
    rb_tv_str(t, "convergence", conv);
    return RB_OK;
}

rb_status rb_report_render_text(const rb_report *r, const char *tmpl,
                                char **out, rb_diag *diag)
{
    size_t n = r->n_motions, i;
    rb_tvar *vars = calloc((n + 1) * RB_TXT_MAX_VARS, sizeof *vars);
    rb_tscope *items = calloc(n ? n : 1, sizeof *items);
    rb_tlist *motion_lists = calloc(2 * (n ? n : 1), sizeof *motion_lists);
    rb_txt_arena *arena = rb_txt_arena_new();
    rb_tscope top = {0};
    rb_tlist lists[3] = { { "motions", NULL, 0 }, { "design", NULL, 0 },
                          { "concrete", NULL, 0 } };
    char (*heads)[RB_HEADLINE_MAX] = calloc(n ? n : 1, sizeof *heads);
    rb_tvars t;
    rb_status st = RB_ERR_NOMEM;
    *out = NULL;
    if (!vars || !items || !motion_lists || !arena || !heads)
        goto done;
    t.v = vars;
    t.n = 0;
    case_vars(&t, r);
    suite_vars(&t, r);
    top.vars = vars;
    top.n_vars = t.n;
    for (i = 0; i < n; i++) {
        rb_report_norms norms;
        rb_report_norms_compute(r, &r->motions[i], &norms);
        t.v = vars + (i + 1) * RB_TXT_MAX_VARS;
        t.n = 0;
        motion_head_vars(&t, r, i, &norms, heads[i], sizeof heads[i]);
        motion_row_vars(&t, r->motions[i].result, &norms, out_units(r));
        motion_outcome_vars(&t, r->motions[i].result, out_units(r));
        if (motion_validity_vars(&t, r, &r->motions[i], arena) != RB_OK)
            goto done;
        rb_report_text_motion_anchorage(&t, r, &r->motions[i]);
        items[i].vars = t.v;
        items[i].n_vars = t.n;
        if (rb_report_text_motion_design(r, i, arena, &motion_lists[2 * i]) != RB_OK
            || rb_report_text_motion_anchor_modes(r, &r->motions[i], arena,
                                                  &motion_lists[2 * i + 1]) != RB_OK)
            goto done;
        items[i].lists = &motion_lists[2 * i];
        items[i].n_lists = 2;
    }
    if (rb_report_text_case_design(r, arena, &lists[1]) != RB_OK
        || rb_report_text_concrete(r, arena, &lists[2]) != RB_OK)
        goto done;
    lists[0].items = items;
    lists[0].n = n;
    top.lists = lists;
    top.n_lists = 3;
    st = rb_template_render(tmpl, &top, out, diag);
done:
    rb_txt_arena_free(arena);
    free(motion_lists);
    free(heads);
    free(vars);
    free(items);
    return st;
}
