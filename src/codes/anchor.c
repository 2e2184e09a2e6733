/* The anchorage's design strengths in each mode of ACI 318-19 Chapter 17,
 * put together from the clause functions of aci17.c for the layout
 * rockbolt models (rockbolt/anchor.h). */
#include <math.h>
#include <stdio.h>
#include "rockbolt/anchor.h"
#include "rockbolt/names.h"

const rb_enum_name rb_anchor_type_names[] = {
    {"cast-in-headed", RB_ANCHOR_CAST_IN_HEADED}, {"expansion", RB_ANCHOR_EXPANSION},
    {"expansion-displacement", RB_ANCHOR_EXPANSION_DISPLACEMENT}, {"screw", RB_ANCHOR_SCREW},
    {"undercut", RB_ANCHOR_UNDERCUT}, {"adhesive", RB_ANCHOR_ADHESIVE}, {NULL, 0}};
const rb_enum_name rb_anchor_threads_names[] = {
    {"partial", RB_THREADS_PARTIAL}, {"full-length", RB_THREADS_FULL_LENGTH},
    {"upset", RB_THREADS_UPSET}, {NULL, 0}};
const rb_enum_name rb_anchor_mode_names[] = {
    {"steel-tension", RB_ANCHOR_STEEL_N}, {"breakout-tension", RB_ANCHOR_BREAKOUT_N},
    {"pullout", RB_ANCHOR_PULLOUT_N}, {"side-face-blowout", RB_ANCHOR_SIDEFACE_N},
    {"bond", RB_ANCHOR_BOND_N}, {"steel-shear", RB_ANCHOR_STEEL_V}, {"breakout-shear", RB_ANCHOR_BREAKOUT_V},
    {"pryout", RB_ANCHOR_PRYOUT_V}, {NULL, 0}};
const rb_enum_name rb_edge_reinforcement_names[] = {
    {"none", RB_EDGE_REINF_NONE}, {"bar", RB_EDGE_REINF_BAR},
    {"bar-and-stirrups", RB_EDGE_REINF_BAR_STIRRUPS}, {NULL, 0}};

/* The shallowest and deepest embedment checked. Chapter 17 gives no least
 * h_ef for cast-in anchors; 1.5 in (38 mm) is the least of the anchors
 * qualified under ACI 355.2, on which the breakout equations rest. 25 in
 * (635 mm) is the top of Eq. (17.6.2.2.3)'s range. */
#define HEF_MIN_M (1.5 * RB_ACI17_IN_M)
#define HEF_MAX_M (25 * RB_ACI17_IN_M)
/* 17.9.2(a): cast-in anchors that are not torqued (the bolts of a gapped
 * plate never are) need the cover of 20.5.1.3; its least, 3/4 in, for
 * slabs not exposed to weather or earth, to the anchor's surface. */
#define COVER_MIN_M (0.75 * RB_ACI17_IN_M)
/* 17.9.2, Table 17.9.2(a): least spacing of cast-in anchors not torqued */
#define SPACING_MIN_DA 4.0
/* the farthest edge or thickest slab the check takes: beyond, the slab is
 * as good as unbounded and a larger number only hides a typo */
#define DIMENSION_MAX_M 100.0
/* 17.10.5.3: overstrength of the tension the bolts can pass on */
#define ATTACHMENT_OVERSTRENGTH 1.2

static const char *const clauses[RB_ANCHOR_N_MODES] = {
    [RB_ANCHOR_STEEL_N] = "17.6.1", [RB_ANCHOR_BREAKOUT_N] = "17.6.2",
    [RB_ANCHOR_PULLOUT_N] = "17.6.3", [RB_ANCHOR_SIDEFACE_N] = "17.6.4",
    [RB_ANCHOR_BOND_N] = "17.6.5", [RB_ANCHOR_STEEL_V] = "17.7.1",
    [RB_ANCHOR_BREAKOUT_V] = "17.7.2", [RB_ANCHOR_PRYOUT_V] = "17.7.3",
};

/* The code's equation of each mode's nominal strength, as the
 * calculation package quotes it (in-lb and SI editions alike). */
