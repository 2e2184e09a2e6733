/* The five-stage restrained-rocking solver (thesis chapters 5 and 6).
 *
 * rb_solve_run integrates the stage machine 1 -> 2 -> 3 -> 4 -> 5 and back
 * (Fig. 5.3.b) for one model under one floor motion and returns the peak
 * response, energies and counters. Continuous stages are integrated with an
 * embedded Runge-Kutta 5(4) pair (Dormand-Prince) with dense output; stage
 * changes are roots of guard functions located on the dense output; impacts
 * are instantaneous maps. Memory is constant in the record length unless a
 * time history is requested. No I/O. */
#ifndef ROCKBOLT_SOLVE_H
#define ROCKBOLT_SOLVE_H

#include <stddef.h>
#include "rockbolt/model.h"
#include "rockbolt/motion.h"
#include "rockbolt/names.h"

typedef enum {
    RB_STAGE_FIXED = 1,   /* 1: fixed base, SDOF */
    RB_STAGE_UPLIFT = 2,  /* 2: rocking, bolts slack */
    RB_STAGE_IMPACT = 3,  /* 3: plate hits a bolt head (instantaneous) */
    RB_STAGE_HELD = 4,    /* 4: plate held by a bolt row in tension */
    RB_STAGE_YIELD = 5    /* 5: bolt row yielding at Fy */
} rb_stage;

/* How the continuous stages are integrated (docs/solver.md). */
typedef enum {
    RB_INTEGRATOR_AUTO = 0,  /* Taylor series where it applies (stages 1, 2 and
                                4 of the large and small formulations, and 5
                                with elastic-plastic bolts), Dormand-Prince
                                elsewhere */
    RB_INTEGRATOR_RK45       /* Dormand-Prince 5(4) throughout */
} rb_integrator;
extern const rb_enum_name rb_integrator_names[];    /* rb_integrator */

typedef struct {
    rb_formulation formulation;
    rb_integrator integrator;
    double rtol;             /* relative tolerance (default 1e-7): the Taylor
                                and exact steps are held to it, Dormand-Prince
                                steps to a thousandth of it (never below
                                1e-13), which meets the same accuracy */
    double event_tol;        /* transitions to this fraction of the normalising
                                quantity (default 1e-3, sec. 5.7), tightened
                                internally to 1e-9 in time */
    double max_step_s;       /* <= 0 -> 1/(20 f) of the highest frequency */
    int stretch_past_failure;/* 1: bolts keep yielding past their capacity and
                                usage > 1 is reported (ch. 6 earthquake runs) */
    double history_dt_s;     /* > 0: record a time history at this interval */
    double rest_fraction;    /* rocking amplitude below this fraction of the
                                smaller of alpha and theta0 returns to stage 1
                                (default 1e-6) */
    long max_events_per_s;   /* work bound per simulated second (default 20000) */
    long max_steps;          /* total step bound (default 50 000 000) */
    double theta_init_rad;   /* start rocking at this angle (sign = side), at rest */
    int check_reactions;     /* 1: also sum the reactions over mass points and
                                report the largest mismatch (tests) */
    /* > 0: the design tension strength of a row and the design shear
     * strength of the anchorage in the modes concrete governs
     * (rockbolt/anchor.h); the run then follows the 17.8 utilization of the
     * loaded row's tension and the horizontal floor reaction, taken
     * together at each instant, under anchor_interaction (default the
     * trilinear rule) */
    double anchor_phi_nn_n, anchor_phi_vn_n;
    int anchor_interaction;  /* rb_aci17_interaction_rule */
    /* 1 (default): on the floor under a sampled motion, steps with nothing
     * to locate inside them are taken by the exact transition of the
     * frame and the building (docs/solver.md); 0: by Taylor series, the
     * cross-check of the tests */
    int exact_floor;
    /* the least check points of a Taylor or exact step (default 2, at
     * least 2; more where an eighth of the fastest mode's period asks for
     * them): more are the tests' way to read a run at finer points */
    int min_checks;
    /* RB_STOP_* bits (default 0: every run goes to the end). A search that
     * decides one limit state (a fragility's first yield or lift-off) ends
     * a run at its first crossing: the flags and least values that decide
     * it only ever move towards failing, so the verdict on that state is
     * the full run's, and nothing else of the result is. */
    unsigned stop_at;
} rb_solve_opts;

/* rb_solve_opts.stop_at: end the run once a bolt row yields or its force
 * reaches Fy (max_bolt_force_n >= fy_row_n), or once the least vertical
 * floor reaction is at or below zero. */
#define RB_STOP_FIRST_YIELD 1u
#define RB_STOP_LIFT_OFF 2u

