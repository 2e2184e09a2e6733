/* The equipment-anchorage model of the restrained-rocking solver.
 *
 * A cabinet (uniform shear beam of height 2h and mass M in one assumed mode
 * phi(y) = sin(pi y / 4h)) on a rigid base plate of width 2b, anchored by two
 * bolt rows at lever arm l from the opposite pivot edge, with gap g0 between
 * bolt heads and plate. All quantities are SI. Side index 0 is the LEFT bolt
 * row, 1 the RIGHT row. A positive floor acceleration (polarity +1) tips the
 * cabinet about its left edge and loads the RIGHT row, as in the thesis
 * (eq. 5.6, Fig. 5.13). */
#ifndef ROCKBOLT_MODEL_H
#define ROCKBOLT_MODEL_H

#include "rockbolt/status.h"
#include "rockbolt/units.h"
#include "rockbolt/names.h"

#define RB_LEFT 0
#define RB_RIGHT 1

/* Standard gravity, used for g in the equations and for the unit "g". */
#define RB_G0 RB_UNIT_G_MPS2

typedef enum {
    RB_BOLT_NONE = 0,        /* free-standing: no anchorage at all */
    RB_BOLT_RIGID_PLASTIC,   /* rigid until Fy, then yields (ch. 6); rb_model_init's
                                default, not a case file's (elastic-plastic) */
    RB_BOLT_NONYIELDING,     /* rigid and never yields (ch. 5 runs) */
    RB_BOLT_ELASTIC_PLASTIC  /* stiff elastic spring, then yields (sec. 5.7) */
} rb_bolt_model;
extern const rb_enum_name rb_bolt_model_names[];    /* rb_bolt_model */

typedef enum {
    RB_FORM_LARGE = 0,   /* large-angle eqs. 5.5, 5.6, 5.11, 5.13, 5.15 (+mirror) */
    RB_FORM_SMALL,       /* small-angle eqs. 5.21-5.24 (eq. 2.6 when rigid) */
    RB_FORM_CONSISTENT   /* large-angle with the U/b coupling terms kept in
                            both equations (Lagrangian of the same kinematics) */
} rb_formulation;
extern const rb_enum_name rb_formulation_names[];   /* rb_formulation */

/* What a caller fills in. rb_model_derive() checks it and computes the
 * derived quantities in rb_derived. */
typedef struct {
    double mass_kg;            /* M > 0 */
    double cm_height_m;        /* h, centre of mass above the plate; total height 2h */
    double half_width_m;       /* b, half the base plate width */
    double freq_hz;            /* fixed-base frequency (unused when rigid) */
    double damping;            /* xi, 0 <= xi < 1 */
    int rigid;                 /* 1: rigid body, no frame deformation */
    double inertia_kgm2;       /* I_o about a pivot edge; <= 0 -> M (4h^2/3 + b^2) */
    double restitution;        /* delta in (0,1]; < 0 -> eq. 5.19 (Housner) */
    rb_bolt_model bolt_model;
    int bolts_per_row;         /* >= 1 unless bolt_model is NONE */
    double bolt_area_m2;       /* tensile area of one bolt */
    double yield_stress_pa;
    double toughness_jpm3;     /* energy to rupture per unit volume */
    double deformable_length_m;
    double elastic_modulus_pa; /* for the elastic-plastic bolt; <= 0 -> 200 GPa */
    double lever_arm_m;        /* l, pivot edge to the far bolt row, <= 2b */
    double gap_m;              /* g0 >= 0, initial gap on both rows */
    double gravity_mps2;       /* <= 0 -> RB_G0 */
} rb_model;

/* Quantities that follow from an rb_model (eqs. 5.3b, 5.19, 5.29, A*). */
typedef struct {
    double g;              /* gravity used */
    double W;              /* weight M g */
    double R, alpha;       /* pivot to centre of mass: R cos(alpha) = h, R sin(alpha) = b */
    double omega;          /* 2 pi f */
    double Mstar, Nstar, Fstar, Kstar, Cstar; /* generalized mode quantities */
    double Io;             /* moment of inertia about a pivot */
    double delta;          /* floor restitution used */
    double fy_row_n;       /* yield force of one row, n A fy */
    double capacity_j;     /* toughness x volume of one row */
    double k_row_npm;      /* elastic stiffness of one row, n E A / L */
    double a_star_mps2;    /* A* = (Fy_row l + W b) / (M h) */
    double a_uplift_mps2;  /* static uplift acceleration W b / (M h) */
    double theta0_rad;     /* angle at which the plate meets the bolt heads */
} rb_derived;

/* Check a model and derive its constants. Returns RB_ERR_INVALID with the
 * offending field named in diag->key and the reason in diag->msg (diag may be
 * NULL). Rejects NaN, infinities, non-positive mass or size, damping outside
 * [0,1), a bolt outside the plate, a gap the plate cannot rotate through. */
rb_status rb_model_derive(const rb_model *model, rb_derived *out, rb_diag *diag);

/* A model with the defaults filled in and every required field zero. */
void rb_model_init(rb_model *model);

/* The reference cabinet of the project docs (454 kg, 5 Hz, 1 %, four 1/2 in
 * bolts, l = 0.78 m, 2b = 0.9 m, h = 0.979 m, gap ratio 0.01). */
void rb_model_reference(rb_model *model);

#endif
