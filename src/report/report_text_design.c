/* The design parts of the text report: the template lists "design" (one
 * item under `rockbolt design`, none for a check) and, inside each motion,
 * "motion_design", each with their sweep tables. Their tables are many and
 * small, so they come from one arena the renderer frees in one go. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/names.h"
#include "report_internal.h"
#include "util/grow.h"

struct rb_txt_arena {
    void **blocks;
    size_t n, cap;
    int nomem;
};

static void *arena_alloc(rb_txt_arena *a, size_t n, size_t size)
{
    void *p;
    if (a->nomem)
        return NULL;
    if (a->n == a->cap) {
        void **b = rb_grow(a->blocks, &a->cap, sizeof *b, 16);
        if (!b) {
            a->nomem = 1;
            return NULL;
        }
        a->blocks = b;
    }
    if (!(p = calloc(n ? n : 1, size))) {
        a->nomem = 1;
        return NULL;
    }
    a->blocks[a->n++] = p;
    return p;
}

void *rb_txt_arena_alloc(rb_txt_arena *a, size_t n, size_t size)
{
    return arena_alloc(a, n, size);
}

rb_txt_arena *rb_txt_arena_new(void)
{
    return calloc(1, sizeof(rb_txt_arena));
}

void rb_txt_arena_free(rb_txt_arena *a)
{
    size_t i;
    if (!a)
        return;
    for (i = 0; i < a->n; i++)
        free(a->blocks[i]);
    free(a->blocks);
    free(a);
}

/* A scope with room for RB_TXT_MAX_VARS variables and n_lists lists. */
static rb_tscope *new_scope(rb_txt_arena *a, rb_tvars *t, size_t n_lists)
{
    rb_tscope *sc = arena_alloc(a, 1, sizeof *sc);
    t->v = arena_alloc(a, RB_TXT_MAX_VARS, sizeof *t->v);
    t->n = 0;
    if (!sc || !t->v)
        return NULL;
    sc->vars = t->v;
    if (n_lists && !(sc->lists = arena_alloc(a, n_lists, sizeof *sc->lists)))
        return NULL;
    return sc;
}

/* The thesis marks yield with o and failure with x. */
static const char *point_mark(const rb_sweep_point *p)
{
    if (p->status != RB_OK)
        return "run failed";
    /* a run stretching past failure never sets broken: read the usage */
    if (p->overturned || p->broken[0] || p->broken[1] || p->usage[0] >= 1.0
        || p->usage[1] >= 1.0)
        return "x";
    if (p->yielded[0] || p->yielded[1])
        return "o";
    return "";
}

static int sweep_points(rb_txt_arena *a, const rb_sweep *s, rb_tlist *list)
{
    rb_tscope *items = arena_alloc(a, s->n_points, sizeof *items);
    size_t i;
    list->name = "points";
    list->items = items;
    list->n = s->n_points;
    if (!items)
        return 0;
    for (i = 0; i < s->n_points; i++) {
        const rb_sweep_point *p = &s->points[i];
        rb_tvars t = { arena_alloc(a, RB_TXT_MAX_VARS, sizeof(rb_tvar)), 0 };
        int ok = p->status == RB_OK;
        if (!t.v)
            return 0;
        rb_tv_num(&t, "x", p->x);
        rb_tv_opt(&t, "freq_hz", p->freq_hz > 0, p->freq_hz);
        rb_tv_num(&t, "level_astar", p->level_astar);
        rb_tv_opt(&t, "u_over_ustatic", ok, p->max_u_over_ustatic);
        rb_tv_opt(&t, "theta_over_alpha", ok, p->max_theta_over_alpha);
        rb_tv_opt(&t, "force_left_over_fy", ok, p->max_force_over_fy[RB_LEFT]);
        rb_tv_opt(&t, "force_right_over_fy", ok, p->max_force_over_fy[RB_RIGHT]);
        rb_tv_opt(&t, "usage_left", ok, p->usage[RB_LEFT]);
        rb_tv_opt(&t, "usage_right", ok, p->usage[RB_RIGHT]);
        rb_tv_str(&t, "mark", point_mark(p));
        items[i].vars = t.v;
        items[i].n_vars = t.n;
    }
    return 1;
}

