/* ACI 318-19 Chapter 17: the clauses that post-installed anchors add to
 * those of cast-in anchors (rockbolt/aci17.h) -- expansion, screw,
 * undercut and adhesive anchors qualified by ACI 355.2 (mechanical) or
 * ACI 355.4 (adhesive). One small pure function per clause; no I/O, no
 * allocation, no state.
 *
 * Units and coefficient systems as in aci17.h: every input and output is
 * SI (m, m^2, Pa, N); a dimensional formula takes an rb_aci17_coef and
 * evaluates the SI edition's coefficient (ACI 318M-19) or the in-lb
 * edition's, the latter through exact unit conversions.
 *
 * The product values (k_c,cr and k_c,uncr, N_p,cr and N_p,uncr, c_ac,
 * c_min, s_min, h_min, h_ef,min, alpha_N,seis, V_sa,eq or alpha_V,seis,
 * the anchor category, tau_cr and tau_uncr) come from the anchor's
 * evaluation report; these functions apply the code's equations to them.
 * docs/post-installed.md lists the clauses, the values each needs and
 * what is not implemented. Clause, equation and table numbers are those
 * of ACI 318-19. */
#ifndef ROCKBOLT_ACI17_POST_H
#define ROCKBOLT_ACI17_POST_H

#include <stdbool.h>
#include "rockbolt/aci17.h"

/* The post-installed anchor types that Tables 17.9.2(b) and 17.9.5 tell
 * apart (an expansion anchor is torque- or displacement-controlled). */
typedef enum {
    RB_ACI17_POST_TORQUE_EXPANSION = 0,
    RB_ACI17_POST_DISPLACEMENT_EXPANSION,
    RB_ACI17_POST_SCREW,
    RB_ACI17_POST_UNDERCUT,
    RB_ACI17_POST_ADHESIVE
} rb_aci17_post_type;

/* ---- Strength reduction factors, Table 17.5.3 ---- */

/* Table 17.5.3(b), tension governed by concrete breakout, bond or
 * side-face blowout, post-installed anchor of category 1, 2 or 3 (from
 * ACI 355.2 / 355.4, in the evaluation report): Condition A
 * (supplementary reinforcement) 0.75, 0.65, 0.55; Condition B 0.65, 0.55,
 * 0.45. NAN for a category other than 1 to 3. Shear breakout of a
 * post-installed anchor takes the cast-in values (0.75 / 0.70:
 * rb_aci17_phi(RB_ACI17_BREAKOUT_SHEAR, ...)). */
double rb_aci17_post_phi_tension(int category, bool condition_a);

/* Table 17.5.3(c), concrete pullout of a post-installed anchor: 0.65,
 * 0.55, 0.45 for categories 1, 2, 3, whether or not supplementary
 * reinforcement is present (the table has one column for pullout and
 * pryout); NAN for another category. Cast-in: 0.70 (rb_aci17_phi). */
double rb_aci17_post_phi_pullout(int category);

/* Table 17.5.3(c), concrete pryout: 0.70 for cast-in and post-installed
 * anchors alike, with or without supplementary reinforcement. */
double rb_aci17_post_phi_pryout(void);

/* ---- Lightweight concrete, Table 17.2.4.1 ---- */

/* lambda_a = 1.0 lambda for undercut (and cast-in) anchors failing in
 * concrete; 0.8 lambda for expansion, screw and adhesive anchors failing
 * in concrete; 0.6 lambda for adhesive anchors failing in bond
 * (Eq. (17.6.5.2.1)). lambda per 19.2.4; normalweight concrete
 * (lambda = 1) gives lambda_a = 1, the table being of lightweight
 * concrete.
 * bond_failure is read for adhesive anchors only. (17.2.4.1 lets tests
 * per ACI 355.2 / 355.4 give another value; the caller then uses it.) */
double rb_aci17_post_lambda_a(rb_aci17_post_type type, bool bond_failure,
                              double lambda);

/* ---- Concrete breakout in tension, 17.6.2 ---- */

/* 17.6.2.2.1: k_c = 17 (in-lb) or 7 (SI) for post-installed anchors
 * without a product value. */
double rb_aci17_post_kc(rb_aci17_coef coef);

/* 17.6.2.2.2: a product k_c from ACI 355.2 / 355.4 tests, not above 24
 * (in-lb) or 10 (SI). */
double rb_aci17_post_kc_limited(rb_aci17_coef coef, double kc_report);

