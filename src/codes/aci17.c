/* ACI 318-19 Chapter 17 strengths of cast-in headed anchors
 * (include/rockbolt/aci17.h; docs/code-check.md). Inputs and outputs in SI
 * (m, m^2, Pa, N). A dimensional formula is evaluated in the units of its
 * coefficient system: MPa, mm and N for RB_ACI17_SI; psi, in and lb for
 * RB_ACI17_INLB, converted exactly. */
#include <math.h>
#include "rockbolt/aci17.h"

const rb_enum_name rb_aci17_coef_names[] = {
    {"si", RB_ACI17_SI}, {"in-lb", RB_ACI17_INLB}, {NULL, 0}};

/* 17.6.1.2 and 17.7.1.2: futa <= 125 ksi in the in-lb edition, 860 MPa in
 * ACI 318M-19 (not the conversion of 125 ksi, 861.8 MPa). */
#define FUTA_CAP_INLB_PA (125000 * RB_ACI17_PSI_PA)
#define FUTA_CAP_SI_PA 860e6

/* Lengths, stresses and forces in the units of a coefficient system. */
static double len_u(rb_aci17_coef c, double m)
{
    return c == RB_ACI17_INLB ? m / RB_ACI17_IN_M : m * 1e3;
}

static double stress_u(rb_aci17_coef c, double pa)
{
    return c == RB_ACI17_INLB ? pa / RB_ACI17_PSI_PA : pa * 1e-6;
}

static double force_si(rb_aci17_coef c, double f)
{
    return c == RB_ACI17_INLB ? f * RB_ACI17_LBF_N : f;
}

double rb_aci17_futa_used(rb_aci17_coef coef, double futa_pa, double fya_pa)
{
    /* 17.6.1.2: futa shall not be taken greater than 1.9 fya or 125 ksi
     * (860 MPa). */
    double cap = coef == RB_ACI17_INLB ? FUTA_CAP_INLB_PA : FUTA_CAP_SI_PA;
    return fmin(futa_pa, fmin(1.9 * fya_pa, cap));
}

/* ---- Tension ---- */

double rb_aci17_nsa(rb_aci17_coef coef, double ase_n_m2, double futa_pa, double fya_pa)
{
    /* 17.6.1.2, Eq. (17.6.1.2): Nsa = Ase,N futa. */
    return ase_n_m2 * rb_aci17_futa_used(coef, futa_pa, fya_pa);
}

double rb_aci17_kc_cast_in(rb_aci17_coef coef)
{
    /* 17.6.2.2.1: kc = 24 for cast-in anchors (10 in SI). */
    return coef == RB_ACI17_INLB ? 24.0 : 10.0;
}

double rb_aci17_nb_basic(rb_aci17_coef coef, double kc, double lambda_a,
                         double fc_pa, double hef_m)
{
    /* 17.6.2.2.1, Eq. (17.6.2.2.1): Nb = kc lambda_a sqrt(f'c) hef^1.5. */
    double h = len_u(coef, hef_m);
    return force_si(coef, kc * lambda_a * sqrt(stress_u(coef, fc_pa)) * pow(h, 1.5));
}

double rb_aci17_hef_deep_m(rb_aci17_coef coef)
{
    /* 17.6.2.2.3: 11 in <= hef <= 25 in (280 mm <= hef <= 635 mm). */
    return coef == RB_ACI17_INLB ? 11.0 * RB_ACI17_IN_M : 0.280;
}

double rb_aci17_nb_cast_in(rb_aci17_coef coef, double lambda_a, double fc_pa,
                           double hef_m)
{
    if (hef_m < rb_aci17_hef_deep_m(coef))
        return rb_aci17_nb_basic(coef, rb_aci17_kc_cast_in(coef), lambda_a, fc_pa, hef_m);
    /* 17.6.2.2.3, Eq. (17.6.2.2.3): Nb = 16 lambda_a sqrt(f'c) hef^(5/3)
     * (3.9 in SI) for cast-in headed studs and bolts. */
    double k = coef == RB_ACI17_INLB ? 16.0 : 3.9;
    double h = len_u(coef, hef_m);
    return force_si(coef, k * lambda_a * sqrt(stress_u(coef, fc_pa)) * pow(h, 5.0 / 3.0));
}

double rb_aci17_hef_limited(double hef_m, const double edges_m[4], double s_max_m)
{
    /* 17.6.2.1.2: anchors near three or more edges, each closer than
     * 1.5 hef: hef is the larger of ca,max / 1.5 and s / 3. */
    int near = 0;
    double ca_max = 0;
    for (int i = 0; i < 4; i++) {
        if (edges_m[i] < 1.5 * hef_m) {
            near++;
            ca_max = fmax(ca_max, edges_m[i]);
        }
    }
    if (near < 3)
        return hef_m;
    /* ca,max is the largest of the influencing edge distances that are
     * less than or equal to 1.5 hef. */
    return fmin(hef_m, fmax(ca_max / 1.5, s_max_m / 3.0));
}

