/* Spectrum-compatible motions by iterative correction of Fourier
 * amplitudes (Gasparini and Vanmarcke, SIMQKE, MIT report R76-4, 1976):
 *
 *   s(t) = sum_k A_k cos(2 pi f_k t + phi_k)   (one inverse real FFT)
 *   a(t) = e(t) s(t), then baseline-corrected
 *   A_k <- A_k * aim * target(f_k) / TRS(f_k)
 *
 * with random phases phi_k from the seeded generator, fixed through the
 * passes, and the ratio interpolated in log-log between the frequencies
 * where the response spectrum is computed. The frequency-domain method
 * is chosen over time-domain wavelets (RspMatch: Abrahamson 1992, Hancock
 * et al. 2006) because there is no recorded seed whose phasing must be
 * kept: the seed is random, and correcting all frequencies at once in one
 * FFT per pass is fast and never creates the local drifts that wavelet
 * corrections need tapering for. Why it converges: the response of a
 * lightly damped oscillator at f is governed by the motion's content near
 * f, so scaling that content scales the ordinate nearly in proportion. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/synth.h"
#include "synth_internal.h"
#include "fft.h"
#include "util/rng.h"

/* What the generator aims at, as a ratio of the spectrum to the target, by
 * zone: within the cutoffs [AIM_LO, AIM_HI] (every point at or above the
 * target, so that every offset passes the laboratory's rules with room);
 * above the high cutoff to the rules' tail [TAIL_AIM_LO, TAIL_AIM_HI];
 * within 1/3 octave below the low cutoff (where the laboratory's code
 * takes one point of each offset, and the oscillators still answer the
 * content at the cutoff) [EDGE_AIM_LO, EDGE_AIM_HI]; from there down, at
 * most the target's own line (1), and less where the table's envelope
 * needs it. A point within its aim is left alone, so that the passes do
 * not fight over points already accepted. */
#define SYNTH_AIM_LO 1.05
#define SYNTH_AIM_HI 1.22
#define SYNTH_TAIL_AIM_LO 1.0
#define SYNTH_TAIL_AIM_HI 1.12
#define SYNTH_EDGE_AIM_LO 1.0
#define SYNTH_EDGE_AIM_HI 1.15
/* What a motion must meet: within the cutoffs [1, band_upper] at the
 * correction points (the laboratory's rules on the fine grid), above them
 * [TAIL_LOWER, TAIL_UPPER] of the target, within 1/3 octave below them at
 * most band_upper, further below at most the target. */
#define SYNTH_FLOOR 1.0
#define SYNTH_TAIL_LOWER 0.9
#define SYNTH_TAIL_UPPER 1.3
#define SYNTH_BELOW_MAX 1.0
/* Aimed a little under the line below the cutoffs' zone: a pass counts
 * as met there at 1 less the quick spectrum's slack (3e-3), and a ratio
 * aimed at the line itself stalls just above that. */
#define SYNTH_BELOW_AIM_HI 0.97
/* The correction grid: 1/12 octave from half the low cutoff to the top
 * (the tail's end, or the high cutoff), finer in proportion below 5 %
 * damping: an oscillator's half-power band is 2 xi wide (1/7 octave at
 * 5 %, 1/17 at 2 %), and a grid coarser than that misses the peaks
 * between its points that the laboratory's 1/72-octave grid finds, so
 * that passes alternating between the grids undo each other (IEEE 693 at
 * 2 %: 30 points an octave). */
#define SYNTH_PER_OCTAVE 12.0
#define SYNTH_GRID_DAMPING 0.05
#define SYNTH_BELOW 0.5
/* Content above the top fades out (cos^2) by this multiple of it (or
 * 0.4 / dt). The peak is lifted by content there, where it raises the
 * peak acceleration more than any ordinate aimed at (an oscillator at the
 * top passes 1 / (r^2 - 1) of content at r times its frequency), with a
 * weight that grows from 0 at SYNTH_LIFT_FROM to 1 at SYNTH_LIFT_FULL
 * times it (an oscillator at the top answers content just above it). */
#define SYNTH_FADE 1.6
#define SYNTH_LIFT_FROM 1.15
#define SYNTH_LIFT_FULL 1.35
#define SYNTH_LIFT_GAIN 2.0
/* The envelope is aimed at with this margin. */
#define SYNTH_ENVELOPE_AIM 0.95
/* A random start that does not converge in SYNTH_PASSES passes is
 * replaced by another, up to the options' passes in all: with the phases
 * fixed, the peak factor is too. */
