/* The `design:` section of a case: the design-factor scan grid, the gap
 * grid, the sweeps and the code-static inputs `rockbolt design` runs.
 *
 * Code inputs use the standards' own symbols (sds, ip, ap, rp, car, rpo,
 * omega0p, futa, ase) because the engineer copies them from the code's
 * tables; which of them are required depends on the edition, and a missing
 * one is reported here, at the `code:` mapping, rather than as a bare
 * field name from the library at run time. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "case_internal.h"
#include "rockbolt/design.h"

static const char *const design_keys[] = {
    "scan_start", "scan_step", "scan_end", "resolution", "gap_ratio_min",
    "gap_ratio_max", "gap_ratio_step", "max_gap", "sweeps", "code", NULL};
static const char *const sweep_keys[] = {
    "type", "from", "to", "points", "amplitude", "duration", "ramp", NULL};
static const char *const code_keys[] = {
    "edition", "sds", "ip", "z_over_h", "at_or_below_grade", "ap", "rp", "car",
    "rpo", "ta", "r", "ie", "omega0", "anchorage_in_concrete", "omega0p",
    "futa", "ase", NULL};
const char *const *const rb_case_design_keys = design_keys;
const char *const *const rb_case_code_keys = code_keys;

/* A plain fraction of A* or "<x> A*" (astar_ok), or a plain ratio; > 0, or
 * >= 0 when zero_ok. */
static void design_value(rb_cctx *c, rb_ynode *map, const char *path,
                            const char *key, int zero_ok, int astar_ok,
                            double *out)
{
    char k[RB_CASE_KEY_MAX];
    rb_quantity q;
    rb_ynode *v = rb_cv_get(c, map, path, key, 0, "");
    if (!v)
        return;
    rb_case_keypath(k, path, key);
    size_t len = v->kind == RB_YNODE_SCALAR ? strlen(v->text) : 0;
    int astar = astar_ok && len >= 2 && strcmp(v->text + len - 2, "A*") == 0;
    if (!rb_cv_quantity(c, v, k, astar ? RB_DIM_ACCEL : RB_DIM_RATIO, &q))
        return;
    if (q.value < 0 || (!zero_ok && q.value == 0)) {
        rb_cctx_error(c, v, k, "must be %s 0 (got '%s')", zero_ok ? ">=" : ">",
                      v->text);
        return;
    }
    *out = q.value;
}

static void read_sweep(rb_cctx *c, rb_ynode *m, const char *path,
                          rb_sweep_opts *sw)
{
    static const char *const kinds[] = {"frequency", "amplitude", NULL};
    int kind = 0;
    char k[RB_CASE_KEY_MAX];
    long n;
    rb_ynode *v = rb_cv_get(c, m, path, "type", 1,
                            "'frequency' (harmonic, x = f / f_fixed-base) or "
                            "'amplitude' (the case's motion, x in A*)");
    rb_case_keypath(k, path, "type");
    if (v && !rb_cv_enum(c, v, k, kinds, &kind))
        kind = 0;
    rb_sweep_opts_init(sw, kind == 0 ? RB_SWEEP_FREQUENCY : RB_SWEEP_AMPLITUDE);
    int freq = sw->kind == RB_SWEEP_FREQUENCY;
    /* frequency ratios are plain numbers; amplitude levels may say A* */
    design_value(c, m, path, "from", 0, !freq, &sw->from);
    design_value(c, m, path, "to", 0, !freq, &sw->to);
    if ((v = rb_cv_get(c, m, path, "points", 0, ""))) {
        rb_case_keypath(k, path, "points");
        if (rb_cv_int(c, v, k, 1, 10000, &n))
            sw->n_points = (size_t)n;
    }
    if (freq) {
        design_value(c, m, path, "amplitude", 0, 1, &sw->amplitude_astar);
        /* the case's own time limits: 1 ms (ramp 0) to one simulated hour */
        const rb_ynode *t = rb_cv_number(c, m, path, "duration", 0, RB_DIM_TIME, 0, 0,
                                         (double)NAN, 0, &sw->duration_s);
        rb_case_keypath(k, path, "duration");
        if (t)
            rb_cv_time_range(c, t, k, sw->duration_s, 0);
        t = rb_cv_number(c, m, path, "ramp", 0, RB_DIM_TIME, 0, 1, (double)NAN, 0,
                         &sw->ramp_s);
        rb_case_keypath(k, path, "ramp");
        if (t)
            rb_cv_time_range(c, t, k, sw->ramp_s, 1);
    } else {
        static const char *const freq_only[] = {"amplitude", "duration", "ramp"};
        size_t i;
        for (i = 0; i < 3; i++)
            if ((v = rb_cv_get(c, m, path, freq_only[i], 0, ""))) {
                rb_case_keypath(k, path, freq_only[i]);
                rb_cctx_error(c, v, k, "only frequency sweeps take '%s'; an "
                              "amplitude sweep scales the case's own motion",
                              freq_only[i]);
            }
    }
    if (sw->to < sw->from) {
        rb_case_keypath(k, path, "to");
        rb_cctx_error(c, m, k, "must not be below 'from' (%g < %g)", sw->to,
                      sw->from);
    }
    rb_cv_unknown_keys(c, m, path, sweep_keys);
}

