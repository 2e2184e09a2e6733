/* Spectrum-compatible floor motions: a seeded random motion shaped by a
 * time envelope and matched to a target spectrum in the frequency domain
 * (docs/motion.md, "Synthetic motions"). The same seed gives the same
 * motion on every machine and thread count. No I/O. */
#ifndef ROCKBOLT_SYNTH_H
#define ROCKBOLT_SYNTH_H

#include <stdint.h>
#include "rockbolt/accept.h"
#include "rockbolt/motion.h"
#include "rockbolt/names.h"
#include "rockbolt/spectrum.h"
#include "rockbolt/status.h"

typedef struct {
    const rb_target *target;  /* borrowed */
    double dt_s;              /* sample interval, default 0.005 s */
    double total_s;           /* default 30 s (AC156) */
    double strong_s;          /* the envelope's full-level part, default
                                 22 s; the rest is split between a rise and
                                 a decay, both cosine tapers */
    uint64_t seed;
    unsigned index;           /* the motion's place in its suite: each has
                                 its own random stream */
    unsigned max_iterations;  /* matching passes in all, default 128; a
                                 start that has not converged after 16 is
                                 replaced by a new random one */
    const rb_accept_rules *rules; /* borrowed; NULL: rb_accept_rules_init of
                                     the target */
    /* The table's envelope: the largest displacement and velocity a motion
     * may ask of it (defaults 0.15 m and 1.0 m/s); 0: not limited. */
    double table_displacement_m, table_velocity_mps;
} rb_synth_opts;

/* The components of a suite's set: H1 in the model's plane, H2 out of it,
 * V vertical; each its own random stream (index + component x this). */
typedef enum {
    RB_SYNTH_H1 = 0,
    RB_SYNTH_H2,
    RB_SYNTH_V
} rb_synth_component;
#define RB_SYNTH_COMPONENT_STREAM 0x10000u
/* What a suite's entry generates: the horizontal alone, or the set. */
typedef enum {
    RB_SYNTH_HORIZONTAL = 0,
    RB_SYNTH_TRIAXIAL
} rb_synth_components;
extern const rb_enum_name rb_synth_components_names[]; /* horizontal, triaxial */

#define RB_SYNTH_TABLE_DISPLACEMENT_M 0.15
#define RB_SYNTH_TABLE_VELOCITY_MPS 1.0
/* The least peak a generated motion reaches, over the target's least
 * (AC156: 0.95 A_RIG against the 0.9 A_RIG of 6.5.4.2.3), for the table's
 * reproduction error. */
#define RB_SYNTH_PEAK_MARGIN (0.95 / 0.9)

void rb_synth_opts_init(rb_synth_opts *o, const rb_target *target);

/* The ranges rb_synth_generate takes (docs/robustness.md). */
#define RB_SYNTH_MIN_TOTAL_S 2.0     /* duration; strong alike */
#define RB_SYNTH_MAX_TOTAL_S 600.0
#define RB_SYNTH_MIN_DT_S 1e-3
#define RB_SYNTH_MAX_DT_S 0.02

/* AC156's proportion, 22 s at full level of 30, for a motion of total_s;
 * never under the 2 s a strong part needs, nor over total_s. */
double rb_synth_default_strong(double total_s);

/* 1 when o is what rb_synth_generate takes; else 0, with *key the option
 * at fault ("spectrum", "dt", "duration", "strong") and in why its value
 * and its limit, for the caller to report at that key. */
int rb_synth_opts_check(const rb_synth_opts *o, const char **key, char *why, size_t n);

/* What a generated motion is, as the reports state it. */
typedef struct {
    double peak_mps2;          /* peak floor acceleration */
    double arias_t5_s, arias_t95_s; /* 5 % and 95 % of the Arias intensity */
    double arias_mps;          /* the Arias intensity, pi / (2 g) int a^2 dt */
    double end_velocity_mps;   /* after baseline correction */
    double end_displacement_m;
    double peak_velocity_mps, peak_displacement_m;
    rb_target_fit fit;         /* against the target, at its check points */
    rb_motion_summary summary; /* the laboratory's acceptance, and the
                                  peaks the table must reach */
    unsigned iterations;       /* matching passes made, in all */
    unsigned attempts;         /* random starts made */
} rb_synth_info;

/* Generate one motion into out (free with rb_series_free): RB_OK when it
 * meets the laboratory's rules at every offset (summary.accept.pass), stays
 * under the upper band within the cutoffs and within [0.9, 1.3] of the
 * target above the high cutoff to the rules' tail, reaches
 * RB_SYNTH_PEAK_MARGIN times the target's least peak, and stays within the
 * table's envelope; RB_ERR_INVALID for options out of range (a target, dt
 * from 1 ms to 0.02 s with the check range's top below 0.4 / dt,
 * 2 s <= strong <= total <= 600 s); RB_ERR_LIMIT when the matching passes
 * run out first (out then holds the closest motion and info says how
 * close: fit, summary); RB_ERR_NOMEM. */
rb_status rb_synth_generate(const rb_synth_opts *o, rb_series *out, rb_synth_info *info);

/* Fill what info says of a motion that can be measured on it (all but
 * iterations and attempts), for a motion that was generated before: a
 * cached copy. RB_ERR_NOMEM, RB_ERR_INVALID. */
rb_status rb_synth_describe(const rb_target *t, const rb_series *s, rb_synth_info *info);

/* ---- statistical independence of a set's components -------------------
 * AC156 5.2.2.7.3 asks the simultaneous motions of a test to be
 * statistically independent; laboratories check it as (docs/motion.md):
 * the largest |normalised cross-correlation| over all lags at most 0.3,
 * and the largest magnitude-squared coherence (Welch, Hann windows of
 * 1.25 s overlapping by half, the first and last 5 s left out) at the
 * 1/72-octave frequencies from 1.3 to 33.3 Hz at most 0.5. */
#define RB_SYNTH_MAX_CORRELATION 0.3
#define RB_SYNTH_MAX_COHERENCE 0.5
#define RB_SYNTH_COHERENCE_WINDOW_S 1.25
#define RB_SYNTH_COHERENCE_TRIM_S 5.0

typedef struct {
    double correlation;   /* max over lags of |sum a b| / (n sd_a sd_b) */
    double coherence;     /* max over the frequencies; NaN for a motion
                             too short for two windows after the trim
                             (not judged) */
    int independent;      /* both at or under their limits */
} rb_synth_pair;

/* The independence of two motions of one sample interval and length.
 * RB_ERR_INVALID (different intervals or lengths), RB_ERR_NOMEM. */
rb_status rb_synth_independence(const rb_series *a, const rb_series *b, rb_synth_pair *out);

#endif
