/* Dormand-Prince 5(4) coefficients and dense output (dopri5's contd5). */
#include <math.h>
#include <string.h>
#include "rk45.h"

static const double C2 = 1.0 / 5, C3 = 3.0 / 10, C4 = 4.0 / 5, C5 = 8.0 / 9;
static const double A21 = 1.0 / 5;
static const double A31 = 3.0 / 40, A32 = 9.0 / 40;
static const double A41 = 44.0 / 45, A42 = -56.0 / 15, A43 = 32.0 / 9;
static const double A51 = 19372.0 / 6561, A52 = -25360.0 / 2187, A53 = 64448.0 / 6561,
                    A54 = -212.0 / 729;
static const double A61 = 9017.0 / 3168, A62 = -355.0 / 33, A63 = 46732.0 / 5247,
                    A64 = 49.0 / 176, A65 = -5103.0 / 18656;
static const double A71 = 35.0 / 384, A73 = 500.0 / 1113, A74 = 125.0 / 192,
                    A75 = -2187.0 / 6784, A76 = 11.0 / 84;
static const double E1 = 71.0 / 57600, E3 = -71.0 / 16695, E4 = 71.0 / 1920,
                    E5 = -17253.0 / 339200, E6 = 22.0 / 525, E7 = -1.0 / 40;
static const double D1 = -12715105075.0 / 11282082432, D3 = 87487479700.0 / 32700410799,
                    D4 = -10690763975.0 / 1880347072, D5 = 701980252875.0 / 199316789632,
                    D6 = -1453857185.0 / 822651844, D7 = 69997945.0 / 29380423;

double rb_rk_step_try(const rb_sys *S, const rb_disc *D, double t0, const double *y0,
                      const double *f0, double h, double t_end, const double *atol,
                      double rtol, rb_rk_step *st)
{
    double (*k)[RB_NY] = st->k, yt[RB_NY];
    int i;
    st->t0 = t0;
    st->h = h;
    st->t1 = t0 + h;
    st->is_taylor = 0;
    memcpy(st->y0, y0, sizeof st->y0);
    memcpy(k[0], f0, sizeof k[0]);
    for (i = 0; i < RB_NY; i++) yt[i] = y0[i] + h * A21 * k[0][i];
    rb_dyn_rhs(S, D, t0 + C2 * h, yt, k[1], NULL);
    for (i = 0; i < RB_NY; i++) yt[i] = y0[i] + h * (A31 * k[0][i] + A32 * k[1][i]);
    rb_dyn_rhs(S, D, t0 + C3 * h, yt, k[2], NULL);
    for (i = 0; i < RB_NY; i++)
        yt[i] = y0[i] + h * (A41 * k[0][i] + A42 * k[1][i] + A43 * k[2][i]);
    rb_dyn_rhs(S, D, t0 + C4 * h, yt, k[3], NULL);
    for (i = 0; i < RB_NY; i++)
        yt[i] = y0[i] + h * (A51 * k[0][i] + A52 * k[1][i] + A53 * k[2][i] + A54 * k[3][i]);
    rb_dyn_rhs(S, D, t0 + C5 * h, yt, k[4], NULL);
    for (i = 0; i < RB_NY; i++)
        yt[i] = y0[i] + h * (A61 * k[0][i] + A62 * k[1][i] + A63 * k[2][i] + A64 * k[3][i]
                             + A65 * k[4][i]);
    rb_dyn_rhs(S, D, t_end, yt, k[5], NULL);
    for (i = 0; i < RB_NY; i++)
        st->y1[i] = y0[i] + h * (A71 * k[0][i] + A73 * k[2][i] + A74 * k[3][i]
                                 + A75 * k[4][i] + A76 * k[5][i]);
    rb_dyn_rhs(S, D, t_end, st->y1, k[6], &st->aux1);
    double err = 0;
    for (i = 0; i < RB_NY; i++) {
        if (atol[i] <= 0)
            continue;
        double e = h * (E1 * k[0][i] + E3 * k[2][i] + E4 * k[3][i] + E5 * k[4][i]
                        + E6 * k[5][i] + E7 * k[6][i]);
        double sc = atol[i] + rtol * fmax(fabs(y0[i]), fabs(st->y1[i]));
        double r = e / sc;
        err += r * r;
    }
    err = sqrt(err / 4);
    return isfinite(err) ? err : HUGE_VAL;
}

void rb_rk_dense_init(rb_rk_step *st)
{
    const double (*k)[RB_NY] = (const double (*)[RB_NY])st->k;
    double h = st->h;
    for (int i = 0; i < RB_NY; i++) {
        double dy = st->y1[i] - st->y0[i];
        double bspl = h * k[0][i] - dy;
        st->cont[0][i] = st->y0[i];
        st->cont[1][i] = dy;
        st->cont[2][i] = bspl;
        st->cont[3][i] = dy - h * k[6][i] - bspl;
        st->cont[4][i] = h * (D1 * k[0][i] + D3 * k[2][i] + D4 * k[3][i] + D5 * k[4][i]
                              + D6 * k[5][i] + D7 * k[6][i]);
    }
}

void rb_rk_dense_eval(const rb_rk_step *st, double t, double *y)
{
    if (st->is_taylor) {
        rb_taylor_all(&st->ts, t - st->t0, y);
        return;
    }
    double s = st->h != 0 ? (t - st->t0) / st->h : 0, s1 = 1 - s;
    for (int i = 0; i < RB_NY; i++)
        y[i] = st->cont[0][i] + s * (st->cont[1][i] + s1 * (st->cont[2][i]
               + s * (st->cont[3][i] + s1 * st->cont[4][i])));
}

void rb_rk_dense_state(const rb_rk_step *st, double t, double *y)
{
    if (st->is_taylor) {
        rb_taylor_state(&st->ts, t - st->t0, y);
        return;
    }
    double s = st->h != 0 ? (t - st->t0) / st->h : 0, s1 = 1 - s;
    for (int i = RB_Y_U; i <= RB_Y_THD; i++)
        y[i] = st->cont[0][i] + s * (st->cont[1][i] + s1 * (st->cont[2][i]
               + s * (st->cont[3][i] + s1 * st->cont[4][i])));
}

double rb_rk_dense_one(const rb_rk_step *st, double t, int i)
{
    if (st->is_taylor)
        return rb_taylor_one(&st->ts, t - st->t0, i);
    double s = st->h != 0 ? (t - st->t0) / st->h : 0, s1 = 1 - s;
    return st->cont[0][i] + s * (st->cont[1][i] + s1 * (st->cont[2][i]
           + s * (st->cont[3][i] + s1 * st->cont[4][i])));
}
