/* ACI 318-19 Chapter 17: strengths of cast-in headed anchors (headed bolts
 * and headed studs) in concrete, one small pure function per clause. No
 * I/O, no allocation, no state.
 *
 * Units: every input and output is SI -- lengths in m, areas in m^2,
 * stresses (f'c, futa, fya) in Pa, forces in N. Ratios and factors are
 * dimensionless.
 *
 * The concrete formulas are dimensional. Each dimensional function takes a
 * coefficient system:
 *   RB_ACI17_SI    the coefficients of the SI edition (ACI 318M-19:
 *                  kc = 10, 3.9 for deep cast-in anchors, 13 for side-face
 *                  blowout, 0.6 and 3.7 for shear breakout; f'c in MPa and
 *                  lengths in mm inside the formula);
 *   RB_ACI17_INLB  the coefficients of the inch-pound edition (kc = 24, 16,
 *                  160, 7 and 9; f'c in psi, lengths in in, forces in lb),
 *                  applied to the SI inputs through exact unit conversions,
 *                  so that a US-customary design gives the in-lb code's
 *                  numbers to the last digit.
 * The SI coefficients are rounded conversions of the in-lb ones; the two
 * systems differ by up to about 3 % (docs/code-check.md lists each).
 *
 * Clause, equation and table numbers are those of ACI 318-19. What is not
 * implemented (post-installed anchors, bond, hooked bolts, anchor
 * reinforcement) is listed in docs/code-check.md. */
#ifndef ROCKBOLT_ACI17_H
#define ROCKBOLT_ACI17_H

#include <stdbool.h>
#include "rockbolt/interaction.h"
#include "rockbolt/names.h"

typedef enum {
    RB_ACI17_SI = 0,  /* ACI 318M-19 coefficients */
    RB_ACI17_INLB     /* ACI 318-19 (in-lb) coefficients, converted exactly */
} rb_aci17_coef;
extern const rb_enum_name rb_aci17_coef_names[];    /* rb_aci17_coef: si, in-lb */

/* Exact unit conversions (m per in, N per lbf, Pa per psi). */
#define RB_ACI17_IN_M 0.0254
#define RB_ACI17_LBF_N 4.4482216152605
#define RB_ACI17_PSI_PA 6894.757293168361

/* ---- Materials (17.6.1.2, 17.7.1.2) ---- */

/* futa used in the steel strengths: at most 1.9 fya and 125 ksi
 * (in-lb edition; 861.8 MPa) or 860 MPa (ACI 318M-19), 17.6.1.2 and
 * 17.7.1.2. */
double rb_aci17_futa_used(rb_aci17_coef coef, double futa_pa, double fya_pa);

/* ---- Tension ---- */

/* 17.6.1.2, Eq. (17.6.1.2): Nsa = Ase,N futa (futa limited as above), one
 * anchor. */
double rb_aci17_nsa(rb_aci17_coef coef, double ase_n_m2, double futa_pa, double fya_pa);

/* Table 17.6.2.2.1 / 17.6.2.2.1: kc for cast-in anchors, 24 (in-lb) or 10
 * (SI), in the units of coef. */
double rb_aci17_kc_cast_in(rb_aci17_coef coef);

/* 17.6.2.2.1, Eq. (17.6.2.2.1): basic breakout strength of one anchor in
 * cracked concrete, Nb = kc lambda_a sqrt(f'c) hef^1.5, with kc in the
 * units of coef (24 / 10 cast-in; a post-installed product's kc from its
 * evaluation report). */
double rb_aci17_nb_basic(rb_aci17_coef coef, double kc, double lambda_a,
                         double fc_pa, double hef_m);

/* 17.6.2.2.3: hef from which Eq. (17.6.2.2.3) applies to cast-in headed
 * studs and bolts: 11 in (in-lb) or 280 mm (SI). The clause covers hef up
 * to 25 in (635 mm); deeper anchors are outside it. */
double rb_aci17_hef_deep_m(rb_aci17_coef coef);

/* Nb of a cast-in headed stud or bolt: Eq. (17.6.2.2.1) with kc = 24 (10)
 * below rb_aci17_hef_deep_m, Eq. (17.6.2.2.3)
 * Nb = 16 lambda_a sqrt(f'c) hef^(5/3) (3.9 in SI) from it. */
