/* Floor motions: what the solver is driven by.
 *
 * The solver sees an rb_motion, a floor total acceleration x''(t) in m/s^2
 * (eq. 5.28), either in closed form (harmonic, single pulses of chapter 2,
 * the critical alternating pulses of chapter 3) or as samples at a fixed
 * interval, interpolated linearly. Sampled series are held in an rb_series,
 * which owns its array; filters and scaling make new series. No I/O here:
 * record files are read by rb_record (record.h). */
#ifndef ROCKBOLT_MOTION_H
#define ROCKBOLT_MOTION_H

#include <stddef.h>
#include "rockbolt/status.h"
#include "rockbolt/names.h"

/* The building a floor series came through (eqs. 5.27-5.28): the ground
 * acceleration and the building's state at every sample. Between two
 * samples the ground is linear and the floor is the building's exact
 * response to it: the ground plus a damped oscillation, not a straight
 * line between the floor samples. */
#define RB_FLOOR_TAYLOR_TERMS 40

typedef struct {
    double omega_rps, xi;   /* the building's circular frequency and damping */
    double *ground_mps2;    /* owned, n: NULL when there is no building */
    double *u_m, *v_mps;    /* owned, n: relative displacement and velocity */
    double peak_mps2;       /* largest |floor| between samples as well */
    /* Order k of the floor's Taylor series is du[k] u + dv[k] v for a free
     * vibration in state (u, v): the building's own constants, formed once
     * so that a series costs no division (rb_series_building_filter) */
    double taylor_du[RB_FLOOR_TAYLOR_TERMS], taylor_dv[RB_FLOOR_TAYLOR_TERMS];
} rb_series_building;

typedef struct {
    double *accel_mps2; /* owned; n values at t = t0 + i dt: the floor */
    size_t n;
    double dt_s;
    double t0_s;
    rb_series_building bld; /* zeroed: the samples are the floor motion
                               itself, linear between */
} rb_series;

/* Allocate n zeroed samples. Returns RB_ERR_NOMEM or RB_ERR_INVALID (n == 0,
 * dt not finite and > 0). */
rb_status rb_series_alloc(rb_series *s, size_t n, double dt_s);
/* Free the samples; accepts NULL and an already freed series. */
void rb_series_free(rb_series *s);
/* A deep copy of from into to (free with rb_series_free): RB_ERR_NOMEM. */
rb_status rb_series_copy(const rb_series *from, rb_series *to);
/* The largest |a| of the motion the series describes: over the samples;
 * through a building, over the continuous floor motion between samples as
 * well (the floor peaks between samples). Non-finite samples are left out. */
double rb_series_peak(const rb_series *s);
/* Multiply the motion by factor (samples, and the building's ground and
 * state, which are linear in it). */
void rb_series_scale(rb_series *s, double factor);
/* Replace s by the floor total acceleration of a linear SDOF building with
 * frequency f_hz and damping 0 <= xi <= 1 under ground acceleration s
 * (eqs. 5.27-5.28), integrated exactly for piecewise-linear input; the
 * building is kept in s->bld, so that the floor is exact between samples. */
rb_status rb_series_building_filter(rb_series *s, double f_hz, double xi);
/* Keep only samples with t in [t_start, t_end]; t0 is reset to 0. */
rb_status rb_series_window(rb_series *s, double t_start_s, double t_end_s);
/* The motion at time t (0 outside the samples): linear between samples, or
 * the building's exact response. */
double rb_series_at(const rb_series *s, double t);
/* Taylor coefficients coef[0..n] of the motion at t0 + tau, for tau up to
 * the next sample; returns the degree (1 for a straight line, n through a
 * building). */
int rb_series_taylor(const rb_series *s, double t0, int n, double *coef);

/* The floor as a linear system from t0 up to the next sample: a line
 * g0 + slope tau (the ground through a building, else the floor itself)
 * and, through a building (omega > 0), the building's relative state
 * (u, v) at t0, the floor being -(2 xi omega v + omega^2 u) then. Exact
 * transitions of a linear system driven by the floor start from it.
 * Returns 0 outside the samples. */
typedef struct {
    double g0, slope;
    double u, v;
    double omega, xi; /* 0 without a building */
} rb_floor_line;
int rb_series_floor_line(const rb_series *s, double t0, rb_floor_line *fl);
/* The same from sample i, t0 being the sample's time, t0_s + i dt_s
 * (what rb_series_floor_line gives there, without finding the sample);
 * 0 where no interval starts at sample i. */
int rb_series_floor_line_at(const rb_series *s, long i, rb_floor_line *fl);

/* The Arias intensity pi / (2 g) int a^2 dt of a series (over its samples,
 * linear between; a floor through a building is taken at its samples) and
 * the times at which 5 % and 95 % of it have built up. */
void rb_series_arias(const rb_series *s, double *arias_mps, double *t5_s, double *t95_s);
/* The velocity and displacement from rest of n accelerations dt apart,
 * linear between them (exact for such a motion): at the end, and their
 * largest magnitudes (v_peak, d_peak may be NULL). */
