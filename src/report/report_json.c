/* The JSON report (layout version RB_REPORT_FORMAT_VERSION, documented in
 * docs/report-format.md).
 *
 * Everything is SI; every normalised form sits next to the quantity it
 * normalises; per-row arrays are {"left": .., "right": ..}. A ratio with a
 * zero denominator, or a time that did not happen (no yield, no break), is
 * null. Any other number that is NaN or infinite means a bug upstream: the
 * report refuses to be written (RB_ERR_NONFINITE, naming the field) rather
 * than emit JSON that standard parsers reject. The cJSON tree never leaves
 * this file. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cjson/cJSON.h>
#include "rockbolt/jsonprint.h"
#include "rockbolt/version.h"
#include "rockbolt/names.h"
#include "report_internal.h"
#include "rockbolt/jsonnum.h"
#include "report_json_build.h"
#include "report_peaks.h"

static void add_model(rb_jctx *cx, cJSON *root, const rb_model *m)
{
    cJSON *o = rb_j_obj(cx, root, "model");
    cx->where = "model";
    rb_j_num(cx, o, "mass_kg", m->mass_kg);
    rb_j_num(cx, o, "cm_height_m", m->cm_height_m);
    rb_j_num(cx, o, "half_width_m", m->half_width_m);
    rb_j_bool(cx, o, "rigid", m->rigid);
    rb_j_num(cx, o, "freq_hz", m->freq_hz);
    rb_j_num(cx, o, "damping", m->damping);
    rb_j_opt(cx, o, "inertia_kgm2", m->inertia_kgm2 > 0, m->inertia_kgm2);
    rb_j_opt(cx, o, "restitution", m->restitution >= 0, m->restitution);
    rb_j_str(cx, o, "bolt_model", rb_enum_str(rb_bolt_model_names, (int)m->bolt_model));
    rb_j_num(cx, o, "bolts_per_row", m->bolts_per_row);
    rb_j_num(cx, o, "bolt_area_m2", m->bolt_area_m2);
    rb_j_num(cx, o, "yield_stress_pa", m->yield_stress_pa);
    rb_j_num(cx, o, "toughness_jpm3", m->toughness_jpm3);
    rb_j_num(cx, o, "deformable_length_m", m->deformable_length_m);
    rb_j_opt(cx, o, "elastic_modulus_pa", m->elastic_modulus_pa > 0,
          m->elastic_modulus_pa);
    rb_j_num(cx, o, "lever_arm_m", m->lever_arm_m);
    rb_j_num(cx, o, "gap_m", m->gap_m);
    rb_j_norm(cx, o, "gap_ratio", rb_report_ratio(m->gap_m, m->lever_arm_m));
    rb_j_opt(cx, o, "gravity_mps2", m->gravity_mps2 > 0, m->gravity_mps2);
}

static void add_derived(rb_jctx *cx, cJSON *root, const rb_derived *d)
{
    cJSON *o = rb_j_obj(cx, root, "derived");
    cx->where = "derived";
    rb_j_num(cx, o, "g_mps2", d->g);
    rb_j_num(cx, o, "weight_n", d->W);
    rb_j_num(cx, o, "R_m", d->R);
    rb_j_num(cx, o, "alpha_rad", d->alpha);
    rb_j_num(cx, o, "omega_radps", d->omega);
    rb_j_num(cx, o, "Mstar_kg", d->Mstar);
    rb_j_num(cx, o, "Nstar_kg", d->Nstar);
    rb_j_num(cx, o, "Fstar_kgm", d->Fstar);
    rb_j_num(cx, o, "Kstar_npm", d->Kstar);
    rb_j_num(cx, o, "Cstar_nspm", d->Cstar);
    rb_j_num(cx, o, "Io_kgm2", d->Io);
    rb_j_num(cx, o, "delta", d->delta);
    rb_j_num(cx, o, "fy_row_n", d->fy_row_n);
    rb_j_num(cx, o, "capacity_j", d->capacity_j);
    rb_j_num(cx, o, "k_row_npm", d->k_row_npm);
    rb_j_num(cx, o, "a_star_mps2", d->a_star_mps2);
    rb_j_norm(cx, o, "a_star_g", rb_report_ratio(d->a_star_mps2, d->g));
    rb_j_num(cx, o, "a_uplift_mps2", d->a_uplift_mps2);
    rb_j_norm(cx, o, "a_uplift_over_a_star",
           rb_report_ratio(d->a_uplift_mps2, d->a_star_mps2));
    rb_j_theta0(cx, o, d->theta0_rad);
}

static void add_settings(rb_jctx *cx, cJSON *root, const rb_case *c)
{
    const rb_solve_opts *s = &c->solve;
    const rb_criteria *k = &c->criteria;
    cJSON *o = rb_j_obj(cx, root, "solver");
    cx->where = "solver";
    rb_j_str(cx, o, "formulation", rb_enum_str(rb_formulation_names, (int)s->formulation));
    rb_j_str(cx, o, "integrator", rb_enum_str(rb_integrator_names, (int)s->integrator));
    rb_j_num(cx, o, "rtol", s->rtol);
    rb_j_num(cx, o, "event_tol", s->event_tol);
    rb_j_opt(cx, o, "max_step_s", s->max_step_s > 0, s->max_step_s);
    rb_j_bool(cx, o, "stretch_past_failure", s->stretch_past_failure);
    rb_j_opt(cx, o, "history_dt_s", s->history_dt_s > 0, s->history_dt_s);
    rb_j_num(cx, o, "rest_fraction", s->rest_fraction);
    rb_j_num(cx, o, "max_events_per_s", (double)s->max_events_per_s);
    rb_j_num(cx, o, "max_steps", (double)s->max_steps);
    rb_j_num(cx, o, "theta_init_rad", s->theta_init_rad);
    o = rb_j_obj(cx, root, "criteria");
    cx->where = "criteria";
    rb_j_str(cx, o, "kind", rb_enum_str(rb_criterion_names, (int)k->kind));
    rb_j_num(cx, o, "usage_limit", k->usage_limit);
    rb_j_opt(cx, o, "max_shear_over_w", k->max_shear_over_w > 0, k->max_shear_over_w);
    rb_j_opt(cx, o, "max_theta_over_alpha", k->max_theta_over_alpha > 0,
          k->max_theta_over_alpha);
    rb_j_opt(cx, o, "friction_coefficient", k->friction_coefficient > 0,
             k->friction_coefficient);
    rb_j_str(cx, o, "validity", rb_enum_str(rb_validity_mode_names, (int)k->validity));
    rb_j_str(cx, o, "confirm", rb_enum_str(rb_confirm_mode_names, (int)k->confirm));
    rb_j_num(cx, o, "confirm_band", k->confirm_band);
    if (c->has_concrete)
        rb_j_bool(cx, o, "concrete", k->concrete);
}

static void add_motion_desc(rb_jctx *cx, cJSON *parent, const rb_case_motion *cm,
                            const rb_report_norms *n, const rb_result *res)
{
    const rb_motion *m = &cm->motion;
    cJSON *o = rb_j_obj(cx, parent, "motion"), *b;
    rb_j_str(cx, o, "kind", rb_enum_str(rb_case_motion_type_names, (int)cm->type));
    rb_j_str(cx, o, "source", cm->source);
    rb_j_num(cx, o, "peak_floor_mps2", res->peak_floor_mps2);
    rb_j_norm(cx, o, "peak_floor_g", n->peak_g);
    rb_j_norm(cx, o, "peak_floor_over_a_star", n->peak_over_a_star);
    rb_j_num(cx, o, "duration_s", m->duration_s);
    rb_j_num(cx, o, "polarity", m->polarity);
    if (m->kind == RB_MOTION_SAMPLED) {
        const rb_series *s = m->series;
        rb_j_num(cx, o, "scale", m->scale);
        rb_j_num(cx, o, "samples", s ? (double)s->n : 0);
        rb_j_opt(cx, o, "dt_s", s != NULL, s ? s->dt_s : 0);
    } else {
        rb_j_num(cx, o, "amplitude_mps2", m->amplitude_mps2);
    }
    if (m->kind == RB_MOTION_HARMONIC) {
        rb_j_num(cx, o, "freq_hz", m->freq_hz);
        rb_j_num(cx, o, "ramp_s", m->ramp_s);
    }
    if (m->kind == RB_MOTION_PULSE) {
        rb_j_str(cx, o, "pulse_shape", rb_enum_str(rb_pulse_shape_names, (int)m->pulse));
        rb_j_num(cx, o, "pulse_s", m->pulse_s);
    }
    rb_j_opt(cx, o, "target_peak_mps2", cm->target_peak_mps2 > 0, cm->target_peak_mps2);
    if (cm->building_freq_hz > 0) {
        b = rb_j_obj(cx, o, "building");
        rb_j_num(cx, b, "freq_hz", cm->building_freq_hz);
        rb_j_num(cx, b, "damping", cm->building_damping);
    } else {
        rb_j_null(cx, o, "building");
    }
    /* only where there is one: reports without a vertical keep their bytes */
    if (cm->vertical) {
        const rb_motion *v = &cm->vertical->motion;
        b = rb_j_obj(cx, o, "vertical");
        rb_j_str(cx, b, "kind", rb_enum_str(rb_case_motion_type_names, (int)cm->vertical->type));
        rb_j_str(cx, b, "source", cm->vertical->source);
        rb_j_num(cx, b, "peak_mps2", rb_motion_peak(v));
        rb_j_num(cx, b, "least_mps2", rb_motion_least(v, m->duration_s));
        rb_j_num(cx, b, "polarity", v->polarity);
    }
}

