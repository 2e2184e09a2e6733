/* The concrete side of the anchorage (ACI 318-19 Chapter 17): the design
 * strengths of the cabinet's anchors in each mode, from the model's bolts
 * and the slab. No I/O.
 *
 * Layout (docs/code-check.md, "The anchorage"): two rows of n anchors at
 * spacing s, the rows 2 (l - b) apart (each row l - b from the plate's
 * centre), one slab edge parallel to the rows at c_a1 from the nearer row,
 * the slab h_a thick. Tension: the loaded row, as a group of n (the other
 * row is slack whenever one is loaded), taken as the row nearer the edge.
 * Shear: the whole horizontal floor reaction, no friction counted (ASCE 7
 * 13.4), shared as in Fig. R17.7.2.1b: where the rows are closer together
 * than c_a1 (Case 3) the row nearer the edge takes all of it, steel and
 * breakout alike; otherwise steel is shared by all 2n anchors and breakout
 * is the worse of the front row with half of it at c_a1 (Case 1) and the
 * rear row with all of it at c_a1 + 2 (l - b) (Case 2). Pryout: both rows.
 * Projected areas are unions of the anchors' own regions
 * (rb_aci17_anc, rb_aci17_avc). Units SI throughout (rockbolt/aci17.h). */
#ifndef ROCKBOLT_ANCHOR_H
#define ROCKBOLT_ANCHOR_H

#include <stdbool.h>
#include "rockbolt/aci17.h"
#include "rockbolt/aci17_post.h"
#include "rockbolt/anchor_hardware.h"
#include "rockbolt/criteria.h"
#include "rockbolt/model.h"
#include "rockbolt/units.h"
#include "rockbolt/status.h"
#include "rockbolt/names.h"

typedef enum {
    RB_ANCHOR_CAST_IN_HEADED = 0,  /* headed bolts or studs, or rods with a nut */
    RB_ANCHOR_EXPANSION,           /* torque-controlled expansion (ACI 355.2) */
    RB_ANCHOR_EXPANSION_DISPLACEMENT, /* displacement-controlled (drop-in) */
    RB_ANCHOR_SCREW,
    RB_ANCHOR_UNDERCUT,
    RB_ANCHOR_ADHESIVE             /* bonded (ACI 355.4) */
} rb_anchor_type;
extern const rb_enum_name rb_anchor_type_names[];   /* rb_anchor_type */

/* A post-installed anchor's values from its evaluation report (ICC-ES
 * ESR under ACI 355.2 / 355.4), in SI. A value of 0 takes the code's
 * default where Chapter 17 has one (k_c 17 / 7, c_ac of Table 17.9.5,
 * the minimums of 17.9, alpha 1); the category, and for adhesive anchors
 * both bond stresses, have none and are required. */
typedef struct {
    int category;                  /* Table 17.5.3: 1, 2 or 3 */
    double kc_cracked, kc_uncracked; /* k_c,cr; k_c,uncr (0: k_c,cr with 1.4) */
    /* N_p,cr and N_p,uncr of one anchor at the report's reference f'c;
     * the report's "does not govern": pullout_governs false */
    bool pullout_governs;
    double pullout_cracked_n, pullout_uncracked_n;
    double pullout_exponent;       /* n of (f'c / f'c,ref)^n; 0: 0.5 */
    double critical_edge_m;        /* c_ac */
    double bond_cracked_pa, bond_uncracked_pa; /* tau_cr, tau_uncr */
    double seismic_tension_factor; /* alpha_N,seis on pullout and bond */
    double seismic_shear_n;        /* V_sa,eq of one anchor; 0: alpha_V,seis V_sa */
    double seismic_shear_factor;   /* alpha_V,seis */
    double min_edge_m, min_spacing_m, min_thickness_m, min_embedment_m;
} rb_anchor_product;

/* Whether an anchor type is post-installed, and its type in aci17_post.h */
bool rb_anchor_post_installed(rb_anchor_type type);

/* The conditions of 17.10.5.3(a) (RB_NOT_DUCTILE_*) and its routes
 * (rb_seismic_route, rb_route_applied) are the judge's: rockbolt/criteria.h. */

/* Reinforcement between the anchors and the edge (17.7.2.5.1, psi_c,V in
 * cracked concrete): none (1.0), a No. 4 bar or larger (1.2), and that bar
 * enclosed by stirrups at 4 in or less (1.4). */
