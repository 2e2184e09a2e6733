/* The exact stepping of a response-spectrum oscillator (with or without
 * the building it stands on) and the peaks between exact states: shared
 * by the cascade through a building (spectrum.c) and the bank of
 * oscillators on a floor given directly (spectrum_bank.c). Internal. */
#ifndef RB_MOTION_SPECTRUM_STEP_H
#define RB_MOTION_SPECTRUM_STEP_H

#include <stddef.h>

/* The exact transition over a (sub-)step of the state x (2 or 4 values)
 * under a load g linear across it: x1 = phi x0 + in0 g0 + in1 g1. */
typedef struct {
    size_t m;
    double phi[16], in0[4], in1[4];
} rb_spec_transition;

/* The state's rates: A x + B g. Without a building (wb = 0, m = 2)
 * x = (w u, v) and g is the floor; with one (m = 4) x = (w_b u_b, v_b,
 * w u, v) and g is the ground. */
void rb_spec_system(double w, double xi, double wb, double xib, size_t m, double *a,
                    double *b);
void rb_spec_transition_init(rb_spec_transition *tr, size_t m, const double *a,
                             const double *b, double h);
void rb_spec_transition_apply(const rb_spec_transition *tr, double *x, double g0,
                              double g1);

/* The running peaks of one oscillator, w u and the absolute acceleration,
 * found between exact states on the cubic through their values and
 * slopes. */
typedef struct {
    double w, xi;
    double psa, sa;          /* peaks so far, as w u and absolute accel */
    double p, v, acc, jerk;  /* w u, v, absolute accel and its rate now */
} rb_spec_tracker;

/* Take (pw, v) under the load (-floor) as the state now, counting nothing. */
void rb_spec_tracker_read(rb_spec_tracker *t, double pw, double v, double load);
/* Count the sub-step of length h that ends in (pw, v, load). */
void rb_spec_tracker_step(rb_spec_tracker *t, double pw, double v, double load, double h);

/* After the samples the floor is zero (as the solver's is) and the
 * oscillator vibrates freely for one of its periods, where the peak of a
 * slow oscillator may still come: count it, from the state y = (w u, v),
 * with sub-steps of at most `phase` radians. dt: the series' step. */
void rb_spec_free_tail(rb_spec_tracker *t, const double *y, double f_hz, double dt,
                       double phase);
/* The same with the sub-step's transition made (rb_spec_sub_transition). */
void rb_spec_free_tail_with(rb_spec_tracker *t, const double *y, double f_hz, double dt,
                            double phase, const rb_spec_transition *sub, unsigned k);

/* The transition over a sub-step of an oscillator alone (w, xi) when a
 * step dt is cut into k = ceil(w dt / phase) (at least 1) of them: the
 * sub-steps of a flagged interval and of the free tail alike. */
void rb_spec_sub_transition(rb_spec_transition *tr, double w, double xi, double dt,
                            double phase, unsigned *k);

#endif