static void add_peaks(rb_jctx *cx, cJSON *res_o, const rb_result *r,
                      const rb_report_norms *n)
{
    cJSON *o = rb_j_obj(cx, res_o, "constants");
    rb_j_num(cx, o, "a_star_mps2", r->a_star_mps2);
    rb_j_num(cx, o, "a_uplift_mps2", r->a_uplift_mps2);
    rb_j_num(cx, o, "peak_floor_mps2", r->peak_floor_mps2);
    rb_j_num(cx, o, "u_static_m", r->u_static_m);
    rb_j_num(cx, o, "alpha_rad", r->alpha_rad);
    rb_j_theta0(cx, o, r->theta0_rad);
    rb_j_num(cx, o, "fy_row_n", r->fy_row_n);
    rb_j_num(cx, o, "capacity_j", r->capacity_j);
    rb_j_num(cx, o, "weight_n", r->weight_n);
    rb_j_num(cx, o, "v0_n", n->v0_n);
    rb_j_num(cx, o, "delta", r->delta);
    rb_report_json_peaks(cx, rb_j_obj(cx, res_o, "peaks"), r, n);
}

static void add_rows_outcome(rb_jctx *cx, cJSON *res_o, const rb_result *r,
                             const rb_report_norms *n)
{
    static const char *const stage_names[6] = { NULL, "fixed", "uplift",
                                                "impact", "held", "yield" };
    cJSON *o = rb_j_obj(cx, res_o, "bolts"), *t;
    int s;
    rb_j_pair(cx, o, "final_gap_m", r->final_gap_m);
    rb_j_pair_norm(cx, o, "final_gap_ratio", n->final_gap_ratio);
    rb_j_pair(cx, o, "absorbed_j", r->absorbed_j);
    rb_j_pair(cx, o, "usage", r->usage);
    rb_j_pair_bool(cx, o, "yielded", r->yielded);
    rb_j_pair_when(cx, o, "first_yield_s", r->yielded, r->first_yield_s);
    rb_j_pair_bool(cx, o, "broken", r->broken);
    rb_j_pair_when(cx, o, "break_s", r->broken, r->break_s);
    o = rb_j_obj(cx, res_o, "outcome");
    rb_j_bool(cx, o, "overturned", r->overturned);
    if (r->overturned)
        rb_j_str(cx, o, "overturn_side", rb_report_side_str(r->overturn_side));
    else
        rb_j_null(cx, o, "overturn_side");
    rb_j_opt(cx, o, "overturn_s", r->overturned, r->overturn_s);
    rb_j_num(cx, o, "t_end_s", r->t_end_s);
    t = rb_j_obj(cx, o, "stage_time_s");
    for (s = 1; s <= 5; s++)
        rb_j_num(cx, t, stage_names[s], r->stage_time_s[s]);
    rb_j_num(cx, o, "floor_impacts", (double)r->floor_impacts);
    rb_j_num(cx, o, "bolt_impacts", (double)r->bolt_impacts);
    rb_j_num(cx, o, "uplifts", (double)r->uplifts);
}

