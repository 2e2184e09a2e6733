/* Response spectra of floor motions, and the target spectra they are
 * compared with or matched to.
 *
 * A response spectrum is the peak response of a linear single-degree-of-
 * freedom oscillator of frequency f and damping xi standing on the floor:
 * the pseudo-acceleration w^2 max|u| and the absolute acceleration
 * max|u'' + floor|. The oscillator is stepped exactly for a floor that is
 * linear between samples, and through a building for the ground that is
 * linear between samples (building and oscillator as one linear system),
 * so that the spectrum is that of the motion the solver sees. No I/O. */
#ifndef ROCKBOLT_SPECTRUM_H
#define ROCKBOLT_SPECTRUM_H

#include <stddef.h>
#include "rockbolt/motion.h"
#include "rockbolt/status.h"
#include "rockbolt/names.h"

/* The analysis grid: f_min * 2^(k / per_octave) for k = 0, 1, ... up to
 * f_max (included when it falls on the grid to 1e-9). */
typedef struct {
    double damping;     /* xi, default 0.05 */
    double f_min_hz;    /* default 0.5 */
    double f_max_hz;    /* default 50 */
    double per_octave;  /* default 12 */
} rb_spectrum_opts;

#define RB_SPECTRUM_MAX_POINTS 2000
/* The frequencies a spectrum is taken at (`spectrum --from`, `--to`) and a
 * target table may name: below 0.001 Hz the oscillator's free period
 * outlasts any motion a thousandfold, above 10 kHz no record is sampled. */
#define RB_SPECTRUM_MIN_HZ 1e-3
#define RB_SPECTRUM_MAX_HZ 1e4
/* A target table's largest ordinate, 1000 g: the cap of `amplitude`,
 * `peak` and AC156's `sds` (1e30 g overflowed the state). */
#define RB_SPECTRUM_MAX_ACCEL_MPS2 (1000.0 * 9.80665)

void rb_spectrum_opts_init(rb_spectrum_opts *o);

typedef struct {
    size_t n;
    double damping;
    /* The largest phase of the fastest mode over one sub-step, in radians:
     * 0.2 from rb_spectrum_alloc (peaks within 4e-6); a quick estimate may
     * take up to 1 (peaks within 3e-3). */
    double step_phase;
    double *freq_hz;    /* owned, n, ascending */
    double *psa_mps2;   /* owned, n: w^2 max|u| */
    double *sa_mps2;    /* owned, n: max |absolute acceleration| */
} rb_spectrum;

/* Allocate the grid of o with zero ordinates. RB_ERR_INVALID when
 * 0 < f_min < f_max, per_octave > 0 and 0 <= damping < 1 do not hold or
 * the grid would exceed RB_SPECTRUM_MAX_POINTS; RB_ERR_NOMEM. */
rb_status rb_spectrum_grid(const rb_spectrum_opts *o, rb_spectrum *sp);
/* Allocate n given frequencies (each > 0, ascending). */
rb_status rb_spectrum_alloc(rb_spectrum *sp, const double *freq_hz, size_t n,
                            double damping);
void rb_spectrum_free(rb_spectrum *sp);

/* Fill the ordinates of sp for the series s multiplied by scale. The
 * oscillator starts at rest with the series and, once the samples end
 * (where the solver's floor stops), vibrates freely for one more of its
 * periods, where its peak may still come. Peaks between the exact states
 * are found on the cubic through their values and slopes, with steps of
 * at most step_phase / w: the cubic's error is (step_phase)^4 / 384 of the
 * peak. RB_ERR_INVALID for an empty series. */
rb_status rb_spectrum_of_series(const rb_series *s, double scale, rb_spectrum *sp);

/* The oscillators of a spectrum made ready for the spectra of many series
 * of one time step on a floor given directly (their exact transitions
 * made once): for a caller that takes the spectrum of every pass of an
 * iteration on one grid. rb_spectrum_of_series_banked gives
 * rb_spectrum_of_series's ordinates (to the bit in test_spectrum_bank),
 * through the bank when it was made for sp's grid, damping and step_phase
 * and the series' step (and the series has no building), by
 * rb_spectrum_of_series otherwise. A run walks again only the intervals
 * that could raise a peak above 0.8 of the last run's, and is made again
 * in full where a peak stays under that.
 * rb_spectrum_bank_new: RB_ERR_INVALID as rb_spectrum_of_series, and
 * RB_ERR_NOMEM. */
typedef struct rb_spectrum_bank rb_spectrum_bank;
rb_status rb_spectrum_bank_new(const rb_spectrum *sp, double dt_s, rb_spectrum_bank **out);
rb_status rb_spectrum_of_series_banked(rb_spectrum_bank *b, const rb_series *s,
                                       double scale, rb_spectrum *sp);
void rb_spectrum_bank_free(rb_spectrum_bank *b);

/* The spectrum of any motion: a sampled one through rb_spectrum_of_series
 * (with its scale); a closed form (harmonic, pulse) sampled every
 * 1 / (200 f_max) s over its duration first, a straight-line
 * approximation whose error that spacing keeps under 1e-4. The polarity
 * does not change a spectrum. RB_ERR_INVALID for the critical excitation,
 * which depends on the response. */