/* 17.6.2.5.1 and 17.6.2.5.2: psi_c,N of a post-installed anchor.
 * Cracked concrete: 1.0. Uncracked: 1.4 where the k_c in Nb is 17 (7 SI)
 * or the report's cracked value k_c,cr; 1.0 where it is the report's
 * k_c,uncr (the report's uncracked value already holds the gain; reports
 * state psi_c,N = 1.0 with it). */
double rb_aci17_post_psi_c_n(bool cracked, bool kc_is_uncracked_value);

/* 17.6.2.6.1, Eqs. (17.6.2.6.1a, b): psi_cp,N of a post-installed anchor
 * designed for uncracked concrete without supplementary reinforcement to
 * control splitting: 1.0 for c_a,min >= c_ac, else
 * max(c_a,min, 1.5 h_ef) / c_ac, not above 1. 17.6.2.6.2: 1.0 in every
 * other case (cracked concrete, splitting reinforcement, cast-in):
 * uncracked_unreinforced false. */
double rb_aci17_post_psi_cp_n(bool uncracked_unreinforced, double ca_min_m,
                              double cac_m, double hef_m);

/* 17.9.5, Table 17.9.5: c_ac where the evaluation report gives none:
 * 4 h_ef torque-controlled, displacement-controlled and screw; 2.5 h_ef
 * undercut; 2 h_ef adhesive. */
double rb_aci17_post_cac_default(rb_aci17_post_type type, double hef_m);

/* ---- Pullout, 17.6.3 ---- */

/* The reference strength of the reports' pullout values: 2500 psi (in-lb,
 * 17.24 MPa exactly converted) or 17.2 MPa (SI reports). */
double rb_aci17_post_fc_ref_pa(rb_aci17_coef coef);

/* 17.6.3.1 and 17.6.3.2.1, Eq. (17.6.3.1) with psi_c,P = 1.0: N_pn of one
 * expansion, screw or undercut anchor from the report's N_p (N_p,cr in
 * cracked, N_p,uncr in uncracked concrete; the clause forbids calculating
 * it), adjusted to f'c as the report directs:
 * N_p (f'c / f'c,ref)^n, n as the report states (0.5 for most; some
 * reports give 0.3 or other exponents). */
double rb_aci17_post_npn(rb_aci17_coef coef, double np_report_n, double fc_pa,
                         double exponent);

/* ---- Bond of adhesive anchors, 17.6.5 ---- */

/* 17.6.5.1.2, Eq. (17.6.5.1.2b): c_Na = 10 d_a sqrt(tau_uncr / 1100)
 * (in-lb, tau in psi) or 10 d_a sqrt(tau_uncr / 7.6) (SI, MPa). */
double rb_aci17_cna(rb_aci17_coef coef, double da_m, double tau_uncr_pa);

/* 17.6.5.1.2, Eq. (17.6.5.1.2a): A_Nao = (2 c_Na)^2. */
double rb_aci17_anao(double cna_m);

/* 17.6.5.1.1: A_Na of a grid of nx by ny anchors sx and sy apart, the
 * union of each anchor's square c_Na each side cut by the edges, as
 * rb_aci17_anc with c_Na for 1.5 h_ef: below 2 c_Na spacing the one
 * rectangle c_Na beyond the outer anchors. */
double rb_aci17_ana(double cna_m, int nx, double sx_m, double cx1_m, double cx2_m,
                    int ny, double sy_m, double cy1_m, double cy2_m);

/* 17.6.5.2.1, Eq. (17.6.5.2.1): basic bond strength of one adhesive
 * anchor, N_ba = lambda_a tau pi d_a h_ef; tau = tau_cr (cracked) or
 * tau_uncr where analysis shows no cracking at service loads (17.6.5.2.4).
 * lambda_a: 0.6 lambda (rb_aci17_post_lambda_a). No dimensional
 * coefficient. */
double rb_aci17_nba(double lambda_a, double tau_pa, double da_m, double hef_m);

/* 17.6.5.3.1, Eq. (17.6.5.3.1): psi_ec,Na = 1 / (1 + e'_N / c_Na) <= 1. */
double rb_aci17_psi_ec_na(double e_n_m, double cna_m);

/* 17.6.5.4.1, Eqs. (17.6.5.4.1a, b): psi_ed,Na = 1 for c_a,min >= c_Na,
 * else 0.7 + 0.3 c_a,min / c_Na. */
double rb_aci17_psi_ed_na(double ca_min_m, double cna_m);