/* history_rows counts the rows the report carries (analysis.history), not
 * those kept for --history or the figures: the JSON report must not change
 * with the other outputs asked for. */
static void add_energy_cost(rb_jctx *cx, cJSON *res_o, const rb_result *r,
                            int with_history)
{
    cJSON *o = rb_j_obj(cx, res_o, "energy_j");
    rb_j_num(cx, o, "input", r->e_input);
    rb_j_num(cx, o, "kinetic", r->e_kinetic);
    rb_j_num(cx, o, "potential", r->e_potential);
    rb_j_num(cx, o, "strain", r->e_strain);
    rb_j_num(cx, o, "damping", r->e_damping);
    rb_j_num(cx, o, "impact", r->e_impact);
    rb_j_num(cx, o, "plastic", r->e_plastic);
    rb_j_num(cx, o, "coupling", r->e_coupling);
    o = rb_j_obj(cx, res_o, "cost");
    rb_j_num(cx, o, "steps", (double)r->steps);
    rb_j_num(cx, o, "exact_steps", (double)r->exact_steps);
    rb_j_num(cx, o, "rejected_steps", (double)r->rejected_steps);
    rb_j_num(cx, o, "events", (double)r->events);
    rb_j_num(cx, o, "rhs_evals", (double)r->rhs_evals);
    rb_j_num(cx, o, "history_rows",
             with_history && r->history ? (double)r->history->n : 0);
}

