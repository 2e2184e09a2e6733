/* The keys of a case file (docs/case-format.md) and their SI values.
 *
 * Reads the merged tree section by section into the rb_case: equipment,
 * anchorage, gap, criteria, analysis, design, name and description; the
 * motions are read by case_motion.c. Each section checks what it can from
 * its own values (types, units, ranges, alternatives such as height vs
 * cm_height) and notes where each model field came from, so that the
 * cross-field checks of rb_model_derive can later be reported against the
 * right line. Unknown keys are reported per section with a hint. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "case_internal.h"

#define RB_PI 3.14159265358979323846

static const char *const equipment_keys[] = {
    "mass", "height", "cm_height", "base_width", "frequency", "damping",
    "restitution", "inertia", "rigid", NULL};
static const char *const anchorage_keys[] = {
    "model", "bolts_per_row", "diameter", "area", "yield_stress", "toughness",
    "deformable_length", "lever_arm", "edge_distance", "elastic_modulus",
    /* the concrete check's (case_concrete.c) */
    "type", "embedment", "spacing", "ultimate_stress", "head_bearing_area", "grout_pad",
    "tensile_area", "threads", "head", "washer_diameter", "thread_pitch", "threads_per_inch",
    "product",
    NULL};
static const char *const criteria_keys[] = {
    "kind", "usage_limit", "max_shear_over_w", "max_rotation_over_alpha",
    "friction_coefficient", "validity", "concrete", "confirm", "confirm_band", NULL};
static const char *const analysis_keys[] = {
    "formulation", "integrator", "tolerance", "output_interval", "history",
    "stretch_past_failure", "rest_fraction", NULL};
/* for the keys a list column may name (case_keys.c) */
const char *const *const rb_case_equipment_keys = equipment_keys;
const char *const *const rb_case_anchorage_keys = anchorage_keys;
const char *const *const rb_case_criteria_keys = criteria_keys;
const char *const *const rb_case_analysis_keys = analysis_keys;

/* Which of two alternative keys the map gives: 0 for a, 1 for b, -1 when
 * neither (an error if required) or both (always an error). */
static int one_of(rb_cctx *c, rb_ynode *map, const char *path, const char *a,
                     const char *b, int required, const char *expected)
{
    rb_yentry *ea = rb_ymap_find(map, a), *eb = rb_ymap_find(map, b);
    char k[RB_CASE_KEY_MAX];
    if (ea && eb) {
        const rb_yentry *later = ea->line > eb->line ? ea : eb;
        rb_case_keypath(k, path, later->key);
        rb_cctx_error(c, later->value, k, "give either '%s' or '%s', not both",
                      a, b);
        ea->used = eb->used = 1;
        return -1;
    }
    if (!ea && !eb) {
        if (required) {
            rb_case_keypath(k, path, a);
            rb_cctx_error(c, map, k, "missing required key '%s' or '%s' (%s)",
                          a, b, expected);
        }
        return -1;
    }
    return ea ? 0 : 1;
}

/* A section that must be a mapping; NULL if absent or not a mapping. */
static rb_ynode *schema_section(rb_cctx *c, rb_ynode *root, const char *name,
                            int required, const char *expected)
{
    rb_ynode *v = rb_cv_get(c, root, "", name, required, expected);
    if (v && !rb_cv_map(c, v, name))
        return NULL;
    return v;
}

/* A value outside [lo, hi] (what the solver takes, docs/robustness.md) is
 * an error at its node v, if v is set; range says the bounds in units. */
/* An error unless lo <= x <= hi. si_range: the limits as SI users read
 * them ("1 MPa and 10 GPa"); a case in US customary units gets them in its
 * own units, made from lo and hi. */
static void within(rb_cctx *c, const rb_ynode *v, const char *key, double x,
                      double lo, double hi, rb_qty q, const char *si_range)
{
    if (!v || (x >= lo && x <= hi))
        return;
    char range[120];
    if (c->units == RB_UNITS_US)
        snprintf(range, sizeof range, "%s and %s", rb_qty_str(c->units, q, lo, 4).s,
                 rb_qty_str(c->units, q, hi, 4).s);
    else
        snprintf(range, sizeof range, "%s", si_range);
    rb_cctx_error(c, v, key, "must be between %s (got '%s')", range, v->text);
    c->model_errors++;
}

