/* concrete: and the anchorage's keys for the concrete check (ACI 318-19
 * Chapter 17): read with the rest of the case, then, once the model is
 * whole, the anchorage's strengths, which every run of the case tracks its
 * demand against (rb_solve_opts.anchor_phi_*) and the judge reads. */
#include <math.h>
#include <string.h>
#include "case_internal.h"
#include "rockbolt/design.h"
#include "rockbolt/names.h"

static const char *const concrete_keys[] = {
    "strength", "cracked", "lightweight", "thickness", "edge_distance", "reinforcement",
    "edge_reinforcement", "seismic", "seismic_route", "interaction", "coefficients", NULL};

static void flag(rb_cctx *c, rb_ynode *m, const char *path, const char *key, bool *out)
{
    char k[RB_CASE_KEY_MAX];
    int b;
    rb_ynode *v = rb_cv_get(c, m, path, key, 0, "");
    rb_case_keypath(k, path, key);
    if (v && rb_cv_bool(c, v, k, &b))
        *out = b != 0;
}

static void read_slab(rb_cctx *c, rb_ynode *cn, rb_anchor_inputs *in)
{
    static const char *const reinforcement[] = {"none", "present", NULL};
    const char *p = "concrete";
    int i;
    rb_cv_number(c, cn, p, "strength", 1, RB_DIM_STRESS, 6.9e6, 1, 138e6, 1, &in->fc_pa);
    flag(c, cn, p, "cracked", &in->cracked);
    rb_cv_number(c, cn, p, "lightweight", 0, RB_DIM_RATIO, 0, 0, 1, 1, &in->lambda_a);
    rb_cv_number(c, cn, p, "thickness", 1, RB_DIM_LENGTH, 0, 0, 100, 1, &in->thickness_m);
    rb_cv_number(c, cn, p, "edge_distance", 0, RB_DIM_LENGTH, 0, 0, (double)NAN, 0,
                 &in->edge_m);
    rb_ynode *v = rb_cv_get(c, cn, p, "reinforcement", 0, "");
    if (v && rb_cv_enum(c, v, "concrete.reinforcement", reinforcement, &i))
        in->condition_a = i == 1;
    v = rb_cv_get(c, cn, p, "edge_reinforcement", 0, "");
    if (v && rb_cv_enum_table(c, v, "concrete.edge_reinforcement", rb_edge_reinforcement_names,
                              0, &i))
        in->edge_reinforcement = (rb_edge_reinforcement)i;
    flag(c, cn, p, "seismic", &in->seismic);
    v = rb_cv_get(c, cn, p, "seismic_route", 0, "");
    if (v && rb_cv_enum_table(c, v, "concrete.seismic_route", rb_seismic_route_names, 0, &i)) {
        in->route = (rb_seismic_route)i;
        c->seismic_route_node = v;
    }
    v = rb_cv_get(c, cn, p, "interaction", 0, "");
    if (v && rb_cv_enum_table(c, v, "concrete.interaction", rb_interaction_names, 0, &i))
        in->interaction = (rb_aci17_interaction_rule)i;
    v = rb_cv_get(c, cn, p, "coefficients", 0, "");
    if (v && rb_cv_enum_table(c, v, "concrete.coefficients", rb_aci17_coef_names, 0, &i)) {
        in->coef = (rb_aci17_coef)i;
        c->anchor_coef_given = 1;
    }
    rb_cv_unknown_keys(c, cn, p, concrete_keys);
}

/* A thread other than the coarse one of the bolt's size: its pitch as a
 * length, or as threads per inch. */
static void read_pitch(rb_cctx *c, rb_ynode *an, rb_anchor_inputs *in)
{
    const char *p = "anchorage";
    rb_ynode *tpi_node = rb_cv_get(c, an, p, "threads_per_inch", 0, "");
    rb_cv_number(c, an, p, "thread_pitch", 0, RB_DIM_LENGTH, 0, 0, 0.01, 1, &in->thread_pitch_m);
    double tpi = 0;
    rb_cv_number(c, an, p, "threads_per_inch", 0, RB_DIM_RATIO, 1, 1, 100, 1, &tpi);
    if (tpi > 0 && in->thread_pitch_m > 0)
        rb_cctx_error(c, tpi_node, "anchorage.threads_per_inch",
                      "give thread_pitch or threads_per_inch, not both");
    else if (tpi > 0)
        in->thread_pitch_m = RB_ACI17_IN_M / tpi;
}