typedef enum {
    RB_EDGE_REINF_NONE = 0,
    RB_EDGE_REINF_BAR,
    RB_EDGE_REINF_BAR_STIRRUPS
} rb_edge_reinforcement;
extern const rb_enum_name rb_edge_reinforcement_names[]; /* rb_edge_reinforcement */

/* How the anchor's threads run (17.10.5.3(a)): along part of its length
 * with the threads cut or rolled into the shank (a headed bolt or a rod
 * threaded at its top: the ratio f_uta / f_ya must be at least 1.3), over
 * its whole length, or on upset ends (no ratio needed; the upset ends are
 * not part of the stretch length). */
typedef enum {
    RB_THREADS_PARTIAL = 0,
    RB_THREADS_FULL_LENGTH,
    RB_THREADS_UPSET
} rb_anchor_threads;
extern const rb_enum_name rb_anchor_threads_names[]; /* rb_anchor_threads */

typedef struct {
    /* the slab */
    double fc_pa;          /* f'c */
    bool cracked;          /* default true */
    double lambda_a;       /* lightweight-concrete factor, default 1 */
    double thickness_m;    /* h_a */
    double edge_m;         /* c_a1 from the nearer row to the slab edge;
                              INFINITY: no edge near */
    bool condition_a;      /* supplementary reinforcement (17.5.3, condition A) */
    bool seismic;          /* SDC C-F: 17.10 applies; default true */
    /* the anchors (diameter, area, fya and number per row: the model's) */
    rb_anchor_type type;
    double hef_m;          /* effective embedment */
    double spacing_m;      /* between the anchors of a row */
    double futa_pa;        /* specified tensile strength */
    rb_anchor_threads threads; /* default partial */
    double abrg_m2;        /* bearing area of the head; <= 0: from head */
    double ase_m2;         /* effective (tensile stress) area A_se of one
                              anchor, for the steel strengths; <= 0: from
                              the thread standard of the bolt's diameter
                              (rockbolt/anchor_hardware.h), or the bolt's
                              area where the case gave it as an area */
    bool head_given;       /* head names the head; else a heavy hex nut for
                              inch sizes (ASTM F1554 rods take A563 heavy
                              hex nuts), an ISO 4032 nut for metric ones */
    rb_anchor_head head;
    double washer_d_m;     /* outside diameter of a washer head */
    double thread_pitch_m; /* > 0: a fine or other pitch; else coarse */
    bool area_is_tensile;  /* the bolt was given by its (tensile) area */
    rb_anchor_product product; /* post-installed anchors only */
    bool grout_pad;        /* shear through a grout pad (17.7.1.2.1) */
    rb_aci17_coef coef;    /* coefficients of the SI or the in-lb edition */
    rb_edge_reinforcement edge_reinforcement; /* psi_c,V (17.7.2.5.1) */
    rb_aci17_interaction_rule interaction;    /* 17.8 or R17.8 */
    rb_seismic_route route;                   /* 17.10.5.3 */
    /* the units the check's messages print lengths in (the case's output
     * units); default RB_UNITS_SI, which names millimetres and inches */
    rb_unit_system units;
} rb_anchor_inputs;

enum { RB_ASE_GIVEN = 0, RB_ASE_THREADS, RB_ASE_BOLT_AREA };

/* Defaults: cracked, lambda_a 1, seismic, no edge, condition B, no grout
 * pad, cast-in headed, SI coefficients, no edge reinforcement, the
 * trilinear interaction, route auto; the rest zero (required). */
void rb_anchor_inputs_init(rb_anchor_inputs *in);

typedef enum {
    RB_ANCHOR_STEEL_N = 0,  /* 17.6.1 */
    RB_ANCHOR_BREAKOUT_N,   /* 17.6.2 */
    RB_ANCHOR_PULLOUT_N,    /* 17.6.3 */
    RB_ANCHOR_SIDEFACE_N,   /* 17.6.4 */
    RB_ANCHOR_BOND_N,       /* 17.6.5, adhesive anchors */
    RB_ANCHOR_STEEL_V,      /* 17.7.1 */
    RB_ANCHOR_BREAKOUT_V,   /* 17.7.2 */
    RB_ANCHOR_PRYOUT_V,     /* 17.7.3 */
    RB_ANCHOR_N_MODES
} rb_anchor_mode;
extern const rb_enum_name rb_anchor_mode_names[];   /* rb_anchor_mode */

/* Whether a mode is one of tension (17.6) or of shear (17.7), and whether
 * the steel of the anchors, not the concrete, governs it. */
