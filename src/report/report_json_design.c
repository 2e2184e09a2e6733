/* The design parts of the JSON report (`rockbolt design`): per motion the
 * two design factors, the recommended gap and the amplitude sweeps; for
 * the case the search settings, the frequency sweeps and the code-static
 * comparison. Counts of runs made ahead by idle threads are left out: they
 * depend on the thread count, and a report must not. */
#include <math.h>
#include <stdio.h>
#include <cjson/cJSON.h>
#include "rockbolt/version.h"
#include "rockbolt/names.h"
#include "report_internal.h"
#include "report_json_build.h"

/* HUGE_VAL marks "none" in the design results (no failing level, no
 * passing level): null in JSON. */
static void j_level(rb_jctx *cx, cJSON *o, const char *key, double v)
{
    rb_j_opt(cx, o, key, isfinite(v), v);
}

static void add_factor(rb_jctx *cx, cJSON *parent, const char *key,
                       const rb_design_factor_result *f, const rb_criteria *crit)
{
    char sentence[640];
    cJSON *o = rb_j_obj(cx, parent, key);
    rb_design_factor_describe(f, NULL, 0, sentence, sizeof sentence);
    rb_j_str(cx, o, "criterion", rb_enum_str(rb_criterion_names, (int)crit->kind));
    rb_j_num(cx, o, "usage_limit", crit->usage_limit);
    j_level(cx, o, "factor", f->factor);
    rb_j_num(cx, o, "level_mps2", f->level_mps2);
    rb_j_num(cx, o, "level_astar", f->level_astar);
    j_level(cx, o, "fail_mps2", f->fail_mps2);
    j_level(cx, o, "fail_astar", f->fail_astar);
    j_level(cx, o, "first_fail_astar", f->first_fail_astar);
    rb_j_num(cx, o, "resolution_astar", f->resolution_astar);
    rb_j_num(cx, o, "bracket_astar", f->bracket_astar);
    rb_j_num(cx, o, "scan_end_astar", f->scan_end_astar);
    rb_j_bool(cx, o, "no_failure", f->no_failure);
    rb_j_bool(cx, o, "fails_at_start", f->fails_at_start);
    rb_j_num(cx, o, "runs", (double)f->runs);
    rb_j_num(cx, o, "scan_runs", (double)f->scan_runs);
    rb_j_num(cx, o, "bisect_runs", (double)f->bisect_runs);
    rb_j_num(cx, o, "confirm_fails", (double)f->confirm_fails);
    rb_j_str(cx, o, "pass_reason", f->pass_reason);
    rb_j_str(cx, o, "fail_reason", f->fail_reason);
    rb_j_str(cx, o, "summary", sentence);
}

static void add_gap_points(rb_jctx *cx, cJSON *o, const rb_gap_result *g)
{
    cJSON *arr = rb_j_arr(cx, o, "grid");
    size_t i;
    for (i = 0; i < g->n_points && cx->st == RB_OK; i++) {
        const rb_gap_point *p = &g->points[i];
        cJSON *q = rb_j_item(cx, arr);
        rb_j_num(cx, q, "gap_ratio", p->gap_ratio);
        rb_j_bool(cx, q, "evaluated", p->evaluated);
        if (!p->evaluated)
            continue;
        rb_j_bool(cx, q, "meets", p->meets);
        rb_j_num(cx, q, "max_force_over_fy", p->max_force_over_fy);
        rb_j_num(cx, q, "max_u_over_ustatic", p->max_u_over_ustatic);
        rb_j_num(cx, q, "max_theta_over_alpha", p->max_theta_over_alpha);
        rb_j_num(cx, q, "usage_max", p->usage_max);
        rb_j_str(cx, q, "reason", p->reason);
    }
}