/* A quantity that is also a model field (see rb_cv_note_field). */
static const rb_ynode *schema_field(rb_cctx *c, rb_ynode *map, const char *path,
                                const char *key, const char *field, int required,
                                rb_dim dim, double lo, int lo_incl, double hi,
                                int hi_incl, double *out)
{
    char k[RB_CASE_KEY_MAX];
    const rb_ynode *v = rb_cv_number(c, map, path, key, required, dim, lo,
                                     lo_incl, hi, hi_incl, out);
    rb_case_keypath(k, path, key);
    if (v)
        rb_cv_note_field(c, field, k, v);
    else if (rb_ymap_find(map, key) || required)
        c->model_errors++;
    return v;
}

static void read_equipment(rb_cctx *c, rb_ynode *eq, rb_model *m)
{
    const char *p = "equipment";
    double x;
    const rb_ynode *mv = schema_field(c, eq, p, "mass", "mass", 1, RB_DIM_MASS, 0, 0,
                                  (double)NAN, 0, &m->mass_kg);
    within(c, mv, "equipment.mass", m->mass_kg, RB_CASE_MIN_MASS_KG,
              RB_CASE_MAX_MASS_KG, RB_Q_MASS, "1 kg and 1e9 kg");
    int which = one_of(c, eq, p, "height", "cm_height", 1,
                          "the total height, or the height of the centre of mass");
    if (which < 0)
        c->model_errors++;
    else if (schema_field(c, eq, p, which ? "cm_height" : "height", "cm_height", 1,
                      RB_DIM_LENGTH, 0, 0, (double)NAN, 0, &x))
        m->cm_height_m = which ? x : x / 2;
    if (schema_field(c, eq, p, "base_width", "half_width", 1, RB_DIM_LENGTH, 0, 0,
                 (double)NAN, 0, &x))
        m->half_width_m = x / 2;
    rb_ynode *v = rb_cv_get(c, eq, p, "rigid", 0, "");
    if (v && !rb_cv_bool(c, v, "equipment.rigid", &m->rigid))
        c->model_errors++;
    const rb_ynode *f = schema_field(c, eq, p, "frequency", "frequency", !m->rigid,
                                 RB_DIM_FREQUENCY, 0, 0, (double)NAN, 0, &m->freq_hz);
    if (f && m->freq_hz < RB_CASE_MIN_FREQ_HZ) {
        rb_cctx_error(c, f, "equipment.frequency", "must be at least %g Hz (got "
                      "'%s'): a frame that flexible has no static deflection "
                      "the model can hold", RB_CASE_MIN_FREQ_HZ, f->text);
        c->model_errors++;
    }
    schema_field(c, eq, p, "damping", "damping", !m->rigid, RB_DIM_RATIO, 0, 1, 1,
             0, &m->damping);
    v = rb_cv_get(c, eq, p, "restitution", 0, "");
    if (v && v->kind == RB_YNODE_SCALAR && strcmp(v->text, "housner") == 0)
        m->restitution = -1.0;
    else if (v)
        schema_field(c, eq, p, "restitution", "restitution", 0, RB_DIM_RATIO, 0, 0,
                 1, 1, &m->restitution);
    schema_field(c, eq, p, "inertia", "inertia", 0, RB_DIM_INERTIA, 0, 0, (double)NAN, 0,
             &m->inertia_kgm2);
    rb_cv_unknown_keys(c, eq, p, equipment_keys);
}

/* The lever arm, given directly or as the bolt's distance from the plate
 * edge (l = 2b - e), checked against the plate. */