static void read_sweeps(rb_cctx *c, rb_ynode *seq, rb_case *cs)
{
    size_t i;
    if (seq->kind != RB_YNODE_SEQ) {
        rb_cctx_error(c, seq, "design.sweeps", "expected a list of sweeps, "
                      "each a mapping with 'type', 'from', 'to', 'points'");
        return;
    }
    if (seq->n > RB_CASE_MAX_SWEEPS) {
        rb_cctx_error(c, seq, "design.sweeps", "at most %d sweeps (got %zu)",
                      RB_CASE_MAX_SWEEPS, seq->n);
        return;
    }
    for (i = 0; i < seq->n; i++) {
        char path[RB_CASE_KEY_MAX];
        snprintf(path, sizeof path, "design.sweeps[%zu]", i + 1);
        if (!rb_cv_map(c, seq->items[i], path))
            continue;
        c->sweep_maps[cs->n_sweeps] = seq->items[i];
        read_sweep(c, seq->items[i], path, &cs->sweeps[cs->n_sweeps++]);
    }
}

/* A dimensionless code factor, > 0; whether it is required depends on the
 * edition. */
static void code_factor(rb_cctx *c, rb_ynode *m, const char *key, int required,
                           double *out)
{
    rb_cv_number(c, m, "design.code", key, required, RB_DIM_RATIO, 0, 0,
                 1000, 1, out);
}

/* S_DS is a spectral acceleration the standard states in g: a bare
 * number is read in g, as ASCE 7 writes it, and "1.0 g" or "9.8 m/s^2"
 * is taken too, as the AC156 spectrum's sds is. */
static void code_sds(rb_cctx *c, rb_ynode *m, double *sds_g)
{
    char msg[300];
    rb_quantity q;
    rb_ynode *v = rb_cv_get(c, m, "design.code", "sds", 1,
                            "S_DS in g: a number such as 1.0, or '1.0 g'");
    if (!v)
        return;
    if (v->kind == RB_YNODE_SCALAR && rb_unit_parse(v->text, RB_DIM_RATIO, &q, msg,
                                                    sizeof msg) == RB_OK) {
        q.value *= RB_UNIT_G_MPS2;   /* the bare number is in g */
    } else if (!rb_cv_quantity(c, v, "design.code.sds", RB_DIM_ACCEL, &q)) {
        return;
    } else if (q.relative_a_star) {
        rb_cctx_error(c, v, "design.code.sds",
                      "S_DS is a site value: give it in g or m/s^2, not A*");
        return;
    }
    double g = q.value / RB_UNIT_G_MPS2;
    if (!(g > 0 && g <= 10)) {
        rb_cctx_error(c, v, "design.code.sds", "must be > 0 and <= 10 g (got '%s')",
                      v->text);
        return;
    }
    *sds_g = g;
}

static void code_flag(rb_cctx *c, rb_ynode *m, const char *key, int *out)
{
    char k[RB_CASE_KEY_MAX];
    rb_ynode *v = rb_cv_get(c, m, "design.code", key, 0, "");
    rb_case_keypath(k, "design.code", key);
    if (v)
        rb_cv_bool(c, v, k, out);
}

/* A factor of the other edition is a mix-up the engineer should hear of,
 * not a value to ignore. */
static void reject_other_edition(rb_cctx *c, rb_ynode *m, int e16)
{
    static const char *const only16[] = {"ap", "rp", NULL};
    static const char *const only22[] = {"car", "rpo", "ta", "r", "ie", "omega0", NULL};
    const char *const *k;
    for (k = e16 ? only22 : only16; *k; k++) {
        rb_yentry *e = rb_ymap_find(m, *k);
        char key[RB_CASE_KEY_MAX];
        if (!e)
            continue;
        e->used = 1;
        rb_case_keypath(key, "design.code", *k);
        rb_cctx_error(c, e->value, key, "'%s' belongs to ASCE %s, but the edition is "
                      "ASCE %s (7-16 takes ap and rp; 7-22 takes car, rpo, ta, r, ie "
                      "and omega0)", *k, e16 ? "7-22" : "7-16", e16 ? "7-16" : "7-22");
    }
}