static const char *const equations[RB_ANCHOR_N_MODES] = {
    [RB_ANCHOR_STEEL_N] = "N_sa = A_se,N f_uta (Eq. 17.6.1.2), n anchors of a row",
    [RB_ANCHOR_BREAKOUT_N] = "N_cbg = (A_Nc / A_Nco) psi_ec,N psi_ed,N psi_c,N psi_cp,N N_b "
                             "(Eq. 17.6.2.1b)",
    [RB_ANCHOR_PULLOUT_N] = "N_pn = psi_c,P N_p (Eq. 17.6.3.1), N_p = 8 A_brg f'c "
                            "(Eq. 17.6.3.2.2a) or the evaluation report's",
    [RB_ANCHOR_SIDEFACE_N] = "N_sb = k c_a1 sqrt(A_brg) lambda_a sqrt(f'c) (Eq. 17.6.4.1), "
                             "k = 160 in-lb, 13 SI",
    [RB_ANCHOR_BOND_N] = "N_ag = (A_Na / A_Nao) psi_ec,Na psi_ed,Na psi_cp,Na N_ba "
                         "(Eq. 17.6.5.1b)",
    [RB_ANCHOR_STEEL_V] = "V_sa = 0.6 A_se,V f_uta (Eq. 17.7.1.2b), all anchors; x 0.8 on a "
                          "grout pad (17.7.1.2.1)",
    [RB_ANCHOR_BREAKOUT_V] = "V_cbg = (A_Vc / A_Vco) psi_ec,V psi_ed,V psi_c,V psi_h,V V_b "
                             "(Eq. 17.7.2.1b)",
    [RB_ANCHOR_PRYOUT_V] = "V_cpg = k_cp N_cpg (Eq. 17.7.3.1b)",
};

const char *rb_anchor_equation(rb_anchor_mode mode)
{
    return (unsigned)mode < RB_ANCHOR_N_MODES ? equations[mode] : "?";
}

const char *rb_anchor_clause(rb_anchor_mode mode)
{
    return (unsigned)mode < RB_ANCHOR_N_MODES ? clauses[mode] : "?";
}

rb_anchor_mode rb_anchor_governing_mode(const rb_anchor_strength *s, double tension_n,
                                        double shear_n)
{
    return tension_n / s->phi_nn_concrete_n >= shear_n / s->phi_vn_concrete_n
           ? s->concrete_tension_mode : s->concrete_shear_mode;
}

bool rb_anchor_mode_in_tension(rb_anchor_mode mode)
{
    return mode <= RB_ANCHOR_BOND_N;
}

bool rb_anchor_mode_is_steel(rb_anchor_mode mode)
{
    return mode == RB_ANCHOR_STEEL_N || mode == RB_ANCHOR_STEEL_V;
}

void rb_anchor_inputs_init(rb_anchor_inputs *in)
{
    *in = (rb_anchor_inputs){0};
    in->cracked = true;
    in->lambda_a = 1.0;
    in->edge_m = INFINITY;
    in->seismic = true;
    in->type = RB_ANCHOR_CAST_IN_HEADED;
    in->coef = RB_ACI17_SI;
    in->edge_reinforcement = RB_EDGE_REINF_NONE;
    in->interaction = RB_ACI17_TRILINEAR;
    in->route = RB_ROUTE_AUTO;
    in->units = RB_UNITS_SI;
}

static rb_status bad(rb_diag *diag, const char *key, const char *msg)
{
    return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, key, "%s", msg);
}

/* A length of a message: in mm for SI, in inches for US customary. */
static rb_qtext len(const rb_anchor_inputs *in, double m)
{
    return rb_qty_str(in->units, RB_Q_SMALL_LENGTH, m, 4);
}

/* A bolt's diameter: in SI in mm and in, as bolts are sized in both */
static rb_qtext diameter(const rb_anchor_inputs *in, double m)
{
    rb_qtext t;
    if (in->units == RB_UNITS_US)
        return len(in, m);
    snprintf(t.s, sizeof t.s, "%.4g mm (%.4g in)", m * 1e3, m / RB_ACI17_IN_M);
    return t;
}

/* A length within [lo, hi]; in SI named in mm and in, as SI users may
 * write either */
static rb_status within(rb_diag *diag, const rb_anchor_inputs *in, const char *key,
                        double v, double lo, double hi, const char *why)
{
    if (v >= lo && v <= hi)
        return RB_OK;
    if (in->units == RB_UNITS_US)
        return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, key,
                           "must be from %s to %s%s%s; got %s", len(in, lo).s,
                           len(in, hi).s, why[0] ? ": " : "", why, len(in, v).s);
    return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, key,
                       "must be from %.4g mm (%.4g in) to %.4g mm (%.4g in)%s%s; got %.4g mm",
                       lo * 1e3, lo / RB_ACI17_IN_M, hi * 1e3, hi / RB_ACI17_IN_M,
                       why[0] ? ": " : "", why, v * 1e3);
}