static void add_gap(rb_jctx *cx, cJSON *parent, const rb_motion_design *md,
                    const rb_criteria *crit)
{
    const rb_gap_result *g = &md->gap;
    char sentence[512];
    cJSON *o, *y;
    if (!md->has_gap) {
        rb_j_null(cx, parent, "recommended_gap");
        return;
    }
    o = rb_j_obj(cx, parent, "recommended_gap");
    rb_gap_describe(g, NULL, sentence, sizeof sentence);
    rb_j_str(cx, o, "criterion", rb_enum_str(rb_criterion_names, (int)crit->kind));
    rb_j_bool(cx, o, "found", g->found);
    rb_j_opt(cx, o, "gap_ratio", g->found, g->gap_ratio);
    rb_j_opt(cx, o, "gap_m", g->found, g->gap_m);
    rb_j_str(cx, o, "summary", sentence);
    rb_j_num(cx, o, "range_min", g->points[0].gap_ratio);
    rb_j_num(cx, o, "range_max", g->range_max);
    rb_j_str(cx, o, "bounded_by", g->bound == RB_GAP_BOUND_MAX_GAP ? "max_gap"
                                                                  : "gap_ratio_max");
    rb_j_bool(cx, o, "own_above", g->own_above);
    rb_j_opt(cx, o, "max_gap_m", g->max_gap_m > 0, g->max_gap_m);
    rb_j_num(cx, o, "own_gap_ratio", g->own_gap_ratio);
    rb_j_bool(cx, o, "own_meets", g->own_meets);
    rb_j_bool(cx, o, "own_only", g->own_only);
    rb_j_num(cx, o, "runs", (double)g->runs);
    add_gap_points(cx, o, g);
    if (!g->yield_run) {
        rb_j_null(cx, o, "yielding_run");
        return;
    }
    /* the thesis's reading: how far a yielding run opens the gaps */
    y = rb_j_obj(cx, o, "yielding_run");
    rb_j_num(cx, y, "initial_gap_ratio", g->yield_initial_gap_ratio);
    rb_j_pair(cx, y, "final_gap_ratio", g->yield_final_gap_ratio);
    rb_j_num(cx, y, "final_gap_ratio_max", g->yield_final_gap_ratio_max);
    rb_j_pair(cx, y, "usage", g->yield_usage);
}

static void add_sweeps(rb_jctx *cx, cJSON *parent, const char *key, const rb_sweep *s,
                       size_t n)
{
    cJSON *arr = rb_j_arr(cx, parent, key);
    for (size_t i = 0; i < n && cx->st == RB_OK; i++)
        rb_report_json_sweep(cx, arr, &s[i]);
}

void rb_report_json_motion_design(rb_jctx *cx, cJSON *motion_o, const rb_report *r,
                                  size_t i)
{
    const rb_case_design *d = r->design;
    const rb_motion_design *md;
    cJSON *o, *f;
    if (!d || i >= d->n_motions)
        return;
    md = &d->motions[i];
    o = rb_j_obj(cx, motion_o, "design");
    f = rb_j_obj(cx, o, "design_factor");
    for (int k = 0; k < RB_N_CRITERIA; k++) {
        char key[32];   /* "no_yield": the kind's name as a key */
        rb_enum_str_sep(rb_criterion_names, k, '_', key, sizeof key);
        add_factor(cx, f, key, &md->factor[k], &d->factor_criteria[k]);
    }
    add_gap(cx, o, md, &d->gap_criteria);
    add_sweeps(cx, o, "amplitude_sweeps", md->sweeps, md->n_sweeps);
}

