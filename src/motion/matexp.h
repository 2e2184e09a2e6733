/* The exponential of a small dense matrix, for the exact transitions of
 * linear systems under loads that are linear over a step (sdof.c, the
 * response spectra's building-and-oscillator cascade). Internal. */
#ifndef RB_MOTION_MATEXP_H
#define RB_MOTION_MATEXP_H

#include <stddef.h>

#define RB_MATEXP_MAX 8

/* e = exp(a) for an n x n matrix (row-major, 1 <= n <= RB_MATEXP_MAX) by
 * scaling, Taylor series and squaring. The caller scales the system so
 * that the entries are of order one: the squarings then stay few and the
 * Taylor remainder, 0.5^21 / 21!, is far below double precision. */
void rb_matexp(size_t n, const double *a, double *e);

#endif