bool rb_anchor_post_installed(rb_anchor_type type)
{
    return type != RB_ANCHOR_CAST_IN_HEADED;
}

static rb_aci17_post_type post_type(rb_anchor_type type)
{
    switch (type) {
    case RB_ANCHOR_EXPANSION_DISPLACEMENT: return RB_ACI17_POST_DISPLACEMENT_EXPANSION;
    case RB_ANCHOR_SCREW: return RB_ACI17_POST_SCREW;
    case RB_ANCHOR_UNDERCUT: return RB_ACI17_POST_UNDERCUT;
    case RB_ANCHOR_ADHESIVE: return RB_ACI17_POST_ADHESIVE;
    default: return RB_ACI17_POST_TORQUE_EXPANSION;
    }
}

/* A post-installed anchor's product values and the limits of 17.9 and
 * 17.3 (the report's own where it gives them, else the code's). */
static rb_status check_product(const rb_model *m, const rb_anchor_inputs *in, double da,
                               rb_diag *diag)
{
    const rb_anchor_product *p = &in->product;
    rb_aci17_post_type t = post_type(in->type);
    rb_status st;
    if (p->category < 1 || p->category > 3)
        return bad(diag, "anchorage.product.category",
                   "a post-installed anchor needs its category (1, 2 or 3, Table 17.5.3) "
                   "from its evaluation report");
    if (in->type == RB_ANCHOR_ADHESIVE
        && !(p->bond_cracked_pa > 0 && p->bond_uncracked_pa >= p->bond_cracked_pa))
        return bad(diag, "anchorage.product.bond_strength_cracked",
                   "an adhesive anchor needs bond_strength_cracked and "
                   "bond_strength_uncracked (tau_cr <= tau_uncr) from its report");
    if (in->type != RB_ANCHOR_ADHESIVE && p->pullout_governs
        && !((in->cracked ? p->pullout_cracked_n : p->pullout_uncracked_n) > 0))
        return bad(diag, in->cracked ? "anchorage.product.pullout_cracked"
                                     : "anchorage.product.pullout_uncracked",
                   "give the report's pullout strength, or 'does-not-govern' where the "
                   "report says so");
    if (!rb_aci17_post_hef_in_scope(t, in->hef_m, da))
        return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, "anchorage.embedment",
                           "outside 17.3.3/17.3.4 for this anchor type (adhesive 4 d_a to "
                           "20 d_a, screw 5 d_a to 10 d_a; d_a %s)", len(in, da).s);
    if (p->min_embedment_m > 0 && in->hef_m < p->min_embedment_m)
        return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, "anchorage.embedment",
                           "below the report's h_ef,min %s", len(in, p->min_embedment_m).s);
    if (!rb_aci17_post_hef_ok(in->coef, t, in->hef_m, in->thickness_m))
        return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, "anchorage.embedment",
                           "17.9.4: at most the greater of 2/3 h_a and h_a - 4 in (%s "
                           "here)", len(in, rb_aci17_post_hef_max(in->coef, in->thickness_m)).s);
    if (p->min_thickness_m > 0 && in->thickness_m < p->min_thickness_m)
        return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, "concrete.thickness",
                           "below the report's h_min %s", len(in, p->min_thickness_m).s);
    double s_min = p->min_spacing_m > 0 ? p->min_spacing_m
                                        : rb_aci17_post_s_min(t, da, in->hef_m);
    if (m->bolts_per_row > 1
        && (st = within(diag, in, "anchorage.spacing", in->spacing_m, s_min, DIMENSION_MAX_M,
                        "17.9.2, the report's s_min or Table 17.9.2(a)")) != RB_OK)
        return st;
    double c_min = rb_aci17_post_c_min(t, da, COVER_MIN_M, 0, p->min_edge_m);
    if (!isinf(in->edge_m)
        && (st = within(diag, in, "concrete.edge_distance", in->edge_m, c_min, DIMENSION_MAX_M,
                        "17.9.2, the report's c_min or Table 17.9.2(b)")) != RB_OK)
        return st;
    return RB_OK;
}

