/* A laboratory's acceptance of a table motion (rockbolt/accept.h): the
 * rules as a published AC156-24 processing code applies them (docs/
 * motion.md, "Acceptance"), at every one of the 12 offsets of the
 * 1/72-octave grid rather than the most favourable one. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/accept.h"

#define AC156_SPLIT_HZ 8.3
#define LOW_CUTOFF_MIN_HZ 1.3
#define LOW_CUTOFF_MAX_HZ 3.5
#define LOW_CUTOFF_OF_RESONANCE 0.75

void rb_accept_rules_init(rb_accept_rules *r, const rb_target *t)
{
    memset(r, 0, sizeof *r);
    r->damping = t->damping;
    r->low_cutoff_hz = t->check_from_hz;
    r->high_cutoff_hz = t->check_to_hz;
    r->split_hz = AC156_SPLIT_HZ;
    r->lower = t->band_lower;
    r->guide = t->band_upper;
    int rigid_line = t->kind == RB_TARGET_AC156 || t->kind == RB_TARGET_IEEE693;
    r->tail_to_hz = rigid_line ? RB_ACCEPT_GRID_TO_HZ : 0.0;
}

double rb_accept_low_cutoff(double f_lowest_hz)
{
    if (!(f_lowest_hz > 0) || !isfinite(f_lowest_hz))
        return LOW_CUTOFF_MIN_HZ;
    double f = LOW_CUTOFF_OF_RESONANCE * f_lowest_hz;
    if (f > LOW_CUTOFF_MAX_HZ)
        f = LOW_CUTOFF_MAX_HZ;
    if (f < LOW_CUTOFF_MIN_HZ)
        f = LOW_CUTOFF_MIN_HZ;
    /* up to the next 0.1 Hz; 1e-9 keeps 1.3 (13.000000000000002 tenths)
     * from becoming 1.4 */
    return ceil(f * 10.0 - 1e-9) / 10.0;
}

static double grid_hz(long k)
{
    return RB_ACCEPT_GRID_FROM_HZ * exp2((double)k / RB_ACCEPT_PER_OCTAVE);
}

/* The first grid index at or above f. */
static long grid_at_or_above(double f)
{
    return (long)ceil(log2(f / RB_ACCEPT_GRID_FROM_HZ) * RB_ACCEPT_PER_OCTAVE - 1e-9);
}

static int rules_ok(const rb_accept_rules *r)
{
    /* the grid goes on below 0.1 Hz (k < 0) for a table that does; an
     * offset's points outside the cutoffs stay within the spectra's range */
    double step = exp2(1.0 / 6.0);
    return r->low_cutoff_hz >= RB_SPECTRUM_MIN_HZ * step && r->high_cutoff_hz > r->low_cutoff_hz
        && r->high_cutoff_hz <= RB_SPECTRUM_MAX_HZ / step && r->damping >= 0
        && r->damping < 1 && r->lower > 0 && r->max_ratio >= 0
        && !(r->tail_to_hz > RB_ACCEPT_GRID_TO_HZ);
}

rb_status rb_accept_grid(const rb_accept_rules *r, rb_spectrum *sp)
{
    memset(sp, 0, sizeof *sp);
    if (!rules_ok(r))
        return RB_ERR_INVALID;
    /* an offset's nearest point outside each cutoff is at most 12 steps out */
    long k0 = grid_at_or_above(r->low_cutoff_hz) - RB_ACCEPT_OFFSETS;
    long k1 = grid_at_or_above(r->high_cutoff_hz * (1 + 1e-12)) + RB_ACCEPT_OFFSETS;
    double top = r->tail_to_hz > r->high_cutoff_hz ? r->tail_to_hz : 0.0;
    while (top > 0 && grid_hz(k1 + 1) <= top * (1 + 1e-9))
        k1++;
    size_t n = (size_t)(k1 - k0 + 1);
    if (n > RB_SPECTRUM_MAX_POINTS)
        return RB_ERR_INVALID;
    double *f = malloc(n * sizeof *f);
    if (!f)
        return RB_ERR_NOMEM;
    for (size_t i = 0; i < n; i++)
        f[i] = grid_hz(k0 + (long)i);
    rb_status st = rb_spectrum_alloc(sp, f, n, r->damping);
    free(f);
    return st;
}

/* The grid index of a frequency of rb_accept_grid's grid. */
static long grid_index(double f)
{
    return lround(log2(f / RB_ACCEPT_GRID_FROM_HZ) * RB_ACCEPT_PER_OCTAVE);
}

/* The third smallest of the values below 1 (INFINITY when fewer than
 * three are): the largest s with at most two values below s. */
static double third_smallest(const double *v, size_t n)
{
    double a = INFINITY, b = INFINITY, c = INFINITY;
    for (size_t i = 0; i < n; i++) {
        double x = v[i];
        if (x < a) {
            c = b;
            b = a;
            a = x;
        } else if (x < b) {
            c = b;
            b = x;
        } else if (x < c) {
            c = x;
        }
    }
    return c;
}