static double side(double c, double limit)
{
    return fmin(c, limit);
}

double rb_aci17_span(int n, double pitch_m, double r_m, double c_lo_m, double c_hi_m)
{
    return side(c_lo_m, r_m) + (n > 1 ? n - 1 : 0) * fmin(pitch_m, 2 * r_m)
           + side(c_hi_m, r_m);
}

double rb_aci17_anc(double hef_m, int nx, double sx_m, double cx1_m, double cx2_m,
                    int ny, double sy_m, double cy1_m, double cy2_m)
{
    /* 17.6.2.1, Fig. R17.6.2.1(b): the breakout prism extends 1.5 hef
     * beyond each anchor, cut by the edges. A point of the slab lies in
     * some anchor's square exactly when its x lies within 1.5 hef of some
     * column and its y of some row, so the union is a product. */
    double r = 1.5 * hef_m;
    return rb_aci17_span(nx, sx_m, r, cx1_m, cx2_m) * rb_aci17_span(ny, sy_m, r, cy1_m, cy2_m);
}

double rb_aci17_anco(double hef_m)
{
    /* 17.6.2.1.4, Eq. (17.6.2.1.4): A_Nco = 9 hef^2. */
    return 9.0 * hef_m * hef_m;
}

double rb_aci17_psi_ec_n(double e_n_m, double hef_m)
{
    /* 17.6.2.3.1, Eq. (17.6.2.3.1). */
    return fmin(1.0, 1.0 / (1.0 + fabs(e_n_m) / (1.5 * hef_m)));
}

double rb_aci17_psi_ed_n(double ca_min_m, double hef_m)
{
    /* 17.6.2.4.1, Eqs. (17.6.2.4.1a, b). */
    if (ca_min_m >= 1.5 * hef_m)
        return 1.0;
    return 0.7 + 0.3 * ca_min_m / (1.5 * hef_m);
}

double rb_aci17_psi_c_n(bool cracked)
{
    /* 17.6.2.5.1: cast-in anchors, uncracked 1.25; cracked 1.0. */
    return cracked ? 1.0 : 1.25;
}

double rb_aci17_ncbg(int n, double anc_m2, double anco_m2, double psi_ec,
                     double psi_ed, double psi_c, double psi_cp, double nb_n)
{
    /* 17.6.2.1.1: A_Nc <= n A_Nco; Eq. (17.6.2.1b). */
    double anc = fmin(anc_m2, (n > 0 ? n : 1) * anco_m2);
    return anc / anco_m2 * psi_ec * psi_ed * psi_c * psi_cp * nb_n;
}

double rb_aci17_np(double abrg_m2, double fc_pa)
{
    /* 17.6.3.2.2(a), Eq. (17.6.3.2.2a): Np = 8 Abrg f'c. */
    return 8.0 * abrg_m2 * fc_pa;
}

double rb_aci17_psi_c_p(bool cracked)
{
    /* 17.6.3.3.1: uncracked 1.4, cracked 1.0. */
    return cracked ? 1.0 : 1.4;
}

double rb_aci17_npn(double abrg_m2, double fc_pa, bool cracked)
{
    /* 17.6.3.1, Eq. (17.6.3.1): Npn = psi_c,P Np. */
    return rb_aci17_psi_c_p(cracked) * rb_aci17_np(abrg_m2, fc_pa);
}

bool rb_aci17_sideface_applies(double ca1_m, double hef_m)
{
    /* 17.6.4.1: hef > 2.5 ca1. */
    return hef_m > 2.5 * ca1_m;
}

double rb_aci17_nsb(rb_aci17_coef coef, double ca1_m, double ca2_m,
                    double abrg_m2, double lambda_a, double fc_pa)
{
    /* 17.6.4.1, Eq. (17.6.4.1): Nsb = 160 ca1 sqrt(Abrg) lambda_a sqrt(f'c)
     * (13 in SI). sqrt(Abrg) is a length. */
    double k = coef == RB_ACI17_INLB ? 160.0 : 13.0;
    double nsb = force_si(coef, k * len_u(coef, ca1_m) * len_u(coef, sqrt(abrg_m2)) * lambda_a
                                    * sqrt(stress_u(coef, fc_pa)));
    /* 17.6.4.1.1: corner, ca2 < 3 ca1: (1 + ca2/ca1) / 4, 1 <= ca2/ca1 <= 3. */
    if (ca2_m < 3.0 * ca1_m) {
        double r = fmax(1.0, ca2_m / ca1_m);
        nsb *= (1.0 + r) / 4.0;
    }
    return nsb;
}

