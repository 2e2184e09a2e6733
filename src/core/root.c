/* Illinois root finding in a bracket (root.h). */
#include <math.h>
#include "root.h"

double rb_root_illinois(double (*f)(const void *ctx, double x), const void *ctx, double a,
                        double b, double fa, double fb, double tol)
{
    int last = 0, hugged = 0;
    for (int i = 0; i < 100 && b - a > tol * (1 + fabs(b)); i++) {
        double m = (a * fb - b * fa) / (fb - fa);
        int hug = !(m > a + 1e-3 * (b - a) && m < b - 1e-3 * (b - a));
        if (!(m > a && m < b) || (hug && hugged))
            m = 0.5 * (a + b);
        hugged = hug;
        double fm = f(ctx, m);
        if (fm == 0)
            return m;
        rb_illinois_narrow(&a, &fa, &b, &fb, &last, m, fm);
    }
    return 0.5 * (a + b);
}

double rb_max_brent(double (*f)(const void *ctx, double x), const void *ctx,
                    const double *t, const double *ft, int n, double tol, double *at)
{
    const double golden = 0.3819660112501051;
    double a = t[0], b = t[n - 1];
    /* Brent's minimization of -f: parabolic steps through the three best
     * points, golden sections where they do not shrink the bracket. The
     * points already known seed the parabola, so that a smooth peak
     * bracketed by three samples takes its first step to the vertex. */
    double x = NAN, gx = HUGE_VAL, w = a, gw = -ft[0], v = b, gv = -ft[n - 1];
    if (gv < gw) {
        w = b; gw = -ft[n - 1];
        v = a; gv = -ft[0];
    }
    for (int i = 1; i < n - 1; i++)
        if (-ft[i] < gx) {
            x = t[i];
            gx = -ft[i];
        }
    if (isnan(x)) {
        x = a + golden * (b - a);
        gx = -f(ctx, x);
    }
    if (gw < gx) {
        /* an end above the point inside: keep x inside, the end as w */
        double tt = w, gt = gw;
        v = w == a ? b : a;
        gv = w == a ? -ft[n - 1] : -ft[0];
        w = tt;
        gw = gt;
    }
    double d = b - a, e = b - a;
    for (int i = 0; i < 60; i++) {
        double m = 0.5 * (a + b), tol1 = 1e-15 * fabs(x) + tol, tol2 = 2 * tol1;
        if (fabs(x - m) <= tol2 - 0.5 * (b - a))
            break;
        double p = 0, q = 0, r = 0;
        if (fabs(e) > tol1) {
            r = (x - w) * (gx - gv);
            q = (x - v) * (gx - gw);
            p = (x - v) * q - (x - w) * r;
            q = 2 * (q - r);
            if (q > 0)
                p = -p;
            else
                q = -q;
            r = e;
            e = d;
        }
        int settled = 0;
        if (fabs(p) < fabs(0.5 * q * r) && p > q * (a - x) && p < q * (b - x)) {
            d = p / q;
            double u = x + d;
            if (u - a < tol2 || b - u < tol2)
                d = x < m ? tol1 : -tol1;
            /* a parabolic step within the tolerance: the parabolas converge
             * superlinearly, so the peak is this close; shrinking the
             * bracket to it as well would take tol-sized steps on both
             * sides */
            settled = fabs(d) <= tol1;
        } else {
            e = (x < m ? b : a) - x;
            d = golden * e;
        }
        double u = x + (fabs(d) >= tol1 ? d : d > 0 ? tol1 : -tol1);
        double gu = -f(ctx, u);
        if (gu <= gx) {
            if (u < x)
                b = x;
            else
                a = x;
            v = w; gv = gw;
            w = x; gw = gx;
            x = u; gx = gu;
        } else {
            if (u < x)
                a = u;
            else
                b = u;
            if (gu <= gw || w == x) {
                v = w; gv = gw;
                w = u; gw = gu;
            } else if (gu <= gv || v == x || v == w) {
                v = u; gv = gu;
            }
        }
        if (settled)
            break;
    }
    *at = x;
    return -gx;
}
