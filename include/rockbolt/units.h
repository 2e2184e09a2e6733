/* Quantities with units, as written in case files ("7.8 mm", "36 ksi").
 *
 * rb_unit_parse turns one such string into an SI double for an expected
 * dimension. A floor acceleration may be given relative to the system's A*
 * ("0.4 A*"); that cannot be resolved until the model is known, so the
 * parser only flags it and the caller multiplies by A* later. Parsing never
 * prints; a failed parse fills a caller-owned message buffer. */
#ifndef ROCKBOLT_UNITS_H
#define ROCKBOLT_UNITS_H

#include <stddef.h>
#include "rockbolt/status.h"

typedef enum {
    RB_DIM_RATIO = 0,       /* dimensionless: plain number or "%" */
    RB_DIM_LENGTH,          /* m */
    RB_DIM_MASS,            /* kg */
    RB_DIM_FORCE,           /* N */
    RB_DIM_STRESS,          /* Pa */
    RB_DIM_ENERGY_DENSITY,  /* J/m^3 */
    RB_DIM_ACCEL,           /* m/s^2, or relative to A* */
    RB_DIM_FREQUENCY,       /* Hz (rad/s is converted) */
    RB_DIM_TIME,            /* s */
    RB_DIM_AREA,            /* m^2 */
    RB_DIM_INERTIA,         /* kg m^2 */
    RB_DIM_STIFFNESS,       /* N/m */
    RB_DIM_VELOCITY,        /* m/s */
    RB_DIM_COUNT
} rb_dim;

/* The unit system a quantity was written in. Units that belong to neither
 * (Hz, s, g, A*, %, a bare number) are RB_UNITS_NEUTRAL; m/s^2, cm/s^2 and
 * gal are SI, in/s^2 and ft/s^2 are US customary. */
typedef enum {
    RB_UNITS_NEUTRAL = 0,
    RB_UNITS_SI,              /* m, mm, kg, N, kN, MPa, J/m^3, ... */
    RB_UNITS_US               /* in, ft, lb, lbf, kip, psi, ksi, in-lb/in^3, ... */
} rb_unit_system;

typedef struct {
    double value;     /* SI value; when relative_a_star, the multiple of A* */
    int relative_a_star; /* 1 when the text was "<x> A*" */
    rb_unit_system system; /* the system of the unit written */
} rb_quantity;

/* Parse "<number> [unit]" for dimension dim. The number is a plain decimal
 * (sign, digits, point, exponent); no hex, no separators. A unit is required
 * unless dim is RB_DIM_RATIO. Returns RB_OK, or RB_ERR_PARSE with a one-line
 * reason in msg (msg may be NULL) for: empty text, no number, NaN or
 * infinity, a number out of range, missing unit, unknown unit, a unit of
 * another dimension, text after the unit. */
rb_status rb_unit_parse(const char *text, rb_dim dim, rb_quantity *out,
                        char *msg, size_t msg_size);

/* The system of the unit of a quantity's text ("7.8 mm": SI, "1/2 in":
 * US), without checking its dimension; RB_UNITS_NEUTRAL for a text that is
 * no number with a known unit, and for the neutral units. */
rb_unit_system rb_unit_system_of_text(const char *text);

/* The exact factors of the US customary units to SI. */
#define RB_UNIT_IN_M 0.0254               /* inch in m */
#define RB_UNIT_FT_M 0.3048               /* foot in m */
#define RB_UNIT_LB_KG 0.45359237          /* pound (mass) in kg */
#define RB_UNIT_LBF_N 4.4482216152605     /* pound-force in N */
#define RB_UNIT_PSI_PA 6894.757293168361  /* lbf/in^2 in Pa */
#define RB_UNIT_G_MPS2 9.80665            /* standard gravity, the unit g */

/* The units every output for people shows in one unit system: each name
 * with the SI value of one such unit (a shown value is SI / factor).
 * SI: kg, kN, m, mm, mm^2, MPa, J, MN/m, kN*m, m/s^2, kJ/m^3; US customary:
 * lb, kip, in, in, in^2, ksi, ft-lbf, kip/in, kip-in, g, in-lb/in^3. */
typedef struct {
    rb_unit_system system;    /* RB_UNITS_SI or RB_UNITS_US */
    const char *mass, *force, *length, *small_length, *area, *stress,
               *energy, *stiffness;
    double mass_f, force_f, length_f, small_length_f, area_f, stress_f,
           energy_f, stiffness_f;
    const char *moment, *accel, *energy_density;
    double moment_f, accel_f, energy_density_f;
} rb_out_units;

/* The output units of system (RB_UNITS_US, else SI); never NULL. */
const rb_out_units *rb_out_units_of(rb_unit_system system);

/* The kinds of quantity the outputs for people print. */
typedef enum {
    RB_Q_MASS = 0,
    RB_Q_FORCE,
    RB_Q_LENGTH,          /* a dimension of the cabinet: m, in */
    RB_Q_SMALL_LENGTH,    /* a gap, a deflection, a bolt: mm, in */
    RB_Q_AREA,            /* of a bolt: mm^2, in^2 */
    RB_Q_STRESS,
    RB_Q_ENERGY,
    RB_Q_STIFFNESS,
    RB_Q_MOMENT,
    RB_Q_ACCEL,           /* m/s^2 in SI, g in US customary */
    RB_Q_ENERGY_DENSITY,
    RB_Q_COUNT
} rb_qty;

/* The unit name of q in system's output units ("kip"); never NULL. */
const char *rb_qty_unit(rb_unit_system system, rb_qty q);
/* The SI value si of q in system's output unit (14.14 for 62.89e3 N in US). */
double rb_qty_value(rb_unit_system system, rb_qty q, double si);

/* The kind of quantity that prints a value of dimension dim (a length as
 * RB_Q_LENGTH); 0 for a dimension whose units are the same in both systems
 * or have no output unit (ratio, frequency, time, inertia). */
int rb_dim_qty(rb_dim dim, rb_qty *q);

/* One quantity as text, value and unit: "62.89 kN", "14.14 kip". */
typedef struct {
    char s[48];
} rb_qtext;
/* si as q in system's output unit with digits significant digits (printf
 * %.*g) and the unit after a blank; "n/a" when si is not finite. Returned
 * by value, so that a call can stand as a printf argument:
 * printf("tension %s", rb_qty_str(u, RB_Q_FORCE, t, 4).s). This is the one
 * place that turns a quantity into text for people: every message,
 * report and figure of a case prints through it or through rb_out_units. */
rb_qtext rb_qty_str(rb_unit_system system, rb_qty q, double si, int digits);

/* "a length", "a mass", ...: the dimension as a phrase; never NULL. */
const char *rb_dim_str(rb_dim dim);

/* The accepted units of a dimension as a comma-separated list, for
 * messages ("m, mm, cm, in, ft"); never NULL. */
const char *rb_dim_units(rb_dim dim);

#endif