static void read_lever_arm(rb_cctx *c, rb_ynode *an, rb_model *m)
{
    const char *p = "anchorage";
    int which = one_of(c, an, p, "lever_arm", "edge_distance", 1,
                          "the bolt's distance from the far edge, or from its own edge");
    double x, width = 2 * m->half_width_m;
    if (which < 0) {
        c->model_errors++;
        return;
    }
    const char *key = which ? "edge_distance" : "lever_arm";
    const rb_ynode *v = schema_field(c, an, p, key, "lever_arm", 1, RB_DIM_LENGTH,
                                 which ? 0 : (double)NAN, 0, (double)NAN, 0, &x);
    if (!v)
        return;
    m->lever_arm_m = which ? width - x : x;
    if (width <= 0)
        return;     /* base_width was bad, already reported */
    if (m->lever_arm_m <= 0 || m->lever_arm_m > width) {
        rb_cctx_error(c, v, which ? "anchorage.edge_distance" : "anchorage.lever_arm",
                      "puts the bolt outside the base plate (base_width is %s, "
                      "lever arm would be %s)", rb_qty_str(c->units, RB_Q_LENGTH, width, 6).s,
                      rb_qty_str(c->units, RB_Q_LENGTH, m->lever_arm_m, 6).s);
        c->model_errors++;
    } else if (m->lever_arm_m <= m->half_width_m) {
        rb_cctx_error(c, v, which ? "anchorage.edge_distance" : "anchorage.lever_arm",
                      "puts the bolt on the near half of the base plate: the "
                      "lever arm %s must exceed half the base width (%s)",
                      rb_qty_str(c->units, RB_Q_LENGTH, m->lever_arm_m, 6).s,
                      rb_qty_str(c->units, RB_Q_LENGTH, m->half_width_m, 6).s);
        c->model_errors++;
    }
}

static void read_anchorage(rb_cctx *c, rb_ynode *an, rb_model *m)
{
    const char *p = "anchorage";
    /* A case's rows are springs unless it asks for the thesis's rigid stop:
     * a rigid stop hides the impact that an elastic row of n E A / L_d
     * meets (docs/solver.md, Bolt impact), and a default must not pass
     * what the bolts themselves would fail. */
    int i = RB_BOLT_ELASTIC_PLASTIC;
    double x;
    rb_ynode *v = rb_cv_get(c, an, p, "model", 0, "");
    if (v && !rb_cv_enum_table(c, v, "anchorage.model", rb_bolt_model_names, 0, &i))
        c->model_errors++;
    m->bolt_model = (rb_bolt_model)i;
    if (m->bolt_model == RB_BOLT_NONE) {
        /* Free-standing: bolt data inherited from a base case is ignored. */
        for (size_t k = 0; k < an->n; k++)
            an->entries[k].used = 1;
        return;
    }
    long n = 0;
    v = rb_cv_get(c, an, p, "bolts_per_row", 1, "a whole number >= 1");
    if (v && rb_cv_int(c, v, "anchorage.bolts_per_row", 1, 1000, &n))
        m->bolts_per_row = (int)n;
    else
        c->model_errors++;
    int which = one_of(c, an, p, "diameter", "area", 1,
                          "the bolt diameter, or its tensile area");
    const rb_ynode *bv;
    if (which == 0 && (bv = schema_field(c, an, p, "diameter", "bolt_area", 1,
                                     RB_DIM_LENGTH, 0, 0, (double)NAN, 0, &x))) {
        m->bolt_area_m2 = RB_PI * x * x / 4;
        within(c, bv, "anchorage.diameter", x, RB_CASE_MIN_DIAMETER_M,
                  RB_CASE_MAX_DIAMETER_M, RB_Q_SMALL_LENGTH, "1 mm and 200 mm");
    } else if (which == 1) {
        c->bolt_by_area = 1;
        bv = schema_field(c, an, p, "area", "bolt_area", 1, RB_DIM_AREA, 0, 0, (double)NAN, 0,
                      &m->bolt_area_m2);
        within(c, bv, "anchorage.area", m->bolt_area_m2,
                  RB_PI * RB_CASE_MIN_DIAMETER_M * RB_CASE_MIN_DIAMETER_M / 4,
                  RB_PI * RB_CASE_MAX_DIAMETER_M * RB_CASE_MAX_DIAMETER_M / 4,
                  RB_Q_AREA, "0.785 mm^2 and 31 416 mm^2 (a bolt of 1 mm to 200 mm)");
    }
    else if (which < 0)
        c->model_errors++;
    bv = schema_field(c, an, p, "yield_stress", "yield_stress", 1, RB_DIM_STRESS, 0, 0,
                  (double)NAN, 0, &m->yield_stress_pa);
    within(c, bv, "anchorage.yield_stress", m->yield_stress_pa, RB_CASE_MIN_YIELD_PA,
              RB_CASE_MAX_YIELD_PA, RB_Q_STRESS, "1 MPa and 10 GPa");
    bv = schema_field(c, an, p, "toughness", "toughness", 1, RB_DIM_ENERGY_DENSITY, 0,
                  0, (double)NAN, 0, &m->toughness_jpm3);
    within(c, bv, "anchorage.toughness", m->toughness_jpm3, RB_CASE_MIN_TOUGHNESS,
              RB_CASE_MAX_TOUGHNESS, RB_Q_ENERGY_DENSITY, "1 kJ/m^3 and 1e7 kJ/m^3");
    v = (rb_ynode *)schema_field(c, an, p, "deformable_length", "deformable_length", 1,
                             RB_DIM_LENGTH, 0, 0, (double)NAN, 0,
                             &m->deformable_length_m);
    if (v && (m->deformable_length_m < RB_CASE_MIN_BOLT_LENGTH_M
              || m->deformable_length_m > RB_CASE_MAX_BOLT_LENGTH_M)) {
        rb_cctx_error(c, v, "anchorage.deformable_length", "must be between %s "
                      "and %s (got '%s')",
                      rb_qty_str(c->units, RB_Q_SMALL_LENGTH, RB_CASE_MIN_BOLT_LENGTH_M, 4).s,
                      rb_qty_str(c->units, RB_Q_LENGTH, RB_CASE_MAX_BOLT_LENGTH_M, 4).s,
                      v->text);
        c->model_errors++;
    }
    bv = schema_field(c, an, p, "elastic_modulus", "elastic_modulus", 0, RB_DIM_STRESS,
                  0, 0, (double)NAN, 0, &m->elastic_modulus_pa);
    within(c, bv, "anchorage.elastic_modulus", m->elastic_modulus_pa,
              RB_CASE_MIN_MODULUS_PA, RB_CASE_MAX_MODULUS_PA, RB_Q_STRESS, "1 GPa and 1000 GPa");
    read_lever_arm(c, an, m);
    /* unknown keys once the concrete check has read its own */
}

