/* A testing laboratory's acceptance of a table motion against its required
 * response spectrum, and the summary of a motion that goes with it.
 *
 * The test response spectrum (TRS, the absolute acceleration at the
 * target's damping) is taken on a 1/72-octave grid, 0.1 2^(k/72) Hz; the
 * 1/6-octave points are one of its 12 offsets (k mod 12). At each offset,
 * over the points from the low cutoff to the high cutoff and the nearest
 * point outside each end, with r = TRS / RRS:
 *   - no point below `lower` (0.9);
 *   - no two adjacent points below 1.0;
 *   - at most two points below 1.0 up to `split_hz` (8.3 Hz), and at most
 *     two above it;
 *   - when the user sets `max_ratio`, no point above it (the 1.3 line is
 *     otherwise reported, not enforced).
 * A laboratory picks the most favourable offset; rockbolt asks every one
 * of the 12 to pass, so that a motion passes whichever a laboratory
 * draws. docs/motion.md ("Acceptance") gives the sources. No I/O. */
#ifndef ROCKBOLT_ACCEPT_H
#define ROCKBOLT_ACCEPT_H

#include <stddef.h>
#include "rockbolt/motion.h"
#include "rockbolt/spectrum.h"
#include "rockbolt/status.h"

#define RB_ACCEPT_GRID_FROM_HZ 0.1
#define RB_ACCEPT_PER_OCTAVE 72
#define RB_ACCEPT_OFFSETS 12
/* The grid's top: the rigid end is reported up to 50 Hz. */
#define RB_ACCEPT_GRID_TO_HZ 50.0

typedef struct {
    double damping;         /* of the TRS: the target's */
    double low_cutoff_hz;   /* AC156: rb_accept_low_cutoff, 1.3 by default */
    double high_cutoff_hz;  /* AC156: 33.3 */
    double split_hz;        /* 8.3: the two ranges of "at most two below 1.0" */
    double lower;           /* 0.9: no point below */
    double guide;           /* 1.3: the upper line drawn, reported */
    double max_ratio;       /* 0: none; else no point above it */
    double tail_to_hz;      /* the rigid end is reported from high_cutoff
                               to here (50 Hz); 0: not reported */
} rb_accept_rules;

/* The rules of the target t: its damping, its check range as the cutoffs,
 * its lower band as `lower`, its upper band as the guide; 8.3 Hz split,
 * no max_ratio, the tail to 50 Hz for AC156 and IEEE 693 (their rigid
 * lines, A_RIG and the ZPA; none for a table). */
void rb_accept_rules_init(rb_accept_rules *r, const rb_target *t);

/* The laboratory's low cutoff for a unit whose lowest resonance is
 * f_lowest_hz: max(1.3, min(3.5, 0.75 f_lowest)), rounded up to 0.1 Hz as
 * the laboratory's processing does; 1.3 when f_lowest is not a positive
 * number (no resonance known). */
double rb_accept_low_cutoff(double f_lowest_hz);

/* One offset's verdict. margin is the largest s for which the TRS meets
 * the lower rules against s x RRS: min(min r / lower, the larger r of
 * every adjacent pair, the third smallest r of each range); it passes
 * when margin >= 1 (and max r <= max_ratio when that is set). */
typedef struct {
    double margin;
    double min_ratio, min_at_hz;
    double max_ratio, max_at_hz;
    unsigned below_one_low, below_one_high; /* points below 1.0 in each range */
    int adjacent_below;                     /* two adjacent points below 1.0 */
    size_t n_points;
    int pass;
} rb_accept_offset;

typedef struct {
    rb_accept_offset offset[RB_ACCEPT_OFFSETS];
    unsigned worst;          /* the offset of least margin (ties: the first) */
    double margin;           /* offset[worst].margin */
    /* over every grid point from the low to the high cutoff */
    double min_ratio, min_at_hz, max_ratio, max_at_hz;
    int above_guide;         /* some point above the guide line (reported) */
    /* the rigid end: TRS / RRS over the grid above the high cutoff up to
     * tail_to_hz (NaN when not reported) */
    double tail_min_ratio, tail_max_ratio;
    int pass;                /* every offset passes */
} rb_accept_result;

/* Allocate the part of the acceptance grid the rules need (from the point
 * below the low cutoff to the top; the grid goes on below 0.1 Hz for a
 * table that does), at the rules' damping. RB_ERR_INVALID unless
 * 1.12e-3 Hz <= low < high <= 8909 Hz (an offset's points outside stay in
 * the spectra's range), tail_to <= 50 Hz, 0 <= damping < 1, lower > 0,
 * max_ratio >= 0, and the grid holds at most RB_SPECTRUM_MAX_POINTS. */
rb_status rb_accept_grid(const rb_accept_rules *r, rb_spectrum *sp);

/* Judge a spectrum taken on rb_accept_grid's grid against t. */
rb_status rb_accept_judge(const rb_accept_rules *r, const rb_target *t,
                          const rb_spectrum *sp, rb_accept_result *out);

/* What describes a motion: its peaks, its strong-motion duration and, with
 * a target, its acceptance. */
typedef struct {
    double pga_mps2;            /* rb_series_peak */
    double pgv_mps, pgd_m;      /* from rest, the samples linear between */
    double end_velocity_mps, end_displacement_m;
    double arias_mps, arias_t5_s, arias_t95_s; /* duration: t95 - t5 */
    int has_target;
    rb_accept_result accept;    /* with a target */
    int peak_ok;                /* pga >= the target's least peak (1 without) */
} rb_motion_summary;

/* Summarise s (with its scale 1); t and r may be NULL (no acceptance), r
 * NULL takes rb_accept_rules_init(t). RB_ERR_INVALID, RB_ERR_NOMEM. */
rb_status rb_motion_summarise(const rb_series *s, const rb_target *t,
                              const rb_accept_rules *r, rb_motion_summary *out);

#endif
