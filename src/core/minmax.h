/* Internal: fmax and fmin inline. Without -ffinite-math-only the compiler
 * calls them out of libm, and in a rocking run those calls were 2.7 % of
 * the instructions (issue 41's profile). These give what the library
 * gives on x86-64 (maxsd and minsd: the first operand where it is the
 * larger, resp. smaller, else the second; a NaN operand yields the
 * other), so that no result moves by a bit. */
#ifndef RB_MINMAX_H
#define RB_MINMAX_H

static inline double rb_fmax(double a, double b)
{
    return a > b || b != b ? a : b;
}

static inline double rb_fmin(double a, double b)
{
    return a < b || b != b ? a : b;
}

#endif