static rb_status check_inputs(const rb_model *m, const rb_anchor_inputs *in, rb_diag *diag)
{
    rb_status st;
    if (m->bolt_model == RB_BOLT_NONE || m->bolts_per_row < 1 || !(m->bolt_area_m2 > 0))
        return bad(diag, "anchorage", "the concrete check needs bolts");
    double da = sqrt(4 * m->bolt_area_m2 / M_PI);
    if (!(in->fc_pa > 0) || !isfinite(in->fc_pa))
        return bad(diag, "concrete.strength", "must be > 0");
    if (!(in->lambda_a > 0 && in->lambda_a <= 1))
        return bad(diag, "concrete.lightweight", "must be in (0, 1]");
    if ((st = within(diag, in, "concrete.thickness", in->thickness_m, 0, DIMENSION_MAX_M, ""))
        != RB_OK || !(in->thickness_m > 0))
        return st != RB_OK ? st : bad(diag, "concrete.thickness", "must be > 0");
    if (rb_anchor_post_installed(in->type) && (st = check_product(m, in, da, diag)) != RB_OK)
        return st;
    if (!isinf(in->edge_m)
        && (st = within(diag, in, "concrete.edge_distance", in->edge_m, COVER_MIN_M + da / 2,
                        DIMENSION_MAX_M, "17.9.2(a), the least cover of 20.5.1.3 (3/4 in) "
                        "plus half the anchor's diameter")) != RB_OK)
        return st;
    if ((st = within(diag, in, "anchorage.embedment", in->hef_m, HEF_MIN_M, HEF_MAX_M,
                     "the range of Chapter 17's breakout equations")) != RB_OK)
        return st;
    if (!(in->hef_m < in->thickness_m))
        return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, "anchorage.embedment",
                           "must be less than the slab's thickness (embedment "
                           "%s, slab %s)", rb_qty_str(in->units, RB_Q_SMALL_LENGTH, in->hef_m, 6).s,
                           rb_qty_str(in->units, RB_Q_SMALL_LENGTH, in->thickness_m, 6).s);
    if (m->bolts_per_row > 1 && !rb_anchor_post_installed(in->type)
        && (st = within(diag, in, "anchorage.spacing", in->spacing_m, SPACING_MIN_DA * da,
                        DIMENSION_MAX_M, "17.9.2, 4 d_a for cast-in anchors not torqued"))
           != RB_OK)
        return st;
    if (in->ase_m2 > m->bolt_area_m2)
        return bad(diag, "anchorage.tensile_area", "must not exceed the bolt's area");
    if (!(in->futa_pa >= m->yield_stress_pa) || !isfinite(in->futa_pa))
        return bad(diag, "anchorage.ultimate_stress", "must be at least the yield stress");
    return RB_OK;
}

double rb_anchor_ase(const rb_model *m, const rb_anchor_inputs *in, int *source,
                     rb_thread_std *std, double *pitch_m)
{
    double coarse = 0, da = sqrt(4 * m->bolt_area_m2 / M_PI);
    rb_thread_std ts = rb_thread_standard(da, &coarse);
    double pitch = in->thread_pitch_m > 0 ? in->thread_pitch_m : coarse;
    int src;
    double ase;
    if (in->ase_m2 > 0)
        src = RB_ASE_GIVEN, ase = in->ase_m2;
    else if (in->area_is_tensile)
        src = RB_ASE_BOLT_AREA, ase = m->bolt_area_m2;
    else
        src = RB_ASE_THREADS, ase = rb_thread_ase(ts, da, pitch);
    if (source)
        *source = src;
    if (std)
        *std = ts;
    if (pitch_m)
        *pitch_m = pitch;
    return ase > 0 ? ase : 0;
}

/* A_se and A_brg: given, or from the standards of the bolt's size
 * (docs/anchor-hardware.md). The gross area would overstate the steel by
 * 26-38 %, and one head for every size the pullout by up to 64 %: where no
 * standard names the size, the user is asked, not a value guessed. */
static rb_status hardware(const rb_model *m, const rb_anchor_inputs *in, rb_anchor_strength *o,
                          rb_diag *diag)
{
    o->ase_m2 = rb_anchor_ase(m, in, &o->ase_source, &o->thread_std,
                              &o->thread_pitch_used_m);
    if (o->ase_source == RB_ASE_THREADS) {
        if (!(o->ase_m2 > 0))
            return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, "anchorage.tensile_area",
                               "the bolt's diameter %s is no UNC or ISO "
                               "metric size%s, so its tensile stress area cannot be worked "
                               "out: give tensile_area (A_se)", diameter(in, o->da_m).s,
                               o->thread_std != RB_THREAD_UNKNOWN ? " with that pitch" : "");
    }
    o->head = in->head_given ? in->head
            : o->thread_std == RB_THREAD_ISO ? RB_HEAD_HEX : RB_HEAD_HEAVY_HEX;
    o->abrg_given = in->abrg_m2 > 0;
    o->abrg_m2 = o->abrg_given ? in->abrg_m2
                               : rb_head_abrg(o->head, o->thread_std, o->da_m, in->washer_d_m);
    if (!(o->abrg_m2 > 0) && o->head == RB_HEAD_WASHER)
        return bad(diag, "anchorage.washer_diameter",
                   "a washer head needs washer_diameter, wider than the bolt");
    if (!(o->abrg_m2 > 0))
        return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, "anchorage.head_bearing_area",
                           "no %s head is tabulated for a bolt of %s: give "
                           "head_bearing_area (A_brg) or a washer",
                           rb_enum_str(rb_anchor_head_names, (int)o->head),
                           diameter(in, o->da_m).s);
    return RB_OK;
}

