/* Sampled accelerations (rb_series): allocation, copy, peak, scaling,
 * windowing and the linear building of eqs. 5.27-5.28 that turns a ground
 * record into a floor motion (its motion between samples: floor.c). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/motion.h"
#include "sdof.h"

#define RB_TWO_PI 6.283185307179586
/* Window ends within this fraction of a step of a sample keep that sample,
 * so that 2.0 s still includes the sample that 200 * 0.01 puts at
 * 1.9999999999999998 s. */
#define RB_WINDOW_SLACK 1e-9

rb_status rb_series_alloc(rb_series *s, size_t n, double dt_s)
{
    if (!s)
        return RB_ERR_INVALID;
    memset(s, 0, sizeof *s);
    if (n == 0 || !isfinite(dt_s) || !(dt_s > 0.0))
        return RB_ERR_INVALID;
    if (n > SIZE_MAX / sizeof(double))
        return RB_ERR_NOMEM;
    s->accel_mps2 = calloc(n, sizeof(double));
    if (!s->accel_mps2)
        return RB_ERR_NOMEM;
    s->n = n;
    s->dt_s = dt_s;
    return RB_OK;
}

static void building_free(rb_series_building *b)
{
    free(b->ground_mps2);
    free(b->u_m);
    free(b->v_mps);
    memset(b, 0, sizeof *b);
}

void rb_series_free(rb_series *s)
{
    if (!s)
        return;
    free(s->accel_mps2);
    s->accel_mps2 = NULL;
    s->n = 0;
    building_free(&s->bld);
}

static double *dup_array(const double *a, size_t n)
{
    double *p = a ? malloc(n * sizeof *p) : NULL;
    if (p)
        memcpy(p, a, n * sizeof *p);
    return p;
}

rb_status rb_series_copy(const rb_series *from, rb_series *to)
{
    rb_series s = *from;
    memset(&s.bld, 0, sizeof s.bld);
    s.accel_mps2 = dup_array(from->accel_mps2, from->n);
    int ok = s.accel_mps2 != NULL;
    if (ok && from->bld.ground_mps2) {
        s.bld = from->bld;
        s.bld.ground_mps2 = dup_array(from->bld.ground_mps2, from->n);
        s.bld.u_m = dup_array(from->bld.u_m, from->n);
        s.bld.v_mps = dup_array(from->bld.v_mps, from->n);
        ok = s.bld.ground_mps2 && s.bld.u_m && s.bld.v_mps;
    }
    if (!ok) {
        rb_series_free(&s);
        return RB_ERR_NOMEM;
    }
    *to = s;
    return RB_OK;
}

double rb_series_peak(const rb_series *s)
{
    double peak = 0.0;
    if (!s || !s->accel_mps2)
        return 0.0;
    if (s->bld.ground_mps2)
        return s->bld.peak_mps2;
    /* a non-finite sample is the solver's to report, at its time */
    for (size_t i = 0; i < s->n; i++)
        if (isfinite(s->accel_mps2[i]) && fabs(s->accel_mps2[i]) > peak)
            peak = fabs(s->accel_mps2[i]);
    return peak;
}

void rb_series_scale(rb_series *s, double factor)
{
    if (!s || !s->accel_mps2)
        return;
    for (size_t i = 0; i < s->n; i++)
        s->accel_mps2[i] *= factor;
    if (!s->bld.ground_mps2)
        return;
    for (size_t i = 0; i < s->n; i++) {
        s->bld.ground_mps2[i] *= factor;
        s->bld.u_m[i] *= factor;
        s->bld.v_mps[i] *= factor;
    }
    s->bld.peak_mps2 *= fabs(factor);
}

