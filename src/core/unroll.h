/* Internal: a Horner pass over a Taylor step's series as a straight run.
 * A step's order n changes from step to step, and a loop over it ends in
 * a branch that a processor mispredicts about once a pass when its length
 * changes; a run entered at n has no such branch (docs/solver.md, "The
 * Taylor step's order loop"). It keeps the loop's operations in the
 * loop's order, so the doubles are the loop's. */
#ifndef RB_UNROLL_H
#define RB_UNROLL_H
#include "taylor.h"

#if defined(__GNUC__) || defined(__clang__)
#define RB_FALLTHROUGH __attribute__((fallthrough))
#else
#define RB_FALLTHROUGH ((void)0)
#endif

/* STEP(k) for k = n - 1 down to 0, for 0 <= n <= RB_TAYLOR_MAX: a Horner
 * pass over a step's series, entered at its order (one jump, which the
 * next pass of the same step takes again) and run down to k = 0. */
#define RB_DOWN_FROM(n, STEP)                                                    \
    switch (n) {                                                                 \
    case 32: STEP(31); RB_FALLTHROUGH; case 31: STEP(30); RB_FALLTHROUGH;       \
    case 30: STEP(29); RB_FALLTHROUGH; case 29: STEP(28); RB_FALLTHROUGH;       \
    case 28: STEP(27); RB_FALLTHROUGH; case 27: STEP(26); RB_FALLTHROUGH;       \
    case 26: STEP(25); RB_FALLTHROUGH; case 25: STEP(24); RB_FALLTHROUGH;       \
    case 24: STEP(23); RB_FALLTHROUGH; case 23: STEP(22); RB_FALLTHROUGH;       \
    case 22: STEP(21); RB_FALLTHROUGH; case 21: STEP(20); RB_FALLTHROUGH;       \
    case 20: STEP(19); RB_FALLTHROUGH; case 19: STEP(18); RB_FALLTHROUGH;       \
    case 18: STEP(17); RB_FALLTHROUGH; case 17: STEP(16); RB_FALLTHROUGH;       \
    case 16: STEP(15); RB_FALLTHROUGH; case 15: STEP(14); RB_FALLTHROUGH;       \
    case 14: STEP(13); RB_FALLTHROUGH; case 13: STEP(12); RB_FALLTHROUGH;       \
    case 12: STEP(11); RB_FALLTHROUGH; case 11: STEP(10); RB_FALLTHROUGH;       \
    case 10: STEP(9); RB_FALLTHROUGH; case 9: STEP(8); RB_FALLTHROUGH;          \
    case 8: STEP(7); RB_FALLTHROUGH; case 7: STEP(6); RB_FALLTHROUGH;           \
    case 6: STEP(5); RB_FALLTHROUGH; case 5: STEP(4); RB_FALLTHROUGH;           \
    case 4: STEP(3); RB_FALLTHROUGH; case 3: STEP(2); RB_FALLTHROUGH;           \
    case 2: STEP(1); RB_FALLTHROUGH; case 1: STEP(0); RB_FALLTHROUGH;           \
    default: break;                                                              \
    }
_Static_assert(RB_TAYLOR_MAX == 32, "RB_DOWN_FROM runs from order 32 down");

#endif