#define SYNTH_PASSES 16
/* Phase draws a start picks its peak factor from. */
#define SYNTH_CANDIDATES 8
/* Passes use a quick spectrum (peaks within 3e-3, rb_spectrum's
 * step_phase, found low, never high); its verdicts keep that much room. */
#define SYNTH_QUICK_PHASE 1.0
#define SYNTH_QUICK_SLACK 3e-3

void rb_synth_opts_init(rb_synth_opts *o, const rb_target *target)
{
    memset(o, 0, sizeof *o);
    o->target = target;
    o->dt_s = 0.005;
    o->total_s = 30.0;
    o->strong_s = 22.0;
    o->max_iterations = 128;
    o->table_displacement_m = RB_SYNTH_TABLE_DISPLACEMENT_M;
    o->table_velocity_mps = RB_SYNTH_TABLE_VELOCITY_MPS;
}

double rb_synth_default_strong(double total_s)
{
    /* 22/30 of a 2.5 s motion is 1.83 s, under the 2 s minimum: documented
     * durations from 2 s were refused by their own default */
    double s = total_s * 22.0 / 30.0;
    if (s < RB_SYNTH_MIN_TOTAL_S)
        s = RB_SYNTH_MIN_TOTAL_S;
    return s < total_s ? s : total_s;
}

typedef struct {
    const rb_synth_opts *o;
    rb_accept_rules rules;
    size_t n;                /* samples */
    double rise_s, decay_s;
    double top_hz;           /* the highest frequency aimed at */
    double peak_want;        /* the least peak aimed at; 0: none */
    rb_fft_real fft;
    double *amp;             /* per bin */
    double *cos_phase, *sin_phase; /* per bin: of its random phase, drawn once */
    double *envelope;        /* per sample */
    rb_spectrum grid;        /* the correction frequencies */
    double *target;          /* the target at grid */
    rb_spectrum fine;        /* the laboratory's grid (rb_accept_grid) */
    double *fine_target;
    double *log_ratio;       /* per point of either grid */
    rb_spectrum_bank *grid_bank, *fine_bank; /* the grids' oscillators, made once */
    rb_synth_baseline_basis baseline;
    double pgv, pgd;         /* of the last motion made */
} generator;

static void generator_free(generator *g)
{
    rb_fft_real_free(&g->fft);
    free(g->amp);
    free(g->cos_phase);
    free(g->sin_phase);
    free(g->envelope);
    free(g->target);
    free(g->fine_target);
    free(g->log_ratio);
    rb_spectrum_free(&g->grid);
    rb_spectrum_free(&g->fine);
    rb_spectrum_bank_free(g->grid_bank);
    rb_spectrum_bank_free(g->fine_bank);
    rb_synth_baseline_free(&g->baseline);
}