static const char *const product_keys[] = {
    "category", "kc_cracked", "kc_uncracked", "pullout_cracked", "pullout_uncracked",
    "pullout_exponent", "critical_edge_distance", "bond_strength_cracked",
    "bond_strength_uncracked", "seismic_tension_factor", "seismic_shear",
    "seismic_shear_factor", "min_edge_distance", "min_spacing", "min_thickness",
    "min_embedment", NULL};
const char *const *const rb_case_concrete_keys = concrete_keys;
const char *const *const rb_case_product_keys = product_keys;

/* A pullout strength from the report, or its "does not govern". */
static void read_pullout(rb_cctx *c, rb_ynode *pm, const char *key, rb_anchor_product *p,
                         double *out)
{
    rb_ynode *v = rb_cv_get(c, pm, "anchorage.product", key, 0, "");
    if (v && v->kind == RB_YNODE_SCALAR && v->text && strcmp(v->text, "does-not-govern") == 0) {
        p->pullout_governs = false;
        return;
    }
    rb_cv_number(c, pm, "anchorage.product", key, 0, RB_DIM_FORCE, 0, 0, 10e6, 1, out);
}

/* anchorage.product: a post-installed anchor's values from its evaluation
 * report (rb_anchor_product). */
static void read_product(rb_cctx *c, rb_ynode *an, rb_anchor_inputs *in)
{
    const char *p = "anchorage.product";
    rb_anchor_product *pr = &in->product;
    pr->pullout_governs = true;
    rb_ynode *pm = rb_cv_get(c, an, "anchorage", "product", 1,
                             "the anchor's values from its evaluation report (category, ...)");
    if (!pm || !rb_cv_map(c, pm, p))
        return;
    double cat = 0;
    rb_ynode *cv = rb_cv_get(c, pm, p, "category", 1, "1, 2 or 3 (Table 17.5.3)");
    if (cv && rb_cv_number(c, pm, p, "category", 0, RB_DIM_RATIO, 1, 1, 3, 1, &cat)) {
        if (cat != 1 && cat != 2 && cat != 3)
            rb_cctx_error(c, cv, "anchorage.product.category", "must be 1, 2 or 3");
        pr->category = (int)cat;
    }
    rb_cv_number(c, pm, p, "kc_cracked", 0, RB_DIM_RATIO, 0, 0, 100, 1, &pr->kc_cracked);
    rb_cv_number(c, pm, p, "kc_uncracked", 0, RB_DIM_RATIO, 0, 0, 100, 1, &pr->kc_uncracked);
    read_pullout(c, pm, "pullout_cracked", pr, &pr->pullout_cracked_n);
    read_pullout(c, pm, "pullout_uncracked", pr, &pr->pullout_uncracked_n);
    rb_cv_number(c, pm, p, "pullout_exponent", 0, RB_DIM_RATIO, 0, 0, 2, 1,
                 &pr->pullout_exponent);
    rb_cv_number(c, pm, p, "critical_edge_distance", 0, RB_DIM_LENGTH, 0, 0, 10, 1,
                 &pr->critical_edge_m);
    int adhesive = in->type == RB_ANCHOR_ADHESIVE;
    rb_cv_number(c, pm, p, "bond_strength_cracked", adhesive, RB_DIM_STRESS, 0, 0, 100e6, 1,
                 &pr->bond_cracked_pa);
    rb_cv_number(c, pm, p, "bond_strength_uncracked", adhesive, RB_DIM_STRESS, 0, 0, 100e6, 1,
                 &pr->bond_uncracked_pa);
    rb_cv_number(c, pm, p, "seismic_tension_factor", 0, RB_DIM_RATIO, 0, 0, 1, 1,
                 &pr->seismic_tension_factor);
    rb_cv_number(c, pm, p, "seismic_shear", 0, RB_DIM_FORCE, 0, 0, 10e6, 1,
                 &pr->seismic_shear_n);
    rb_cv_number(c, pm, p, "seismic_shear_factor", 0, RB_DIM_RATIO, 0, 0, 1, 1,
                 &pr->seismic_shear_factor);
    rb_cv_number(c, pm, p, "min_edge_distance", 0, RB_DIM_LENGTH, 0, 0, 10, 1, &pr->min_edge_m);
    rb_cv_number(c, pm, p, "min_spacing", 0, RB_DIM_LENGTH, 0, 0, 10, 1, &pr->min_spacing_m);
    rb_cv_number(c, pm, p, "min_thickness", 0, RB_DIM_LENGTH, 0, 0, 10, 1,
                 &pr->min_thickness_m);
    rb_cv_number(c, pm, p, "min_embedment", 0, RB_DIM_LENGTH, 0, 0, 10, 1,
                 &pr->min_embedment_m);
    rb_cv_unknown_keys(c, pm, p, product_keys);
}

