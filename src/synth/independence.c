/* Whether two motions of a set are statistically independent, as
 * laboratories check it (rockbolt/synth.h, docs/motion.md): the
 * normalised cross-correlation at every lag, and the magnitude-squared
 * coherence over 1.25 s windows at 1/72 octave from 1.3 to 33.3 Hz. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/synth.h"
#include "fft.h"

#define COHERENCE_FROM_HZ 1.3
#define COHERENCE_TO_HZ 33.3
#define COHERENCE_PER_OCTAVE 72.0

static double deviation(const double *a, size_t n)
{
    double mean = 0, s = 0;
    for (size_t i = 0; i < n; i++)
        mean += a[i];
    mean /= (double)n;
    for (size_t i = 0; i < n; i++)
        s += (a[i] - mean) * (a[i] - mean);
    return sqrt(s / (double)n);
}

/* max over lags of |sum_j a[j + k] b[j]| / (n sd_a sd_b), by one FFT of
 * each padded to twice the length (no lag wraps onto another) */
static rb_status correlation(const double *a, const double *b, size_t n, double *out)
{
    rb_fft_real fa, fb;
    rb_status st = rb_fft_real_init(&fa, 2 * n);
    if (st != RB_OK)
        return st;
    st = rb_fft_real_init(&fb, 2 * n);
    if (st != RB_OK) {
        rb_fft_real_free(&fa);
        return st;
    }
    memset(fa.time, 0, 2 * n * sizeof *fa.time);
    memset(fb.time, 0, 2 * n * sizeof *fb.time);
    memcpy(fa.time, a, n * sizeof *a);
    memcpy(fb.time, b, n * sizeof *b);
    rb_fft_real_forward(&fa);
    rb_fft_real_forward(&fb);
    for (size_t k = 0; k <= n; k++) {
        double ar = fa.freq[k][0], ai = fa.freq[k][1];
        double br = fb.freq[k][0], bi = fb.freq[k][1];
        /* A conj(B): sum_j a[j + k] b[j] at lag k */
        fa.freq[k][0] = ar * br + ai * bi;
        fa.freq[k][1] = ai * br - ar * bi;
    }
    rb_fft_real_inverse(&fa);
    double peak = 0;
    for (size_t i = 0; i < 2 * n; i++)
        if (fabs(fa.time[i]) > peak)
            peak = fabs(fa.time[i]);
    double norm = (double)(2 * n) * (double)n * deviation(a, n) * deviation(b, n);
    *out = norm > 0 ? peak / norm : 0.0;
    rb_fft_real_free(&fa);
    rb_fft_real_free(&fb);
    return RB_OK;
}

/* Welch's magnitude-squared coherence (scipy.signal.coherence's defaults:
 * periodic Hann window, each segment's mean removed), at most at the
 * frequencies from 1.3 to 33.3 Hz at 1/72 octave, interpolated linearly
 * between the segments' bins. */
static rb_status coherence(const double *a, const double *b, size_t n, double dt,
                           double *out)
{
    size_t w = (size_t)llround(RB_SYNTH_COHERENCE_WINDOW_S / dt);
    size_t trim = (size_t)llround(RB_SYNTH_COHERENCE_TRIM_S / dt);
    if (trim >= n / 2)
        trim = 0;
    a += trim;
    b += trim;
    n -= 2 * trim;
    if (w < 4 || n < 2 * w) {
        *out = NAN;   /* too short for two windows: not judged */
        return RB_OK;
    }
    double df = 1.0 / ((double)w * dt);
    size_t kmax = (size_t)ceil(COHERENCE_TO_HZ / df) + 1;
    if (kmax > w / 2)
        kmax = w / 2;
    size_t bins = kmax + 1;
    double *win = malloc(w * sizeof *win), *cs = malloc(2 * w * sizeof *cs);
    double *pxx = calloc(bins, sizeof *pxx), *pyy = calloc(bins, sizeof *pyy);
    double *pre = calloc(bins, sizeof *pre), *pim = calloc(bins, sizeof *pim);
    double *sa = malloc(w * sizeof *sa), *sb = malloc(w * sizeof *sb);
    rb_status st = RB_OK;
    if (!win || !cs || !pxx || !pyy || !pre || !pim || !sa || !sb) {
        st = RB_ERR_NOMEM;
        goto done;
    }
    for (size_t j = 0; j < w; j++) {
        win[j] = 0.5 - 0.5 * cos(2.0 * M_PI * (double)j / (double)w);
        cs[2 * j] = cos(2.0 * M_PI * (double)j / (double)w);
        cs[2 * j + 1] = sin(2.0 * M_PI * (double)j / (double)w);
    }
    for (size_t s0 = 0; s0 + w <= n; s0 += w / 2) {
        double ma = 0, mb = 0;
        for (size_t j = 0; j < w; j++) {
            ma += a[s0 + j];
            mb += b[s0 + j];
        }
        ma /= (double)w;
        mb /= (double)w;
        for (size_t j = 0; j < w; j++) {
            sa[j] = (a[s0 + j] - ma) * win[j];
            sb[j] = (b[s0 + j] - mb) * win[j];
        }
        for (size_t k = 0; k < bins; k++) {
            double xr = 0, xi = 0, yr = 0, yi = 0;
            for (size_t j = 0, idx = 0; j < w; j++, idx = (idx + k) % w) {
                xr += sa[j] * cs[2 * idx];
                xi -= sa[j] * cs[2 * idx + 1];
                yr += sb[j] * cs[2 * idx];
                yi -= sb[j] * cs[2 * idx + 1];
            }
            pxx[k] += xr * xr + xi * xi;
            pyy[k] += yr * yr + yi * yi;
            pre[k] += xr * yr + xi * yi;   /* conj(X) Y */
            pim[k] += xr * yi - xi * yr;
        }
    }
    double best = 0;
    for (int j = 0;; j++) {
        double f = COHERENCE_FROM_HZ * exp2(j / COHERENCE_PER_OCTAVE);
        if (f > COHERENCE_TO_HZ * (1 + 1e-12))
            break;
        size_t k = (size_t)floor(f / df);
        if (k + 1 >= bins)
            break;
        double c[2];
        for (int e = 0; e < 2; e++) {
            size_t q = k + (size_t)e;
            double d = pxx[q] * pyy[q];
            c[e] = d > 0 ? (pre[q] * pre[q] + pim[q] * pim[q]) / d : 0.0;
        }
        double x = f / df - (double)k;
        double v = (1 - x) * c[0] + x * c[1];
        if (v > best)
            best = v;
    }
    *out = best;
done:
    free(win);
    free(cs);
    free(pxx);
    free(pyy);
    free(pre);
    free(pim);
    free(sa);
    free(sb);
    return st;
}

rb_status rb_synth_independence(const rb_series *a, const rb_series *b, rb_synth_pair *out)
{
    memset(out, 0, sizeof *out);
    if (!a || !b || a->n != b->n || a->dt_s != b->dt_s || a->n < 2)
        return RB_ERR_INVALID;
    rb_status st = correlation(a->accel_mps2, b->accel_mps2, a->n, &out->correlation);
    if (st == RB_OK)
        st = coherence(a->accel_mps2, b->accel_mps2, a->n, a->dt_s, &out->coherence);
    out->independent = st == RB_OK && out->correlation <= RB_SYNTH_MAX_CORRELATION
                       && !(out->coherence > RB_SYNTH_MAX_COHERENCE);
    return st;
}