void rb_samples_integrate(const double *a, size_t n, double dt, double *v_end,
                          double *d_end, double *v_peak, double *d_peak);

typedef enum {
    RB_MOTION_HARMONIC = 0, /* a sin(2 pi f t), optional linear ramp */
    RB_MOTION_PULSE,        /* one pulse of duration pulse_s, zero after */
    RB_MOTION_SAMPLED,      /* piecewise-linear through series samples */
    RB_MOTION_CRITICAL      /* a sign(theta'): alternating rectangular pulses
                               that always do positive work (ch. 3) */
} rb_motion_kind;

typedef enum {
    RB_PULSE_RECT = 0,
    RB_PULSE_TRI_DEC,   /* a (1 - t/t1): peak at the start (type 1) */
    RB_PULSE_TRI_INC,   /* a t / t1: peak at the end (type 2) */
    RB_PULSE_HALF_SINE  /* a sin(pi t / t1) */
} rb_pulse_shape;
extern const rb_enum_name rb_pulse_shape_names[];   /* rb_pulse_shape */

typedef struct rb_motion {
    rb_motion_kind kind;
    double amplitude_mps2;     /* peak of the closed forms; sampled: multiplier
                                  applied to the samples is 'scale' instead */
    double freq_hz;            /* harmonic */
    double ramp_s;             /* harmonic: linear ramp-up time, 0 for none */
    rb_pulse_shape pulse;
    double pulse_s;            /* pulse duration t1 */
    const rb_series *series;   /* sampled: borrowed, must outlive the run */
    double scale;              /* sampled: factor on the samples (1 if unset) */
    int polarity;              /* +1 as given, -1 reversed */
    double duration_s;         /* how long the solver runs */
    /* The floor's vertical total acceleration z''(t) in m/s^2, positive
     * upward, or NULL for none (rb_motion_init): a harmonic, pulse or
     * sampled motion with its own scale, polarity and breaks (its
     * duration_s is not read; past its end it is 0). The building is taken
     * as rigid vertically: the vertical reaches the floor unfiltered.
     * Borrowed, must outlive the run; it has no vertical of its own. */
    const struct rb_motion *vertical;
} rb_motion;

/* A motion with polarity +1, scale 1 and everything else zero. */
void rb_motion_init(rb_motion *m);

/* Floor total acceleration at time t (m/s^2), polarity applied. For
 * RB_MOTION_CRITICAL theta_dot gives the sign; elsewhere it is ignored. */
double rb_motion_accel(const rb_motion *m, double t, double theta_dot);

/* The next time strictly after t where x''(t), or the vertical z''(t), has
 * a kink or jump (a sample time, a pulse end, the end of a ramp), or
 * INFINITY if none. The solver never steps across one. */
double rb_motion_next_break(const rb_motion *m, double t);

/* Whether x'' or z'' jumps at t (t > 0): a rectangular pulse, or one that
 * ends at its peak, drops to zero at its end. Everywhere else the breaks
 * are kinks, across which x'' and z'' are continuous. */
int rb_motion_jumps_at(const rb_motion *m, double t);

/* Taylor coefficients of x''(t0 + tau), valid for tau from 0 up to the
 * next break: coef[k] for k = 0..n (n >= 1). Returns the degree of the
 * polynomial (the last nonzero coefficient can be below it), n for the
 * sines, or -1 for RB_MOTION_CRITICAL, whose sign follows the response. */
int rb_motion_taylor(const rb_motion *m, double t0, int n, double *coef);

/* rb_series_floor_line of a sampled motion, its scale and polarity
 * applied; 0 for the closed forms and outside the samples. */
int rb_motion_floor_line(const rb_motion *m, double t0, rb_floor_line *fl);
/* The same from the series' sample i (rb_series_floor_line_at). */
int rb_motion_floor_line_at(const rb_motion *m, long i, rb_floor_line *fl);

/* Largest |x''| the motion can reach (the peak floor acceleration 'a').
 * Non-finite samples are left out: the solver stops where it meets one. */
double rb_motion_peak(const rb_motion *m);

/* The apparent gravity g + z''(t) the body feels on a floor that
 * accelerates vertically (z'' of m->vertical, polarity and scale applied);
 * g itself, to the bit, without a vertical. */
double rb_motion_gravity(const rb_motion *m, double g, double t);

/* The least value the motion's acceleration reaches for t in [0, t_end]
 * (signed; 0 where it has ended; a sine's trough -|a| whatever t_end, a
 * series' least sample, -peak through a building, whose floor peaks
 * between samples). */
double rb_motion_least(const rb_motion *m, double t_end);

/* Whether m's vertical can drive the solver under gravity g: a harmonic,
 * pulse or sampled motion without a vertical of its own, whose z'' stays
 * above -g throughout (a floor falling faster than gravity would throw the
 * body off it: free flight, which the model does not follow). RB_OK
 * without a vertical; else RB_ERR_INVALID with diag->key "vertical" and
 * the reason. */
rb_status rb_motion_vertical_check(const rb_motion *m, double g, rb_diag *diag);

#endif
