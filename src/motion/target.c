/* Target spectra: the AC156 required response spectrum and tables.
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

void rb_ac156_levels(rb_ac156_edition ed, double sds_mps2, double z_over_h,
                     double *a_flx, double *a_rig)
{
    double amp;
    if (ed == RB_AC156_2024) {
        double hf = 1.0 + 2.5 * z_over_h;
        double rmu = z_over_h > 0 ? 1.3 : 1.0;
        amp = hf / rmu;
    } else {
        amp = 1.0 + 2.0 * z_over_h;
    }
    double flx = sds_mps2 * amp;
    *a_flx = flx < AC156_FLX_CAP * sds_mps2 ? flx : AC156_FLX_CAP * sds_mps2;
    *a_rig = 0.4 * sds_mps2 * amp;
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
        rb_ac156_levels(t->edition, t->sds_mps2, t->z_over_h, a_flx, a_rig);
    }
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
    return t->kind == RB_TARGET_AC156 ? ac156_at(t, f_hz) : table_at(t, f_hz);
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
