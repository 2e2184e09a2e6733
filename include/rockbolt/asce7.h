/* ASCE 7 (7-16 and 7-22) Chapter 13: the code-static comparison. The
 * component force of eq. 13.3-1, applied at the centre of mass, turned
 * into the tension of the far bolt row by the overturning equilibrium that
 * defines A*, and compared with the ACI 318-19 design steel strength of
 * the row in tension (docs/design.md, "Code-static comparison"). SI units.
 * No I/O. */
#ifndef ROCKBOLT_ASCE7_H
#define ROCKBOLT_ASCE7_H

#include "rockbolt/model.h"
#include "rockbolt/status.h"

typedef enum {
    RB_ASCE7_16 = 16,   /* ASCE/SEI 7-16, eq. 13.3-1 to 13.3-3 */
    RB_ASCE7_22 = 22    /* ASCE/SEI 7-22, eq. 13.3-1 to 13.3-3 with Hf, Rmu */
} rb_code_edition;

typedef struct {
    rb_code_edition edition;
    double sds;               /* SDS, in g */
    double ip;                /* component importance factor Ip (1.0 or 1.5) */
    double z_over_h;          /* attachment height / roof height, 0..1 */
    int at_or_below_grade;    /* 7-22: Hf = Rmu = 1 */
    /* ASCE 7-16 */
    double ap, rp;            /* component amplification, response modification */
    /* ASCE 7-22 */
    double car, rpo;          /* Table 13.5-1 / 13.6-1 */
    double ta_s;              /* building approximate period; <= 0: unknown,
                                 Hf = 1 + 2.5 z/h */
    double r, ie, omega0;     /* building's R, Ie, Omega0 (for Rmu) */
    /* anchorage */
    int anchorage_in_concrete;/* 1: Fp x Omega0p for the anchors (13.4.2) */
    double omega0p;           /* component overstrength Omega0p */
    double futa_pa;           /* specified anchor tensile strength */
    double ase_m2;            /* effective tensile area of one anchor;
                                 <= 0: the model's bolt area */
} rb_code_inputs;

/* Edition 7-22, Ip = 1, Omega0p = 2, anchorage in concrete, Ta unknown;
 * every other field 0 (to be given). */
void rb_code_inputs_init(rb_code_inputs *in);

typedef struct {
    double fp_formula_n;      /* Fp from eq. 13.3-1 before the bounds */
    double fp_min_n, fp_max_n;/* 0.3 SDS Ip Wp, 1.6 SDS Ip Wp */
    double fp_n;              /* design Fp after the bounds */
    int bound;                /* -1 minimum governs, +1 maximum, 0 neither */
    double hf, rmu;           /* 7-22 factors (7-16: 1 + 2 z/h and 1) */
    double fp_anchor_n;       /* Fp x Omega0p when anchorage in concrete */
    double fp_over_wp;        /* Fp / Wp, the equivalent static floor
                                 acceleration in g */
    double accel_mps2;        /* Fp / Wp x g */
    double accel_astar;       /* accel_mps2 / A* */
    double a_star_mps2;
    double tension_n;         /* row tension T, >= 0 */
    double tension_raw_n;     /* before clipping at 0 (negative: no uplift) */
    double futa_used_pa;      /* min(futa, 1.9 fya, 861.8 MPa) */
    double phi_nsa_n;         /* 0.75 n Ase futa of one row */
    double ratio;             /* T / phi Nsa */
    /* with the concrete check (rb_run_design): the 17.8 utilization of the
     * row tension T with the anchor design force as shear, against the
     * anchorage's design strengths, and the clause (1-3) */
    int has_concrete;
    double concrete_utilization;
    int concrete_clause;
} rb_code_result;

/* Compare the model's anchorage with the code-static design. W, h, b, l,
 * the number of bolts per row, their area and yield stress come from the
 * model. RB_ERR_INVALID (diag->key names the field) for missing or out of
 * range inputs. */
rb_status rb_code_static(const rb_model *model, const rb_code_inputs *in,
                         rb_code_result *out, rb_diag *diag);

#endif
