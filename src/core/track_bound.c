/* Bounds of the quantities tracked in a rocking Taylor step (stage 2),
 * over the whole step, from the step's own series: U, theta, the total
 * shear and the floor's vertical reaction. Where they keep every tracked
 * quantity short of its running peak and the reaction clear of the
 * friction floor and of zero, the step's check points cannot move a
 * result and are not read (track.c, rb_track_rocking_quiet).
 *
 * Each series' values over [0, h] lie within its start plus or minus its
 * reach, the sum of |p_k| h^k (rb_taylor_reach); the reactions are those
 * of rb_dyn_reactions taken over such ranges by interval arithmetic. The
 * parts that would lose most to interval arithmetic (the floor, U'' and
 * theta'' in the shear, which partly cancel; theta'' in the reaction) are
 * summed as series first, so that their reach is that of their sum. */
#include <float.h>
#include <math.h>
#include "solver.h"

/* A value known to lie within r of m (midpoint-radius intervals: no
 * branches, no min or max; a little wider than end-point intervals). */
typedef struct {
    double m, r;
} ball;

static ball b_add(ball a, ball b)
{
    return (ball){a.m + b.m, a.r + b.r};
}

static ball b_scale(ball a, double k)
{
    return (ball){k * a.m, fabs(k) * a.r};
}

static ball b_mul(ball a, ball b)
{
    return (ball){a.m * b.m, fabs(a.m) * b.r + a.r * (fabs(b.m) + b.r)};
}

static double b_abs_max(ball a)
{
    return fabs(a.m) + a.r;
}

int rb_track_step_bounds(const rb_solver *sv, const rb_taylor *ts, double h,
                         rb_track_bounds *b)
{
    const rb_sys *S = &sv->sys;
    const rb_derived *d = &S->d;
    double s = sv->disc.side < 0 ? -1.0 : 1.0, M = S->M, N = d->Nstar;
    double Mh = M * S->h, Mbh = M * S->b;
    /* the shear's part linear in the series, -M s x + N* U'' + M h theta''
     * (mirrored), and the reaction's, M b theta'' + M z'': the rest
     * corrects them by (c - 1), the squares and the products */
    double wx = -M * s, wu = N * s, wt = Mh * s, wv = Mbh * s;
    /* one pass over the powers: each series' reach, and the two sums' in
     * a loop of their own (the first then vectorizes) */
    double reach[RB_TS_CHECK] = {0}, rh = 0, rv = 0;
    const double (*p)[RB_TS_N] = (const double (*)[RB_TS_N])ts->p;
    for (int k = ts->order; k >= 1; k--)
        for (int i = 0; i < RB_TS_CHECK; i++)
            reach[i] = (reach[i] + fabs(p[k][i])) * h;
    for (int k = ts->order; k >= 1; k--) {
        rh = (rh + fabs(wx * p[k][RB_TS_X] + wu * p[k][RB_TS_UDD] + wt * p[k][RB_TS_THDD])) * h;
        rv = (rv + fabs(wv * p[k][RB_TS_THDD] + M * p[k][RB_TS_Z])) * h;
    }
    /* the Horner passes of the dense output read each series within
     * n eps of its terms' sizes (Higham 5.1), widened as rb_taylor_range
     * widens them, and the sums add their parts' */
    double eps = (4.0 * ts->order + 24.0) * DBL_EPSILON, size[RB_TS_CHECK];
    ball r[RB_TS_CHECK];
    for (int i = 0; i < RB_TS_CHECK; i++) {
        size[i] = fabs(p[0][i]) + reach[i];
        r[i] = (ball){p[0][i], reach[i] + eps * size[i]};
    }
    ball hlin = {wx * p[0][RB_TS_X] + wu * p[0][RB_TS_UDD] + wt * p[0][RB_TS_THDD],
                 rh + eps * (fabs(wx) * size[RB_TS_X] + fabs(wu) * size[RB_TS_UDD]
                             + fabs(wt) * size[RB_TS_THDD])};
    ball vlin = {wv * p[0][RB_TS_THDD] + M * p[0][RB_TS_Z],
                 rv + eps * (fabs(wv) * size[RB_TS_THDD] + M * size[RB_TS_Z])};
    /* the mirrored state, as rb_dyn_reactions reads it */
    ball u = b_scale(r[RB_TS_U], s), ud = b_scale(r[RB_TS_UD], s);
    ball thd = b_scale(r[RB_TS_THD], s), udd = b_scale(r[RB_TS_UDD], s);
    ball thdd = b_scale(r[RB_TS_THDD], s), c = r[RB_TS_COS], sn = r[RB_TS_SIN];
    ball Mb = {Mbh - N * u.m, N * u.r};
    ball thd2 = b_mul(thd, thd);
    ball inert = b_add(b_scale(udd, N), b_scale(thdd, Mh)); /* N* U'' + M h theta'' */
    ball Mbthd2 = b_mul(Mb, thd2);
    ball Ad = b_add(inert, Mbthd2);
    ball A2rate = b_add(b_scale(thd2, -Mh), b_scale(b_mul(ud, thd), -2 * N));
    ball A2 = b_add(A2rate, b_mul(Mb, thdd));
    ball cm1 = {c.m - 1, c.r};
    /* s H = -M s x + c Ad + sin A2 */
    ball H = b_add(b_add(hlin, b_mul(cm1, inert)), b_add(b_mul(c, Mbthd2), b_mul(sn, A2)));
    /* V = W (M (g + z'') under a vertical) + c A2 - sin Ad, c A2 being
     * M b theta'' + (c Mb - M b) theta'' + c (-M h theta'^2 - 2 N* U' theta') */
    ball cMb = b_add(b_scale(cm1, Mbh), b_scale(b_mul(c, u), -N));
    double W = S->motion->vertical ? M * d->g : d->W;
    ball V = b_add(b_add((ball){W, 0}, vlin),
                   b_add(b_add(b_mul(cMb, thdd), b_mul(c, A2rate)), b_scale(b_mul(sn, Ad), -1)));
    /* the midpoints' and the reactions' own sums round within a few eps
     * of their terms */
    double round = 1e-13 * (M * b_abs_max(r[RB_TS_X]) + b_abs_max(hlin) + b_abs_max(inert)
                            + b_abs_max(Ad) + b_abs_max(A2) + W + b_abs_max(vlin));
    b->u = b_abs_max(r[RB_TS_U]);
    b->theta = b_abs_max(r[RB_TS_TH]);
    b->shear = b_abs_max(H) + round;
    b->floor_lo = V.m - V.r - round;
    return isfinite(b->u) && isfinite(b->theta) && isfinite(b->shear) && isfinite(b->floor_lo);
}
