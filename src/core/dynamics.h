/* Internal: equations of motion, bolt forces, reactions and energies of the
 * restrained-rocking model, stage by stage (thesis sec. 5.4).
 *
 * The continuous state is kept in the physical frame, y = {U, U', theta,
 * theta', W_damping, W_input, W_coupling}. Equations are written once, for
 * rocking about the left edge (theta >= 0, right bolt row), and applied to the
 * other edge through the exact mirror U -> -U, theta -> -theta, x'' -> -x''
 * (MODEL.md: eq. 5.15* as printed is not that mirror). */
#ifndef RB_DYNAMICS_H
#define RB_DYNAMICS_H

#include "rockbolt/model.h"
#include "rockbolt/motion.h"
#include "rockbolt/solve.h"

enum { RB_Y_U, RB_Y_UD, RB_Y_TH, RB_Y_THD, RB_Y_WDAMP, RB_Y_WIN, RB_Y_WCPL, RB_NY };

typedef struct rb_bolt_ops rb_bolt_ops; /* bolt.h */

/* The closed forms an evaluation of the equations reads, at the last
 * argument each was read at (NAN: none): the floor at t, which through a
 * building is an exponential, a sine and a cosine, and cos and sin of the
 * angle. After an event the tracked point, the test for an immediate
 * transition and the restart read the floor at one instant, and a rigid
 * row holds the angle through stage 4, whose guards read the equations
 * at every check point. Not the critical excitation's floor, which
 * follows the state. */
typedef struct {
    double t, x;
    double th, c, sn;
} rb_eval_memo;

typedef struct {
    const rb_model *model;
    rb_derived d;
    rb_eval_memo *memo; /* the run's own, or NULL */
    rb_formulation form;
    const rb_motion *motion;
    const rb_bolt_ops *bolt;    /* the bolt model's operations (bolt.h) */
    double l, b, h, M;
} rb_sys;

/* Discrete state: the stage, the side rocked about and the bolt rows. */
typedef struct {
    int stage;            /* 1..5 (3 is never held) */
    int side;             /* +1: about the left edge, right row loaded; -1 mirror */
    double theta_hold;    /* mirrored angle held in stage 4 (rigid bolts) */
    double gap[2];        /* total gap g_t of each row */
    double contact[2];    /* contact angle of each row: chord(contact) = gap,
                             kept with the gap so that stage 2 watches an
                             angle instead of a chord (no sine per check) */
    double yield_at[2];   /* a row that is a force law (not a rigid stop):
                             the angle at which it reaches Fy, chord(yield_at)
                             = gap + its elastic stretch at Fy, so that stage
                             4's guards are angles too (transitions.c) */
    double absorbed[2];   /* plastic work of each row */
    int broken[2];
    double chord_entry;   /* stage 5: chord and absorbed energy on entry */
    double absorbed_entry;
} rb_disc;

/* What one evaluation yields besides the derivatives. */
typedef struct {
    double x;          /* floor acceleration, physical */
    double gz;         /* apparent gravity g + z'' (g without a vertical) */
    double udd, thdd;  /* mirrored accelerations */
    double bolt_force; /* tension of the loaded row (0 when slack) */
    double p_input, p_coupling;
    double cos_th, sin_th; /* of the mirrored angle the equations used */
} rb_aux;

static inline int rb_row_of_side(int side) { return side > 0 ? RB_RIGHT : RB_LEFT; }

/* Bolt chord p-p' (eq. 5.9b) and its lever arm about the pivot (5.13). */
double rb_dyn_chord(const rb_sys *S, double th);
double rb_dyn_lever(const rb_sys *S, double th);
/* Angle at which the plate meets a bolt head with total gap g. */
double rb_dyn_contact_angle(const rb_sys *S, double g);

/* Whether the plate rotates in the current stage (2, 5, and 4 against a
 * row that is not a rigid stop). */
int rb_dyn_rocking(const rb_sys *S, const rb_disc *D);

/* Derivatives for the current stage; dy may be NULL when only aux is wanted. */
void rb_dyn_rhs(const rb_sys *S, const rb_disc *D, double t, const double *y,
                double *dy, rb_aux *aux);
/* The derivatives that rb_dyn_rhs gives with the evaluation a at the
 * state y (the same bits): a restart that has read the aux already, for
 * its guards and tracked point, forms them without a second evaluation. */
void rb_dyn_deriv(const rb_sys *S, const rb_disc *D, const double *y, const rb_aux *a,
                  double *dy);

/* Uplift guard of stage 1 for side s: > 0 when the plate would lift about
 * that edge (eq. 5.3d written through the stage-2 moment equation so that it
 * agrees in sign with theta'' of stage 2). */
double rb_dyn_uplift_guard(const rb_sys *S, double t, const double *y, int side);
/* Both sides at once: g[0] about the left edge, g[1] about the right. */
void rb_dyn_uplift_guards(const rb_sys *S, double t, const double *y, double *g);
/* The same with the floor acceleration x (physical) and the apparent
 * gravity ge = g + z'' given. */
void rb_dyn_uplift_guards_x(const rb_sys *S, double x, double ge, const double *y,
                            double *g);

/* Energies in the relative frame (J). The potential is gravity's at the
 * static g; a vertical floor's work is booked with the input (rb_aux's
 * p_input), so that the balance closes with it. */
double rb_dyn_kinetic(const rb_sys *S, const rb_disc *D, const double *y);
double rb_dyn_potential(const rb_sys *S, const rb_disc *D, const double *y);
double rb_dyn_strain(const rb_sys *S, const rb_disc *D, const double *y);

/* Horizontal and vertical floor reactions on the body (N, physical sign).
 * Inline: the tracking reads them at every check point, where the call
 * cost a fifth of the arithmetic again. */
static inline void rb_dyn_reactions(const rb_sys *S, const rb_disc *D, const double *y,
                                    const rb_aux *a, double *horizontal, double *vertical)
{
    const rb_derived *d = &S->d;
    /* the mirrored state, as rb_dyn_rhs takes it */
    double s = D->side < 0 ? -1.0 : 1.0;
    double u = s * y[RB_Y_U], ud = s * y[RB_Y_UD], thd = s * y[RB_Y_THD];
    /* the angle's cosine and sine come with aux, from the same evaluation */
    double c = a->cos_th, sn = a->sin_th;
    /* Newton's law on the deformed body whatever the formulation: a mass
     * point moved by u along the base's axis rises by u sin theta */
    double Mb = S->M * S->b - d->Nstar * u;
    double Ad = d->Nstar * a->udd + S->M * S->h * a->thdd + Mb * thd * thd;
    double A2 = -S->M * S->h * thd * thd - 2 * d->Nstar * ud * thd + Mb * a->thdd;
    *horizontal = s * (-S->M * s * a->x + c * Ad + sn * A2);
    *vertical = (a->gz == d->g ? d->W : S->M * a->gz) - sn * Ad + c * A2;
}
/* The same, summed over mass points: an independent check of the above. */
void rb_dyn_reactions_points(const rb_sys *S, const rb_disc *D, const double *y,
                             const rb_aux *aux, double *horizontal, double *vertical);

#endif