static int sweep_list(rb_txt_arena *a, const char *name, const rb_sweep *s, size_t n,
                      rb_tlist *list)
{
    rb_tscope *items = arena_alloc(a, n, sizeof *items);
    size_t i;
    list->name = name;
    list->items = items;
    list->n = n;
    if (!items)
        return 0;
    for (i = 0; i < n; i++) {
        rb_tvars t = { arena_alloc(a, RB_TXT_MAX_VARS, sizeof(rb_tvar)), 0 };
        rb_tlist *pts = arena_alloc(a, 1, sizeof *pts);
        if (!t.v || !pts || !sweep_points(a, &s[i], pts))
            return 0;
        rb_tv_int(&t, "sweep_index", (long)(i + 1));
        rb_tv_str(&t, "sweep_x", s[i].kind == RB_SWEEP_FREQUENCY
                  ? "f / f_fixed-base" : "level (A*)");
        rb_tv_num(&t, "sweep_amplitude_astar", s[i].amplitude_astar);
        rb_tv_num(&t, "sweep_fixed_base_hz", s[i].fixed_base_hz);
        rb_tv_int(&t, "sweep_points", (long)s[i].n_points);
        ((rb_tscope *)items)[i].vars = t.v;
        ((rb_tscope *)items)[i].n_vars = t.n;
        ((rb_tscope *)items)[i].lists = pts;
        ((rb_tscope *)items)[i].n_lists = 1;
    }
    return 1;
}

const char *rb_report_code_bound_str(int bound)
{
    return bound < 0 ? "the minimum 0.3 SDS Ip Wp governs"
           : bound > 0 ? "the maximum 1.6 SDS Ip Wp governs" : "within the bounds";
}

int rb_report_code_steel_pass(const rb_code_result *k)
{
    return k->ratio <= 1.0;
}

int rb_report_code_concrete_pass(const rb_code_result *k)
{
    return k->concrete_utilization < 1.0;
}

static void code_vars(rb_tvars *t, const rb_report *r)
{
    const rb_case_design *d = r->design;
    const rb_code_result *k = &d->code;
    const rb_code_inputs *in = &r->kase->code;
    rb_tv_int(t, "has_code", d->has_code);
    rb_tv_str(t, "code_edition", in->edition == RB_ASCE7_16 ? "ASCE 7-16" : "ASCE 7-22");
    rb_tv_num(t, "code_sds", in->sds);
    rb_tv_num(t, "code_ip", in->ip);
    rb_tv_num(t, "code_z_over_h", in->z_over_h);
    rb_tv_num(t, "code_hf", k->hf);
    rb_tv_num(t, "code_rmu", k->rmu);
    rb_tv_num(t, "code_fp_formula_kn", k->fp_formula_n * 1e-3);
    rb_tv_num(t, "code_fp_kn", k->fp_n * 1e-3);
    rb_tv_str(t, "code_bound", rb_report_code_bound_str(k->bound));
    rb_tv_num(t, "code_fp_over_wp", k->fp_over_wp);
    rb_tv_num(t, "code_fp_anchor_kn", k->fp_anchor_n * 1e-3);
    rb_tv_num(t, "code_accel_g", k->fp_over_wp);
    rb_tv_num(t, "code_accel_astar", k->accel_astar);
    rb_tv_num(t, "code_tension_kn", k->tension_n * 1e-3);
    rb_tv_num(t, "code_phi_nsa_kn", k->phi_nsa_n * 1e-3);
    rb_tv_num(t, "code_ratio", k->ratio);
    rb_tv_str(t, "code_verdict", rb_report_code_steel_pass(k) ? "PASS" : "FAIL");
    const rb_out_units *u = rb_out_units_of(r->kase->output_units);
    rb_tv_num(t, "code_fp_formula", k->fp_formula_n / u->force_f);
    rb_tv_num(t, "code_fp", k->fp_n / u->force_f);
    rb_tv_num(t, "code_fp_anchor", k->fp_anchor_n / u->force_f);
    rb_tv_num(t, "code_tension", k->tension_n / u->force_f);
    rb_tv_num(t, "code_phi_nsa", k->phi_nsa_n / u->force_f);
    rb_tv_int(t, "code_concrete", k->has_concrete);
    rb_tv_num(t, "code_concrete_utilization", k->concrete_utilization);
    rb_tv_str(t, "code_concrete_clause", rb_aci17_interaction_clause(k->concrete_clause));
    rb_tv_str(t, "code_concrete_verdict", rb_report_code_concrete_pass(k) ? "PASS" : "FAIL");
}