/* One column of a history as a JSON array of numbers. */
static void j_column(rb_jctx *cx, cJSON *o, const char *key, const double *v, size_t n)
{
    cJSON *a = rb_j_arr(cx, o, key);
    for (size_t i = 0; i < n && cx->st == RB_OK; i++) {
        if (!isfinite(v[i])) {
            cx->st = RB_ERR_NONFINITE;
            snprintf(cx->bad_key, sizeof cx->bad_key, "%s.history.%s[%zu]",
                     cx->where, key, i);
            return;
        }
        char buf[RB_JSONNUM_MAX];
        rb_json_number(v[i], buf);
        rb_j_append(cx, a, cJSON_CreateRaw(buf));
    }
}

/* The time history, column-wise (same columns as the CSV). */
static void add_history(rb_jctx *cx, cJSON *parent, const rb_history *h)
{
    cJSON *o, *a;
    size_t i;
    if (!h) {
        rb_j_null(cx, parent, "history");
        return;
    }
    o = rb_j_obj(cx, parent, "history");
    rb_j_num(cx, o, "rows", (double)h->n);
    j_column(cx, o, "t_s", h->t, h->n);
    j_column(cx, o, "accel_mps2", h->accel, h->n);
    j_column(cx, o, "theta_rad", h->theta, h->n);
    j_column(cx, o, "u_m", h->u, h->n);
    j_column(cx, o, "bolt_force_left_n", h->bolt_force_left, h->n);
    j_column(cx, o, "bolt_force_right_n", h->bolt_force_right, h->n);
    j_column(cx, o, "shear_elastic_n", h->shear_elastic, h->n);
    j_column(cx, o, "shear_total_n", h->shear_total, h->n);
    j_column(cx, o, "energy_left_j", h->energy_left, h->n);
    j_column(cx, o, "energy_right_j", h->energy_right, h->n);
    j_column(cx, o, "kinetic_j", h->kinetic, h->n);
    j_column(cx, o, "potential_j", h->potential, h->n);
    j_column(cx, o, "strain_j", h->strain, h->n);
    a = rb_j_arr(cx, o, "stage");
    for (i = 0; i < h->n && cx->st == RB_OK; i++)
        rb_j_append(cx, a, cJSON_CreateNumber(h->stage[i]));
}

static void add_motion(rb_jctx *cx, cJSON *arr, const rb_report *r, size_t i)
{
    const rb_report_motion *m = &r->motions[i];
    rb_report_norms n;
    cJSON *o, *v;
    if (!(o = rb_j_item(cx, arr)))
        return;
    snprintf(cx->where_buf, sizeof cx->where_buf, "motions[%zu]", i);
    cx->where = cx->where_buf;
    rb_report_norms_compute(r, m, &n);
    rb_j_num(cx, o, "index", (double)(i + 1));
    rb_j_str(cx, o, "name", m->motion->name);
    add_motion_desc(cx, o, m->motion, &n, m->result);
    v = rb_j_obj(cx, o, "verdict");
    rb_j_bool(cx, v, "pass", m->verdict.pass);
    rb_j_bool(cx, v, "criteria_pass", m->verdict.criteria_pass);
    rb_j_warnings(cx, v, "validity_warnings", m->verdict.warnings);
    rb_j_str(cx, v, "reason", m->verdict.reason);
    rb_report_json_validity(cx, o, r, m);
    rb_report_json_motion_anchorage(cx, o, r, m);
    v = rb_j_obj(cx, o, "result");
    add_peaks(cx, v, m->result, &n);
    add_rows_outcome(cx, v, m->result, &n);
    add_energy_cost(cx, v, m->result, r->with_history);
    rb_report_json_motion_design(cx, o, r, i);
    if (r->with_history)
        add_history(cx, o, m->result->history);
}