rb_status rb_spectrum_of_motion(const rb_motion *m, rb_spectrum *sp);

/* ---- target spectra ---------------------------------------------------- */

typedef enum {
    RB_TARGET_AC156 = 0,  /* ICC-ES AC156 required response spectrum */
    RB_TARGET_TABLE,      /* frequency / acceleration pairs */
    RB_TARGET_IEEE693,    /* IEEE 693 performance level spectrum */
    RB_TARGET_GR63        /* Telcordia GR-63-CORE: a user's RRS table, judged
                             from 1 to 50 Hz at 2 % (rb_target_gr63) */
} rb_target_kind;
extern const rb_enum_name rb_target_type_names[];   /* rb_target_kind: ac156, table,
                                                       ieee693, gr63 */

/* IEEE 693's qualification levels: High (a ZPA of 1.0 g at 5 %) and
 * Moderate (half of High at every frequency and damping). */
typedef enum {
    RB_IEEE693_HIGH = 0,
    RB_IEEE693_MODERATE
} rb_ieee693_level;
extern const rb_enum_name rb_ieee693_level_names[]; /* rb_ieee693_level: high, moderate */

/* Which AC156 form of the horizontal levels (docs/motion.md):
 * 2010: A_FLX-H = S_DS (1 + 2 z/h) <= 1.6 S_DS, A_RIG-H = 0.4 S_DS (1 + 2 z/h)
 *       (AC156 with ASCE 7-05 to 7-16);
 * 2024: A_FLX-H = S_DS H_f / R_mu <= 1.6 S_DS, A_RIG-H = 0.4 S_DS H_f / R_mu
 *       with ASCE 7-22's H_f and R_mu (rb_asce722_hf, rb_asce722_rmu): the
 *       building's where given, else H_f = 1 + 2.5 z/h and R_mu = 1.3
 *       (1.0 at grade). */
typedef enum {
    RB_AC156_2010 = 0,
    RB_AC156_2024
} rb_ac156_edition;
extern const rb_enum_name rb_ac156_edition_names[]; /* rb_ac156_edition */

/* ASCE 7-22 13.3.1.1, eq. 13.3-4 and 13.3-5: H_f = 1 + a1 z/h + a2 (z/h)^10,
 * a1 = min(1 / T_a, 2.5), a2 = max(0, 1 - (0.4 / T_a)^2); T_a not > 0
 * (unknown): 1 + 2.5 z/h; 1 at or below grade. */
double rb_asce722_hf(double z_over_h, double ta_s, int at_or_below_grade);
/* ASCE 7-22 13.3.1.2, eq. 13.3-6: R_mu = max(1.3, sqrt(1.1 R / (I_e
 * Omega_0))); 1.3 when any of them is not > 0 (unknown); 1 at or below
 * grade. */
double rb_asce722_rmu(double r, double ie, double omega0, int at_or_below_grade);

/* The building an AC156-24 target's H_f and R_mu take (0: not given). */
typedef struct {
    double ta_s;            /* T_a, the building's approximate period */
    double r, ie, omega0;   /* R, I_e, Omega_0: all three or none */
} rb_ac156_building;

typedef struct {
    rb_target_kind kind;
    double damping;         /* of the target's ordinates: 0.05 for AC156 */
    /* AC156 */
    rb_ac156_edition edition;
    double sds_mps2;        /* S_DS as an acceleration */
    double z_over_h;        /* 0 (grade) to 1 (roof) */
    rb_ac156_building building; /* 2024: H_f and R_mu from these */
    /* a second level the RRS envelopes (a laboratory certifies a unit for
     * a roof and a grade S_DS at once): each of A_FLX and A_RIG the larger
     * of the two levels'; sds2_mps2 0: none */
    double sds2_mps2, z_over_h2;
    int vertical;           /* the vertical RRS: AC156's A_FLX-V = 0.67 S_DS,
                               A_RIG-V = 0.27 S_DS, no height term; IEEE
                               693's 80 % of the horizontal */
    /* IEEE 693 */
    rb_ieee693_level level;
    /* table: owned, n points, frequencies ascending; log-log between */
    double *freq_hz;
    double *accel_mps2;
    size_t n;
    /* The frequencies over which a motion must envelope the target, and
     * the band it must stay within there: [lower, upper] x target. */
    double check_from_hz, check_to_hz;
    double band_lower, band_upper;
    double check_per_octave; /* analysis resolution of the check: 6 */
    /* The least peak acceleration a motion must reach: for AC156 0.9
     * A_RIG (the peak table acceleration, AC156-24 6.5.4.2.3); 0: none. */
    double min_peak_mps2;
} rb_target;

/* AC156's horizontal flexible and rigid levels A_FLX-H and A_RIG-H, the
 * building not known. */
void rb_ac156_levels(rb_ac156_edition ed, double sds_mps2, double z_over_h,
                     double *a_flx, double *a_rig);
