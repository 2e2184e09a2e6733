/* Spectrum-compatible floor motions: a seeded random motion shaped by a
 * time envelope and matched to a target spectrum in the frequency domain
 * (docs/motion.md, "Synthetic motions"). The same seed gives the same
 * motion on every machine and thread count. No I/O. */
#ifndef ROCKBOLT_SYNTH_H
#define ROCKBOLT_SYNTH_H

#include <stdint.h>
#include "rockbolt/motion.h"
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
} rb_synth_opts;

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
    unsigned iterations;       /* matching passes made, in all */
    unsigned attempts;         /* random starts made */
} rb_synth_info;

/* Generate one motion into out (free with rb_series_free): RB_OK when it
 * envelopes the target within the target's band at every check point
 * (fit.within); RB_ERR_INVALID for options out of range (a target, dt
 * from 1 ms to 0.02 s with the check range's top below 0.4 / dt,
 * 2 s <= strong <= total <= 600 s); RB_ERR_LIMIT when the matching passes
 * run out first (out then holds the closest motion and info says how
 * close); RB_ERR_NOMEM. */
rb_status rb_synth_generate(const rb_synth_opts *o, rb_series *out, rb_synth_info *info);

/* Fill what info says of a motion that can be measured on it (all but
 * iterations and attempts), for a motion that was generated before: a
 * cached copy. RB_ERR_NOMEM, RB_ERR_INVALID. */
rb_status rb_synth_describe(const rb_target *t, const rb_series *s, rb_synth_info *info);

#endif