/* The breakout in tension of a group of post-installed anchors whose
 * projected area is anc (17.6.2 with the report's k_c and psi_cp,N). */
static double post_breakout(const rb_anchor_inputs *in, int n, double anc)
{
    const rb_anchor_product *p = &in->product;
    rb_aci17_post_type t = post_type(in->type);
    bool uncr_kc = !in->cracked && p->kc_uncracked > 0;
    double kc = uncr_kc ? p->kc_uncracked
              : p->kc_cracked > 0 ? p->kc_cracked : rb_aci17_post_kc(in->coef);
    kc = rb_aci17_post_kc_limited(in->coef, kc);
    double hef = in->hef_m;
    double cac = p->critical_edge_m > 0 ? p->critical_edge_m : rb_aci17_post_cac_default(t, hef);
    double nb = rb_aci17_nb_basic(in->coef, kc, rb_aci17_post_lambda_a(t, false, in->lambda_a),
                                  in->fc_pa, hef);
    return rb_aci17_ncbg(n, anc, rb_aci17_anco(hef), 1.0, rb_aci17_psi_ed_n(in->edge_m, hef),
                         rb_aci17_post_psi_c_n(in->cracked, uncr_kc),
                         rb_aci17_post_psi_cp_n(!in->cracked && !in->condition_a, in->edge_m,
                                                cac, hef), nb);
}

/* The bond strength of a group of n adhesive anchors s apart in each of
 * rows rows sy apart (17.6.5), seismic tau where 17.10 applies. */
static double post_bond(const rb_anchor_inputs *in, double da, int n, int rows, double sy)
{
    const rb_anchor_product *p = &in->product;
    double tau = in->cracked ? p->bond_cracked_pa : p->bond_uncracked_pa;
    if (in->seismic && p->seismic_tension_factor > 0)
        tau = rb_aci17_post_seismic_tension(p->seismic_tension_factor, tau);
    double cna = rb_aci17_cna(in->coef, da, p->bond_uncracked_pa);
    double cac = p->critical_edge_m > 0 ? p->critical_edge_m
                                        : rb_aci17_post_cac_default(RB_ACI17_POST_ADHESIVE,
                                                                    in->hef_m);
    double ana = rb_aci17_ana(cna, n, in->spacing_m, INFINITY, INFINITY, rows, sy, in->edge_m,
                              INFINITY);
    double nba = rb_aci17_nba(rb_aci17_post_lambda_a(RB_ACI17_POST_ADHESIVE, true,
                                                     in->lambda_a), tau, da, in->hef_m);
    return rb_aci17_nag(n * rows, ana, rb_aci17_anao(cna), 1.0,
                        rb_aci17_psi_ed_na(in->edge_m, cna),
                        rb_aci17_psi_cp_na(!in->cracked && !in->condition_a, in->edge_m, cac,
                                           cna), nba);
}

/* Tension of a row of post-installed anchors: steel, breakout with the
 * report's k_c, pullout from the report's N_p, bond of adhesive ones; no
 * side-face blowout (17.6.4 is for headed anchors). */
