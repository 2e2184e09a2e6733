/* ACI 318-19 Chapter 17, the clauses of post-installed anchors
 * (include/rockbolt/aci17_post.h; docs/post-installed.md). Inputs and
 * outputs in SI (m, m^2, Pa, N); a dimensional constant is taken in the
 * units of its coefficient system and converted exactly, as in aci17.c. */
#include <math.h>
#include "rockbolt/aci17_post.h"

static bool category_ok(int category)
{
    return category >= 1 && category <= 3;
}

/* ---- phi ---- */

double rb_aci17_post_phi_tension(int category, bool condition_a)
{
    /* Table 17.5.3(b): a step of 0.10 per category, Condition B 0.10
     * below Condition A. */
    static const double a[3] = {0.75, 0.65, 0.55}, b[3] = {0.65, 0.55, 0.45};
    if (!category_ok(category))
        return NAN;
    return condition_a ? a[category - 1] : b[category - 1];
}

double rb_aci17_post_phi_pullout(int category)
{
    /* Table 17.5.3(c): pullout is not helped by supplementary
     * reinforcement, so the table gives one value per category. */
    static const double p[3] = {0.65, 0.55, 0.45};
    if (!category_ok(category))
        return NAN;
    return p[category - 1];
}

double rb_aci17_post_phi_pryout(void)
{
    /* Table 17.5.3(c): pryout 0.70, installation and reinforcement
     * notwithstanding. */
    return 0.70;
}

/* ---- lambda_a ---- */

double rb_aci17_post_lambda_a(rb_aci17_post_type type, bool bond_failure,
                              double lambda)
{
    /* Table 17.2.4.1: an undercut anchor bears on the concrete like a
     * headed one (1.0); expansion, screw and adhesive anchors load it
     * through friction, threads or bond (0.8); bond in lightweight
     * concrete is weaker still (0.6). The table is of lightweight
     * concrete: normalweight concrete (lambda = 1, 19.2.4) takes
     * lambda_a = 1 whatever the anchor. */
    if (lambda >= 1.0)
        return 1.0;
    switch (type) {
    case RB_ACI17_POST_UNDERCUT:
        return lambda;
    case RB_ACI17_POST_ADHESIVE:
        return (bond_failure ? 0.6 : 0.8) * lambda;
    case RB_ACI17_POST_TORQUE_EXPANSION:
    case RB_ACI17_POST_DISPLACEMENT_EXPANSION:
    case RB_ACI17_POST_SCREW:
        return 0.8 * lambda;
    }
    return 0.8 * lambda;
}

/* ---- breakout ---- */

double rb_aci17_post_kc(rb_aci17_coef coef)
{
    /* 17.6.2.2.1: k_c = 17 for post-installed anchors (7 in SI). */
    return coef == RB_ACI17_INLB ? 17.0 : 7.0;
}

double rb_aci17_post_kc_limited(rb_aci17_coef coef, double kc_report)
{
    /* 17.6.2.2.2: product tests may raise k_c, but not above 24 (10 SI),
     * the cast-in value. */
    return fmin(kc_report, rb_aci17_kc_cast_in(coef));
}

double rb_aci17_post_psi_c_n(bool cracked, bool kc_is_uncracked_value)
{
    /* 17.6.2.5.2: cracked, 1.0. 17.6.2.5.1(b): uncracked with k_c = 17,
     * 1.4 (24/17 = 1.41, the uncracked gain of the cast-in k_c); with the
     * report's uncracked k_c the gain is in k_c already. */
    if (cracked || kc_is_uncracked_value)
        return 1.0;
    return 1.4;
}

double rb_aci17_post_psi_cp_n(bool uncracked_unreinforced, double ca_min_m,
                              double cac_m, double hef_m)
{
    /* 17.6.2.6.2: splitting is a concern only in uncracked concrete
     * without reinforcement against it. */
    if (!uncracked_unreinforced || ca_min_m >= cac_m)
        return 1.0;
    /* Eq. (17.6.2.6.1b): not less than 1.5 h_ef / c_ac, the edge distance
     * at which psi_ed,N already takes the breakout's loss; a report's c_ac
     * below 1.5 h_ef would lift that floor above 1, which the factor
     * never is. */
    return fmin(1.0, fmax(ca_min_m, 1.5 * hef_m) / cac_m);
}