int rb_synth_opts_check(const rb_synth_opts *o, const char **key, char *why, size_t n)
{
    const rb_target *t = o ? o->target : NULL;
    *key = "spectrum";
    if (!t || !(t->check_from_hz > 0) || !(t->check_to_hz > t->check_from_hz)) {
        snprintf(why, n, "the target's check range must be a band of positive "
                 "frequencies");
        return 0;
    }
    *key = "dt";
    if (!(o->dt_s >= RB_SYNTH_MIN_DT_S && o->dt_s <= RB_SYNTH_MAX_DT_S)) {
        snprintf(why, n, "dt (%g s) must be from %g to %g s", o->dt_s, RB_SYNTH_MIN_DT_S,
                 RB_SYNTH_MAX_DT_S);
        return 0;
    }
    if (!(t->check_to_hz < 0.4 / o->dt_s)) {
        snprintf(why, n, "the target is checked up to %g Hz, which needs samples at "
                 "most %g s apart (dt is %g s)", t->check_to_hz,
                 0.4 / t->check_to_hz * 0.999, o->dt_s);
        return 0;
    }
    *key = "duration";
    if (!(o->total_s >= RB_SYNTH_MIN_TOTAL_S && o->total_s <= RB_SYNTH_MAX_TOTAL_S)) {
        snprintf(why, n, "duration (%g s) must be from %g to %g s", o->total_s,
                 RB_SYNTH_MIN_TOTAL_S, RB_SYNTH_MAX_TOTAL_S);
        return 0;
    }
    *key = "strong";
    if (!(o->strong_s >= RB_SYNTH_MIN_TOTAL_S && o->strong_s <= o->total_s)) {
        snprintf(why, n, "strong (%g s) must be from %g s to the duration (%g s)",
                 o->strong_s, RB_SYNTH_MIN_TOTAL_S, o->total_s);
        return 0;
    }
    *key = "table";
    if (!(o->table_displacement_m >= 0 && o->table_velocity_mps >= 0)
        || !isfinite(o->table_displacement_m) || !isfinite(o->table_velocity_mps)) {
        snprintf(why, n, "the table's displacement and velocity must be positive "
                 "(or 0 for no limit)");
        return 0;
    }
    *key = "spectrum";
    rb_accept_rules own;
    const rb_accept_rules *r = o->rules;
    if (!r) {
        rb_accept_rules_init(&own, t);
        r = &own;
    }
    rb_spectrum probe;
    if (rb_accept_grid(r, &probe) != RB_OK) {
        snprintf(why, n, "the acceptance's cutoffs (%g to %g Hz) and damping (%g) are "
                 "out of range", r->low_cutoff_hz, r->high_cutoff_hz, r->damping);
        return 0;
    }
    rb_spectrum_free(&probe);
    double top = r->tail_to_hz > r->high_cutoff_hz ? r->tail_to_hz : r->high_cutoff_hz;
    *key = "dt";   /* dt is what is too coarse for the rigid end */
    if (!(top < 0.4 / o->dt_s)) {
        snprintf(why, n, "the motion is shaped up to %g Hz, which needs samples at most "
                 "%g s apart (dt is %g s)", top, 0.4 / top * 0.999, o->dt_s);
        return 0;
    }
    *key = "";
    if (o->max_iterations < 1) {
        snprintf(why, n, "at least one matching pass is needed");
        return 0;
    }
    return 1;
}


static int options_ok(const rb_synth_opts *o)
{
    const char *key;
    char why[200];
    return rb_synth_opts_check(o, &key, why, sizeof why);
}

/* The aim [lo, hi] and the bounds [ok_lo, ok_hi] of the ratio at f. */
static void aim_at(const generator *g, double f, double *lo, double *hi, double *ok_lo,
                   double *ok_hi)
{
    const rb_accept_rules *r = &g->rules;
    if (f < r->low_cutoff_hz * (1 - 1e-9)) {
        int edge = f * exp2(1.0 / 3.0) > r->low_cutoff_hz * (1 + 1e-9);
        *lo = edge ? SYNTH_EDGE_AIM_LO : 0.0;
        *hi = edge ? SYNTH_EDGE_AIM_HI : SYNTH_BELOW_AIM_HI;
        *ok_lo = 0.0;
        *ok_hi = edge ? g->o->target->band_upper : SYNTH_BELOW_MAX;
    } else if (f <= r->high_cutoff_hz * (1 + 1e-9)) {
        *lo = SYNTH_AIM_LO;
        *hi = SYNTH_AIM_HI;
        *ok_lo = SYNTH_FLOOR;
        *ok_hi = g->o->target->band_upper;
    } else {
        *lo = SYNTH_TAIL_AIM_LO;
        *hi = SYNTH_TAIL_AIM_HI;
        *ok_lo = SYNTH_TAIL_LOWER;
        *ok_hi = SYNTH_TAIL_UPPER;
    }
}

static rb_status grid_targets(const rb_target *t, const rb_spectrum *sp, double **out)
{
    *out = malloc(sp->n * sizeof **out);
    if (!*out)
        return RB_ERR_NOMEM;
    for (size_t i = 0; i < sp->n; i++)
        (*out)[i] = rb_target_at(t, sp->freq_hz[i]);
    return RB_OK;
}