/* gap (a length) or gap_ratio (of the lever arm), both rows alike. */
static void read_gap(rb_cctx *c, rb_ynode *root, rb_model *m)
{
    if (m->bolt_model == RB_BOLT_NONE) {
        rb_cv_get(c, root, "", "gap", 0, "");
        rb_cv_get(c, root, "", "gap_ratio", 0, "");
        return;
    }
    int which = one_of(c, root, "", "gap", "gap_ratio", 1,
                          "the gap under the bolt heads, e.g. 'gap: 7.8 mm' "
                          "or 'gap_ratio: 0.01'");
    if (which < 0) {
        c->model_errors++;
        return;
    }
    const rb_ynode *v;
    if (which == 0) {
        v = schema_field(c, root, "", "gap", "gap", 1, RB_DIM_LENGTH, 0, 1, (double)NAN, 0,
                     &m->gap_m);
    } else if ((v = schema_field(c, root, "", "gap_ratio", "gap", 1, RB_DIM_RATIO, 0, 1,
                             1, 0, &c->gap_ratio))) {
        c->gap_is_ratio = 1;
        m->gap_m = c->gap_ratio * m->lever_arm_m;
    }
    /* a gap that is not zero but a rounding error of the lever arm makes
     * the bolts chatter at every contact */
    double l = m->lever_arm_m;
    if (v && l > 0 && m->gap_m > 0 && m->gap_m < RB_CASE_MIN_GAP_RATIO * l) {
        rb_cctx_error(c, v, which ? "gap_ratio" : "gap", "must be 0 or at least "
                      "%g of the lever arm (%s here; got '%s')", RB_CASE_MIN_GAP_RATIO,
                      rb_qty_str(c->units, RB_Q_SMALL_LENGTH, RB_CASE_MIN_GAP_RATIO * l, 6).s,
                      v->text);
        c->model_errors++;
    }
}

