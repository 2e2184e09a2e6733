/* The tension-shear interaction of ACI 318-19 17.8 (and the power rule of
 * R17.8): the one clause of the anchorage code the solver evaluates at
 * every step (the anchor's utilization over a run) and the judge names.
 * It lives with them in rb_core, under the codes (src/codes), which stand
 * on the model; rockbolt/aci17.h includes it with the rest of Chapter 17.
 * Forces in N. */
#ifndef ROCKBOLT_INTERACTION_H
#define ROCKBOLT_INTERACTION_H

#include "rockbolt/names.h"

/* Utilization of an anchor or group under tension Nua and shear Vua
 * (both >= 0) against the design strengths phi Nn and phi Vn (the least
 * of the modes): 17.8.1, Vua <= 0.2 phi Vn: Nua / phi Nn; 17.8.2,
 * Nua <= 0.2 phi Nn: Vua / phi Vn; 17.8.3 otherwise: the largest of
 * Nua / phi Nn, Vua / phi Vn and (Nua / phi Nn + Vua / phi Vn) / 1.2.
 * <= 1 passes. *which: 1, 2 or 3 for the clause used (may be NULL). */
double rb_aci17_interaction(double nua_n, double phi_nn_n, double vua_n,
                            double phi_vn_n, int *which);

/* The interaction rule a check applies: the trilinear rule of 17.8.1-17.8.3,
 * or the 5/3-power rule of R17.8, (N/phi Nn)^(5/3) + (V/phi Vn)^(5/3) <= 1
 * (Hilti PROFIS's default). */
typedef enum {
    RB_ACI17_TRILINEAR = 0,
    RB_ACI17_POWER
} rb_aci17_interaction_rule;

/* Which value of rb_aci17_interaction_by's *which the power rule gives. */
#define RB_ACI17_WHICH_POWER 4

/* The utilization under rule: rb_aci17_interaction for the trilinear rule;
 * for the power rule ((N/phi Nn)^(5/3) + (V/phi Vn)^(5/3))^(3/5), which
 * scales with the loads as the trilinear one does and reaches 1 where the
 * sum of R17.8 does; *which = RB_ACI17_WHICH_POWER. */
double rb_aci17_interaction_by(rb_aci17_interaction_rule rule, double nua_n,
                               double phi_nn_n, double vua_n, double phi_vn_n, int *which);

/* The clause a *which of rb_aci17_interaction_by names: "17.8.1",
 * "17.8.2", "17.8.3" or "R17.8"; never NULL. */
const char *rb_aci17_interaction_clause(int which);

/* rb_aci17_interaction_rule: trilinear, power */
extern const rb_enum_name rb_interaction_names[];

#endif
