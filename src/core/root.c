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
        if ((fm < 0) == (fa < 0)) {
            a = m;
            fa = fm;
            if (last == 1)
                fb *= 0.5;
            last = 1;
        } else {
            b = m;
            fb = fm;
            if (last == -1)
                fa *= 0.5;
            last = -1;
        }
    }
    return 0.5 * (a + b);
}