static void add_head(rb_jctx *cx, cJSON *root, const rb_report *r)
{
    cJSON *o;
    size_t i, failed = 0;
    cx->where = "report";
    rb_j_str(cx, root, "format", "rockbolt-report");
    rb_j_num(cx, root, "format_version", RB_REPORT_FORMAT_VERSION);
    o = rb_j_obj(cx, root, "tool");
    rb_j_str(cx, o, "name", "rockbolt");
    rb_j_str(cx, o, "version", RB_VERSION_STRING);
    o = rb_j_obj(cx, root, "case");
    rb_j_str(cx, o, "name", r->kase->name);
    rb_j_str(cx, o, "path", r->kase->path);
    rb_j_str(cx, o, "description", r->kase->description);
    for (i = 0; i < r->n_motions; i++)
        failed += !r->motions[i].verdict.pass;
    o = rb_j_obj(cx, root, "verdict");
    rb_j_bool(cx, o, "pass", r->pass);
    rb_j_str(cx, o, "result", r->pass ? "PASS" : "FAIL");
    rb_j_str(cx, o, "headline", r->headline);
    rb_j_warnings(cx, o, "validity_warnings", r->warnings);
    rb_j_str(cx, o, "reason", r->reason);
    rb_j_num(cx, o, "motions", (double)r->n_motions);
    rb_j_num(cx, o, "motions_failed", (double)failed);
}

/* Always written, also for one motion, so that readers of many reports
 * find the governing motion in one place. */
static void add_suite(rb_jctx *cx, cJSON *root, const rb_report *r)
{
    rb_report_suite su;
    cJSON *o, *mean, *max;
    size_t k;
    if (cx->st != RB_OK || r->n_motions == 0)
        return;
    cx->where = "suite";
    rb_report_suite_compute(r, &su);
    o = rb_j_obj(cx, root, "suite");
    rb_j_num(cx, o, "motions", (double)r->n_motions);
    rb_j_num(cx, o, "governing_index", (double)(su.governing + 1));
    rb_j_str(cx, o, "governing_name", r->motions[su.governing].motion->name);
    rb_j_str(cx, o, "governing_limit", rb_governs_name((rb_governs_limit)su.limit));
    rb_j_num(cx, o, "governing_margin", su.margin);
    rb_j_str(cx, o, "governing_reason", r->motions[su.governing].verdict.reason);
    mean = rb_j_obj(cx, o, "mean");
    max = rb_j_obj(cx, o, "max");
    for (k = 0; k < RB_SUITE_N; k++) {
        rb_j_norm(cx, mean, rb_suite_names[k], su.mean[k]);
        rb_j_norm(cx, max, rb_suite_names[k], su.max[k]);
    }
}

/* cJSON_Print's text plus the final newline a text file should end with,
 * in memory the caller can free(). */
static char *print_with_newline(cJSON *root)
{
    char *p = rb_json_print(root, 1), *q;
    size_t n;
    if (!p)
        return NULL;
    n = strlen(p);
    if ((q = malloc(n + 2)) != NULL) {
        memcpy(q, p, n);
        q[n] = '\n';
        q[n + 1] = '\0';
    }
    free(p);
    return q;
}

rb_status rb_report_render_json(const rb_report *r, char **out, rb_diag *diag)
{
    rb_jctx cx = { RB_OK, "report", "", "" };
    cJSON *root = cJSON_CreateObject(), *arr = NULL;
    size_t i;
    *out = NULL;
    if (!root)
        return RB_ERR_NOMEM;
    add_head(&cx, root, r);
    add_model(&cx, root, &r->kase->model);
    add_derived(&cx, root, &r->derived);
    add_settings(&cx, root, r->kase);
    rb_report_json_anchorage(&cx, root, r);
    if (cx.st == RB_OK && !(arr = cJSON_AddArrayToObject(root, "motions")))
        cx.st = RB_ERR_NOMEM;
    for (i = 0; i < r->n_motions && cx.st == RB_OK; i++)
        add_motion(&cx, arr, r, i);
    add_suite(&cx, root, r);
    rb_report_json_case_design(&cx, root, r);
    if (cx.st == RB_OK && !(*out = print_with_newline(root)))
        cx.st = RB_ERR_NOMEM;
    cJSON_Delete(root);
    if (cx.st == RB_ERR_NONFINITE && diag) {
        rb_diag_set_key(diag, "%s", cx.bad_key);
        rb_diag_set_msg(diag, "non-finite number in the report (a bug: please report it)");
    }
    return cx.st;
}
