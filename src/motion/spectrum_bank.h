/* The peaks of response-spectrum oscillators under a series: a bank of
 * oscillators stepped together, one exact transition per sample, for a
 * floor given directly (spectrum_bank.c), and the sub-stepped walk of one
 * oscillator, with the building when there is one (spectrum.c). The
 * tests hold the two to each other on floors given directly. Internal. */
#ifndef RB_MOTION_SPECTRUM_BANK_H
#define RB_MOTION_SPECTRUM_BANK_H

#include <stddef.h>
#include "rockbolt/motion.h"
#include "rockbolt/spectrum.h"

/* psa[i] = w^2 max|u| and sa[i] = max|u'' + floor| of the oscillators at
 * f_hz[0..n) (damping xi) under s, which has no building; peaks between
 * samples located on sub-steps of at most `phase` radians where a sample
 * interval can hold one above the running peak. RB_ERR_NOMEM. */
rb_status rb_spec_bank_peaks(const rb_series *s, const double *f_hz, size_t n, double xi,
                             double phase, double *psa, double *sa);

/* The same in parts, for many series of one step on one grid: the bank's
 * transitions are made once (rb_spec_bank_new, a copy of f_hz) and each
 * run (rb_spec_bank_run) starts from rest; the sub-steps' transitions are
 * made when first needed and kept. The results are rb_spec_bank_peaks'
 * (to the bit in test_spectrum_bank). rb_spec_bank_fits: whether b was made for these. */
rb_status rb_spec_bank_new(const double *f_hz, size_t n, double xi, double dt, double phase,
                           rb_spectrum_bank **out);
rb_status rb_spec_bank_run(rb_spectrum_bank *b, const rb_series *s, double *psa, double *sa);
int rb_spec_bank_fits(const rb_spectrum_bank *b, const double *f_hz, size_t n, double xi,
                      double dt, double phase);
void rb_spec_bank_free(rb_spectrum_bank *b);

/* The same for one oscillator, every sample interval cut into sub-steps
 * of at most `phase` radians of the fastest mode (oscillator or building). */
void rb_spec_substep_peaks(const rb_series *s, double f_hz, double xi, double phase,
                           double *psa, double *sa);

#endif