static void judge_offset(const rb_accept_rules *r, const double *f, const double *q,
                         size_t n, rb_accept_offset *o)
{
    memset(o, 0, sizeof *o);
    o->n_points = n;
    o->min_ratio = INFINITY;
    o->max_ratio = -INFINITY;
    double margin = INFINITY;
    double low[RB_SPECTRUM_MAX_POINTS], high[RB_SPECTRUM_MAX_POINTS];
    size_t nl = 0, nh = 0;
    for (size_t i = 0; i < n; i++) {
        if (q[i] < o->min_ratio) {
            o->min_ratio = q[i];
            o->min_at_hz = f[i];
        }
        if (q[i] > o->max_ratio) {
            o->max_ratio = q[i];
            o->max_at_hz = f[i];
        }
        if (f[i] <= r->split_hz) {
            low[nl++] = q[i];
            o->below_one_low += q[i] < 1.0;
        } else {
            high[nh++] = q[i];
            o->below_one_high += q[i] < 1.0;
        }
        if (i > 0) {
            double pair = q[i] > q[i - 1] ? q[i] : q[i - 1];
            if (pair < margin)
                margin = pair;
            o->adjacent_below |= pair < 1.0;
        }
    }
    if (o->min_ratio / r->lower < margin)
        margin = o->min_ratio / r->lower;
    double t = third_smallest(low, nl);
    if (t < margin)
        margin = t;
    t = third_smallest(high, nh);
    if (t < margin)
        margin = t;
    o->margin = margin;
    o->pass = margin >= 1.0 && (r->max_ratio == 0 || o->max_ratio <= r->max_ratio);
}

rb_status rb_accept_judge(const rb_accept_rules *r, const rb_target *t,
                          const rb_spectrum *sp, rb_accept_result *out)
{
    memset(out, 0, sizeof *out);
    if (!rules_ok(r) || sp->n == 0 || sp->n > RB_SPECTRUM_MAX_POINTS)
        return RB_ERR_INVALID;
    size_t n = sp->n;
    double *q = malloc(n * sizeof *q);
    double *fo = malloc(n * sizeof *fo), *qo = malloc(n * sizeof *qo);
    if (!q || !fo || !qo) {
        free(q);
        free(fo);
        free(qo);
        return RB_ERR_NOMEM;
    }
    for (size_t i = 0; i < n; i++)
        q[i] = sp->sa_mps2[i] / rb_target_at(t, sp->freq_hz[i]);
    double lo = r->low_cutoff_hz, hi = r->high_cutoff_hz;
    out->min_ratio = out->tail_min_ratio = INFINITY;
    out->max_ratio = out->tail_max_ratio = -INFINITY;
    for (size_t i = 0; i < n; i++) {
        double f = sp->freq_hz[i];
        if (f >= lo && f <= hi) {
            if (q[i] < out->min_ratio) {
                out->min_ratio = q[i];
                out->min_at_hz = f;
            }
            if (q[i] > out->max_ratio) {
                out->max_ratio = q[i];
                out->max_at_hz = f;
            }
        } else if (f > hi && f <= r->tail_to_hz * (1 + 1e-9)) {
            if (q[i] < out->tail_min_ratio)
                out->tail_min_ratio = q[i];
            if (q[i] > out->tail_max_ratio)
                out->tail_max_ratio = q[i];
        }
    }
    if (!(out->tail_max_ratio >= out->tail_min_ratio))
        out->tail_min_ratio = out->tail_max_ratio = NAN;
    out->above_guide = out->max_ratio > r->guide;
    rb_status st = RB_OK;
    out->pass = 1;
    out->margin = INFINITY;
    for (unsigned j = 0; j < RB_ACCEPT_OFFSETS && st == RB_OK; j++) {
        /* this offset's points within the cutoffs, and the nearest one
         * outside each end, which the spectrum must hold */
        long below = -1, above = -1;
        size_t m = 0;
        for (size_t i = 0; i < n; i++) {
            long k = grid_index(sp->freq_hz[i]);
            if (((k % RB_ACCEPT_OFFSETS) + RB_ACCEPT_OFFSETS) % RB_ACCEPT_OFFSETS != (long)j)
                continue;
            double f = sp->freq_hz[i];
            if (f < lo)
                below = (long)i;
            else if (f > hi) {
                if (above < 0)
                    above = (long)i;
            } else {
                if (m == 0 && below >= 0) {
                    fo[m] = sp->freq_hz[below];
                    qo[m++] = q[below];
                }
                fo[m] = f;
                qo[m++] = q[i];
            }
        }
        if (m == 0 || below < 0 || above < 0) {
            st = RB_ERR_INVALID;   /* not the grid rb_accept_grid makes */
            break;
        }
        fo[m] = sp->freq_hz[above];
        qo[m++] = q[above];
        judge_offset(r, fo, qo, m, &out->offset[j]);
        if (out->offset[j].margin < out->margin) {
            out->margin = out->offset[j].margin;
            out->worst = j;
        }
        out->pass &= out->offset[j].pass;
    }
    free(q);
    free(fo);
    free(qo);
    if (st != RB_OK)
        memset(out, 0, sizeof *out);
    return st;
}

rb_status rb_motion_summarise(const rb_series *s, const rb_target *t,
                              const rb_accept_rules *r, rb_motion_summary *out)
{
    memset(out, 0, sizeof *out);
    if (!s || s->n == 0)
        return RB_ERR_INVALID;
    out->pga_mps2 = rb_series_peak(s);
    rb_samples_integrate(s->accel_mps2, s->n, s->dt_s, &out->end_velocity_mps,
                         &out->end_displacement_m, &out->pgv_mps, &out->pgd_m);
    rb_series_arias(s, &out->arias_mps, &out->arias_t5_s, &out->arias_t95_s);
    out->peak_ok = 1;
    if (!t)
        return RB_OK;
    rb_accept_rules own;
    if (!r) {
        rb_accept_rules_init(&own, t);
        r = &own;
    }
    rb_spectrum sp;
    rb_status st = rb_accept_grid(r, &sp);
    if (st == RB_OK)
        st = rb_spectrum_of_series(s, 1.0, &sp);
    if (st == RB_OK)
        st = rb_accept_judge(r, t, &sp, &out->accept);
    rb_spectrum_free(&sp);
    if (st != RB_OK)
        return st;
    out->has_target = 1;
    out->peak_ok = !(t->min_peak_mps2 > 0) || out->pga_mps2 >= t->min_peak_mps2;
    return RB_OK;
}