/* Give an AC156 target the building of its H_f and R_mu (edition 2024)
 * and a second level to envelope (sds2_mps2 0: none); its least peak
 * follows the enveloped A_RIG. */
void rb_target_ac156_more(rb_target *t, const rb_ac156_building *b, double sds2_mps2,
                          double z_over_h2);
/* An AC156 target for S_DS and z/h with the criteria's check range, band
 * and resolution. */
void rb_target_ac156(rb_target *t, rb_ac156_edition ed, double sds_mps2, double z_over_h);
/* AC156's vertical target for S_DS (the same corners, band and least peak
 * of 0.9 A_RIG-V). */
void rb_target_ac156_vertical(rb_target *t, double sds_mps2);
/* The flexible and rigid levels of an AC156 target, either component. */
void rb_target_ac156_levels(const rb_target *t, double *a_flx, double *a_rig);
/* IEEE 693-2005's High performance level spectrum at damping xi (Figure
 * A.1, as CODES.md states it), in units of g:
 *   2.288 beta f                        f <= 1.1 Hz
 *   2.5 beta                            1.1 < f <= 8 Hz
 *   (26.4 beta - 10.56) / f - 0.8 beta + 1.32    8 < f <= 33 Hz
 *   1.0                                 f > 33 Hz
 * beta = (3.21 - 0.68 ln(100 xi)) / 2.1156 (1 at 5 %). */
double rb_ieee693_beta(double damping);
/* An IEEE 693 target of a level at a damping (0 < damping < 1), checked
 * from 1.1 to 33 Hz at 1/6 octave within [0.9, 1.3], its least peak 0.9
 * of its ZPA; vertical: 80 % of the horizontal (Annex A). */
void rb_target_ieee693(rb_target *t, rb_ieee693_level level, double damping, int vertical);
/* A table target (takes ownership of freq and accel, n >= 2, frequencies
 * ascending and > 0, accelerations > 0) checked over its own frequency
 * range at 1/6 octave within [0.9, 1.3], as AC156 does, until
 * rb_target_tolerance says otherwise. */
void rb_target_table(rb_target *t, double *freq_hz, double *accel_mps2, size_t n,
                     double damping);
/* GR-63-CORE's check of a waveform against a user's RRS (CODES.md: TRS >=
 * RRS from 1 to 50 Hz at 2 % damping): a table target (takes ownership
 * as rb_target_table, the table from at most 1 Hz) at 2 %, checked from 1
 * to 50 Hz with no point below 1.0 x RRS; 1.3 is drawn and reported as
 * the guide line, no least peak. */
#define RB_GR63_DAMPING 0.02
#define RB_GR63_FROM_HZ 1.0
#define RB_GR63_TO_HZ 50.0
void rb_target_gr63(rb_target *t, double *freq_hz, double *accel_mps2, size_t n);
/* A table's own tolerance: no point of the TRS below `below` x RRS (the
 * acceptance's lower rule), `above` its upper line (held by the generator,
 * reported by the acceptance). RB_TARGET_MIN_ABOVE: the generator aims up
 * to 1.22 x RRS. */
#define RB_TARGET_MIN_BELOW 0.5
#define RB_TARGET_MIN_ABOVE 1.25
#define RB_TARGET_MAX_ABOVE 3.0
void rb_target_tolerance(rb_target *t, double below, double above);
/* The target's acceleration at f (> 0); a table is constant above its
 * last frequency and falls in proportion to f below its first (the
 * taper, docs/motion.md "Tables"). */
double rb_target_at(const rb_target *t, double f_hz);
void rb_target_free(rb_target *t);

/* How well a spectrum of the target's damping follows it: over the
 * spectrum's points within the check range, the least and the largest
 * ratio of the absolute acceleration to the target (the test response
 * spectrum of a shake table is the absolute acceleration), and where. */
typedef struct {
    double min_ratio, min_at_hz;
    double max_ratio, max_at_hz;
    size_t n_checked;
    int within;   /* every ratio within [band_lower, band_upper] */
} rb_target_fit;

/* Allocate the target's check grid: check_from * 2^(k / check_per_octave)
 * up to check_to, with the target's damping. */
rb_status rb_target_check_grid(const rb_target *t, rb_spectrum *sp);
rb_status rb_target_compare(const rb_target *t, const rb_spectrum *sp,
                            rb_target_fit *fit);

/* ---- spectra of a suite of motions (rb_run_spectra, rockbolt/run.h) --- */

/* One motion's spectrum on the options' grid, and what describes it. */
typedef struct {
    rb_spectrum sp;
    double peak_mps2;          /* peak floor acceleration */
    double arias_mps, arias_t5_s, arias_t95_s; /* over the samples */
    int has_target;            /* a synthetic motion: its target */
    rb_target_fit fit;         /* against it, at its check points and damping */
} rb_motion_spectrum;

typedef struct {
    rb_spectrum_opts opts;
    rb_motion_spectrum *motions;  /* owned, n_motions */
    size_t n_motions;
    double g_mps2;
} rb_case_spectra;

void rb_case_spectra_free(rb_case_spectra *s);

#endif
