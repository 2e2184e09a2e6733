/* Lognormal fragility curves (FEMA P-58): the probability that a limit
 * state is reached at intensity im,
 *
 *     P(im) = Phi(ln(im / median) / beta),
 *
 * fitted by maximum likelihood to the capacities of a suite of motions
 * (the intensity at which each first reaches the limit state). A motion
 * that never reaches it within the range searched is censored: its
 * capacity is only known to exceed the end of the range. No I/O. */
#ifndef ROCKBOLT_FRAGILITY_H
#define ROCKBOLT_FRAGILITY_H

#include <stddef.h>
#include <stdint.h>
#include "rockbolt/status.h"
#include "rockbolt/names.h"

typedef struct {
    double median;     /* intensity at P = 0.5 */
    double beta;       /* lognormal dispersion (standard deviation of ln) */
    double loglik;     /* log-likelihood at the fit */
    int iterations;
} rb_fragility_fit;

/* Maximum-likelihood fit to n capacities > 0, censored[i] != 0 marking a
 * capacity known only to exceed capacity[i] (censored may be NULL: none).
 * Without censoring the fit is the closed form (mean and standard
 * deviation, over n, of ln capacity); with it, the EM iteration for a
 * right-censored normal, to 1e-12 relative. RB_ERR_INVALID for fewer than
 * two uncensored capacities, a capacity that is not finite and > 0, or
 * uncensored capacities all equal (no dispersion to fit). */
rb_status rb_fragility_mle(const double *capacity, const int *censored, size_t n,
                           rb_fragility_fit *out);

/* P(im) of a fit; 0 for im <= 0. */
double rb_fragility_prob(const rb_fragility_fit *f, double im);
/* The intensity at probability 0 < p < 1. */
double rb_fragility_quantile(const rb_fragility_fit *f, double p);

/* The standard normal distribution and its inverse (0 < p < 1). */
double rb_normal_cdf(double z);
double rb_normal_quantile(double p);

/* A percentile-bootstrap confidence interval of the median at the given
 * level (0.9: 5th to 95th percentile): the motions resampled with
 * replacement n_boot times from a seeded generator (the same interval on
 * every machine), each resample refitted; resamples that cannot be fitted
 * are skipped and counted in *skipped (may be NULL). RB_ERR_NOMEM, or
 * RB_ERR_INVALID as rb_fragility_mle for the whole sample, or when fewer
 * than half the resamples can be fitted. */
rb_status rb_fragility_bootstrap(const double *capacity, const int *censored, size_t n,
                                 unsigned n_boot, uint64_t seed, double level,
                                 double *lo, double *hi, unsigned *skipped);

/* ---- A case's fragility (rb_run_fragility, rockbolt/run.h) ------------ */

/* The bootstrap's resamples in `rockbolt fragility` and `batch --fragility`,
 * which must agree to give the same interval. */
#define RB_FRAGILITY_RESAMPLES 1000
/* The level of its interval of the median (5th to 95th percentile). */
#define RB_FRAGILITY_INTERVAL 0.9

typedef enum {
    RB_LIMIT_FIRST_YIELD = 0, /* a bolt row yields or reaches Fy */
    RB_LIMIT_USAGE,           /* toughness usage reaches the case's limit
                                 (no-break's, else 1) */
    RB_LIMIT_OVERTURN,        /* the cabinet overturns, bolts stretching on */
    RB_LIMIT_LIFT_OFF,        /* the base lifts off the floor (the validity
                                 check), bolts stretching on */
    RB_LIMIT_ANCHORAGE,       /* the concrete check fails as the judge fails
                                 it: the 17.8 utilization of the run's own
                                 demand reaches 1, or the 17.10.5.3 route the
                                 judge applies is not met; bolts stretching
                                 on. Only a case with concrete: has it */
    RB_N_LIMITS
} rb_limit_state;
extern const rb_enum_name rb_limit_state_names[];   /* rb_limit_state (fragility.h) */

/* The limit state that governs a case's fragility: of the limit states in
 * the mask `judged` (bit 1 << k) that are fitted, the one of the lowest
 * median; of medians that are equal, the first in rb_limit_state's order.
 * -1 when none of them is fitted. One rule for every output (the fragility
 * report, batch --fragility, merge and the P-58 row). */
int rb_fragility_governing(unsigned judged, const int fitted[RB_N_LIMITS],
                           const double median[RB_N_LIMITS]);

