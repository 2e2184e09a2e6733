/* The floor accelerations of a case's motions as the cabinet feels them,
 * sampled for a shake table or another program (`rockbolt motion`,
 * rb_run_floors in rockbolt/run.h): each component after building,
 * window, scaling and polarity, up to the end of the run. No I/O. */
#ifndef ROCKBOLT_FLOORS_H
#define ROCKBOLT_FLOORS_H

#include <stddef.h>
#include "rockbolt/accept.h"
#include "rockbolt/motion.h"
#include "rockbolt/names.h"
#include "rockbolt/spectrum.h"

/* The components of a floor motion (rb_floor_axis_names: h1, h2, v): H1
 * in the model's plane, H2 out of it (for the table only: the model is
 * planar), V the vertical, positive upward. */
typedef enum {
    RB_FLOOR_H1 = 0,
    RB_FLOOR_H2,
    RB_FLOOR_V,
    RB_FLOOR_AXES
} rb_floor_axis;
extern const rb_enum_name rb_floor_axis_names[];    /* rb_floor_axis: h1, h2, v */

/* How the solver's floor runs between the samples written. */
typedef enum {
    RB_BETWEEN_LINEAR = 0, /* a straight line: the samples are the floor itself */
    RB_BETWEEN_BUILDING,   /* the building's exact response to a linear ground:
                              the samples are exact, a straight line between
                              them is not (docs/motion.md) */
    RB_BETWEEN_SAMPLED     /* a closed form, sampled 200 times in its period
                              (a harmonic) or its duration (a pulse) */
} rb_between;
extern const rb_enum_name rb_between_names[];       /* rb_between: linear, building, sampled */

/* Closed forms are sampled this many times per period or pulse. */
#define RB_FLOOR_CLOSED_FORM_RATE 200.0
/* The most samples one component takes (80 MB): a longer one is refused. */
#define RB_FLOOR_MAX_SAMPLES 10000000u

/* One component of one motion. */
typedef struct {
    int present;
    rb_series s;            /* owned: samples at t = i dt from 0, m/s^2, up to
                               the run's end (the solver's floor is 0 past
                               the last one); through a building with the
                               building's state (s.bld), the solver's own */
    rb_between between;
    const rb_target *target;/* borrowed: the target it was matched to, or NULL */
    rb_motion_summary sum;  /* rb_motion_summarise of s against target */
    rb_spectrum trs;        /* owned, with a target: the TRS the acceptance
                               judged, on rb_accept_grid's grid at the
                               target's damping (what the figure draws) */
    rb_accept_rules rules;  /* with a target: the motion's (rb_case_motion.rules:
                               rb_accept_rules_init's, with the case's
                               low_cutoff and max_ratio) */
} rb_floor_component;

typedef struct {
    rb_floor_component axis[RB_FLOOR_AXES];
    double run_s;           /* how long the solver runs on this motion */
} rb_floor_motion;

typedef struct {
    rb_floor_motion *motions; /* owned, n_motions: the case's, in order */
    size_t n_motions;
    double g_mps2;
} rb_case_floors;

void rb_case_floors_free(rb_case_floors *f);

/* 1 when some component matched to a target fails its acceptance (an
 * offset fails the laboratory's rules, or the peak is below the target's
 * least): `rockbolt motion` then exits 1. A component without a target
 * has no acceptance and never fails. */
int rb_case_floors_fail(const rb_case_floors *f);

#endif