static rb_status generator_init(generator *g, const rb_synth_opts *o)
{
    memset(g, 0, sizeof *g);
    g->o = o;
    if (o->rules)
        g->rules = *o->rules;
    else
        rb_accept_rules_init(&g->rules, o->target);
    g->n = (size_t)llround(o->total_s / o->dt_s) + 1;
    g->rise_s = g->decay_s = 0.5 * (o->total_s - o->strong_s);
    const rb_target *t = o->target;
    const rb_accept_rules *r = &g->rules;
    g->top_hz = r->tail_to_hz > r->high_cutoff_hz ? r->tail_to_hz : r->high_cutoff_hz;
    g->peak_want = RB_SYNTH_PEAK_MARGIN * t->min_peak_mps2;
    /* the grid is anchored at the low cutoff */
    double per_octave = SYNTH_PER_OCTAVE;
    if (r->damping < SYNTH_GRID_DAMPING)
        per_octave = ceil(SYNTH_PER_OCTAVE * SYNTH_GRID_DAMPING / r->damping);
    int j0 = (int)floor(log2(SYNTH_BELOW) * per_octave);
    int j1 = (int)floor(log2(g->top_hz / r->low_cutoff_hz) * per_octave + 1e-9);
    size_t m = (size_t)(j1 - j0 + 1);
    double *f = malloc(m * sizeof *f);
    if (!f)
        return RB_ERR_NOMEM;
    for (size_t i = 0; i < m; i++)
        f[i] = r->low_cutoff_hz * exp2((double)(j0 + (int)i) / per_octave);
    rb_status st = rb_spectrum_alloc(&g->grid, f, m, r->damping);
    free(f);
    if (st == RB_OK)
        st = rb_accept_grid(r, &g->fine);
    if (st == RB_OK)
        st = grid_targets(t, &g->grid, &g->target);
    if (st == RB_OK)
        st = grid_targets(t, &g->fine, &g->fine_target);
    /* an FFT period of at least twice the motion: the stationary part
     * does not wrap onto itself within it */
    if (st == RB_OK)
        st = rb_fft_real_init(&g->fft, 2 * g->n);
    g->grid.step_phase = g->fine.step_phase = SYNTH_QUICK_PHASE;
    if (st == RB_OK)
        st = rb_spectrum_bank_new(&g->grid, o->dt_s, &g->grid_bank);
    if (st == RB_OK)
        st = rb_spectrum_bank_new(&g->fine, o->dt_s, &g->fine_bank);
    if (st == RB_OK)
        st = rb_synth_baseline_init(&g->baseline, g->n, o->dt_s);
    if (st != RB_OK)
        return st;
    size_t bins = g->fft.n / 2 + 1;
    size_t most = m > g->fine.n ? m : g->fine.n;
    g->amp = calloc(bins, sizeof *g->amp);
    g->cos_phase = calloc(bins, sizeof *g->cos_phase);
    g->sin_phase = calloc(bins, sizeof *g->sin_phase);
    g->envelope = malloc(g->n * sizeof *g->envelope);
    g->log_ratio = malloc(most * sizeof *g->log_ratio);
    if (!g->amp || !g->cos_phase || !g->sin_phase || !g->envelope || !g->log_ratio)
        return RB_ERR_NOMEM;
    for (size_t i = 0; i < g->n; i++)
        g->envelope[i] = rb_synth_envelope((double)i * o->dt_s, g->rise_s, o->strong_s,
                                           g->decay_s);
    return RB_OK;
}

/* cos^2 from 1 at the top to 0 at SYNTH_FADE times it */
static double fade(const generator *g, double f)
{
    if (f <= g->top_hz)
        return 1.0;
    double end = SYNTH_FADE * g->top_hz;
    if (end > 0.4 / g->o->dt_s)
        end = 0.4 / g->o->dt_s;
    if (end <= g->top_hz)
        return 0.0;
    double x = (f - g->top_hz) / (end - g->top_hz);
    if (x >= 1.0)
        return 0.0;
    double c = cos(0.5 * M_PI * x);
    return c * c;
}

static void synthesise(generator *g, double *a);

/* Random phases and the first amplitudes from stream `stream`. */
static void draw(generator *g, uint64_t stream)
{
    const rb_synth_opts *o = g->o;
    const rb_target *t = o->target;
    rb_rng rng;
    rb_rng_seed(&rng, o->seed ^ (0x9E3779B97F4A7C15ull * (stream + 1)));
    size_t bins = g->fft.n / 2 + 1;
    double df = 1.0 / ((double)g->fft.n * o->dt_s);
    double f_lo = g->grid.freq_hz[0], f_hi = SYNTH_FADE * g->top_hz;
    if (f_hi > 0.4 / o->dt_s)
        f_hi = 0.4 / o->dt_s;
    g->amp[0] = g->cos_phase[0] = g->sin_phase[0] = 0.0;
    for (size_t k = 1; k < bins; k++) {
        double fk = (double)k * df;
        double phase = 2.0 * M_PI * rb_rng_uniform(&rng);
        g->cos_phase[k] = cos(phase);
        g->sin_phase[k] = sin(phase);
        g->amp[k] = fk >= f_lo && fk <= f_hi ? fade(g, fk) * rb_target_at(t, fk) / sqrt(fk)
                                             : 0.0;
    }
}