/* Each motion's capacity for each limit state: the lowest peak floor
 * acceleration found to reach it (the design factor's scan and bisection,
 * with the case's design: settings), or, censored, the top of the scan
 * that never reached it. A motion whose vertical, scaled with the level,
 * reaches -g below the state's crossing has the model's limit instead
 * (model_limited): the level model_limit_mps2 at which it does, where the
 * base would be thrown off the floor, which the model does not follow.
 * The bolts' own capacity lies above it and is not measured; the fit
 * counts it as reached there, so that its median is a lower bound
 * (docs/fragility.md, "Capacities limited by the model"). */
typedef struct {
    double capacity_mps2[RB_N_LIMITS];
    int censored[RB_N_LIMITS];
    int model_limited[RB_N_LIMITS];
    long runs;
    double im_per_pfa;  /* the intensity over the peak floor acceleration:
                           1, or Sa(f0) / peak (linear in the level) */
    double model_limit_mps2; /* where the vertical reaches -g (in the
                                intensity); HUGE_VAL without one */
} rb_motion_fragility;

/* The intensity measure capacities and levels are given in. */
typedef enum {
    RB_IM_PFA = 0,  /* peak floor acceleration */
    RB_IM_SA        /* 5 % pseudo-spectral acceleration at the cabinet's
                       fixed-base frequency */
} rb_fragility_intensity;
extern const rb_enum_name rb_intensity_names[];        /* pfa, sa */
/* the same, as the JSON reports spell it: peak_floor_acceleration,
 * spectral_acceleration */
extern const rb_enum_name rb_intensity_report_names[];

typedef struct {
    rb_motion_fragility *motions;   /* owned, one per motion of the case */
    size_t n_motions;
    /* the limit states the case has (bit 1 << k): all but the anchorage's,
     * which only a case with concrete: has; an absent state has no search,
     * no capacities and no fit, and no output shows it */
    unsigned present;
    /* those the case's own verdict fails on (rb_run_fragility_judged), and
     * the one of them that governs (rb_fragility_governing; -1: none) */
    unsigned judged;
    int governing;
    /* the limit states whose capacities are confirmed at tighter
     * tolerances: the governing state's (rb_run_fragility); the others'
     * are points of fitted curves, each searched at the run's own
     * tolerance */
    unsigned confirmed;
    rb_fragility_intensity intensity;
    double im_freq_hz, im_damping;  /* RB_IM_SA: where Sa is taken */
    double level_mps2;              /* the case's own level: motion 1's
                                       intensity (its peak, or its Sa) */
    double g_mps2, a_star_mps2;
    uint64_t seed;                  /* of the bootstrap */
    unsigned n_boot;
    int fitted[RB_N_LIMITS];        /* 0: fewer than two motions reached it */
    rb_fragility_fit fit[RB_N_LIMITS]; /* median in m/s^2 */
    double median_lo[RB_N_LIMITS], median_hi[RB_N_LIMITS]; /* 90 % bootstrap */
    double p_at_level[RB_N_LIMITS]; /* P of the limit state at level_mps2 */
    double im10[RB_N_LIMITS], im50[RB_N_LIMITS]; /* levels at P = 10 %, 50 % */
    long runs;                      /* the searches' runs, each counted by
                                       every search that reads it */
    long solves;                    /* solver runs made: a run the searches
                                       share, or a confirming run, once */
} rb_case_fragility;

void rb_case_fragility_free(rb_case_fragility *f);

/* How many motions' capacities of limit state k are the model's limit
 * (rb_motion_fragility.model_limited). */
size_t rb_case_fragility_model_limited(const rb_case_fragility *f, int k);

/* Whether f has limit state k (its present mask). */
int rb_case_fragility_has(const rb_case_fragility *f, int k);

/* The limit states of a mask, in rb_limit_state's order, as "usage,
 * overturn, anchorage" ("none" for an empty mask). */
void rb_limit_states_str(unsigned mask, char *buf, size_t n);

/* A case's fragility at each gap ratio of a sweep
 * (rb_run_fragility_gap_sweep, rockbolt/run.h). */
typedef struct {
    double *gap_ratios;             /* owned, as the caller gave them */
    rb_case_fragility *points;      /* owned, one per gap ratio */
    size_t n_points;
} rb_fragility_sweep;

void rb_fragility_sweep_free(rb_fragility_sweep *s);

#endif
