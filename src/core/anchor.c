/* The anchorage's design strengths in each mode of ACI 318-19 Chapter 17,
 * put together from the clause functions of aci17.c for the layout
 * rockbolt models (rockbolt/anchor.h). */
#include <math.h>
#include <stdio.h>
#include "rockbolt/anchor.h"

/* ASME B18.2.1 heavy hex head: width across flats 1.5 d + 1/8 in */
#define HEAVY_HEX_EXTRA_M (0.125 * RB_ACI17_IN_M)

static const char *const clauses[RB_ANCHOR_N_MODES] = {
    [RB_ANCHOR_STEEL_N] = "17.6.1", [RB_ANCHOR_BREAKOUT_N] = "17.6.2",
    [RB_ANCHOR_PULLOUT_N] = "17.6.3", [RB_ANCHOR_SIDEFACE_N] = "17.6.4",
    [RB_ANCHOR_STEEL_V] = "17.7.1", [RB_ANCHOR_BREAKOUT_V] = "17.7.2",
    [RB_ANCHOR_PRYOUT_V] = "17.7.3",
};

const char *rb_anchor_clause(rb_anchor_mode mode)
{
    return (unsigned)mode < RB_ANCHOR_N_MODES ? clauses[mode] : "?";
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
}

static rb_status bad(rb_diag *diag, const char *key, const char *msg)
{
    return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, key, "%s", msg);
}

static rb_status check_inputs(const rb_model *m, const rb_anchor_inputs *in, rb_diag *diag)
{
    if (m->bolt_model == RB_BOLT_NONE || m->bolts_per_row < 1 || !(m->bolt_area_m2 > 0))
        return bad(diag, "anchorage", "the concrete check needs bolts");
    if (!(in->fc_pa > 0) || !isfinite(in->fc_pa))
        return bad(diag, "concrete.strength", "must be > 0");
    if (!(in->lambda_a > 0 && in->lambda_a <= 1))
        return bad(diag, "concrete.lightweight", "must be in (0, 1]");
    if (!(in->thickness_m > 0) || !isfinite(in->thickness_m))
        return bad(diag, "concrete.thickness", "must be > 0");
    if (!(in->edge_m > 0))
        return bad(diag, "concrete.edge_distance", "must be > 0");
    if (!(in->hef_m > 0) || !(in->hef_m < in->thickness_m))
        return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, "anchorage.embedment",
                           "must be > 0 and less than the slab's thickness (embedment "
                           "%g mm, slab %g mm)", in->hef_m * 1e3, in->thickness_m * 1e3);
    if (m->bolts_per_row > 1 && !(in->spacing_m > 0))
        return bad(diag, "anchorage.spacing", "must be > 0 for two or more bolts a row");
    if (in->ase_m2 > m->bolt_area_m2)
        return bad(diag, "anchorage.tensile_area", "must not exceed the bolt's area");
    if (!(in->futa_pa >= m->yield_stress_pa) || !isfinite(in->futa_pa))
        return bad(diag, "anchorage.ultimate_stress", "must be at least the yield stress");
    return RB_OK;
}

/* Tension of the loaded row: n anchors in a line, the edge parallel to the
 * row at c_a1, the other sides free. */
static void tension(const rb_model *m, const rb_anchor_inputs *in, rb_anchor_strength *o)
{
    int n = m->bolts_per_row;
    double s_row = (n - 1) * in->spacing_m, hef = in->hef_m, ca1 = in->edge_m;
    double fya = m->yield_stress_pa;
    double ase = in->ase_m2 > 0 ? in->ase_m2 : m->bolt_area_m2;
    rb_anchor_mode_strength *st = &o->mode[RB_ANCHOR_STEEL_N];
    st->nominal_n = n * rb_aci17_nsa(ase, in->futa_pa, fya);
    st->phi = rb_aci17_phi(RB_ACI17_STEEL_TENSION, true, in->condition_a);

    rb_anchor_mode_strength *br = &o->mode[RB_ANCHOR_BREAKOUT_N];
    double edges[4] = {INFINITY, INFINITY, ca1, INFINITY};
    double hef_use = rb_aci17_hef_limited(hef, edges, in->spacing_m);
    double anc = rb_aci17_anc(hef_use, INFINITY, INFINITY, s_row, ca1, INFINITY, 0);
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
    br->seismic = rb_aci17_seismic_factor(RB_ACI17_BREAKOUT_TENSION, in->seismic);
    po->seismic = rb_aci17_seismic_factor(RB_ACI17_PULLOUT, in->seismic);
    sb->seismic = br->seismic;
}