static void add_code(rb_jctx *cx, cJSON *parent, const rb_case *c, const rb_code_result *k)
{
    const rb_code_inputs *in = &c->code;
    cJSON *o = rb_j_obj(cx, parent, "code_static"), *i;
    rb_j_str(cx, o, "edition", in->edition == RB_ASCE7_16 ? "ASCE 7-16" : "ASCE 7-22");
    i = rb_j_obj(cx, o, "inputs");
    rb_j_num(cx, i, "sds", in->sds);
    rb_j_num(cx, i, "ip", in->ip);
    rb_j_num(cx, i, "z_over_h", in->z_over_h);
    rb_j_bool(cx, i, "at_or_below_grade", in->at_or_below_grade);
    if (in->edition == RB_ASCE7_16) {
        rb_j_num(cx, i, "ap", in->ap);
        rb_j_num(cx, i, "rp", in->rp);
    } else {
        rb_j_num(cx, i, "car", in->car);
        rb_j_num(cx, i, "rpo", in->rpo);
        rb_j_opt(cx, i, "ta_s", in->ta_s > 0, in->ta_s);
        rb_j_num(cx, i, "r", in->r);
        rb_j_num(cx, i, "ie", in->ie);
        rb_j_num(cx, i, "omega0", in->omega0);
    }
    rb_j_bool(cx, i, "anchorage_in_concrete", in->anchorage_in_concrete);
    rb_j_num(cx, i, "omega0p", in->omega0p);
    rb_j_num(cx, i, "futa_pa", in->futa_pa);
    rb_j_opt(cx, i, "ase_m2", in->ase_m2 > 0, in->ase_m2);
    rb_j_num(cx, o, "fp_formula_n", k->fp_formula_n);
    rb_j_num(cx, o, "fp_min_n", k->fp_min_n);
    rb_j_num(cx, o, "fp_max_n", k->fp_max_n);
    rb_j_num(cx, o, "fp_n", k->fp_n);
    rb_j_str(cx, o, "bound", k->bound < 0 ? "minimum" : k->bound > 0 ? "maximum" : "none");
    rb_j_num(cx, o, "hf", k->hf);
    rb_j_num(cx, o, "rmu", k->rmu);
    rb_j_num(cx, o, "fp_anchor_n", k->fp_anchor_n);
    rb_j_num(cx, o, "fp_over_wp", k->fp_over_wp);
    rb_j_num(cx, o, "accel_mps2", k->accel_mps2);
    rb_j_num(cx, o, "accel_astar", k->accel_astar);
    rb_j_num(cx, o, "tension_n", k->tension_n);
    rb_j_num(cx, o, "tension_raw_n", k->tension_raw_n);
    rb_j_num(cx, o, "futa_used_pa", k->futa_used_pa);
    rb_j_num(cx, o, "phi_nsa_n", k->phi_nsa_n);
    rb_j_num(cx, o, "ratio", k->ratio);
    rb_j_bool(cx, o, "pass", k->ratio <= 1.0);
    if (k->has_concrete) {
        char clause[16];
        snprintf(clause, sizeof clause, "%s", rb_aci17_interaction_clause(k->concrete_clause));
        rb_j_num(cx, o, "concrete_utilization", k->concrete_utilization);
        rb_j_str(cx, o, "concrete_clause", clause);
        rb_j_bool(cx, o, "concrete_pass", k->concrete_utilization < 1.0);
    }
}

void rb_report_json_case_design(rb_jctx *cx, cJSON *root, const rb_report *r)
{
    const rb_case_design *d = r->design;
    const rb_design_opts *g = &r->kase->design;
    cJSON *o, *s;
    if (!d)
        return;
    cx->where = "design";
    o = rb_j_obj(cx, root, "design");
    s = rb_j_obj(cx, o, "settings");
    rb_j_num(cx, s, "scan_start_astar", g->scan_start);
    rb_j_num(cx, s, "scan_step_astar", g->scan_step);
    rb_j_num(cx, s, "scan_end_astar", g->scan_end);
    rb_j_num(cx, s, "resolution_astar", g->resolution);
    rb_j_num(cx, s, "gap_ratio_min", g->gap_ratio_min);
    rb_j_num(cx, s, "gap_ratio_max", g->gap_ratio_max);
    rb_j_num(cx, s, "gap_ratio_step", g->gap_ratio_step);
    add_sweeps(cx, o, "frequency_sweeps", d->sweeps, d->n_sweeps);
    if (d->has_code)
        add_code(cx, o, r->kase, &d->code);
    else
        rb_j_null(cx, o, "code_static");
}