double rb_aci17_nb_cast_in(rb_aci17_coef coef, double lambda_a, double fc_pa,
                           double hef_m);

/* 17.6.2.1.2: effective hef of anchors near three or more edges whose
 * distances are all below 1.5 hef: max(ca,max / 1.5, s_max / 3), not above
 * hef. edges[4] are the distances to the four sides (INFINITY: no edge);
 * s_max the largest spacing in the group. Returns hef when the clause does
 * not apply (fewer than three edges closer than 1.5 hef). */
double rb_aci17_hef_limited(double hef_m, const double edges_m[4], double s_max_m);

/* Length of the union of the intervals [x_i - r, x_i + r] of n points
 * pitch apart, cut c_lo before the first point and c_hi after the last
 * (INFINITY: no edge): min(c_lo, r) + (n - 1) min(pitch, 2 r) + min(c_hi, r).
 * The side of a projected area along one direction: where the points are
 * more than 2 r apart the concrete between their regions belongs to none. */
double rb_aci17_span(int n, double pitch_m, double r_m, double c_lo_m, double c_hi_m);

/* 17.6.2.1: projected failure area A_Nc of a grid of nx by ny anchors,
 * sx and sy apart (adjacent anchors), as the union of each anchor's square
 * of 1.5 hef each side cut by the edges (cx1, cx2 beyond the outer anchors
 * in x, cy1, cy2 in y; INFINITY: no edge). A grid's union is the product
 * of the spans of its two directions. Below 3 hef spacing it is the one
 * rectangle of Fig. R17.6.2.1(b); beyond, the concrete between the cones
 * is not counted. */
double rb_aci17_anc(double hef_m, int nx, double sx_m, double cx1_m, double cx2_m,
                    int ny, double sy_m, double cy1_m, double cy2_m);

/* 17.6.2.1.4, Eq. (17.6.2.1.4): A_Nco = 9 hef^2. */
double rb_aci17_anco(double hef_m);

/* 17.6.2.3.1, Eq. (17.6.2.3.1): psi_ec,N = 1 / (1 + e'N / (1.5 hef)) <= 1. */
double rb_aci17_psi_ec_n(double e_n_m, double hef_m);

/* 17.6.2.4.1, Eqs. (17.6.2.4.1a, b): psi_ed,N = 1 for ca,min >= 1.5 hef,
 * else 0.7 + 0.3 ca,min / (1.5 hef). */
double rb_aci17_psi_ed_n(double ca_min_m, double hef_m);

/* 17.6.2.5.1: psi_c,N = 1.25 for cast-in anchors in uncracked concrete,
 * 1.0 cracked. (17.6.2.6: psi_cp,N = 1.0 for cast-in anchors.) */
double rb_aci17_psi_c_n(bool cracked);

/* 17.6.2.1, Eq. (17.6.2.1b): Ncbg = (A_Nc / A_Nco) psi_ec,N psi_ed,N psi_c,N
 * psi_cp,N Nb, with A_Nc <= n A_Nco (17.6.2.1.1) for n anchors. n = 1 gives
 * Ncb, Eq. (17.6.2.1a). */
double rb_aci17_ncbg(int n, double anc_m2, double anco_m2, double psi_ec,
                     double psi_ed, double psi_c, double psi_cp, double nb_n);

/* 17.6.3.2.2(a), Eq. (17.6.3.2.2a): Np = 8 Abrg f'c (dimensionless
 * coefficient: the same in both systems). */
double rb_aci17_np(double abrg_m2, double fc_pa);

/* 17.6.3.3.1: psi_c,P = 1.4 uncracked, 1.0 cracked. */
double rb_aci17_psi_c_p(bool cracked);

/* 17.6.3.1, Eq. (17.6.3.1): Npn = psi_c,P Np, one anchor. */
double rb_aci17_npn(double abrg_m2, double fc_pa, bool cracked);

/* 17.6.4.1: side-face blowout applies to a headed anchor with
 * hef > 2.5 ca1 (ca1 < 0.4 hef). */
bool rb_aci17_sideface_applies(double ca1_m, double hef_m);

/* 17.6.4.1, Eq. (17.6.4.1): Nsb = 160 ca1 sqrt(Abrg) lambda_a sqrt(f'c)
 * (13 in SI), one anchor at edge distance ca1; multiplied by
 * (1 + ca2/ca1) / 4 when ca2 < 3 ca1, with 1 <= ca2/ca1 <= 3 (17.6.4.1.1).
 * ca2: distance to the perpendicular edge (INFINITY: none). */
