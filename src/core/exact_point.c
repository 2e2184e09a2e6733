/* One point of an exact step on the floor (see exact.h): what the check
 * points, the bounds' forms and the peaks located between points read. */
#include <string.h>
#include "exact.h"
#include "taylor.h"

void rb_exact_point_at(const rb_solver *sv, const double *z, rb_exact_point *p)
{
    const rb_derived *d = &sv->sys.d;
    const rb_exact_cache *c = &sv->exact;
    double xd;
    if (c->wb > 0) {
        double w2 = c->wb * c->wb, cb = 2 * c->xib * c->wb;
        double vbd = -w2 * z[ZUB] - cb * z[ZVB] - z[ZG];
        p->x = -(cb * z[ZVB] + w2 * z[ZUB]);
        xd = -(cb * vbd + w2 * z[ZVB]);
    } else {
        p->x = z[ZG];
        xd = z[ZS];
    }
    p->udd = (d->Nstar * p->x - d->Kstar * z[ZU] - d->Cstar * z[ZV]) * c->inv_ms;
    double uddd = (d->Nstar * xd - d->Kstar * z[ZV] - d->Cstar * p->udd) * c->inv_ms;
    p->rate = c->in_th * xd - d->Fstar * uddd;
    /* the angle stays as the floor stage keeps it (as a Taylor step) */
    memcpy(p->y, sv->y, sizeof p->y);
    p->y[RB_Y_U] = z[ZU];
    p->y[RB_Y_UD] = z[ZV];
}

/* laid out as a still Taylor step's series are */
void rb_exact_aux_of(const rb_solver *sv, const rb_exact_point *p, rb_aux *a)
{
    double v[RB_TS_N] = {0};
    v[RB_TS_U] = p->y[RB_Y_U];
    v[RB_TS_UD] = p->y[RB_Y_UD];
    v[RB_TS_X] = p->x;
    v[RB_TS_UDD] = p->udd;
    v[RB_TS_COS] = 1;
    rb_aux_of_values(&sv->sys, &sv->disc, 0, 0, v, a);
}