rb_status rb_report_text_case_design(const rb_report *r, rb_txt_arena *a, rb_tlist *out)
{
    const rb_case_design *d = r->design;
    const rb_design_opts *g = &r->kase->design;
    rb_tscope *sc;
    rb_tvars t;
    out->name = "design";
    out->items = NULL;
    out->n = 0;
    if (!d)
        return RB_OK;
    if (!(sc = new_scope(a, &t, 1)))
        return RB_ERR_NOMEM;
    rb_tv_num(&t, "scan_start", g->scan_start);
    rb_tv_num(&t, "scan_step", g->scan_step);
    rb_tv_num(&t, "scan_end", g->scan_end);
    rb_tv_num(&t, "resolution", g->resolution);
    rb_tv_num(&t, "gap_ratio_min", g->gap_ratio_min);
    rb_tv_num(&t, "gap_ratio_max", g->gap_ratio_max);
    rb_tv_num(&t, "gap_ratio_step", g->gap_ratio_step);
    code_vars(&t, r);
    sc->n_vars = t.n;
    sc->n_lists = 1;
    if (!sweep_list(a, "frequency_sweeps", d->sweeps, d->n_sweeps,
                    (rb_tlist *)sc->lists))
        return RB_ERR_NOMEM;
    out->items = sc;
    out->n = 1;
    return RB_OK;
}

static void factor_vars(const rb_report *r, rb_tvars *t, const char *num, const char *text,
                        const rb_design_factor_result *f, char *buf, size_t n)
{
    rb_design_factor_describe(f, rb_out_units_of(r->kase->output_units), r->derived.g,
                              buf, n);
    rb_tv_opt(t, num, isfinite(f->factor), f->factor);
    rb_tv_str(t, text, buf);
}

#define FACTOR_NAME_MAX 40

/* A kind's variables: factor_no_yield and factor_no_yield_text. */
static void factor_names(int kind, char *num, char *num_text)
{
    char key[FACTOR_NAME_MAX - 8];
    snprintf(num, FACTOR_NAME_MAX, "factor_%s",
             rb_enum_str_sep(rb_criterion_names, kind, '_', key, sizeof key));
    snprintf(num_text, FACTOR_NAME_MAX, "%s_text", num);
}

rb_status rb_report_text_motion_design(const rb_report *r, size_t i, rb_txt_arena *a,
                                       rb_tlist *out)
{
    const rb_case_design *d = r->design;
    const rb_motion_design *md;
    const rb_gap_result *g;
    rb_tscope *sc;
    rb_tvars t;
    char *text, *names;
    out->name = "motion_design";
    out->items = NULL;
    out->n = 0;
    if (!d || i >= d->n_motions)
        return RB_OK;
    md = &d->motions[i];
    g = &md->gap;
    /* a sentence per kind and the gap's, and each kind's two names */
    if (!(sc = new_scope(a, &t, 1)) || !(text = arena_alloc(a, RB_N_CRITERIA + 1, 640))
        || !(names = arena_alloc(a, RB_N_CRITERIA, 2 * FACTOR_NAME_MAX)))
        return RB_ERR_NOMEM;
    for (int k = 0; k < RB_N_CRITERIA; k++) {
        char *num = names + 2 * FACTOR_NAME_MAX * k, *num_text = num + FACTOR_NAME_MAX;
        factor_names(k, num, num_text);
        factor_vars(r, &t, num, num_text, &md->factor[k], text + 640 * k, 640);
    }
    rb_tv_num(&t, "no_break_usage_limit", d->factor_criteria[RB_CRIT_NO_BREAK].usage_limit);
    rb_tv_str(&t, "gap_criterion", rb_enum_str(rb_criterion_names, (int)d->gap_criteria.kind));
    if (md->has_gap)
        rb_gap_describe(g, rb_out_units_of(r->kase->output_units),
                        text + 640 * RB_N_CRITERIA, 640);
    rb_tv_str(&t, "gap_text", md->has_gap ? text + 640 * RB_N_CRITERIA : NULL);
    rb_tv_int(&t, "has_yield_run", md->has_gap && g->yield_run);
    rb_tv_num(&t, "yield_initial_gap_ratio", g->yield_initial_gap_ratio);
    rb_tv_num(&t, "yield_final_gap_left", g->yield_final_gap_ratio[RB_LEFT]);
    rb_tv_num(&t, "yield_final_gap_right", g->yield_final_gap_ratio[RB_RIGHT]);
    rb_tv_num(&t, "yield_usage_left", g->yield_usage[RB_LEFT]);
    rb_tv_num(&t, "yield_usage_right", g->yield_usage[RB_RIGHT]);
    sc->n_vars = t.n;
    sc->n_lists = 1;
    if (!sweep_list(a, "amplitude_sweeps", md->sweeps, md->n_sweeps,
                    (rb_tlist *)sc->lists))
        return RB_ERR_NOMEM;
    out->items = sc;
    out->n = 1;
    return RB_OK;
}