double rb_aci17_nsbg(int n, double s_outer_m, double ca1_m, double nsb_n)
{
    /* 17.6.4.2, Eq. (17.6.4.2): anchor spacing < 6 ca1: Nsbg =
     * (1 + s / (6 ca1)) Nsb, s the distance between the outer anchors.
     * The condition is on the spacing of neighbouring anchors, not on s:
     * anchors 4 ca1 apart share one blowout however long the row. */
    if (n <= 1)
        return nsb_n;
    if (s_outer_m / (n - 1) < 6.0 * ca1_m)
        return (1.0 + s_outer_m / (6.0 * ca1_m)) * nsb_n;
    return n * nsb_n;
}

/* ---- Shear ---- */

double rb_aci17_vsa(rb_aci17_coef coef, double ase_v_m2, double futa_pa, double fya_pa,
                    bool headed_stud, bool grout_pad)
{
    /* 17.7.1.2: (a) headed studs Vsa = Ase,V futa, Eq. (17.7.1.2a);
     * (b) headed bolts Vsa = 0.6 Ase,V futa, Eq. (17.7.1.2b). */
    double v = (headed_stud ? 1.0 : 0.6) * ase_v_m2 * rb_aci17_futa_used(coef, futa_pa, fya_pa);
    /* 17.7.1.2.1: built-up grout pads: times 0.8. */
    return grout_pad ? 0.8 * v : v;
}

double rb_aci17_le(double hef_m, double da_m)
{
    /* 17.7.2.2.1: le = hef for anchors of constant stiffness, <= 8 da. */
    return fmin(hef_m, 8.0 * da_m);
}

double rb_aci17_vb_a(rb_aci17_coef coef, double le_m, double da_m,
                     double lambda_a, double fc_pa, double ca1_m)
{
    /* Eq. (17.7.2.2.1a): 7 (le/da)^0.2 sqrt(da) lambda_a sqrt(f'c) ca1^1.5
     * (0.6 in SI). */
    double k = coef == RB_ACI17_INLB ? 7.0 : 0.6;
    return force_si(coef, k * pow(le_m / da_m, 0.2) * sqrt(len_u(coef, da_m)) * lambda_a
                              * sqrt(stress_u(coef, fc_pa)) * pow(len_u(coef, ca1_m), 1.5));
}

double rb_aci17_vb_b(rb_aci17_coef coef, double lambda_a, double fc_pa, double ca1_m)
{
    /* Eq. (17.7.2.2.1b): 9 lambda_a sqrt(f'c) ca1^1.5 (3.7 in SI). */
    double k = coef == RB_ACI17_INLB ? 9.0 : 3.7;
    return force_si(coef, k * lambda_a * sqrt(stress_u(coef, fc_pa)) * pow(len_u(coef, ca1_m), 1.5));
}

double rb_aci17_vb(rb_aci17_coef coef, double le_m, double da_m,
                   double lambda_a, double fc_pa, double ca1_m)
{
    /* 17.7.2.2.1: the lesser of (a) and (b). */
    return fmin(rb_aci17_vb_a(coef, le_m, da_m, lambda_a, fc_pa, ca1_m),
                rb_aci17_vb_b(coef, lambda_a, fc_pa, ca1_m));
}

double rb_aci17_ca1_limited(double ca1_m, double ca2a_m, double ca2b_m,
                            double ha_m, double s_max_m)
{
    /* 17.7.2.1.2: both ca2 < 1.5 ca1 and ha < 1.5 ca1. */
    double r = 1.5 * ca1_m;
    if (!(ca2a_m < r && ca2b_m < r && ha_m < r))
        return ca1_m;
    double c = fmax(fmax(ca2a_m, ca2b_m) / 1.5, fmax(ha_m / 1.5, s_max_m / 3.0));
    return fmin(ca1_m, c);
}

double rb_aci17_avc(double ca1_m, int n, double s_m, double ca2a_m, double ca2b_m,
                    double ha_m)
{
    /* 17.7.2.1, Fig. R17.7.2.1b: 1.5 ca1 each side of each anchor, depth
     * 1.5 ca1, cut by the side edges and the member thickness. */
    double r = 1.5 * ca1_m;
    return rb_aci17_span(n, s_m, r, ca2a_m, ca2b_m) * fmin(r, ha_m);
}

double rb_aci17_avco(double ca1_m)
{
    /* 17.7.2.1.3, Eq. (17.7.2.1.3): A_Vco = 4.5 ca1^2. */
    return 4.5 * ca1_m * ca1_m;
}

double rb_aci17_psi_ec_v(double e_v_m, double ca1_m)
{
    /* 17.7.2.3.1, Eq. (17.7.2.3.1). */
    return fmin(1.0, 1.0 / (1.0 + fabs(e_v_m) / (1.5 * ca1_m)));
}