double rb_aci17_nsb(rb_aci17_coef coef, double ca1_m, double ca2_m,
                    double abrg_m2, double lambda_a, double fc_pa);

/* 17.6.4.2, Eq. (17.6.4.2): n anchors evenly spaced along the edge, the
 * outer two s_outer apart. Anchor spacing s_outer / (n - 1) < 6 ca1:
 * Nsbg = (1 + s_outer / (6 ca1)) Nsb; from 6 ca1 each anchor alone,
 * Nsbg = n Nsb. nsb_n: Eq. (17.6.4.1) without the corner factor. */
double rb_aci17_nsbg(int n, double s_outer_m, double ca1_m, double nsb_n);

/* ---- Shear ---- */

/* 17.7.1.2, Eqs. (17.7.1.2a, b): Vsa = Ase,V futa for cast-in headed studs,
 * 0.6 Ase,V futa for cast-in headed bolts; times 0.8 on a grout pad
 * (17.7.1.2.1). futa limited as above. */
double rb_aci17_vsa(rb_aci17_coef coef, double ase_v_m2, double futa_pa, double fya_pa,
                    bool headed_stud, bool grout_pad);

/* 17.7.2.2.1: load-bearing length le = hef, at most 8 da. */
double rb_aci17_le(double hef_m, double da_m);

/* 17.7.2.2.1, Eqs. (17.7.2.2.1a, b): Vb, the lesser of
 * 7 (le/da)^0.2 sqrt(da) lambda_a sqrt(f'c) ca1^1.5 and
 * 9 lambda_a sqrt(f'c) ca1^1.5 (0.6 and 3.7 in SI). */
double rb_aci17_vb(rb_aci17_coef coef, double le_m, double da_m,
                   double lambda_a, double fc_pa, double ca1_m);
/* The two forms separately (a) and (b). */
double rb_aci17_vb_a(rb_aci17_coef coef, double le_m, double da_m,
                     double lambda_a, double fc_pa, double ca1_m);
double rb_aci17_vb_b(rb_aci17_coef coef, double lambda_a, double fc_pa,
                     double ca1_m);

/* 17.7.2.1.2: ca1 used for anchors with both side edges ca2 < 1.5 ca1 and
 * ha < 1.5 ca1: the largest of ca2,max / 1.5, ha / 1.5 and s_max / 3 (not
 * above ca1). Returns ca1 when the clause does not apply. */
double rb_aci17_ca1_limited(double ca1_m, double ca2a_m, double ca2b_m,
                            double ha_m, double s_max_m);

/* 17.7.2.1, Fig. R17.7.2.1b: projected area A_Vc of a row of n anchors s
 * apart, parallel to the edge at ca1: the union of 1.5 ca1 each side of
 * each anchor (rb_aci17_span), cut by the side edges ca2a and ca2b beyond
 * the outer anchors, times min(1.5 ca1, ha). */
double rb_aci17_avc(double ca1_m, int n, double s_m, double ca2a_m, double ca2b_m,
                    double ha_m);

/* 17.7.2.1.3, Eq. (17.7.2.1.3): A_Vco = 4.5 ca1^2. */
double rb_aci17_avco(double ca1_m);

/* 17.7.2.3.1, Eq. (17.7.2.3.1): psi_ec,V = 1 / (1 + e'V / (1.5 ca1)) <= 1. */
double rb_aci17_psi_ec_v(double e_v_m, double ca1_m);

/* 17.7.2.4.1, Eqs. (17.7.2.4.1a, b): psi_ed,V = 1 for ca2 >= 1.5 ca1, else
 * 0.7 + 0.3 ca2 / (1.5 ca1). ca2: the smaller side distance. */
double rb_aci17_psi_ed_v(double ca2_m, double ca1_m);

/* 17.7.2.5.1: psi_c,V. */
typedef enum {
    RB_ACI17_SHEAR_UNCRACKED = 0,     /* 1.4 */
    RB_ACI17_SHEAR_CRACKED_PLAIN,     /* no edge bar, or smaller than No. 4: 1.0 */
    RB_ACI17_SHEAR_CRACKED_EDGE_BAR,  /* No. 4 or larger between anchor and edge: 1.2 */
    RB_ACI17_SHEAR_CRACKED_STIRRUPS   /* edge bar and stirrups at <= 4 in: 1.4 */
} rb_aci17_shear_crack;
double rb_aci17_psi_c_v(rb_aci17_shear_crack c);

