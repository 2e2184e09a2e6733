/* A small seeded random generator, the same numbers on every machine and
 * thread count: xoshiro256** (Blackman and Vigna, "Scrambled linear
 * pseudorandom number generators", ACM TOMS 47(4), 2021), seeded through
 * splitmix64 as its authors advise. Not for cryptography. Internal to the
 * libraries (src/util). */
#ifndef RB_UTIL_RNG_H
#define RB_UTIL_RNG_H

#include <stdint.h>

typedef struct {
    uint64_t s[4];
} rb_rng;

void rb_rng_seed(rb_rng *r, uint64_t seed);
uint64_t rb_rng_next(rb_rng *r);
/* Uniform in [0, 1), 53 random bits. */
double rb_rng_uniform(rb_rng *r);
/* Uniform integer in [0, n), n >= 1, without modulo bias. */
uint64_t rb_rng_below(rb_rng *r, uint64_t n);

#endif