double rb_aci17_psi_ed_v(double ca2_m, double ca1_m)
{
    /* 17.7.2.4.1, Eqs. (17.7.2.4.1a, b). */
    if (ca2_m >= 1.5 * ca1_m)
        return 1.0;
    return 0.7 + 0.3 * ca2_m / (1.5 * ca1_m);
}

double rb_aci17_psi_c_v(rb_aci17_shear_crack c)
{
    /* 17.7.2.5.1 (Table 17.7.2.5.1). */
    switch (c) {
    case RB_ACI17_SHEAR_UNCRACKED: return 1.4;
    case RB_ACI17_SHEAR_CRACKED_PLAIN: return 1.0;
    case RB_ACI17_SHEAR_CRACKED_EDGE_BAR: return 1.2;
    case RB_ACI17_SHEAR_CRACKED_STIRRUPS: return 1.4;
    }
    return 1.0;
}

double rb_aci17_psi_h_v(double ca1_m, double ha_m)
{
    /* 17.7.2.6.1, Eq. (17.7.2.6.1): for ha < 1.5 ca1; not less than 1. */
    return fmax(1.0, sqrt(1.5 * ca1_m / ha_m));
}

double rb_aci17_vcbg(int n, double avc_m2, double avco_m2, double psi_ec,
                     double psi_ed, double psi_c, double psi_h, double vb_n)
{
    /* 17.7.2.1.1: A_Vc <= n A_Vco; Eq. (17.7.2.1b). */
    double avc = fmin(avc_m2, (n > 0 ? n : 1) * avco_m2);
    return avc / avco_m2 * psi_ec * psi_ed * psi_c * psi_h * vb_n;
}

double rb_aci17_kcp(rb_aci17_coef coef, double hef_m)
{
    /* 17.7.3.1: kcp = 1.0 for hef < 2.5 in (65 mm), 2.0 for hef >= 2.5 in. */
    double lim = coef == RB_ACI17_INLB ? 2.5 * RB_ACI17_IN_M : 0.065;
    return hef_m < lim ? 1.0 : 2.0;
}

double rb_aci17_vcpg(rb_aci17_coef coef, double hef_m, double ncpg_n)
{
    /* 17.7.3.1, Eq. (17.7.3.1b): Vcpg = kcp Ncpg; 17.7.3.1.1: for cast-in
     * anchors Ncpg = Ncbg. */
    return rb_aci17_kcp(coef, hef_m) * ncpg_n;
}

/* ---- phi, seismic factor, ductility ---- */

double rb_aci17_phi(rb_aci17_mode mode, bool ductile_steel, bool condition_a)
{
    switch (mode) {
    /* Table 17.5.3(a): ductile 0.75 / 0.65, brittle 0.65 / 0.60. */
    case RB_ACI17_STEEL_TENSION: return ductile_steel ? 0.75 : 0.65;
    case RB_ACI17_STEEL_SHEAR: return ductile_steel ? 0.65 : 0.60;
    /* Table 17.5.3(b): cast-in, supplementary reinforcement present
     * (Condition A) 0.75, not present (Condition B) 0.70. */
    case RB_ACI17_BREAKOUT_TENSION:
    case RB_ACI17_BREAKOUT_SHEAR: return condition_a ? 0.75 : 0.70;
    /* Table 17.5.3(c): cast-in pullout and pryout 0.70. */
    case RB_ACI17_PULLOUT:
    case RB_ACI17_PRYOUT: return 0.70;
    }
    return 0.70;
}

double rb_aci17_seismic_factor(rb_aci17_mode mode, bool seismic)
{
    /* 17.10.5.4(b)-(d): 0.75 phi Ncbg, 0.75 phi Npn, 0.75 phi Nsbg. */
    if (seismic && (mode == RB_ACI17_BREAKOUT_TENSION || mode == RB_ACI17_PULLOUT))
        return 0.75;
    return 1.0;
}

double rb_aci17_ductility_margin(double n_concrete_n, double n_steel_n)
{
    /* 17.10.5.3(a): concrete-governed strength > 1.2 x steel strength. */
    return n_concrete_n / (RB_ACI17_DUCTILE_OVERSTRENGTH * n_steel_n);
}

bool rb_aci17_stretch_ok(double stretch_m, double da_m)
{
    /* 17.10.5.3(a): stretch length of at least 8 da. */
    return stretch_m >= 8.0 * da_m;
}

bool rb_aci17_threaded_ratio_ok(double futa_pa, double fya_pa)
{
    /* "not less than 1.3": 130 ksi over 100 ksi, each converted to Pa,
     * is 1.3 to within the rounding of the conversions, not exactly */
    return futa_pa / fya_pa >= RB_ACI17_THREADED_FUTA_OVER_FYA * (1 - 1e-12);
}
