/* Quantities as people read them, in the unit system of a case
 * (include/rockbolt/units.h): the one table of output units, and the one
 * formatter every message, report and figure prints a quantity with. */
#include <math.h>
#include <stdio.h>
#include "rockbolt/units.h"

#define RB_KIP_N (1e3 * RB_UNIT_LBF_N)

const rb_out_units *rb_out_units_of(rb_unit_system system)
{
    static const rb_out_units si = {
        RB_UNITS_SI, "kg", "kN", "m", "mm", "mm^2", "MPa", "J", "MN/m",
        1.0, 1e3, 1.0, 1e-3, 1e-6, 1e6, 1.0, 1e6,
        "kN*m", "m/s^2", "kJ/m^3", 1e3, 1.0, 1e3 };
    /* an acceleration in g: engineers in US customary units read floor and
     * site accelerations in g, not in in/s^2 */
    static const rb_out_units us = {
        RB_UNITS_US, "lb", "kip", "in", "in", "in^2", "ksi", "ft-lbf", "kip/in",
        RB_UNIT_LB_KG, RB_KIP_N, RB_UNIT_IN_M, RB_UNIT_IN_M, RB_UNIT_IN_M * RB_UNIT_IN_M,
        1e3 * RB_UNIT_PSI_PA, RB_UNIT_FT_M * RB_UNIT_LBF_N, RB_KIP_N / RB_UNIT_IN_M,
        "kip-in", "g", "in-lb/in^3", RB_KIP_N * RB_UNIT_IN_M, RB_UNIT_G_MPS2,
        RB_UNIT_PSI_PA };
    return system == RB_UNITS_US ? &us : &si;
}

/* The unit name and factor of q in u. */
static const char *qty_unit(const rb_out_units *u, rb_qty q, double *factor)
{
    switch (q) {
    case RB_Q_MASS: *factor = u->mass_f; return u->mass;
    case RB_Q_FORCE: *factor = u->force_f; return u->force;
    case RB_Q_LENGTH: *factor = u->length_f; return u->length;
    case RB_Q_SMALL_LENGTH: *factor = u->small_length_f; return u->small_length;
    case RB_Q_AREA: *factor = u->area_f; return u->area;
    case RB_Q_STRESS: *factor = u->stress_f; return u->stress;
    case RB_Q_ENERGY: *factor = u->energy_f; return u->energy;
    case RB_Q_STIFFNESS: *factor = u->stiffness_f; return u->stiffness;
    case RB_Q_MOMENT: *factor = u->moment_f; return u->moment;
    case RB_Q_ACCEL: *factor = u->accel_f; return u->accel;
    case RB_Q_ENERGY_DENSITY: *factor = u->energy_density_f; return u->energy_density;
    default: *factor = 1.0; return "";
    }
}

const char *rb_qty_unit(rb_unit_system system, rb_qty q)
{
    double f;
    return qty_unit(rb_out_units_of(system), q, &f);
}

double rb_qty_value(rb_unit_system system, rb_qty q, double si)
{
    double f;
    qty_unit(rb_out_units_of(system), q, &f);
    return si / f;
}

int rb_dim_qty(rb_dim dim, rb_qty *q)
{
    switch (dim) {
    case RB_DIM_LENGTH: *q = RB_Q_LENGTH; return 1;
    case RB_DIM_MASS: *q = RB_Q_MASS; return 1;
    case RB_DIM_FORCE: *q = RB_Q_FORCE; return 1;
    case RB_DIM_STRESS: *q = RB_Q_STRESS; return 1;
    case RB_DIM_ENERGY_DENSITY: *q = RB_Q_ENERGY_DENSITY; return 1;
    case RB_DIM_ACCEL: *q = RB_Q_ACCEL; return 1;
    case RB_DIM_AREA: *q = RB_Q_AREA; return 1;
    case RB_DIM_STIFFNESS: *q = RB_Q_STIFFNESS; return 1;
    default: return 0;
    }
}

rb_qtext rb_qty_str(rb_unit_system system, rb_qty q, double si, int digits)
{
    rb_qtext t;
    double f;
    const char *unit = qty_unit(rb_out_units_of(system), q, &f);
    if (!isfinite(si))
        snprintf(t.s, sizeof t.s, "n/a");
    else
        snprintf(t.s, sizeof t.s, "%.*g %s", digits < 1 ? 1 : digits > 17 ? 17 : digits,
                 si / f, unit);
    return t;
}