/* The peak over the root mean square of the motion of the current phases
 * and amplitudes. */
static double crest(generator *g, double *a)
{
    synthesise(g, a);
    double peak = 0, sum = 0;
    for (size_t i = 0; i < g->n; i++) {
        sum += a[i] * a[i];
        if (fabs(a[i]) > peak)
            peak = fabs(a[i]);
    }
    return sum > 0 ? peak / sqrt(sum / (double)g->n) : 0.0;
}

/* A fresh start for attempt number `attempt`: random phases from the
 * motion's own stream, and amplitudes of the target's shape over
 * target / sqrt(f), that of a stationary process whose spectrum is the
 * target (Vanmarcke 1976), from the grid's bottom, fading out above its
 * top. With the phases fixed the peak factor (peak over rms) is too, and
 * the target asks for one: where its flexible level is over twice its
 * rigid one (AC156 at grade, the vertical) the peak of a motion on the
 * plateau runs above the rigid end, which the spectrum at 33 to 50 Hz
 * cannot fall under, so the least peak factor of SYNTH_CANDIDATES phase
 * draws is taken; where it is less (the roof), the peak runs short and
 * the largest is taken. a: room for a motion. */
static void start(generator *g, unsigned attempt, double *a)
{
    const rb_target *t = g->o->target;
    uint64_t base = (((uint64_t)g->o->index << 8) | attempt) * SYNTH_CANDIDATES;
    int least = rb_target_at(t, 5.0) > 2.0 * rb_target_at(t, g->top_hz);
    if (!(t->min_peak_mps2 > 0) || !least) {
        draw(g, base);
        return;
    }
    double best = least ? INFINITY : -INFINITY;
    unsigned pick = 0;
    for (unsigned c = 0; c < SYNTH_CANDIDATES; c++) {
        draw(g, base + c);
        double q = crest(g, a);
        if (least ? q < best : q > best) {
            best = q;
            pick = c;
        }
    }
    draw(g, base + pick);
}

/* The motion of the current amplitudes into a (n samples). */
static void synthesise(generator *g, double *a)
{
    size_t bins = g->fft.n / 2 + 1;
    for (size_t k = 0; k < bins; k++) {
        g->fft.freq[k][0] = g->amp[k] * g->cos_phase[k];
        g->fft.freq[k][1] = g->amp[k] * g->sin_phase[k];
    }
    rb_fft_real_inverse(&g->fft);
    for (size_t i = 0; i < g->n; i++)
        a[i] = g->envelope[i] * g->fft.time[i];
    rb_synth_baseline(&g->baseline, a);
    double v_end, d_end;
    rb_samples_integrate(a, g->n, g->o->dt_s, &v_end, &d_end, &g->pgv, &g->pgd);
}

/* How far past its limit the motion's envelope is (relative; 0 within). */
static double envelope_excess(const generator *g)
{
    double v = 0;
    const rb_synth_opts *o = g->o;
    if (o->table_displacement_m > 0 && g->pgd > o->table_displacement_m)
        v = g->pgd / o->table_displacement_m - 1.0;
    if (o->table_velocity_mps > 0 && g->pgv > o->table_velocity_mps
        && g->pgv / o->table_velocity_mps - 1.0 > v)
        v = g->pgv / o->table_velocity_mps - 1.0;
    return v;
}

/* How far the motion is from what it must be on the spectrum sp (of the
 * targets tg), its peak and its envelope; 0 when it is. slack: the
 * spectrum's own error, kept as room. On the laboratory's grid the dips
 * within the cutoffs are left to its rules (judge_pass). */