/* Fraction of W the floor's vertical reaction must exceed for a friction
 * demand to be taken there. */
#define RB_FRICTION_FLOOR 0.05

/* Defaults as documented above. */
void rb_solve_opts_init(rb_solve_opts *opts);

/* Time history, one row per history_dt_s (and at the end). All arrays have
 * length n and are owned by the rb_history. Forces are tension positive;
 * vertical is what floor and bolts give together, so that the floor's own
 * reaction is vertical plus the bolt force of the loaded row. */
typedef struct {
    size_t n, cap;
    double *t, *accel, *theta, *u, *bolt_force_left, *bolt_force_right,
           *shear_elastic, *shear_total, *vertical, *energy_left, *energy_right,
           *kinetic, *potential, *strain;
    int *stage;
} rb_history;

void rb_history_free(rb_history *h);

typedef struct {
    /* system constants */
    double a_star_mps2, a_uplift_mps2, peak_floor_mps2;
    double u_static_m;         /* pi^2 a / (8 omega^2), the thesis's tables */
    double alpha_rad, theta0_rad, fy_row_n, capacity_j, weight_n, delta;
    int rigid_bolts;           /* bolts that stop the plate rigidly (rigid-plastic,
                                  non-yielding): the impact check applies */
    /* peaks */
    double max_theta_rad, max_theta_over_alpha;
    double max_u_m, max_u_over_ustatic;
    double max_shear_elastic_n;   /* GA (pi/4h) U = N* omega^2 U (frame shear) */
    double max_shear_total_n;     /* horizontal floor reaction on the body */
    /* max |horizontal| / vertical floor reaction, taken only where the
     * floor's vertical reaction exceeds RB_FRICTION_FLOOR W: nearer zero the
     * ratio has no bound and says nothing a friction coefficient can meet */
    double max_friction_demand;
    /* least vertical floor reaction; at or below zero the base would leave
     * the floor, which the model does not follow (docs/solver.md, Validity) */
    double min_vertical_reaction_n;
    double liftoff_first_s;       /* first time the reaction is <= 0; < 0: never */
    double liftoff_time_s;        /* total time it is <= 0 */
    /* rigid bolt models: the largest elastic impact force a real row of
     * stiffness k_row would take when the plate meets it at the speed the
     * rigid stop destroys, v sqrt(k_row I_o / l^2); 0 for elastic bolts,
     * which resolve the impact themselves */
    double max_bolt_impact_n;
    double max_bolt_impact_s;     /* when it happened */
    /* check_reactions only: the largest difference between the vertical
     * reaction in closed form and summed over the frame's mass points */
    double reaction_mismatch_n;
    /* with the anchorage's strengths (anchor_phi_*): the largest 17.8
     * utilization of concurrent tension and shear, its time, the two
     * demands then, and the clause that gave it (1, 2, 3: 17.8.1-17.8.3);
     * anchor_checked 0 and the rest 0 otherwise */
    int anchor_checked;
    double anchor_max_ratio, anchor_max_s, anchor_tension_n, anchor_shear_n;
    int anchor_clause;       /* as rb_aci17_interaction_by's *which */
    double max_bolt_force_n[2];   /* [RB_LEFT], [RB_RIGHT] */
    /* per bolt row */
    double final_gap_m[2];
    double absorbed_j[2];
    double usage[2];              /* absorbed / capacity */
    int yielded[2];
    double first_yield_s[2];
    int broken[2];
    double break_s[2];
    /* outcome */
    int overturned;
    int overturn_side;            /* RB_LEFT: tipped about the right edge... see docs */
    double overturn_s;
    double t_end_s;               /* time reached */
    double stage_time_s[6];       /* index = stage number 1..5 (3 stays 0) */
    long floor_impacts, bolt_impacts, uplifts;
    /* energy balance (J), relative frame */
    double e_input, e_kinetic, e_potential, e_strain, e_damping, e_impact,
           e_plastic, e_coupling;
    /* cost */
    long steps, rejected_steps, events, rhs_evals;
    long exact_steps;             /* of the steps, those taken exactly on the floor */
    long stage_steps[6];          /* accepted steps (or exact intervals) per stage */
    rb_history *history;          /* owned; NULL unless asked for */
} rb_result;

/* Run one model under one motion. out is overwritten; free it with
 * rb_result_free. On error the status says why and diag (may be NULL) names
 * the time and stage in diag->msg; out holds what was reached. */
rb_status rb_solve_run(const rb_model *model, const rb_motion *motion,
                       const rb_solve_opts *opts, rb_result *out, rb_diag *diag);

/* Free what a result owns (its history); accepts NULL. */
void rb_result_free(rb_result *r);

#endif