double rb_aci17_post_cac_default(rb_aci17_post_type type, double hef_m)
{
    /* Table 17.9.5. */
    switch (type) {
    case RB_ACI17_POST_ADHESIVE: return 2.0 * hef_m;
    case RB_ACI17_POST_UNDERCUT: return 2.5 * hef_m;
    case RB_ACI17_POST_TORQUE_EXPANSION:
    case RB_ACI17_POST_DISPLACEMENT_EXPANSION:
    case RB_ACI17_POST_SCREW: return 4.0 * hef_m;
    }
    return 4.0 * hef_m;
}

/* ---- pullout ---- */

double rb_aci17_post_fc_ref_pa(rb_aci17_coef coef)
{
    /* Reports tabulate N_p in 2500 psi concrete; their SI columns round
     * it to 17.2 MPa. */
    return coef == RB_ACI17_INLB ? 2500.0 * RB_ACI17_PSI_PA : 17.2e6;
}

double rb_aci17_post_npn(rb_aci17_coef coef, double np_report_n, double fc_pa,
                         double exponent)
{
    /* 17.6.3.2.1: N_p of expansion, screw and undercut anchors is the
     * 5 % fractile of ACI 355.2 tests, never calculated; Eq. (17.6.3.1)
     * with psi_c,P = 1.0, the report giving N_p,cr and N_p,uncr apart. */
    return np_report_n * pow(fc_pa / rb_aci17_post_fc_ref_pa(coef), exponent);
}

/* ---- bond ---- */

double rb_aci17_cna(rb_aci17_coef coef, double da_m, double tau_uncr_pa)
{
    /* Eq. (17.6.5.1.2b): the constant carries the unit of stress, 1100 psi
     * or 7.6 MPa (1100 psi is 7.584 MPa). */
    double tau0 = coef == RB_ACI17_INLB ? 1100.0 * RB_ACI17_PSI_PA : 7.6e6;
    return 10.0 * da_m * sqrt(tau_uncr_pa / tau0);
}

double rb_aci17_anao(double cna_m)
{
    /* Eq. (17.6.5.1.2a). */
    return 4.0 * cna_m * cna_m;
}

double rb_aci17_ana(double cna_m, int nx, double sx_m, double cx1_m, double cx2_m,
                    int ny, double sy_m, double cy1_m, double cy2_m)
{
    /* 17.6.5.1.1: c_Na beyond each anchor, cut by the edges; anchors
     * more than 2 c_Na apart share no area */
    return rb_aci17_span(nx, sx_m, cna_m, cx1_m, cx2_m)
           * rb_aci17_span(ny, sy_m, cna_m, cy1_m, cy2_m);
}

double rb_aci17_nba(double lambda_a, double tau_pa, double da_m, double hef_m)
{
    /* Eq. (17.6.5.2.1): the bond stress over the anchor's embedded
     * perimeter. */
    return lambda_a * tau_pa * M_PI * da_m * hef_m;
}

double rb_aci17_psi_ec_na(double e_n_m, double cna_m)
{
    /* Eq. (17.6.5.3.1). */
    return fmin(1.0, 1.0 / (1.0 + fabs(e_n_m) / cna_m));
}

double rb_aci17_psi_ed_na(double ca_min_m, double cna_m)
{
    /* Eqs. (17.6.5.4.1a, b). */
    if (ca_min_m >= cna_m)
        return 1.0;
    return 0.7 + 0.3 * ca_min_m / cna_m;
}

double rb_aci17_psi_cp_na(bool uncracked_unreinforced, double ca_min_m,
                          double cac_m, double cna_m)
{
    /* 17.6.5.5.2: 1.0 but in uncracked concrete without splitting
     * reinforcement. */
    if (!uncracked_unreinforced || ca_min_m >= cac_m)
        return 1.0;
    /* Eq. (17.6.5.5.1b): not less than c_Na / c_ac, the distance at
     * which psi_ed,Na takes over; capped at 1 as in breakout. */
    return fmin(1.0, fmax(ca_min_m, cna_m) / cac_m);
}

