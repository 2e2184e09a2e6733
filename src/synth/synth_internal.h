/* Pieces of the generator shared between its files (internal). */
#ifndef RB_SYNTH_INTERNAL_H
#define RB_SYNTH_INTERNAL_H

#include <stddef.h>

/* The envelope at t: a sin^2 rise, the strong part at 1, a cos^2 decay. */
double rb_synth_envelope(double t, double rise_s, double strong_s, double decay_s);
/* Make the end velocity and displacement zero. */
void rb_synth_baseline(double *a, size_t n, double dt);

#endif
