/* Target spectra: the AC156 required response spectrum, IEEE 693's,
 * tables and GR-63-CORE's check of a user's table.
 *
 * AC156's spectrum (5 % damping) is flat at A_FLX from 1.3 to 8.3 Hz,
 * falls on a straight line in log-log axes to A_RIG at 33.3 Hz and stays
 * there; below 1.3 Hz it falls on a log-log line that reaches 0.1 A_FLX at
 * 0.1 Hz. The test response spectrum must envelope it from 1.3 to 33.3 Hz
 * at 1/6-octave resolution, no point below 0.9 of it; 1.3 of it is the
 * upper line testing practice draws. docs/motion.md gives the sources
 * and what of them could be confirmed. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/spectrum.h"

#define AC156_F_LOW_HZ 1.3
#define AC156_F_FLX_END_HZ 8.3
#define AC156_F_RIG_HZ 33.3
#define AC156_F_TAIL_HZ 0.1
#define AC156_TAIL_FRACTION 0.1
#define AC156_FLX_CAP 1.6
#define AC156_BAND_LOWER 0.9
#define AC156_BAND_UPPER 1.3
#define AC156_PER_OCTAVE 6.0
#define AC156_MIN_PEAK_OF_RIG 0.9
#define AC156_FLX_V_OF_SDS 0.67
#define AC156_RIG_V_OF_SDS 0.27

double rb_asce722_hf(double z_over_h, double ta_s, int at_or_below_grade)
{
    if (at_or_below_grade)
        return 1.0;
    if (!(ta_s > 0))
        return 1.0 + 2.5 * z_over_h;
    double a1 = fmin(1.0 / ta_s, 2.5);
    double a2 = fmax(0.0, 1.0 - pow(0.4 / ta_s, 2));
    return 1.0 + a1 * z_over_h + a2 * pow(z_over_h, 10);
}

double rb_asce722_rmu(double r, double ie, double omega0, int at_or_below_grade)
{
    if (at_or_below_grade)
        return 1.0;
    if (!(r > 0 && ie > 0 && omega0 > 0))
        return 1.3;
    return fmax(1.3, sqrt(1.1 * r / (ie * omega0)));
}

/* One level's A_FLX-H and A_RIG-H; b NULL: the building not known. AC156
 * takes z/h 0 as grade (R_mu 1), as the laboratory's processing does. */
static void level(rb_ac156_edition ed, const rb_ac156_building *b, double sds_mps2,
                  double z_over_h, double *a_flx, double *a_rig)
{
    double amp;
    if (ed == RB_AC156_2024) {
        int grade = !(z_over_h > 0);
        double hf = rb_asce722_hf(z_over_h, b ? b->ta_s : 0.0, grade);
        double rmu = b ? rb_asce722_rmu(b->r, b->ie, b->omega0, grade)
                       : rb_asce722_rmu(0, 0, 0, grade);
        amp = hf / rmu;
    } else {
        amp = 1.0 + 2.0 * z_over_h;
    }
    double flx = sds_mps2 * amp;
    *a_flx = flx < AC156_FLX_CAP * sds_mps2 ? flx : AC156_FLX_CAP * sds_mps2;
    *a_rig = 0.4 * sds_mps2 * amp;
}

void rb_ac156_levels(rb_ac156_edition ed, double sds_mps2, double z_over_h,
                     double *a_flx, double *a_rig)
{
    level(ed, NULL, sds_mps2, z_over_h, a_flx, a_rig);
}

static void band_defaults(rb_target *t)
{
    t->band_lower = AC156_BAND_LOWER;
    t->band_upper = AC156_BAND_UPPER;
    t->check_per_octave = AC156_PER_OCTAVE;
}

void rb_target_ac156(rb_target *t, rb_ac156_edition ed, double sds_mps2, double z_over_h)
{
    memset(t, 0, sizeof *t);
    t->kind = RB_TARGET_AC156;
    t->damping = 0.05;
    t->edition = ed;
    t->sds_mps2 = sds_mps2;
    t->z_over_h = z_over_h;
    t->check_from_hz = AC156_F_LOW_HZ;
    t->check_to_hz = AC156_F_RIG_HZ;
    band_defaults(t);
    double flx, rig;
    rb_ac156_levels(ed, sds_mps2, z_over_h, &flx, &rig);
    t->min_peak_mps2 = AC156_MIN_PEAK_OF_RIG * rig;
}

