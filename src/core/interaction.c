/* The tension-shear interaction of ACI 318-19 17.8 (rockbolt/interaction.h). */
#include <math.h>
#include "rockbolt/interaction.h"

const rb_enum_name rb_interaction_names[] = {
    {"trilinear", RB_ACI17_TRILINEAR}, {"power", RB_ACI17_POWER}, {NULL, 0}};

double rb_aci17_interaction(double nua_n, double phi_nn_n, double vua_n,
                            double phi_vn_n, int *which)
{
    double rn = nua_n / phi_nn_n, rv = vua_n / phi_vn_n;
    int w;
    double u;
    if (vua_n <= 0.2 * phi_vn_n) {          /* 17.8.1 */
        w = 1;
        u = rn;
    } else if (nua_n <= 0.2 * phi_nn_n) {   /* 17.8.2 */
        w = 2;
        u = rv;
    } else {                                /* 17.8.3, Eq. (17.8.3) */
        w = 3;
        u = fmax(fmax(rn, rv), (rn + rv) / 1.2);
    }
    if (which)
        *which = w;
    return u;
}

double rb_aci17_interaction_by(rb_aci17_interaction_rule rule, double nua_n,
                               double phi_nn_n, double vua_n, double phi_vn_n, int *which)
{
    if (rule != RB_ACI17_POWER)
        return rb_aci17_interaction(nua_n, phi_nn_n, vua_n, phi_vn_n, which);
    /* R17.8, Eq. (R17.8): the sum of the 5/3 powers; its 3/5 power is the
     * load factor that brings the sum to 1 */
    double rn = nua_n / phi_nn_n, rv = vua_n / phi_vn_n;
    if (which)
        *which = RB_ACI17_WHICH_POWER;
    return pow(pow(rn, 5.0 / 3.0) + pow(rv, 5.0 / 3.0), 0.6);
}

const char *rb_aci17_interaction_clause(int which)
{
    static const char *const names[] = {"17.8", "17.8.1", "17.8.2", "17.8.3", "R17.8"};
    return which >= 0 && which <= RB_ACI17_WHICH_POWER ? names[which] : "17.8";
}