/* Shear of the anchorage: steel of every anchor, breakout of the row nearer
 * the edge towards it, pryout of both rows together. */
static void shear(const rb_model *m, const rb_anchor_inputs *in, rb_anchor_strength *o)
{
    int n = m->bolts_per_row;
    double s_row = (n - 1) * in->spacing_m, hef = in->hef_m, ca1 = in->edge_m;
    double rows_apart = 2 * (m->lever_arm_m - m->half_width_m);
    rb_anchor_mode_strength *st = &o->mode[RB_ANCHOR_STEEL_V];
    double ase = in->ase_m2 > 0 ? in->ase_m2 : m->bolt_area_m2;
    st->nominal_n = 2 * n * rb_aci17_vsa(ase, in->futa_pa, m->yield_stress_pa, false,
                                         in->grout_pad);
    st->phi = rb_aci17_phi(RB_ACI17_STEEL_SHEAR, true, in->condition_a);

    rb_anchor_mode_strength *br = &o->mode[RB_ANCHOR_BREAKOUT_V];
    br->phi = rb_aci17_phi(RB_ACI17_BREAKOUT_SHEAR, true, in->condition_a);
    br->applies = isfinite(ca1);
    if (br->applies) {
        double c1 = rb_aci17_ca1_limited(ca1, INFINITY, INFINITY, in->thickness_m,
                                         in->spacing_m);
        double avc = rb_aci17_avc(c1, INFINITY, INFINITY, s_row, in->thickness_m);
        double vb = rb_aci17_vb(in->coef, rb_aci17_le(hef, o->da_m), o->da_m,
                                in->lambda_a, in->fc_pa, c1);
        br->nominal_n = rb_aci17_vcbg(n, avc, rb_aci17_avco(c1), 1.0,
                                      rb_aci17_psi_ed_v(INFINITY, c1),
                                      rb_aci17_psi_c_v(in->cracked
                                                       ? RB_ACI17_SHEAR_CRACKED_PLAIN
                                                       : RB_ACI17_SHEAR_UNCRACKED),
                                      rb_aci17_psi_h_v(c1, in->thickness_m), vb);
    }

    /* pryout: the breakout in tension of both rows as one group */
    rb_anchor_mode_strength *pr = &o->mode[RB_ANCHOR_PRYOUT_V];
    double anc = rb_aci17_anc(hef, INFINITY, INFINITY, s_row, ca1, INFINITY,
                              rows_apart > 0 ? rows_apart : 0);
    double ncpg = rb_aci17_ncbg(2 * n, anc, rb_aci17_anco(hef), 1.0,
                                rb_aci17_psi_ed_n(ca1, hef), rb_aci17_psi_c_n(in->cracked),
                                1.0, rb_aci17_nb_cast_in(in->coef, in->lambda_a, in->fc_pa,
                                                         hef));
    pr->nominal_n = rb_aci17_vcpg(in->coef, hef, ncpg);
    pr->phi = rb_aci17_phi(RB_ACI17_PRYOUT, true, in->condition_a);
    st->seismic = br->seismic = pr->seismic = 1.0;
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
    double f = 1.5 * out->da_m + HEAVY_HEX_EXTRA_M;
    out->abrg_m2 = in->abrg_m2 > 0 ? in->abrg_m2
                                   : sqrt(3.0) / 2 * f * f - m->bolt_area_m2;
    tension(m, in, out);
    shear(m, in, out);
    out->phi_nn_n = out->phi_vn_n = INFINITY;
    double concrete_n = INFINITY;
    for (int k = 0; k < RB_ANCHOR_N_MODES; k++) {
        rb_anchor_mode_strength *s = &out->mode[k];
        if (!s->applies)
            continue;
        s->design_n = s->phi * s->seismic * s->nominal_n;
        int in_tension = k <= RB_ANCHOR_SIDEFACE_N;
        double *least = in_tension ? &out->phi_nn_n : &out->phi_vn_n;
        if (s->design_n < *least) {
            *least = s->design_n;
            if (in_tension)
                out->tension_mode = (rb_anchor_mode)k;
            else
                out->shear_mode = (rb_anchor_mode)k;
        }
        if (in_tension && k != RB_ANCHOR_STEEL_N)
            concrete_n = fmin(concrete_n, s->nominal_n);
    }
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
    return RB_OK;
}