void rb_target_ac156_more(rb_target *t, const rb_ac156_building *b, double sds2_mps2,
                          double z_over_h2)
{
    if (b)
        t->building = *b;
    t->sds2_mps2 = sds2_mps2 > 0 ? sds2_mps2 : 0.0;
    t->z_over_h2 = z_over_h2;
    double flx, rig;
    rb_target_ac156_levels(t, &flx, &rig);
    t->min_peak_mps2 = AC156_MIN_PEAK_OF_RIG * rig;
}

void rb_target_ac156_vertical(rb_target *t, double sds_mps2)
{
    rb_target_ac156(t, RB_AC156_2010, sds_mps2, 0.0);
    t->vertical = 1;
    t->min_peak_mps2 = AC156_MIN_PEAK_OF_RIG * AC156_RIG_V_OF_SDS * sds_mps2;
}

void rb_target_ac156_levels(const rb_target *t, double *a_flx, double *a_rig)
{
    if (t->vertical) {
        *a_flx = AC156_FLX_V_OF_SDS * t->sds_mps2;
        *a_rig = AC156_RIG_V_OF_SDS * t->sds_mps2;
    } else {
        level(t->edition, &t->building, t->sds_mps2, t->z_over_h, a_flx, a_rig);
        if (t->sds2_mps2 > 0) {
            double f2, r2;
            level(t->edition, &t->building, t->sds2_mps2, t->z_over_h2, &f2, &r2);
            *a_flx = fmax(*a_flx, f2);
            *a_rig = fmax(*a_rig, r2);
        }
    }
}

/* IEEE 693-2005, Figure A.1 (the High performance level; docs/motion.md
 * says what of it is confirmed): the corners and the ZPA's frequency. */
#define IEEE693_F_RISE_HZ 1.1
#define IEEE693_F_FLAT_HZ 8.0
#define IEEE693_F_ZPA_HZ 33.0
#define IEEE693_MODERATE 0.5
#define IEEE693_VERTICAL 0.8
#define IEEE693_MIN_PEAK_OF_ZPA 0.9
#define STANDARD_G 9.80665

double rb_ieee693_beta(double damping)
{
    return (3.21 - 0.68 * log(100.0 * damping)) / 2.1156;
}

/* The level's factor on the High spectrum, and the vertical's on that. */
static double ieee693_factor(const rb_target *t)
{
    double k = t->level == RB_IEEE693_MODERATE ? IEEE693_MODERATE : 1.0;
    return t->vertical ? IEEE693_VERTICAL * k : k;
}

static double ieee693_at(const rb_target *t, double f)
{
    double b = rb_ieee693_beta(t->damping), g;
    if (f <= IEEE693_F_RISE_HZ)
        g = 2.288 * b * f;
    else if (f <= IEEE693_F_FLAT_HZ)
        g = 2.5 * b;
    else if (f <= IEEE693_F_ZPA_HZ)
        g = (26.4 * b - 10.56) / f - 0.8 * b + 1.32;
    else
        g = 1.0;
    return ieee693_factor(t) * g * STANDARD_G;
}

void rb_target_ieee693(rb_target *t, rb_ieee693_level level, double damping, int vertical)
{
    memset(t, 0, sizeof *t);
    t->kind = RB_TARGET_IEEE693;
    t->damping = damping;
    t->level = level;
    t->vertical = vertical;
    t->check_from_hz = IEEE693_F_RISE_HZ;
    t->check_to_hz = IEEE693_F_ZPA_HZ;
    band_defaults(t);
    t->min_peak_mps2 = IEEE693_MIN_PEAK_OF_ZPA * ieee693_factor(t) * STANDARD_G;
}

void rb_target_table(rb_target *t, double *freq_hz, double *accel_mps2, size_t n,
                     double damping)
{
    memset(t, 0, sizeof *t);
    t->kind = RB_TARGET_TABLE;
    t->damping = damping;
    t->freq_hz = freq_hz;
    t->accel_mps2 = accel_mps2;
    t->n = n;
    t->check_from_hz = freq_hz[0];
    t->check_to_hz = freq_hz[n - 1];
    band_defaults(t);
}