/* The anchors' own keys: read whenever given, required with concrete:. */
static void read_anchors(rb_cctx *c, rb_ynode *an, int required, int per_row,
                         rb_anchor_inputs *in)
{
    const char *p = "anchorage";
    int i;
    rb_ynode *v = rb_cv_get(c, an, p, "type", 0, "");
    if (v && rb_cv_enum_table(c, v, "anchorage.type", rb_anchor_type_names, 0, &i))
        in->type = (rb_anchor_type)i;
    rb_cv_number(c, an, p, "embedment", required, RB_DIM_LENGTH, 0, 0, 10, 1, &in->hef_m);
    rb_cv_number(c, an, p, "spacing", required && per_row > 1, RB_DIM_LENGTH, 0, 0, 100, 1,
                 &in->spacing_m);
    rb_cv_number(c, an, p, "ultimate_stress", required, RB_DIM_STRESS, 0, 0, 10e9, 1,
                 &in->futa_pa);
    rb_cv_number(c, an, p, "head_bearing_area", 0, RB_DIM_AREA, 0, 0, 1, 1, &in->abrg_m2);
    rb_cv_number(c, an, p, "tensile_area", 0, RB_DIM_AREA, 0, 0, 1, 1, &in->ase_m2);
    v = rb_cv_get(c, an, p, "head", 0, "");
    if (v && rb_cv_enum_table(c, v, "anchorage.head", rb_anchor_head_names, 0, &i)) {
        in->head = (rb_anchor_head)i;
        in->head_given = true;
    }
    rb_cv_number(c, an, p, "washer_diameter", in->head_given && in->head == RB_HEAD_WASHER,
                 RB_DIM_LENGTH, 0, 0, 1, 1, &in->washer_d_m);
    read_pitch(c, an, in);
    in->area_is_tensile = c->bolt_by_area != 0;
    if (rb_anchor_post_installed(in->type))
        read_product(c, an, in);
    else if ((v = rb_cv_get(c, an, p, "product", 0, "")) != NULL)
        rb_cctx_error(c, v, "anchorage.product", "product values are for post-installed "
                      "anchors (type: expansion, expansion-displacement, screw, undercut or "
                      "adhesive); this anchor is cast-in");
    flag(c, an, p, "grout_pad", &in->grout_pad);
    v = rb_cv_get(c, an, p, "threads", 0, "");
    if (v && rb_cv_enum_table(c, v, "anchorage.threads", rb_anchor_threads_names, 0, &i))
        in->threads = (rb_anchor_threads)i;
}