static void post_tension(const rb_model *m, const rb_anchor_inputs *in, rb_anchor_strength *o)
{
    const rb_anchor_product *p = &in->product;
    int n = m->bolts_per_row;
    rb_anchor_mode_strength *br = &o->mode[RB_ANCHOR_BREAKOUT_N];
    double anc = rb_aci17_anc(in->hef_m, n, in->spacing_m, INFINITY, INFINITY, 1, 0,
                              in->edge_m, INFINITY);
    br->nominal_n = post_breakout(in, n, anc);
    br->phi = rb_aci17_post_phi_tension(p->category, in->condition_a);
    rb_anchor_mode_strength *po = &o->mode[RB_ANCHOR_PULLOUT_N];
    po->applies = in->type != RB_ANCHOR_ADHESIVE && p->pullout_governs;
    if (po->applies) {
        double np = in->cracked ? p->pullout_cracked_n : p->pullout_uncracked_n;
        double e = p->pullout_exponent > 0 ? p->pullout_exponent : 0.5;
        if (in->seismic && p->seismic_tension_factor > 0)
            np = rb_aci17_post_seismic_tension(p->seismic_tension_factor, np);
        po->nominal_n = n * rb_aci17_post_npn(in->coef, np, in->fc_pa, e);
    }
    po->phi = rb_aci17_post_phi_pullout(p->category);
    o->mode[RB_ANCHOR_SIDEFACE_N].applies = false;
    rb_anchor_mode_strength *bo = &o->mode[RB_ANCHOR_BOND_N];
    bo->applies = in->type == RB_ANCHOR_ADHESIVE;
    if (bo->applies)
        bo->nominal_n = post_bond(in, o->da_m, n, 1, 0);
    bo->phi = br->phi;
    /* 17.10.5.4: 0.75 on every concrete-governed tension strength */
    br->seismic = po->seismic = bo->seismic
        = rb_aci17_seismic_factor(RB_ACI17_BREAKOUT_TENSION, in->seismic);
}

/* Tension of the loaded row: n anchors in a line, the edge parallel to the
 * row at c_a1, the other sides free. */
static void tension(const rb_model *m, const rb_anchor_inputs *in, rb_anchor_strength *o)
{
    int n = m->bolts_per_row;
    double s = in->spacing_m, s_row = (n - 1) * s, hef = in->hef_m, ca1 = in->edge_m;
    double fya = m->yield_stress_pa;
    rb_anchor_mode_strength *st = &o->mode[RB_ANCHOR_STEEL_N];
    st->nominal_n = n * rb_aci17_nsa(in->coef, o->ase_m2, in->futa_pa, fya);
    st->phi = rb_aci17_phi(RB_ACI17_STEEL_TENSION, true, in->condition_a);
    if (rb_anchor_post_installed(in->type)) {
        post_tension(m, in, o);
        return;
    }

    rb_anchor_mode_strength *br = &o->mode[RB_ANCHOR_BREAKOUT_N];
    double edges[4] = {INFINITY, INFINITY, ca1, INFINITY};
    double hef_use = rb_aci17_hef_limited(hef, edges, s_row);
    double anc = rb_aci17_anc(hef_use, n, s, INFINITY, INFINITY, 1, 0, ca1, INFINITY);
    double nb = rb_aci17_nb_cast_in(in->coef, in->lambda_a, in->fc_pa, hef_use);
    br->nominal_n = rb_aci17_ncbg(n, anc, rb_aci17_anco(hef_use), 1.0,
                                  rb_aci17_psi_ed_n(ca1, hef_use),
                                  rb_aci17_psi_c_n(in->cracked), 1.0, nb);
    br->phi = rb_aci17_phi(RB_ACI17_BREAKOUT_TENSION, true, in->condition_a);

    rb_anchor_mode_strength *po = &o->mode[RB_ANCHOR_PULLOUT_N];
    po->nominal_n = n * rb_aci17_npn(o->abrg_m2, in->fc_pa, in->cracked);
    po->phi = rb_aci17_phi(RB_ACI17_PULLOUT, true, in->condition_a);

    rb_anchor_mode_strength *sb = &o->mode[RB_ANCHOR_SIDEFACE_N];
    sb->applies = isfinite(ca1) && rb_aci17_sideface_applies(ca1, hef);
    if (sb->applies) {
        double nsb = rb_aci17_nsb(in->coef, ca1, INFINITY, o->abrg_m2, in->lambda_a,
                                  in->fc_pa);
        sb->nominal_n = rb_aci17_nsbg(n, s_row, ca1, nsb);
    }
    sb->phi = rb_aci17_phi(RB_ACI17_BREAKOUT_TENSION, true, in->condition_a);
    o->mode[RB_ANCHOR_BOND_N].applies = false;
    br->seismic = rb_aci17_seismic_factor(RB_ACI17_BREAKOUT_TENSION, in->seismic);
    po->seismic = rb_aci17_seismic_factor(RB_ACI17_PULLOUT, in->seismic);
    sb->seismic = br->seismic;
}

static rb_aci17_shear_crack shear_crack(const rb_anchor_inputs *in)
{
    if (!in->cracked)
        return RB_ACI17_SHEAR_UNCRACKED;
    return in->edge_reinforcement == RB_EDGE_REINF_BAR_STIRRUPS ? RB_ACI17_SHEAR_CRACKED_STIRRUPS
         : in->edge_reinforcement == RB_EDGE_REINF_BAR ? RB_ACI17_SHEAR_CRACKED_EDGE_BAR
         : RB_ACI17_SHEAR_CRACKED_PLAIN;
}