rb_status rb_series_building_filter(rb_series *s, double f_hz, double xi)
{
    if (!s || !s->accel_mps2 || s->n == 0 || !isfinite(f_hz) || !(f_hz > 0.0))
        return RB_ERR_INVALID;
    rb_sdof_step st;
    double omega = RB_TWO_PI * f_hz;
    if (!(xi <= 1.0))
        return RB_ERR_INVALID;
    rb_status rc = rb_sdof_step_init(&st, omega, xi, s->dt_s);
    if (rc != RB_OK)
        return rc;
    rb_series_building b = {.omega_rps = omega, .xi = xi,
                            .ground_mps2 = malloc(s->n * sizeof(double)),
                            .u_m = malloc(s->n * sizeof(double)),
                            .v_mps = malloc(s->n * sizeof(double))};
    if (!b.ground_mps2 || !b.u_m || !b.v_mps) {
        building_free(&b);
        return RB_ERR_NOMEM;
    }
    /* The building starts at rest, so x_r = x_r' = 0 at the first sample.
     * Floor total acceleration x_r'' + x_g'' equals -(2 xi w x_r' + w^2 x_r)
     * by eq. 5.27; taking it from the state avoids subtracting the two
     * nearly equal accelerations. */
    double *a = s->accel_mps2;
    double u = 0.0, v = 0.0;
    memcpy(b.ground_mps2, a, s->n * sizeof *a);
    for (size_t i = 0; i < s->n; i++) {
        if (i > 0)
            rb_sdof_step_apply(&st, &u, &v, -b.ground_mps2[i - 1], -b.ground_mps2[i]);
        b.u_m[i] = u;
        b.v_mps[i] = v;
        a[i] = -(2.0 * xi * omega * v + omega * omega * u);
    }
    /* the free vibration's series, (u, v)_{k+1} = (v_k, -w^2 u_k - 2 xi w
     * v_k) / (k + 1), from (1, 0) and from (0, 1); the floor's term is
     * -(2 xi w v_k + w^2 u_k) */
    double uu = 1, uv = 0, vu = 0, vv = 1, c = 2.0 * xi * omega, w2 = omega * omega;
    for (int k = 0; k < RB_FLOOR_TAYLOR_TERMS; k++) {
        b.taylor_du[k] = -(c * uv + w2 * uu);
        b.taylor_dv[k] = -(c * vv + w2 * vu);
        double nuu = uv / (k + 1), nuv = -(w2 * uu + c * uv) / (k + 1);
        double nvu = vv / (k + 1), nvv = -(w2 * vu + c * vv) / (k + 1);
        uu = nuu, uv = nuv, vu = nvu, vv = nvv;
    }
    building_free(&s->bld);
    s->bld = b;
    s->bld.peak_mps2 = rb_series_floor_peak(s);
    return RB_OK;
}

rb_status rb_series_window(rb_series *s, double t_start_s, double t_end_s)
{
    if (!s || !s->accel_mps2 || s->n == 0 || !isfinite(t_start_s)
        || !isfinite(t_end_s) || t_end_s < t_start_s)
        return RB_ERR_INVALID;
    double first = ceil((t_start_s - s->t0_s) / s->dt_s - RB_WINDOW_SLACK);
    double last = floor((t_end_s - s->t0_s) / s->dt_s + RB_WINDOW_SLACK);
    if (first < 0.0)
        first = 0.0;
    if (last > (double)(s->n - 1))
        last = (double)(s->n - 1);
    if (last < first)
        return RB_ERR_INVALID;
    size_t i0 = (size_t)first, count = (size_t)last - i0 + 1;
    double **arrays[4] = {&s->accel_mps2, &s->bld.ground_mps2, &s->bld.u_m, &s->bld.v_mps};
    for (int k = 0; k < 4; k++) {
        if (!*arrays[k])
            continue;
        memmove(*arrays[k], *arrays[k] + i0, count * sizeof(double));
        /* Shrinking cannot lose data; if realloc declines, the larger
         * block is still ours and still valid. */
        double *shrunk = realloc(*arrays[k], count * sizeof(double));
        if (shrunk)
            *arrays[k] = shrunk;
    }
    s->n = count;
    s->t0_s = 0.0;
    if (s->bld.ground_mps2)
        s->bld.peak_mps2 = rb_series_floor_peak(s);
    return RB_OK;
}