static double violation(const generator *g, const rb_spectrum *sp, const double *tg,
                        double peak, double slack)
{
    double v = 0;
    int fine = sp == &g->fine;
    for (size_t i = 0; i < sp->n; i++) {
        double lo, hi, ok_lo, ok_hi, q = sp->sa_mps2[i] / tg[i];
        aim_at(g, sp->freq_hz[i], &lo, &hi, &ok_lo, &ok_hi);
        if (fine && ok_lo == SYNTH_FLOOR)
            ok_lo = 0;   /* the laboratory's rules judge the dips here */
        if (ok_lo * (1 + slack) - q > v)
            v = ok_lo * (1 + slack) - q;
        if (q - ok_hi * (1 - slack) > v)
            v = q - ok_hi * (1 - slack);
    }
    if (g->peak_want > 0 && peak < g->peak_want && 1.0 - peak / g->peak_want > v)
        v = 1.0 - peak / g->peak_want;
    double e = envelope_excess(g);
    return e > v ? e : v;
}

/* The first amplitudes have the target's shape but no scale: one factor
 * brings the spectrum within the cutoffs to the middle of the aim. */
static void normalise(generator *g)
{
    size_t m = g->grid.n, bins = g->fft.n / 2 + 1, used = 0;
    double sum = 0;
    for (size_t i = 0; i < m; i++) {
        double f = g->grid.freq_hz[i];
        if (f < g->rules.low_cutoff_hz || f > g->rules.high_cutoff_hz)
            continue;
        sum += log(g->target[i] / g->grid.sa_mps2[i]);
        used++;
    }
    double f = sqrt(SYNTH_AIM_LO * SYNTH_AIM_HI) * exp(sum / (double)(used ? used : 1));
    for (size_t k = 0; k < bins; k++)
        g->amp[k] *= f;
}

/* Scale the amplitudes by want / SA interpolated on log-log axes between
 * the points of sp (of targets tg); below the low cutoff, by less where
 * the envelope is exceeded; above the high cutoff, by enough to lift a
 * peak short of the aim. */
static void correct(generator *g, const rb_spectrum *sp, const double *tg, double peak)
{
    size_t m = sp->n, bins = g->fft.n / 2 + 1;
    for (size_t i = 0; i < m; i++) {
        double lo, hi, ok_lo, ok_hi, q = sp->sa_mps2[i] / tg[i];
        aim_at(g, sp->freq_hz[i], &lo, &hi, &ok_lo, &ok_hi);
        double want = q < lo ? lo : q > hi ? hi : q;
        g->log_ratio[i] = log(want / q);
    }
    /* the envelope: the content below the low cutoff, which drives the
     * displacement and velocity, is lowered in proportion to the excess,
     * fully under 0.7 of the cutoff and less towards it */
    double e = envelope_excess(g), env = 0;
    if (e > 0)
        env = log(SYNTH_ENVELOPE_AIM / (1.0 + e));
    double low = g->rules.low_cutoff_hz, lift = 0;
    if (g->peak_want > 0 && peak < g->peak_want * 1.01)
        lift = SYNTH_LIFT_GAIN * log(g->peak_want * 1.03 / peak);
    double df = 1.0 / ((double)g->fft.n * g->o->dt_s);
    double lf0 = log(sp->freq_hz[0]), lf1 = log(sp->freq_hz[m - 1]);
    size_t i = 0;
    for (size_t k = 1; k < bins; k++) {
        if (g->amp[k] == 0.0)
            continue;
        double fk = (double)k * df, lf = log(fk), r;
        if (lf <= lf0)
            r = g->log_ratio[0];
        else if (lf >= lf1)
            r = g->log_ratio[m - 1];
        else {
            while (i + 1 < m && sp->freq_hz[i + 1] <= fk)
                i++;
            double x0 = log(sp->freq_hz[i]), x1 = log(sp->freq_hz[i + 1]);
            double w = (lf - x0) / (x1 - x0);
            r = (1 - w) * g->log_ratio[i] + w * g->log_ratio[i + 1];
        }
        if (env < 0 && fk < low) {
            double w = fk <= 0.7 * low ? 1.0 : log(low / fk) / log(1.0 / 0.7);
            r += w * env;
        }
        if (lift > 0 && fk > SYNTH_LIFT_FROM * g->top_hz) {
            double w = (fk / g->top_hz - SYNTH_LIFT_FROM) / (SYNTH_LIFT_FULL - SYNTH_LIFT_FROM);
            r += (w < 1 ? w : 1) * lift;
        }
        g->amp[k] *= exp(r);
    }
}