void rb_target_gr63(rb_target *t, double *freq_hz, double *accel_mps2, size_t n)
{
    rb_target_table(t, freq_hz, accel_mps2, n, RB_GR63_DAMPING);
    t->kind = RB_TARGET_GR63;
    t->check_from_hz = RB_GR63_FROM_HZ;
    t->check_to_hz = RB_GR63_TO_HZ;
    /* TRS >= RRS: the envelope itself, no 0.9 allowance */
    t->band_lower = 1.0;
}

void rb_target_tolerance(rb_target *t, double below, double above)
{
    t->band_lower = below;
    t->band_upper = above;
}

void rb_target_free(rb_target *t)
{
    if (!t)
        return;
    free(t->freq_hz);
    free(t->accel_mps2);
    t->freq_hz = t->accel_mps2 = NULL;
    t->n = 0;
}

/* The log-log line through (f0, a0) and (f1, a1), at f. */
static double loglog(double f0, double a0, double f1, double a1, double f)
{
    double s = log(a1 / a0) / log(f1 / f0);
    return a0 * pow(f / f0, s);
}

static double ac156_at(const rb_target *t, double f)
{
    double flx, rig;
    rb_target_ac156_levels(t, &flx, &rig);
    if (f < AC156_F_LOW_HZ)
        return loglog(AC156_F_TAIL_HZ, AC156_TAIL_FRACTION * flx, AC156_F_LOW_HZ, flx, f);
    if (f <= AC156_F_FLX_END_HZ)
        return flx;
    if (f <= AC156_F_RIG_HZ)
        return loglog(AC156_F_FLX_END_HZ, flx, AC156_F_RIG_HZ, rig, f);
    return rig;
}

static double table_at(const rb_target *t, double f)
{
    /* below the first frequency the taper: in proportion to f (never held
     * flat: a flat low end asks metres of table stroke) */
    if (f < t->freq_hz[0])
        return t->accel_mps2[0] * f / t->freq_hz[0];
    if (f <= t->freq_hz[0])
        return t->accel_mps2[0];
    if (f >= t->freq_hz[t->n - 1])
        return t->accel_mps2[t->n - 1];
    size_t lo = 0, hi = t->n - 1;
    while (hi - lo > 1) {
        size_t mid = (lo + hi) / 2;
        if (t->freq_hz[mid] <= f)
            lo = mid;
        else
            hi = mid;
    }
    return loglog(t->freq_hz[lo], t->accel_mps2[lo], t->freq_hz[hi], t->accel_mps2[hi], f);
}

double rb_target_at(const rb_target *t, double f_hz)
{
    switch (t->kind) {
    case RB_TARGET_AC156:
        return ac156_at(t, f_hz);
    case RB_TARGET_IEEE693:
        return ieee693_at(t, f_hz);
    case RB_TARGET_TABLE:
    case RB_TARGET_GR63:
        break;
    }
    return table_at(t, f_hz);
}

rb_status rb_target_check_grid(const rb_target *t, rb_spectrum *sp)
{
    rb_spectrum_opts o;
    rb_spectrum_opts_init(&o);
    o.damping = t->damping;
    o.f_min_hz = t->check_from_hz;
    o.f_max_hz = t->check_to_hz;
    o.per_octave = t->check_per_octave;
    return rb_spectrum_grid(&o, sp);
}

rb_status rb_target_compare(const rb_target *t, const rb_spectrum *sp,
                            rb_target_fit *fit)
{
    memset(fit, 0, sizeof *fit);
    fit->min_ratio = INFINITY;
    fit->max_ratio = -INFINITY;
    double lo = t->check_from_hz * (1 - 1e-9), hi = t->check_to_hz * (1 + 1e-9);
    for (size_t i = 0; i < sp->n; i++) {
        double f = sp->freq_hz[i];
        if (f < lo || f > hi)
            continue;
        double r = sp->sa_mps2[i] / rb_target_at(t, f);
        if (r < fit->min_ratio) {
            fit->min_ratio = r;
            fit->min_at_hz = f;
        }
        if (r > fit->max_ratio) {
            fit->max_ratio = r;
            fit->max_at_hz = f;
        }
        fit->n_checked++;
    }
    if (fit->n_checked == 0)
        return RB_ERR_INVALID;
    fit->within = fit->min_ratio >= t->band_lower && fit->max_ratio <= t->band_upper;
    return RB_OK;
}