/* 17.7.2.6.1, Eq. (17.7.2.6.1): psi_h,V = sqrt(1.5 ca1 / ha), at least 1. */
double rb_aci17_psi_h_v(double ca1_m, double ha_m);

/* 17.7.2.1, Eq. (17.7.2.1b): Vcbg = (A_Vc / A_Vco) psi_ec,V psi_ed,V psi_c,V
 * psi_h,V Vb, with A_Vc <= n A_Vco (17.7.2.1.1). */
double rb_aci17_vcbg(int n, double avc_m2, double avco_m2, double psi_ec,
                     double psi_ed, double psi_c, double psi_h, double vb_n);

/* 17.7.3.1: kcp = 1 for hef < 2.5 in (65 mm in SI), 2 otherwise. */
double rb_aci17_kcp(rb_aci17_coef coef, double hef_m);

/* 17.7.3.1, Eq. (17.7.3.1b): Vcpg = kcp Ncpg; for cast-in anchors Ncpg is
 * the group's Ncbg. */
double rb_aci17_vcpg(rb_aci17_coef coef, double hef_m, double ncpg_n);

/* ---- Strength reduction factors, Table 17.5.3 ---- */

typedef enum {
    RB_ACI17_STEEL_TENSION = 0,
    RB_ACI17_STEEL_SHEAR,
    RB_ACI17_BREAKOUT_TENSION,   /* also side-face blowout */
    RB_ACI17_BREAKOUT_SHEAR,
    RB_ACI17_PULLOUT,
    RB_ACI17_PRYOUT
} rb_aci17_mode;

/* Table 17.5.3(a)-(c), cast-in anchors: steel 0.75 tension / 0.65 shear
 * (ductile), 0.65 / 0.60 (brittle); concrete breakout and side-face
 * blowout 0.75 with supplementary reinforcement (Condition A), 0.70
 * without (B), in tension and in shear; pullout and pryout 0.70. */
double rb_aci17_phi(rb_aci17_mode mode, bool ductile_steel, bool condition_a);

/* 17.10.5.4: in SDC C-F the design tensile strengths governed by concrete
 * (breakout, pullout, side-face blowout; bond) are multiplied by 0.75.
 * Returns 0.75 for those modes in tension and 1 otherwise. */
double rb_aci17_seismic_factor(rb_aci17_mode mode, bool seismic);

/* ---- Interaction, 17.8: rockbolt/interaction.h ---- */

/* ---- Seismic ductility, 17.10.5.3(a) ---- */

/* Overstrength on the steel in 17.10.5.3(a): the concrete-governed nominal
 * strengths are compared with 1.2 times the nominal steel strength. */
#define RB_ACI17_DUCTILE_OVERSTRENGTH 1.2

/* 17.10.5.3(a): margin of a concrete-governed nominal strength (breakout
 * of the row, pullout, side-face blowout; no phi, no 0.75) over 1.2 times
 * the nominal steel strength of the same anchors (n Nsa for a row whose
 * anchors share the tension equally). >= 1 meets the condition; the clause
 * asks the concrete strength to be greater. */
double rb_aci17_ductility_margin(double n_concrete_n, double n_steel_n);

/* 17.10.5.3(a): stretch length (the deformable length of the thesis) of at
 * least 8 da. */
bool rb_aci17_stretch_ok(double stretch_m, double da_m);

/* Least f_uta / f_ya of a ductile steel element with threads that do not
 * run its whole length and are not upset (17.10.5.3(a)): below it the
 * threads, whose area is the smaller, reach f_uta before the shank
 * yields, and the stretch length never stretches. */
#define RB_ACI17_THREADED_FUTA_OVER_FYA 1.3

/* 17.10.5.3(a): whether specified f_uta over f_ya lets an element with
 * threads along part of its length, not upset, yield over its stretch
 * length. Elements threaded over their whole length, or on upset ends,
 * need no such ratio; the caller asks only for the others. */
bool rb_aci17_threaded_ratio_ok(double futa_pa, double fya_pa);

#endif
