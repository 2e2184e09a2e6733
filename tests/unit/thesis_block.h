/* The rigid free-standing block of thesis Table 2.2 and its overturning
 * threshold, shared by the tests that use it as a limit of the engine. */
#ifndef RB_TEST_THESIS_BLOCK_H
#define RB_TEST_THESIS_BLOCK_H
#include <math.h>
#include "rockbolt/model.h"

/* 2b = 0.5 m, 2h = 1.2 m, delta = 0.778, rigid, no anchorage; I_o of a
 * rectangular block about an edge */
static inline void thesis_block_model(rb_model *m)
{
    rb_model_init(m);
    m->mass_kg = 100;
    m->cm_height_m = 0.6;
    m->half_width_m = 0.25;
    m->rigid = 1;
    m->bolt_model = RB_BOLT_NONE;
    m->restitution = 0.778;
    m->inertia_kgm2 = 4.0 / 3.0 * m->mass_kg * (0.6 * 0.6 + 0.25 * 0.25);
}

/* eq. 2.17: normalised overturning amplitude K = a / (g alpha) of the
 * triangular-decreasing pulse of duration t1, for p t1 */
static inline double thesis_eq_2_17(double pt1)
{
    double c1 = 2 * sinh(pt1) / pt1 - 2;
    double c2 = 2 * sinh(pt1) / pt1 + (2 - 2 * cosh(pt1)) / (pt1 * pt1) - 1;
    return (c1 + sqrt(c1 * c1 + 4 * c2)) / (2 * c2);
}

#endif
