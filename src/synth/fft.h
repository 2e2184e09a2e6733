/* The real FFTs the generator needs, through FFTW (internal).
 * FFTW's planner is not thread-safe: plans are made and destroyed under
 * one lock, and executed freely. Plans use FFTW_ESTIMATE and
 * FFTW_NO_SIMD, so that they are chosen without timing and with the same
 * scalar code on every machine: the same seed gives the same motion. */
#ifndef RB_SYNTH_FFT_H
#define RB_SYNTH_FFT_H

#include <stddef.h>
#include <fftw3.h>
#include "rockbolt/status.h"

typedef struct {
    size_t n;              /* real samples; n / 2 + 1 complex bins */
    double *time;          /* n */
    fftw_complex *freq;    /* n / 2 + 1 */
    fftw_plan inverse;     /* freq -> time, unnormalised */
    fftw_plan forward;     /* time -> freq, unnormalised */
} rb_fft_real;

rb_status rb_fft_real_init(rb_fft_real *f, size_t n);
/* time[j] = sum over k of freq[k] e^{2 pi i j k / n}, the conjugate half
 * included (freq is overwritten by FFTW). */
void rb_fft_real_inverse(rb_fft_real *f);
/* freq[k] = sum over j of time[j] e^{-2 pi i j k / n} (time kept). */
void rb_fft_real_forward(rb_fft_real *f);
void rb_fft_real_free(rb_fft_real *f);

#endif
