/* The random terms that test_pair and test_quad sum side by side and
 * term by term: xorshift draws from the seed LANE_SEED (each test its
 * own), terms of either sign over 40 decades, now and then 0, a
 * subnormal or an infinity, and bit-for-bit comparison. */
#ifndef LANE_TERMS_H
#define LANE_TERMS_H
#include <math.h>
#include <stdint.h>
#include <string.h>

static uint64_t lane_rng = LANE_SEED;

static double uniform(void)
{
    lane_rng ^= lane_rng << 13;
    lane_rng ^= lane_rng >> 7;
    lane_rng ^= lane_rng << 17;
    return (double)(lane_rng >> 11) / 9007199254740992.0;
}

static double term(int specials)
{
    double r = uniform();
    if (specials && r < 0.02)
        return 0.0;
    if (specials && r < 0.03)
        return (uniform() < 0.5 ? -1 : 1) * 4.9e-324 * (1 + floor(1e6 * uniform()));
    if (specials && r < 0.035)
        return uniform() < 0.5 ? -INFINITY : INFINITY;
    return (uniform() < 0.5 ? -1 : 1) * pow(10.0, 40 * uniform() - 20);
}

static int same_bits(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0 || (isnan(a) && isnan(b));
}
#endif
