/* A cabinet of the random stress runs, for the solver tests that hold one
 * such run: the reference cabinet with another mass, frame frequency, bolt
 * area and gap, under a floor motion scaled to a level in A*; and the Taft
 * record (in g, 0.01 s) that many of them ran under. */
#ifndef RB_TEST_STRESS_CABINET_H
#define RB_TEST_STRESS_CABINET_H

#include <stdio.h>
#include "rockbolt/record.h"
#include "rockbolt/solve.h"

/* 0 when s holds the Taft record (free it with rb_series_free); else -1,
 * having said why. */
static inline int taft_record(rb_series *s)
{
    rb_record_opts ro;
    rb_diag diag;
    rb_record_opts_init(&ro);
    ro.format = RB_REC_ONE_COLUMN;
    ro.dt_s = 0.01;
    ro.units_to_mps2 = 9.80665;
    if (rb_record_read("cases/records/taft_1952_s69e.txt", &ro, s, &diag) != RB_OK) {
        printf("cannot read the Taft record: %s\n", diag.msg);
        return -1;
    }
    return 0;
}

typedef struct {
    double mass_kg, freq_hz, bolt_area_m2, gap_m, level, duration_s;
} stress_cabinet;

/* The model and motion of c under s; d gets the model's constants. 0, or
 * -1 when the model is refused. */
/* The model of c alone, for a run under a closed-form motion; d gets its
 * constants. 0, or -1 when the model is refused. */
static inline int stress_cabinet_model(const stress_cabinet *c, rb_model *m, rb_derived *d)
{
    rb_model_reference(m);
    m->mass_kg = c->mass_kg;
    m->freq_hz = c->freq_hz;
    m->bolt_area_m2 = c->bolt_area_m2;
    m->gap_m = c->gap_m;
    return rb_model_derive(m, d, NULL) == RB_OK ? 0 : -1;
}

static inline int stress_cabinet_setup(const stress_cabinet *c, const rb_series *s,
                                       rb_model *m, rb_derived *d, rb_motion *mo)
{
    if (stress_cabinet_model(c, m, d) != 0)
        return -1;
    rb_motion_init(mo);
    mo->kind = RB_MOTION_SAMPLED;
    mo->series = s;
    mo->scale = c->level * d->a_star_mps2 / rb_series_peak(s);
    mo->duration_s = c->duration_s;
    return 0;
}

#endif