/* Breakout of a row of n anchors at ca1 from the edge, sheared towards it
 * (no side edges, so neither 17.7.2.1.2 nor psi_ed,V reduces it). */
static double row_breakout(const rb_model *m, const rb_anchor_inputs *in, double da,
                           double ca1)
{
    int n = m->bolts_per_row;
    double ha = in->thickness_m;
    double avc = rb_aci17_avc(ca1, n, in->spacing_m, INFINITY, INFINITY, ha);
    double vb = rb_aci17_vb(in->coef, rb_aci17_le(in->hef_m, da), da, in->lambda_a,
                            in->fc_pa, ca1);
    return rb_aci17_vcbg(n, avc, rb_aci17_avco(ca1), 1.0, rb_aci17_psi_ed_v(INFINITY, ca1),
                         rb_aci17_psi_c_v(shear_crack(in)), rb_aci17_psi_h_v(ca1, ha), vb);
}

/* Shear of the anchorage, shared between the rows as in Fig. R17.7.2.1b,
 * and pryout of both rows together. */
static void shear(const rb_model *m, const rb_anchor_inputs *in, rb_anchor_strength *o)
{
    int n = m->bolts_per_row;
    double s = in->spacing_m, hef = in->hef_m, ca1 = in->edge_m;
    double rows_apart = fmax(0.0, 2 * (m->lever_arm_m - m->half_width_m));
    o->shear_case = !isfinite(ca1) ? 0 : rows_apart < ca1 ? 3 : 1;
    int sharing = o->shear_case == 3 ? n : 2 * n;
    rb_anchor_mode_strength *st = &o->mode[RB_ANCHOR_STEEL_V];
    double vsa = rb_aci17_vsa(in->coef, o->ase_m2, in->futa_pa, m->yield_stress_pa, false,
                              in->grout_pad);
    /* a post-installed anchor's steel in shear under earthquake loads is
     * the report's V_sa,eq, or alpha_V,seis V_sa */
    if (rb_anchor_post_installed(in->type) && in->seismic)
        vsa = rb_aci17_post_vsa_eq(in->product.seismic_shear_n,
                                   in->product.seismic_shear_factor > 0
                                       ? in->product.seismic_shear_factor : 1.0, vsa);
    st->nominal_n = sharing * vsa;
    st->phi = rb_aci17_phi(RB_ACI17_STEEL_SHEAR, true, in->condition_a);

    rb_anchor_mode_strength *br = &o->mode[RB_ANCHOR_BREAKOUT_V];
    br->phi = rb_aci17_phi(RB_ACI17_BREAKOUT_SHEAR, true, in->condition_a);
    br->applies = o->shear_case != 0;
    if (br->applies) {
        o->vcbg_front_n = row_breakout(m, in, o->da_m, ca1);
        if (o->shear_case == 3) {
            br->nominal_n = o->vcbg_front_n;
        } else {
            /* Case 1: half of V on the front row; Case 2: all of V on the
             * rear row at its own distance; the larger ratio governs */
            o->vcbg_rear_n = row_breakout(m, in, o->da_m, ca1 + rows_apart);
            br->nominal_n = fmin(2 * o->vcbg_front_n, o->vcbg_rear_n);
        }
    }

    /* pryout: the breakout in tension of both rows as one group */
    rb_anchor_mode_strength *pr = &o->mode[RB_ANCHOR_PRYOUT_V];
    double anc = rb_aci17_anc(hef, n, s, INFINITY, INFINITY, 2, rows_apart, ca1, INFINITY);
    double ncpg;
    if (rb_anchor_post_installed(in->type))
        ncpg = post_breakout(in, 2 * n, anc);
    else
        ncpg = rb_aci17_ncbg(2 * n, anc, rb_aci17_anco(hef), 1.0, rb_aci17_psi_ed_n(ca1, hef),
                             rb_aci17_psi_c_n(in->cracked), 1.0,
                             rb_aci17_nb_cast_in(in->coef, in->lambda_a, in->fc_pa, hef));
    /* 17.7.3.1.1: adhesive anchors pry out at the lesser of breakout and bond */
    if (in->type == RB_ANCHOR_ADHESIVE)
        ncpg = rb_aci17_post_ncp_adhesive(ncpg, post_bond(in, o->da_m, n, 2, rows_apart));
    pr->nominal_n = rb_aci17_vcpg(in->coef, hef, ncpg);
    pr->phi = rb_anchor_post_installed(in->type) ? rb_aci17_post_phi_pryout()
                                                 : rb_aci17_phi(RB_ACI17_PRYOUT, true,
                                                                in->condition_a);
    st->seismic = br->seismic = pr->seismic = 1.0;
}