static void read_criteria(rb_cctx *c, rb_ynode *cr, rb_criteria *k)
{
    const char *p = "criteria";
    int i;
    rb_ynode *v = rb_cv_get(c, cr, p, "kind", 0, "");
    if (v && rb_cv_enum_table(c, v, "criteria.kind", rb_criterion_names, 0, &i))
        k->kind = (rb_criterion_kind)i;
    rb_cv_number(c, cr, p, "usage_limit", 0, RB_DIM_RATIO, 0, 0, (double)NAN, 0,
                 &k->usage_limit);
    rb_cv_number(c, cr, p, "max_shear_over_w", 0, RB_DIM_RATIO, 0, 1, (double)NAN, 0,
                 &k->max_shear_over_w);
    rb_cv_number(c, cr, p, "max_rotation_over_alpha", 0, RB_DIM_RATIO, 0, 1,
                 (double)NAN, 0, &k->max_theta_over_alpha);
    rb_cv_number(c, cr, p, "friction_coefficient", 0, RB_DIM_RATIO, 0, 1, (double)NAN, 0,
                 &k->friction_coefficient);
    v = rb_cv_get(c, cr, p, "validity", 0, "");
    if (v && rb_cv_enum_table(c, v, "criteria.validity", rb_validity_mode_names, 0, &i))
        k->validity = (rb_validity_mode)i;
    v = rb_cv_get(c, cr, p, "confirm", 0, "");
    if (v && rb_cv_enum_table(c, v, "criteria.confirm", rb_confirm_mode_names, 0, &i))
        k->confirm = (rb_confirm_mode)i;
    rb_cv_number(c, cr, p, "confirm_band", 0, RB_DIM_RATIO, 0, 0, 1, 1, &k->confirm_band);
    v = rb_cv_get(c, cr, p, "concrete", 0, "");
    if (v && rb_cv_bool(c, v, "criteria.concrete", &i))
        c->judge_concrete = i;
    rb_cv_unknown_keys(c, cr, p, criteria_keys);
}

static void read_analysis(rb_cctx *c, rb_ynode *an, rb_case *cs)
{
    const char *p = "analysis";
    int i, b;
    double dt = 0.01;
    rb_ynode *v = rb_cv_get(c, an, p, "formulation", 0, "");
    if (v && rb_cv_enum_table(c, v, "analysis.formulation", rb_formulation_names, 0, &i))
        cs->solve.formulation = (rb_formulation)i;
    v = rb_cv_get(c, an, p, "integrator", 0, "");
    if (v && rb_cv_enum_table(c, v, "analysis.integrator", rb_integrator_names, 0, &i))
        cs->solve.integrator = (rb_integrator)i;
    rb_cv_number(c, an, p, "tolerance", 0, RB_DIM_RATIO, RB_CASE_MIN_TOLERANCE, 1,
                 0.01, 1, &cs->solve.rtol);
    /* above 1e-3 the shipped cases' usage moves by a tenth (at 1e-4
     * already); below 1e-12 the last confirming run (a hundredth of it)
     * would come within two decades of the rounding of an angle of the
     * size of theta0, and each decade finer only adds floor impacts
     * (docs/solver.md, "When rocking stops") */
    rb_cv_number(c, an, p, "rest_fraction", 0, RB_DIM_RATIO, RB_CASE_MIN_REST_FRACTION, 1,
                 RB_CASE_MAX_REST_FRACTION, 1, &cs->solve.rest_fraction);
    /* checked against the motions' run times in case_validate.c, whether or
     * not a history is recorded */
    c->history_dt_node = rb_cv_number(c, an, p, "output_interval", 0, RB_DIM_TIME,
                                      0, 0, (double)NAN, 0, &dt);
    /* the interval serves every history: the case's own (history: true)
     * and those --history, --svg and --html ask for; the pipeline drops it
     * when no history is wanted */
    if (c->history_dt_node)
        c->history_dt_s = cs->solve.history_dt_s = dt;
    v = rb_cv_get(c, an, p, "history", 0, "");
    if (v && rb_cv_bool(c, v, "analysis.history", &b))
        cs->write_history = b;
    v = rb_cv_get(c, an, p, "stretch_past_failure", 0, "");
    if (v && rb_cv_bool(c, v, "analysis.stretch_past_failure", &b))
        cs->solve.stretch_past_failure = b;
    rb_cv_unknown_keys(c, an, p, analysis_keys);
}

