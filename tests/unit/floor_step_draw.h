/* A random cabinet on the floor and a random start state for one exact
 * step: the draws test_exact_bounds and test_exact_turns hold the floor
 * stage's exact steps to. The record (read once by the test) through no
 * building or a random one, a random frame and formulation, and a start
 * state over a wide range with some components zero. */
#ifndef RB_TEST_FLOOR_STEP_DRAW_H
#define RB_TEST_FLOOR_STEP_DRAW_H

#include <math.h>
#include "harness.h"
#include "rockbolt/record.h"
#include "rockbolt/solve.h"
#include "../../src/core/exact.h"

/* A test's own generator: each test keeps its seed, so its draws do not
 * depend on another test's. */
static inline double draw_uniform(unsigned long long *state, double lo, double hi)
{
    *state = *state * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * (double)(*state >> 11) / 9007199254740992.0;
}

/* The record the draws are cut from (El Centro, as shipped); 0 where it
 * cannot be read. */
static inline int floor_draw_record(rb_series *raw)
{
    rb_record_opts ro;
    rb_diag diag;
    rb_record_opts_init(&ro);
    return rb_record_read("cases/records/elcentro_1940_ns.at2", &ro, raw, &diag) == RB_OK;
}

/* qsort's order of doubles, for the tests' medians and percentiles. */
static inline int draw_cmp(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

typedef struct {
    rb_series s;          /* the draw's own copy of the record: free with rb_series_free */
    rb_model m;
    rb_derived d;
    rb_motion mo;
    rb_solve_opts o;
    double wb, xib;       /* the building's circular frequency (0: none) and damping */
} floor_draw;

/* Draw case c (every fourth without a building, every eighth of the rest
 * undamped, every third in the small formulation) over raw; 0 when its
 * series cannot be allocated. */
static inline int floor_draw_case(int c, const rb_series *raw, unsigned long long *rng,
                                  floor_draw *f)
{
    *f = (floor_draw){0};
    if (rb_series_alloc(&f->s, raw->n, raw->dt_s) != RB_OK)
        return 0;
    for (size_t i = 0; i < raw->n; i++)
        f->s.accel_mps2[i] = raw->accel_mps2[i];
    if (c % 4) {
        double hz = exp(draw_uniform(rng, log(0.5), log(60)));
        f->xib = c % 8 == 1 ? 0 : draw_uniform(rng, 0, 0.5);
        f->wb = 2 * M_PI * hz;
        CHECK(rb_series_building_filter(&f->s, hz, f->xib) == RB_OK);
    }
    rb_model_reference(&f->m);
    f->m.mass_kg = draw_uniform(rng, 50, 5000);
    f->m.freq_hz = exp(draw_uniform(rng, log(0.5), log(50)));
    f->m.damping = draw_uniform(rng, 0, 0.5);
    CHECK(rb_model_derive(&f->m, &f->d, NULL) == RB_OK);
    rb_motion_init(&f->mo);
    f->mo.kind = RB_MOTION_SAMPLED;
    f->mo.series = &f->s;
    f->mo.scale = 1;
    f->mo.duration_s = 10;
    rb_solve_opts_init(&f->o);
    f->o.formulation = c % 3 == 2 ? RB_FORM_SMALL : RB_FORM_LARGE;
    return 1;
}

/* Each component of the start state over a wide range, some of them zero
 * (a building at rest, a line with no slope). */
static inline void floor_draw_state(unsigned long long *rng, double z0[RB_EXACT_DIM])
{
    const double scale[RB_EXACT_DIM] = {1e-3, 5e-2, 5e-2, 1, 8, 400};
    for (int j = 0; j < RB_EXACT_DIM; j++)
        z0[j] = draw_uniform(rng, -1, 1) * scale[j];
    for (int j = 0; j < RB_EXACT_DIM; j++)
        if (draw_uniform(rng, 0, 1) < 0.15)
            z0[j] = 0;
}

/* The floor acceleration and U'' at a state of the floor stage (5.3c):
 * the building's response, or the ground line's own value without one. */
static inline void floor_draw_accels(const floor_draw *f, const double *z, double *x,
                                     double *udd)
{
    *x = f->wb > 0 ? -(2 * f->xib * f->wb * z[3] + f->wb * f->wb * z[2]) : z[4];
    *udd = (f->d.Nstar * *x - f->d.Kstar * z[0] - f->d.Cstar * z[1]) / f->d.Mstar;
}

#endif
