/* Exact stepping of a linear single-degree-of-freedom oscillator
 *
 *     u'' + 2 xi w u' + w^2 u = p(t)
 *
 * under a load p that varies linearly between equally spaced samples (the
 * Nigam-Jennings recurrence). The building filter (eq. 5.27) and the
 * fixed-base frame (eq. 5.26) are both this equation with different loads,
 * so both step through here. Internal to the library. */
#ifndef RB_MOTION_SDOF_H
#define RB_MOTION_SDOF_H

#include <stddef.h>
#include "rockbolt/motion.h"
#include "rockbolt/status.h"

/* One step of length dt from (u, v) with load p0 at the start and p1 at
 * the end:
 *     u1 = uu u + uv v + up0 p0 + up1 p1
 *     v1 = vu u + vv v + vp0 p0 + vp1 p1 */
typedef struct {
    double uu, uv, up0, up1;
    double vu, vv, vp0, vp1;
    double omega;   /* w, rad/s */
    double xi;
} rb_sdof_step;

/* Coefficients for natural circular frequency omega > 0, damping
 * 0 <= xi <= 100 (under-, critically and over-damped alike) and step
 * dt > 0 with omega dt <= 1e6, all finite. RB_ERR_INVALID otherwise. */
rb_status rb_sdof_step_init(rb_sdof_step *st, double omega, double xi, double dt);

/* Advance (u, v) by one step. */
void rb_sdof_step_apply(const rb_sdof_step *st, double *u, double *v,
                        double p0, double p1);

/* Start from rest at sample 0 and step through the n loads p; u_out and
 * v_out (each may be NULL) receive the state at every sample. Returns the
 * largest |u| over the samples. */
double rb_sdof_run(const rb_sdof_step *st, const double *p, size_t n,
                   double *u_out, double *v_out);

/* Largest |u| from rest under the n loads p (samples dt apart), looking
 * at k equally spaced points in every step; the state is exact there too,
 * the load being linear. The samples alone (k = 1) miss the peak by up to
 * 1 - cos(w dt / 2), about 1.2 % at 10 samples per period; k points cut
 * that by k^2. RB_ERR_INVALID for k = 0 or as rb_sdof_step_init. */
rb_status rb_sdof_peak_within(double omega, double xi, double dt, unsigned k,
                             const double *p, size_t n, double *peak);

/* floor.c: the largest |floor| of a series through a building, between
 * samples as well. */
double rb_series_floor_peak(const rb_series *s);

#endif