/* 17.6.5.5.1, Eqs. (17.6.5.5.1a, b): psi_cp,Na of an adhesive anchor
 * designed for uncracked concrete without supplementary reinforcement to
 * control splitting: 1.0 for c_a,min >= c_ac, else
 * max(c_a,min, c_Na) / c_ac, not above 1. 17.6.5.5.2: 1.0 otherwise
 * (uncracked_unreinforced false). */
double rb_aci17_psi_cp_na(bool uncracked_unreinforced, double ca_min_m,
                          double cac_m, double cna_m);

/* 17.6.5.1, Eq. (17.6.5.1b): N_ag = (A_Na / A_Nao) psi_ec,Na psi_ed,Na
 * psi_cp,Na N_ba with A_Na <= n A_Nao (17.6.5.1.1); n = 1 and
 * psi_ec,Na = 1 give N_a, Eq. (17.6.5.1a). The sustained-load check
 * (17.5.2.2) and the seismic 0.75 (17.10.5.4(e)) are the caller's. */
double rb_aci17_nag(int n, double ana_m2, double anao_m2, double psi_ec,
                    double psi_ed, double psi_cp, double nba_n);

/* ---- Pryout, 17.7.3 ---- */

/* 17.7.3.1.1: N_cp(g) of adhesive anchors is the lesser of the bond
 * strength N_a (N_ag) and the breakout strength N_cb (N_cbg); of
 * expansion, screw and undercut anchors it is N_cb (N_cbg) alone. Then
 * V_cp(g) = k_cp N_cp(g), rb_aci17_vcpg. */
double rb_aci17_post_ncp_adhesive(double ncbg_n, double nag_n);

/* ---- Seismic product values, 17.10.3 ---- */

/* Seismic pullout: alpha_N,seis N_p (the report's reduction for seismic
 * tension, 1 where it gives none); the result goes to
 * rb_aci17_post_npn. For adhesive anchors the report's alpha_N,seis
 * multiplies tau_cr in the same way. */
double rb_aci17_post_seismic_tension(double alpha_n_seis, double value);

/* Seismic steel shear: the report's V_sa,eq where it gives one
 * (vsa_eq_n > 0), else alpha_V,seis V_sa. */
double rb_aci17_post_vsa_eq(double vsa_eq_n, double alpha_v_seis,
                            double vsa_n);

/* ---- Spacing, edge distance and thickness, 17.9 ---- */

/* Table 17.9.2(a), minimum spacing: cast-in 4 d_a not torqued, 6 d_a
 * torqued. */
double rb_aci17_cast_in_s_min(bool torqued, double da_m);

/* Table 17.9.2(a), minimum spacing of a post-installed anchor without a
 * product value: 6 d_a; screw anchors the greater of 0.6 h_ef and 6 d_a.
 * (An evaluation report's s_min from ACI 355.2 / 355.4 tests replaces it,
 * 17.9.2.) */
double rb_aci17_post_s_min(rb_aci17_post_type type, double da_m, double hef_m);

/* Table 17.9.2(b): minimum edge distance absent product-specific test
 * information: 8 d_a torque-controlled, 10 d_a displacement-controlled,
 * 6 d_a screw, undercut and adhesive. */
double rb_aci17_post_c_min_default(rb_aci17_post_type type, double da_m);

/* Table 17.9.2(a), minimum edge distance of a post-installed anchor: the
 * greatest of the specified cover (20.5.1.3), twice the nominal maximum
 * aggregate size, and the report's c_min (c_min_report_m > 0) or, where
 * it gives none, Table 17.9.2(b). */
double rb_aci17_post_c_min(rb_aci17_post_type type, double da_m, double cover_m,
                           double agg_max_m, double c_min_report_m);

/* 17.9.4: h_ef of an expansion, screw or undercut anchor at most the
 * greater of 2/3 h_a and h_a - 4 in (h_a - 100 mm in SI), unless tension
 * tests per ACI 355.2 show otherwise. */
double rb_aci17_post_hef_max(rb_aci17_coef coef, double ha_m);

/* Whether h_ef meets 17.9.4 (true for adhesive anchors, which the clause
 * does not cover; their member thickness is the report's h_min). */
bool rb_aci17_post_hef_ok(rb_aci17_coef coef, rb_aci17_post_type type,
                          double hef_m, double ha_m);

/* 17.3.3 and 17.3.4: the embedments the bond and breakout models cover:
 * adhesive 4 d_a <= h_ef <= 20 d_a, screw 5 d_a <= h_ef <= 10 d_a (the
 * screw anchor's absolute least h_ef is not checked); true for the other
 * types. */
bool rb_aci17_post_hef_in_scope(rb_aci17_post_type type, double hef_m,
                                double da_m);

#endif
