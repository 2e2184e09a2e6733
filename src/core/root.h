/* Internal: a root of a function of one variable inside a bracket, for the
 * solver's readers of dense output (track.c, taylor_eval.c). */
#ifndef RB_ROOT_H
#define RB_ROOT_H

/* Root in [a, b] of f, which is fa at a and fb at b, of opposite signs:
 * Illinois (modified regula falsi) steps, which converge superlinearly on
 * the low-order polynomials of a step, halving the bracket only when the
 * secant hugs an end twice in a row (once is superlinear convergence,
 * which halving would slow), until the bracket is within tol (1 + |b|), or
100 steps. */
double rb_root_illinois(double (*f)(const void *ctx, double x), const void *ctx, double a,
                        double b, double fa, double fb, double tol);

/* One Illinois narrowing of the bracket [*a, *b] (f is *fa and *fb there,
 * of opposite signs) by m, where f is fm (not 0): m replaces the end on
 * its side, and where the same end was replaced the step before (*last),
 * the other end's value is halved, so that the secant does not keep
 * hugging it. Shared by rb_root_illinois and the callers that stop on
 * their own rule (track.c's crossings of zero). */
static inline void rb_illinois_narrow(double *a, double *fa, double *b, double *fb, int *last,
                                      double m, double fm)
{
    if ((fm < 0) == (*fa < 0)) {
        *a = m;
        *fa = fm;
        if (*last == 1)
            *fb *= 0.5;
        *last = 1;
    } else {
        *b = m;
        *fb = fm;
        if (*last == -1)
            *fa *= 0.5;
        *last = -1;
    }
}

/* The largest value of f inside [t[0], t[n-1]] (a local maximum; the ends
 * are not evaluated, callers know them) and where it is (*at): Brent's
 * method (golden sections and parabolic steps) on -f, seeded with the n
 * points t (ascending) where f is known to be ft, until the bracket is
 * within about 4 tol. GSL has the same method, but its licence is not the
 * project's. */
double rb_max_brent(double (*f)(const void *ctx, double x), const void *ctx,
                    const double *t, const double *ft, int n, double tol, double *at);

#endif