static rb_status describe(const rb_target *t, const rb_accept_rules *r, const rb_series *s,
                          rb_synth_info *info)
{
    rb_spectrum check;
    rb_status st = rb_target_check_grid(t, &check);
    if (st == RB_OK)
        st = rb_spectrum_of_series(s, 1.0, &check);
    if (st == RB_OK)
        st = rb_target_compare(t, &check, &info->fit);
    rb_spectrum_free(&check);
    if (st == RB_OK)
        st = rb_motion_summarise(s, t, r, &info->summary);
    info->peak_mps2 = info->summary.pga_mps2;
    info->arias_mps = info->summary.arias_mps;
    info->arias_t5_s = info->summary.arias_t5_s;
    info->arias_t95_s = info->summary.arias_t95_s;
    info->end_velocity_mps = info->summary.end_velocity_mps;
    info->end_displacement_m = info->summary.end_displacement_m;
    info->peak_velocity_mps = info->summary.pgv_mps;
    info->peak_displacement_m = info->summary.pgd_m;
    return st;
}

rb_status rb_synth_describe(const rb_target *t, const rb_series *s, rb_synth_info *info)
{
    return describe(t, NULL, s, info);
}

/* One pass's verdict: the quick spectrum on the correction grid and, when
 * that is within, on the laboratory's grid; the grid to correct on. */
static rb_status judge_pass(generator *g, const rb_series *work, double peak, double *v,
                            const rb_spectrum **on, const double **on_target)
{
    rb_status st = rb_spectrum_of_series_banked(g->grid_bank, work, 1.0, &g->grid);
    if (st != RB_OK)
        return st;
    *on = &g->grid;
    *on_target = g->target;
    *v = violation(g, &g->grid, g->target, peak, SYNTH_QUICK_SLACK);
    if (*v > 0)
        return RB_OK;
    st = rb_spectrum_of_series_banked(g->fine_bank, work, 1.0, &g->fine);
    if (st != RB_OK)
        return st;
    *on = &g->fine;
    *on_target = g->fine_target;
    *v = violation(g, &g->fine, g->fine_target, peak, SYNTH_QUICK_SLACK);
    if (*v == 0) {
        rb_accept_result a;
        st = rb_accept_judge(&g->rules, g->o->target, &g->fine, &a);
        if (st == RB_OK && a.margin < 1 + SYNTH_QUICK_SLACK)
            *v = 1 + SYNTH_QUICK_SLACK - a.margin;
    }
    return st;
}

rb_status rb_synth_generate(const rb_synth_opts *o, rb_series *out, rb_synth_info *info)
{
    memset(out, 0, sizeof *out);
    memset(info, 0, sizeof *info);
    if (!o || !options_ok(o))
        return RB_ERR_INVALID;
    generator g;
    rb_status st = generator_init(&g, o);
    rb_series work;
    memset(&work, 0, sizeof work);
    if (st == RB_OK)
        st = rb_series_alloc(&work, g.n, o->dt_s);
    if (st == RB_OK)
        st = rb_series_alloc(out, g.n, o->dt_s);
    double best = INFINITY;
    unsigned pass = 0;
    for (unsigned it = 1; st == RB_OK && it <= o->max_iterations; it++, pass++) {
        if (pass == SYNTH_PASSES || it == 1) {
            start(&g, info->attempts++, work.accel_mps2);
            pass = 0;
        }
        synthesise(&g, work.accel_mps2);
        double peak = rb_series_peak(&work), v;
        const rb_spectrum *on;
        const double *on_target;
        st = judge_pass(&g, &work, peak, &v, &on, &on_target);
        if (st != RB_OK)
            break;
        if (v < best) {
            best = v;
            memcpy(out->accel_mps2, work.accel_mps2, g.n * sizeof *work.accel_mps2);
            info->iterations = it;
        }
        if (v == 0.0)
            break;
        if (pass == 0)
            normalise(&g);
        else
            correct(&g, on, on_target, peak);
    }
    rb_series_free(&work);
    rb_accept_rules rules = g.rules;
    generator_free(&g);
    if (st != RB_OK) {
        rb_series_free(out);
        return st;
    }
    st = describe(o->target, &rules, out, info);
    if (st != RB_OK) {
        rb_series_free(out);
        return st;
    }
    return best == 0.0 ? RB_OK : RB_ERR_LIMIT;
}