/* The case name defaults to the file name without directory and extension. */
static void default_name(rb_cctx *c, rb_case *cs)
{
    const char *base = strrchr(cs->path, '/');
    base = base ? base + 1 : cs->path;
    size_t len = strcspn(base, ".");
    char *p = malloc(len + 1);
    if (!p) {
        c->nomem = 1;
        return;
    }
    memcpy(p, base, len);
    p[len] = '\0';
    cs->name = p;
}

/* How many of the quantities under n are written in each unit system
 * (n_sys[RB_UNITS_SI], n_sys[RB_UNITS_US]); names and descriptions are
 * text, not quantities. */
static void count_units(const rb_ynode *n, size_t n_sys[3])
{
    if (n->kind == RB_YNODE_SCALAR) {
        if (n->text)
            n_sys[rb_unit_system_of_text(n->text)]++;
    } else if (n->kind == RB_YNODE_MAP) {
        for (size_t i = 0; i < n->n; i++)
            if (strcmp(n->entries[i].key, "name") != 0
                && strcmp(n->entries[i].key, "description") != 0)
                count_units(n->entries[i].value, n_sys);
    } else {
        for (size_t i = 0; i < n->n; i++)
            count_units(n->items[i], n_sys);
    }
}

/* Output units: as asked, else the system most quantities were written
 * in (SI on a tie, and for a case with no unit of either system). Read
 * before anything else, so that every message about a value of the case
 * speaks the case's units. */
static void read_output_units(rb_cctx *c, rb_ynode *root, rb_case *cs)
{
    size_t n_sys[3] = {0, 0, 0};
    count_units(root, n_sys);
    cs->output_units = n_sys[RB_UNITS_US] > n_sys[RB_UNITS_SI] ? RB_UNITS_US : RB_UNITS_SI;
    rb_ynode *v = rb_cv_get(c, root, "", "output_units", 0, "");
    if (v) {
        static const char *const systems[] = {"si", "us", NULL};
        int i;
        if (rb_cv_enum(c, v, "output_units", systems, &i))
            cs->output_units = i == 1 ? RB_UNITS_US : RB_UNITS_SI;
    }
    c->units = cs->output_units;
    cs->criteria.units = cs->output_units;
}

void rb_case_read_schema(rb_cctx *c, rb_ynode *root, rb_case *cs)
{
    read_output_units(c, root, cs);
    rb_ynode *v = rb_cv_get(c, root, "", "name", 0, "");
    if (!v || !rb_cv_string(c, v, "name", &cs->name))
        default_name(c, cs);
    v = rb_cv_get(c, root, "", "description", 0, "");
    if (v)
        rb_cv_string(c, v, "description", &cs->description);
    rb_ynode *eq = schema_section(c, root, "equipment", 1,
                              "the cabinet: mass, height, base_width, ...");
    if (eq)
        read_equipment(c, eq, &cs->model);
    else
        c->model_errors++;
    rb_ynode *an = schema_section(c, root, "anchorage", 1,
                              "the bolts, or 'model: none' for free-standing");
    if (an)
        read_anchorage(c, an, &cs->model);
    else
        c->model_errors++;
    rb_case_read_concrete(c, root, an, cs);
    if (an && cs->model.bolt_model != RB_BOLT_NONE)
        rb_cv_unknown_keys(c, an, "anchorage", anchorage_keys);
    if (an) {
        read_gap(c, root, &cs->model);
    } else {
        rb_cv_get(c, root, "", "gap", 0, "");   /* judged with the anchorage */
        rb_cv_get(c, root, "", "gap_ratio", 0, "");
    }
    if ((v = schema_section(c, root, "criteria", 0, "")))
        read_criteria(c, v, &cs->criteria);
    if ((v = schema_section(c, root, "analysis", 0, "")))
        read_analysis(c, v, cs);
    if ((v = schema_section(c, root, "design", 0, "")))
        rb_case_read_design(c, v, cs);
    if ((v = schema_section(c, root, "fragility", 0, "")))
        rb_case_read_fragility(c, v, cs);
    if ((v = schema_section(c, root, "project", 0, "")))
        rb_case_read_project(c, v, cs);
    rb_case_read_motions(c, root);
    rb_cv_unknown_keys(c, root, "", rb_case_top_keys);
}