/* The least design strength over the modes of one direction, of all
 * modes or of those concrete governs; INFINITY where none applies. */
static double least(const rb_anchor_strength *o, bool in_tension, bool concrete_only,
                    rb_anchor_mode *which)
{
    double v = INFINITY;
    for (int k = 0; k < RB_ANCHOR_N_MODES; k++) {
        const rb_anchor_mode_strength *s = &o->mode[k];
        if (!s->applies || rb_anchor_mode_in_tension((rb_anchor_mode)k) != in_tension
            || (concrete_only && rb_anchor_mode_is_steel((rb_anchor_mode)k)))
            continue;
        if (s->design_n < v) {
            v = s->design_n;
            *which = (rb_anchor_mode)k;
        }
    }
    return v;
}

static void ductility(const rb_model *m, const rb_anchor_inputs *in, rb_anchor_strength *out)
{
    double concrete_n = INFINITY;
    for (int k = 0; k < RB_ANCHOR_N_MODES; k++)
        if (out->mode[k].applies && rb_anchor_mode_in_tension((rb_anchor_mode)k)
            && !rb_anchor_mode_is_steel((rb_anchor_mode)k))
            concrete_n = fmin(concrete_n, out->mode[k].nominal_n);
    out->ductility_margin = rb_aci17_ductility_margin(concrete_n,
                                                      out->mode[RB_ANCHOR_STEEL_N].nominal_n);
    out->stretch_ok = rb_aci17_stretch_ok(m->deformable_length_m, out->da_m);
    out->futa_over_fya = in->futa_pa / m->yield_stress_pa;
    out->threads_ok = in->threads != RB_THREADS_PARTIAL
                      || rb_aci17_threaded_ratio_ok(in->futa_pa, m->yield_stress_pa);
    out->not_ductile = (out->ductility_margin >= 1 ? 0 : RB_NOT_DUCTILE_CONCRETE)
                       | (out->stretch_ok ? 0 : RB_NOT_DUCTILE_STRETCH)
                       | (out->threads_ok ? 0 : RB_NOT_DUCTILE_THREADS);
    out->ductile = out->not_ductile == 0;
    double row_yield = m->bolts_per_row * m->bolt_area_m2 * m->yield_stress_pa;
    out->attachment_margin = out->phi_nn_concrete_n / (ATTACHMENT_OVERSTRENGTH * row_yield);
}

rb_status rb_anchor_check(const rb_model *m, const rb_anchor_inputs *in,
                          rb_anchor_strength *out, rb_diag *diag)
{
    *out = (rb_anchor_strength){0};
    rb_status st = check_inputs(m, in, diag);
    if (st != RB_OK)
        return st;
    for (int k = 0; k < RB_ANCHOR_N_MODES; k++) {
        out->mode[k].applies = true;
        out->mode[k].seismic = 1.0;
    }
    out->da_m = sqrt(4 * m->bolt_area_m2 / M_PI);
    if ((st = hardware(m, in, out, diag)) != RB_OK)
        return st;
    tension(m, in, out);
    shear(m, in, out);
    for (int k = 0; k < RB_ANCHOR_N_MODES; k++) {
        rb_anchor_mode_strength *s = &out->mode[k];
        if (!s->applies)
            continue;
        s->design_n = s->phi * s->seismic * s->nominal_n;
        /* a strength that is no number would be skipped by every minimum
         * below and pass whatever it should have failed */
        if (!(isfinite(s->design_n) && s->design_n > 0))
            return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, "concrete",
                               "the %s strength (%s) is not a positive number (%s): "
                               "check the anchorage's dimensions",
                               rb_anchor_clause((rb_anchor_mode)k),
                               k == RB_ANCHOR_BOND_N ? "bond" : "ACI 318-19",
                               rb_qty_str(in->units, RB_Q_FORCE, s->design_n, 4).s);
    }
    out->phi_nn_n = least(out, true, false, &out->tension_mode);
    out->phi_vn_n = least(out, false, false, &out->shear_mode);
    out->phi_nn_concrete_n = least(out, true, true, &out->concrete_tension_mode);
    out->phi_vn_concrete_n = least(out, false, true, &out->concrete_shear_mode);
    ductility(m, in, out);
    return RB_OK;
}
