/* Scaling and squaring with a Taylor series: for the few small, well
 * scaled matrices of a run it is exact to rounding, and it needs no branch
 * for complex, repeated or real eigenvalues (critical and over-damping). */
#include <math.h>
#include <string.h>
#include "matexp.h"

#define MATEXP_TAYLOR_TERMS 20

/* out = a b for n x n matrices; out may alias a or b. */
static void mat_mul(size_t n, const double *a, const double *b, double *out)
{
    double r[RB_MATEXP_MAX * RB_MATEXP_MAX];
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            double s = 0.0;
            for (size_t k = 0; k < n; k++)
                s += a[i * n + k] * b[k * n + j];
            r[i * n + j] = s;
        }
    memcpy(out, r, n * n * sizeof *r);
}

static double mat_norm_inf(size_t n, const double *a)
{
    double best = 0.0;
    for (size_t i = 0; i < n; i++) {
        double row = 0.0;
        for (size_t j = 0; j < n; j++)
            row += fabs(a[i * n + j]);
        if (row > best)
            best = row;
    }
    return best;
}

void rb_matexp(size_t n, const double *a, double *e)
{
    int squarings = 0;
    double norm = mat_norm_inf(n, a);
    while (norm > 0.5) {
        norm *= 0.5;
        squarings++;
    }
    double scale = ldexp(1.0, -squarings);
    double x[RB_MATEXP_MAX * RB_MATEXP_MAX], term[RB_MATEXP_MAX * RB_MATEXP_MAX];
    for (size_t i = 0; i < n; i++)
        for (size_t j = 0; j < n; j++) {
            x[i * n + j] = a[i * n + j] * scale;
            term[i * n + j] = (i == j) ? 1.0 : 0.0;
            e[i * n + j] = term[i * n + j];
        }
    for (int k = 1; k <= MATEXP_TAYLOR_TERMS; k++) {
        mat_mul(n, term, x, term);
        for (size_t i = 0; i < n * n; i++) {
            term[i] /= k;
            e[i] += term[i];
        }
    }
    for (int s = 0; s < squarings; s++)
        mat_mul(n, e, e, e);
}