void rb_case_read_concrete(rb_cctx *c, rb_ynode *root, rb_ynode *an, rb_case *cs)
{
    rb_anchor_inputs_init(&cs->anchor_in);
    cs->anchor_in.units = c->units;
    rb_ynode *cn = rb_cv_get(c, root, "", "concrete", 0, "");
    if (cn && rb_cv_map(c, cn, "concrete")) {
        cs->has_concrete = 1;
        c->concrete_node = cn;
        read_slab(c, cn, &cs->anchor_in);
    }
    c->anchorage_node = an;
    if (an && cs->model.bolt_model != RB_BOLT_NONE)
        read_anchors(c, an, cs->has_concrete, cs->model.bolts_per_row, &cs->anchor_in);
    else if (cs->has_concrete)
        rb_cctx_error(c, cn, "concrete", "the concrete check needs bolts: the anchorage "
                      "is free-standing (model: none)");
}

/* The node a key of the check names ("anchorage.embedment"), else the
 * concrete: section. */
static const rb_ynode *node_of(rb_cctx *c, const char *key)
{
    rb_ynode *map = strncmp(key, "anchorage.", 10) == 0 ? c->anchorage_node
                  : strncmp(key, "concrete.", 9) == 0 ? c->concrete_node : NULL;
    const char *k = strchr(key, '.');
    rb_yentry *e = map && k ? rb_ymap_find(map, k + 1) : NULL;
    return e ? e->value : c->concrete_node;
}

/* The code-static demand on the anchorage (design.code): the row tension
 * T and the anchor design force as shear, both with Omega_0p where the
 * anchorage is in concrete, against the design strengths of every mode,
 * steel included. Route (d) of 17.10.5.3 and `design` read it. */
static void static_check(rb_cctx *c, rb_case *cs)
{
    rb_code_result k;
    rb_diag d;
    rb_diag_clear(&d);
    cs->has_anchor_static = 0;
    if (rb_code_static(&cs->model, &cs->code, &k, &d) != RB_OK)
        return;   /* the design's own run reports the code inputs' error */
    cs->has_anchor_static = 1;
    cs->anchor_static_utilization = rb_aci17_interaction_by(
        cs->anchor_in.interaction, k.tension_n, cs->anchor.phi_nn_n, k.fp_anchor_n,
        cs->anchor.phi_vn_n, &cs->anchor_static_clause);
    cs->criteria.anchor_static_utilization = cs->anchor_static_utilization;
    (void)c;
}

void rb_case_resolve_concrete(rb_cctx *c, rb_case *cs)
{
    rb_diag d;
    /* an input already refused would only be refused again here */
    if (!cs->has_concrete || cs->model.bolt_model == RB_BOLT_NONE
        || c->diags->n > c->first_diag)
        return;
    /* the edition of the units the case is written in, unless it says */
    if (!c->anchor_coef_given)
        cs->anchor_in.coef = cs->output_units == RB_UNITS_US ? RB_ACI17_INLB : RB_ACI17_SI;
    rb_diag_clear(&d);
    if (rb_anchor_check(&cs->model, &cs->anchor_in, &cs->anchor, &d) != RB_OK) {
        rb_cctx_error(c, node_of(c, d.key), d.key, "%s", d.msg);
        return;
    }
    /* a run's demand is judged on the strengths concrete governs: the
     * bolts' steel is judged by the run's own criterion */
    cs->solve.anchor_phi_nn_n = cs->anchor.phi_nn_concrete_n;
    cs->solve.anchor_phi_vn_n = cs->anchor.phi_vn_concrete_n;
    cs->solve.anchor_interaction = (int)cs->anchor_in.interaction;
    rb_criteria *cr = &cs->criteria;
    cr->concrete = c->judge_concrete != 0;
    cr->anchor_seismic = cs->anchor_in.seismic;
    cr->anchor_route = (int)cs->anchor_in.route;
    cr->anchor_not_ductile = cs->anchor.not_ductile;
    cr->anchor_attachment_margin = cs->anchor.attachment_margin;
    cr->anchor_static_utilization = (double)NAN;
    if (cs->has_code)
        static_check(c, cs);
    else if (cs->anchor_in.route == RB_ROUTE_OMEGA && cs->anchor_in.seismic)
        rb_cctx_error(c, c->seismic_route_node, "concrete.seismic_route",
                      "'omega' (17.10.5.3(d)) is the static check with Omega_0: it needs "
                      "design.code (sds, z_over_h, ...) to give the static demand");
}