bool rb_anchor_mode_in_tension(rb_anchor_mode mode);
bool rb_anchor_mode_is_steel(rb_anchor_mode mode);

typedef struct {
    bool applies;          /* side-face blowout: only near an edge */
    double nominal_n;      /* of the group the mode takes (see above) */
    double phi;            /* 17.5.3 */
    double seismic;        /* 0.75 on concrete tension modes (17.10.5.4), else 1 */
    double design_n;       /* phi seismic nominal */
} rb_anchor_mode_strength;

typedef struct {
    rb_anchor_mode_strength mode[RB_ANCHOR_N_MODES];
    double da_m;           /* anchor diameter, from the bolt's area */
    double abrg_m2;        /* bearing area used */
    double ase_m2;         /* effective tensile area used */
    /* where A_se came from: RB_ASE_GIVEN, _THREADS (rb_thread_ase of the
     * standard and pitch below) or _BOLT_AREA; and the head A_brg is of
     * (abrg_given: head_bearing_area was given instead) */
    int ase_source;
    rb_thread_std thread_std;
    double thread_pitch_used_m;
    bool abrg_given;
    rb_anchor_head head;
    double phi_nn_n;       /* least design tension strength of a row */
    double phi_vn_n;       /* least design shear strength of the anchorage */
    rb_anchor_mode tension_mode, shear_mode; /* which governs each */
    /* the same over the modes governed by concrete alone: what a run's
     * dynamic demand is judged against (the bolts' steel is judged by the
     * run's own criterion, yield or break, and by the static check) */
    double phi_nn_concrete_n, phi_vn_concrete_n;
    rb_anchor_mode concrete_tension_mode, concrete_shear_mode;
    /* Fig. R17.7.2.1b: 3 where the rows are closer than c_a1, else 1 (the
     * two cases 1 and 2 both checked); 0 without an edge. The nominal
     * breakout of the front row at c_a1 and, for cases 1 and 2, of the
     * rear row at c_a1 + the rows' distance. */
    int shear_case;
    double vcbg_front_n, vcbg_rear_n;
    /* 17.10.5.3(c): the least concrete-governed design tension strength
     * over 1.2 times the row's yield force (>= 1 meets it) */
    double attachment_margin;
    /* 17.10.5.3: the row's concrete-governed nominal tension strength
     * over 1.2 x its steel strength (>= 1: the steel yields first), and
     * the stretch length against 8 da */
    double ductility_margin;
    bool stretch_ok;
    /* f_uta / f_ya, and whether the threads allow it (1.3 or more where
     * they run along part of the anchor and are not upset) */
    double futa_over_fya;
    bool threads_ok;
    unsigned not_ductile;  /* the RB_NOT_DUCTILE_* conditions missed */
    bool ductile;          /* none missed */
} rb_anchor_strength;

/* Strengths of the anchorage of model m (bolts_per_row, bolt area (its
 * diameter for da, and A_se unless in gives it),
 * yield stress, lever arm, half width, deformable length) on the slab and
 * anchors of in. RB_ERR_INVALID with diag->key naming the input for a
 * model without bolts, or an input that is missing or out of range. */
rb_status rb_anchor_check(const rb_model *m, const rb_anchor_inputs *in,
                          rb_anchor_strength *out, rb_diag *diag);

/* The effective tensile area A_se of one anchor, by the one rule of the
 * concrete check and the code-static comparison alike: tensile_area where
 * given, the bolt's area where the case gave the bolt by its (tensile)
 * area, else the thread standard of the bolt's diameter and pitch. 0 where
 * no standard names the size. source (RB_ASE_*), std and pitch_m, when
 * not NULL, say how it was found. */
double rb_anchor_ase(const rb_model *m, const rb_anchor_inputs *in, int *source,
                     rb_thread_std *std, double *pitch_m);

/* The mode that governs a run's demand at one instant: the concrete-
 * governed tension or shear mode, whichever of tension / phi N_n,c and
 * shear / phi V_n,c is the larger (tension on a tie). The one place
 * reports, the batch summary and the JSON take it from. */
rb_anchor_mode rb_anchor_governing_mode(const rb_anchor_strength *s, double tension_n,
                                        double shear_n);

/* The clause of a mode ("17.6.2"); never NULL. */
const char *rb_anchor_clause(rb_anchor_mode mode);
/* The code's equation of a mode's nominal strength, in words and the
 * code's symbols ("N_sa = A_se,N f_uta (Eq. 17.6.1.2), ..."); never NULL. */
const char *rb_anchor_equation(rb_anchor_mode mode);

#endif
