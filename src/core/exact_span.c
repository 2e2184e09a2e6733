/* Peaks between the check points of an exact step on the floor, on the
 * step's own polynomial (exact.c, table_poly): the state at any instant of
 * the step, and the instants where the total shear turns, by Newton on
 * the polynomial's derivative kept inside a bracket. track.c reads them
 * where a peak could pass the running one. */
#include <float.h>
#include <math.h>
#include <string.h>
#include "exact.h"
#include "minmax.h"

/* The span's exact step and its polynomials in f from its z0, formed on
 * first use: the shear's (row 4) alone when want is 1 (its turns), the
 * state's four too when 2; NULL where the span is no exact step of a
 * one-panel table. */
static const rb_exact_table *span_poly(rb_solver *sv, int want)
{
    rb_span *sp = &sv->span;
    if (sp->st || sp->exact_tab < 0)
        return NULL;
    const rb_exact_table *tab = &sv->exact.tab[sp->exact_tab];
    if (!tab->nterm)
        return NULL;
    for (int i = want == 2 ? 0 : 4; i < 5; i++) {
        if (sp->exact_formed & (1 << i))
            continue;
        for (int k = 0; k < tab->nterm; k++) {
            double v = 0;
            for (int j = 0; j < ZN; j++)
                v += tab->poly[k][i][j] * sp->exact_z0[j];
            sp->exact_poly[i][k] = v;
        }
        sp->exact_formed |= 1 << i;
    }
    return tab;
}

static double span_f(const rb_span *sp, double t)
{
    double f = (t - sp->t0) / (sp->t1 - sp->t0);
    return rb_fmin(1, rb_fmax(0, f));
}

/* The polynomial c of n terms at f, and its first two derivatives. */
static double poly_at(const double *c, int n, double f, double *d1, double *d2)
{
    double v = c[n - 1], p = 0, q = 0;
    for (int k = n - 2; k >= 0; k--) {
        q = q * f + p;
        p = p * f + v;
        v = v * f + c[k];
    }
    *d1 = p;
    *d2 = 2 * q;
    return v;
}

int rb_exact_span_state(rb_solver *sv, double t, double *y, rb_aux *a)
{
    const rb_exact_table *tab = span_poly(sv, 2);
    if (!tab)
        return 0;
    const rb_span *sp = &sv->span;
    const double *z0 = sp->exact_z0;
    double f = span_f(sp, t), z[ZN], d1, d2;
    for (int i = 0; i < 4; i++)
        z[i] = poly_at(sp->exact_poly[i], tab->nterm, f, &d1, &d2);
    z[ZG] = z0[ZG] + z0[ZS] * (tab->h * f);
    z[ZS] = z0[ZS];
    rb_exact_point p;
    rb_exact_point_at(sv, z, &p);
    memcpy(y, p.y, sizeof p.y);
    rb_exact_aux_of(sv, &p, a);
    return 1;
}

/* A root of the shear's derivative in [lo, hi] (in f), where it changes
 * sign from dlo to dhi: Newton on the polynomial, each step kept inside
 * the bracket that the signs narrow (halving where Newton would leave it
 * or gains too little), to rounding. */
static double turn_root(const double *c, int n, double lo, double hi, double dlo)
{
    double f = 0.5 * (lo + hi), dx_old = hi - lo;
    for (int it = 0; it < 60; it++) {
        double d1, d2;
        poly_at(c, n, f, &d1, &d2);
        if (d1 == 0)
            return f;
        if ((d1 < 0) == (dlo < 0))
            lo = f;
        else
            hi = f;
        double nf = f - d1 / d2, dx = fabs(nf - f);
        if (!(d2 != 0) || !(nf > lo && nf < hi) || dx > 0.5 * dx_old) {
            nf = 0.5 * (lo + hi);
            dx = hi - lo;
        }
        dx_old = dx;
        if (nf == f || dx <= 4 * DBL_EPSILON * (1 + fabs(f)))
            return nf;
        f = nf;
    }
    return f;
}

/* The polynomial's derivative at f, d1 holding its coefficients k c_k
 * (n - 1 of them). */
static double slope_at(const double *d1, int n, double f)
{
    double v = d1[n - 2];
    for (int k = n - 3; k >= 0; k--)
        v = v * f + d1[k];
    return v;
}

/* Sign changes of the derivative are looked for at this many points a
 * check interval: the shear between two points an eighth of the fastest
 * period apart turns at most once, and two turns inside a sixteenth
 * would be a crest lower than the rounding of its neighbours. */
enum { TURN_PROBES = 2 };

int rb_exact_span_shear_turns(rb_solver *sv, double ta, double tb, double *at, int max)
{
    const rb_exact_table *tab = span_poly(sv, 1);
    if (!tab)
        return -1;
    rb_span *sp = &sv->span;
    /* the friction demand and the anchors' interaction turn where the
     * shear does: the same window asks again */
    if ((sp->exact_formed & 32) && sp->turns_ta == ta && sp->turns_tb == tb) {
        int k = sp->n_turns < max ? sp->n_turns : max;
        memcpy(at, sp->turns, k * sizeof *at);
        return k;
    }
    const double *c = sp->exact_poly[4];
    int n = tab->nterm, found = 0;
    double dc[RB_EXACT_POLY];
    for (int k = 1; k < n; k++)
        dc[k - 1] = k * c[k];
    double fa = span_f(sp, ta), fb = span_f(sp, tb);
    int k = (int)ceil((fb - fa) * tab->n * TURN_PROBES - 1e-9);
    if (k < 1)
        k = 1;
    double f0 = fa, d0 = n > 1 ? slope_at(dc, n, f0) : 0;
    for (int i = 1; i <= k && n > 1 && found < 8; i++) {
        double f1 = i == k ? fb : fa + (fb - fa) * i / k, d1 = slope_at(dc, n, f1);
        if (d1 == 0 && i < k)
            sp->turns[found++] = sp->t0 + f1 * (sp->t1 - sp->t0);
        else if (d0 != 0 && d1 != 0 && (d0 < 0) != (d1 < 0)) {
            double fr = turn_root(c, n, f0, f1, d0);
            sp->turns[found++] = sp->t0 + fr * (sp->t1 - sp->t0);
        }
        f0 = f1;
        d0 = d1;
    }
    sp->exact_formed |= 32;
    sp->turns_ta = ta;
    sp->turns_tb = tb;
    sp->n_turns = found;
    k = found < max ? found : max;
    memcpy(at, sp->turns, k * sizeof *at);
    return k;
}