static void read_code(rb_cctx *c, rb_ynode *m, rb_case *cs)
{
    static const char *const editions[] = {"ASCE 7-16", "ASCE 7-22", NULL};
    rb_code_inputs *in = &cs->code;
    int ed = 1;
    rb_code_inputs_init(in);
    if (!rb_cv_map(c, m, "design.code"))
        return;
    cs->has_code = 1;
    rb_ynode *v = rb_cv_get(c, m, "design.code", "edition", 1,
                            "'ASCE 7-16' or 'ASCE 7-22'");
    if (v && rb_cv_enum(c, v, "design.code.edition", editions, &ed))
        in->edition = ed == 0 ? RB_ASCE7_16 : RB_ASCE7_22;
    int e16 = in->edition == RB_ASCE7_16;
    code_flag(c, m, "at_or_below_grade", &in->at_or_below_grade);
    code_flag(c, m, "anchorage_in_concrete", &in->anchorage_in_concrete);
    code_sds(c, m, &in->sds);
    code_factor(c, m, "ip", 0, &in->ip);
    rb_cv_number(c, m, "design.code", "z_over_h", 1, RB_DIM_RATIO, 0, 1, 1, 1,
                 &in->z_over_h);
    reject_other_edition(c, m, e16);
    code_factor(c, m, "ap", e16, &in->ap);
    code_factor(c, m, "rp", e16, &in->rp);
    code_factor(c, m, "car", !e16, &in->car);
    code_factor(c, m, "rpo", !e16, &in->rpo);
    int building = !e16 && !in->at_or_below_grade;
    code_factor(c, m, "r", building, &in->r);
    code_factor(c, m, "ie", building, &in->ie);
    code_factor(c, m, "omega0", building, &in->omega0);
    rb_cv_number(c, m, "design.code", "ta", 0, RB_DIM_TIME, 0, 0, 100, 1,
                 &in->ta_s);
    code_factor(c, m, "omega0p", 0, &in->omega0p);
    rb_cv_number(c, m, "design.code", "futa", 1, RB_DIM_STRESS, 0, 0, (double)NAN, 0,
                 &in->futa_pa);
    rb_cv_number(c, m, "design.code", "ase", 0, RB_DIM_AREA, 0, 0, (double)NAN, 0,
                 &in->ase_m2);
    rb_cv_unknown_keys(c, m, "design.code", code_keys);
}

void rb_case_read_design(rb_cctx *c, rb_ynode *d, rb_case *cs)
{
    rb_design_opts *o = &cs->design;
    rb_ynode *v;
    design_value(c, d, "design", "scan_start", 0, 1, &o->scan_start);
    design_value(c, d, "design", "scan_step", 0, 1, &o->scan_step);
    design_value(c, d, "design", "scan_end", 0, 1, &o->scan_end);
    design_value(c, d, "design", "resolution", 0, 1, &o->resolution);
    design_value(c, d, "design", "gap_ratio_min", 1, 0, &o->gap_ratio_min);
    design_value(c, d, "design", "gap_ratio_max", 1, 0, &o->gap_ratio_max);
    design_value(c, d, "design", "gap_ratio_step", 0, 0, &o->gap_ratio_step);
    rb_cv_number(c, d, "design", "max_gap", 0, RB_DIM_LENGTH, 0, 0, (double)NAN, 0,
                 &o->max_gap_m);
    rb_yentry *re = rb_ymap_find(d, "resolution");
    double finest = RB_DESIGN_MIN_RESOLUTION * (o->scan_end > 1 ? o->scan_end : 1);
    if (re && o->resolution > 0 && o->resolution < finest)
        rb_cctx_error(c, re->value, "design.resolution", "must be at least %g A* "
                      "(1e-9 of the larger of 1 A* and scan_end): a finer bisection "
                      "is below what double precision can tell apart (got '%s')",
                      finest, re->value->text);
    if (o->scan_end < o->scan_start)
        rb_cctx_error(c, d, "design.scan_end", "must not be below scan_start "
                      "(%g < %g A*)", o->scan_end, o->scan_start);
    if (o->gap_ratio_max < o->gap_ratio_min)
        rb_cctx_error(c, d, "design.gap_ratio_max", "must not be below "
                      "gap_ratio_min (%g < %g)", o->gap_ratio_max,
                      o->gap_ratio_min);
    if ((v = rb_cv_get(c, d, "design", "sweeps", 0, "")))
        read_sweeps(c, v, cs);
    if ((v = rb_cv_get(c, d, "design", "code", 0, "")))
        read_code(c, v, cs);
    rb_cv_unknown_keys(c, d, "design", design_keys);
}
