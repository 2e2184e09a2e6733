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

/* The units a text report and the figures show in one unit system: each
 * name with the SI value of one such unit (a shown value is SI / factor).
 * SI: kg, kN, m, mm, mm^2, MPa, J, MN/m; US customary: lb, kip, in, in,
 * in^2, ksi, ft-lbf, kip/in. Accelerations are shown in g in both. */
typedef struct {
    rb_unit_system system;    /* RB_UNITS_SI or RB_UNITS_US */
    const char *mass, *force, *length, *small_length, *area, *stress,
               *energy, *stiffness;
    double mass_f, force_f, length_f, small_length_f, area_f, stress_f,
           energy_f, stiffness_f;
} rb_out_units;

/* The output units of system (RB_UNITS_US, else SI); never NULL. */
const rb_out_units *rb_out_units_of(rb_unit_system system);

/* "a length", "a mass", ...: the dimension as a phrase; never NULL. */
const char *rb_dim_str(rb_dim dim);

/* The accepted units of a dimension as a comma-separated list, for
 * messages ("m, mm, cm, in, ft"); never NULL. */
const char *rb_dim_units(rb_dim dim);

#endif
