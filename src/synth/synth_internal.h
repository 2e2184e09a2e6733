/* Pieces of the generator shared between its files (internal). */
#ifndef RB_SYNTH_INTERNAL_H
#define RB_SYNTH_INTERNAL_H

#include <stddef.h>
#include "rockbolt/status.h"

/* The envelope at t: a sin^2 rise, the strong part at 1, a cos^2 decay. */
double rb_synth_envelope(double t, double rise_s, double strong_s, double decay_s);
/* The baseline correction of motions of n samples dt apart: two half-sines
 * of the whole duration and the end velocity and displacement each leaves,
 * computed once for all the passes of a motion. */
typedef struct {
    size_t n;
    double dt;
    double v1, d1, v2, d2;   /* the ends of the first and second half-sine */
    double *s1, *s2;         /* their samples */
} rb_synth_baseline_basis;

/* RB_ERR_NOMEM (then nothing to free). */
rb_status rb_synth_baseline_init(rb_synth_baseline_basis *b, size_t n, double dt);
void rb_synth_baseline_free(rb_synth_baseline_basis *b);
/* Make the end velocity and displacement of a (b->n samples) zero. */
void rb_synth_baseline(const rb_synth_baseline_basis *b, double *a);

#endif