double rb_aci17_nag(int n, double ana_m2, double anao_m2, double psi_ec,
                    double psi_ed, double psi_cp, double nba_n)
{
    /* 17.6.5.1.1: A_Na <= n A_Nao; Eq. (17.6.5.1b). */
    double ana = fmin(ana_m2, (n > 0 ? n : 1) * anao_m2);
    return ana / anao_m2 * psi_ec * psi_ed * psi_cp * nba_n;
}

/* ---- pryout ---- */

double rb_aci17_post_ncp_adhesive(double ncbg_n, double nag_n)
{
    /* 17.7.3.1.1: the pryout wedge of an adhesive anchor can also pull
     * the anchor out of its bond. */
    return fmin(ncbg_n, nag_n);
}

/* ---- seismic ---- */

double rb_aci17_post_seismic_tension(double alpha_n_seis, double value)
{
    /* 17.10.3: the values of post-installed anchors under seismic load
     * are those of the simulated seismic tests of ACI 355.2 / 355.4,
     * which reports state as a factor on the static value. */
    return alpha_n_seis * value;
}

double rb_aci17_post_vsa_eq(double vsa_eq_n, double alpha_v_seis, double vsa_n)
{
    /* 17.10.3: likewise V_sa, given outright or as a factor. */
    return vsa_eq_n > 0 ? vsa_eq_n : alpha_v_seis * vsa_n;
}

/* ---- 17.9 ---- */

double rb_aci17_cast_in_s_min(bool torqued, double da_m)
{
    /* Table 17.9.2(a). */
    return (torqued ? 6.0 : 4.0) * da_m;
}

double rb_aci17_post_s_min(rb_aci17_post_type type, double da_m, double hef_m)
{
    /* Table 17.9.2(a): a screw anchor's threads split over its whole
     * embedment, hence the 0.6 h_ef. */
    if (type == RB_ACI17_POST_SCREW)
        return fmax(0.6 * hef_m, 6.0 * da_m);
    return 6.0 * da_m;
}

double rb_aci17_post_c_min_default(rb_aci17_post_type type, double da_m)
{
    /* Table 17.9.2(b): the more an anchor expands as it is set, the
     * farther from the edge it must be. */
    switch (type) {
    case RB_ACI17_POST_TORQUE_EXPANSION: return 8.0 * da_m;
    case RB_ACI17_POST_DISPLACEMENT_EXPANSION: return 10.0 * da_m;
    case RB_ACI17_POST_SCREW:
    case RB_ACI17_POST_UNDERCUT:
    case RB_ACI17_POST_ADHESIVE: return 6.0 * da_m;
    }
    return 10.0 * da_m;
}

double rb_aci17_post_c_min(rb_aci17_post_type type, double da_m, double cover_m,
                           double agg_max_m, double c_min_report_m)
{
    /* Table 17.9.2(a), post-installed: greatest of (a) cover, (b) twice
     * the aggregate, (c) the product's value or Table 17.9.2(b). */
    double c = c_min_report_m > 0 ? c_min_report_m : rb_aci17_post_c_min_default(type, da_m);
    return fmax(fmax(cover_m, 2.0 * agg_max_m), c);
}

double rb_aci17_post_hef_max(rb_aci17_coef coef, double ha_m)
{
    /* 17.9.4: keeps the anchor's cone from blowing through the back of a
     * thin member; 4 in, or 100 mm in SI. */
    double d = coef == RB_ACI17_INLB ? 4.0 * RB_ACI17_IN_M : 0.100;
    return fmax(2.0 / 3.0 * ha_m, ha_m - d);
}

bool rb_aci17_post_hef_ok(rb_aci17_coef coef, rb_aci17_post_type type,
                          double hef_m, double ha_m)
{
    if (type == RB_ACI17_POST_ADHESIVE)
        return true;
    return hef_m <= rb_aci17_post_hef_max(coef, ha_m);
}

bool rb_aci17_post_hef_in_scope(rb_aci17_post_type type, double hef_m,
                                double da_m)
{
    /* 17.3.3 (adhesive) and 17.3.4 (screw): the range the models were
     * calibrated over. */
    if (type == RB_ACI17_POST_ADHESIVE)
        return hef_m >= 4.0 * da_m && hef_m <= 20.0 * da_m;
    if (type == RB_ACI17_POST_SCREW)
        return hef_m >= 5.0 * da_m && hef_m <= 10.0 * da_m;
    return true;
}
