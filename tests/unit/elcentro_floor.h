/* The reference cabinet under the El Centro floor motion, for the solver
 * tests: the record through the 5 Hz, 5 % building (or another), and the model and
 * motion at a level in A*. Shared by the tests that need a record run. */
#ifndef RB_TEST_ELCENTRO_FLOOR_H
#define RB_TEST_ELCENTRO_FLOOR_H

#include "rockbolt/record.h"
#include "rockbolt/solve.h"

/* 0 when s holds the record through a building of frequency f_hz and 5 %
 * damping (free it with rb_series_free). */
static inline int elcentro_floor_of(rb_series *s, double f_hz)
{
    rb_record_opts ro;
    rb_diag diag;
    rb_record_opts_init(&ro);
    if (rb_record_read("cases/records/elcentro_1940_ns.at2", &ro, s, &diag) != RB_OK)
        return -1;
    return rb_series_building_filter(s, f_hz, 0.05) == RB_OK ? 0 : -1;
}

/* 0 when s holds the floor motion (free it with rb_series_free). */
static inline int elcentro_floor(rb_series *s)
{
    return elcentro_floor_of(s, 5.0);
}

/* The reference cabinet with the given bolts, and the floor motion s scaled
 * to level A* over duration_s; d gets the model's constants. */
static inline void elcentro_run_setup(const rb_series *s, rb_bolt_model bolts, double level,
                                      double duration_s, rb_model *m, rb_derived *d,
                                      rb_motion *mo)
{
    rb_model_reference(m);
    m->bolt_model = bolts;
    rb_model_derive(m, d, NULL);
    rb_motion_init(mo);
    mo->kind = RB_MOTION_SAMPLED;
    mo->series = s;
    mo->scale = level * d->a_star_mps2 / rb_series_peak(s);
    mo->duration_s = duration_s;
}

#endif
