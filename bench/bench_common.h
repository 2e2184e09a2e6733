/* What the benchmarks and studies share: a monotonic clock, the El Centro
 * floor motion of the thesis (record through a 5 Hz, 5 % building), the
 * shipped El Centro and Taft records, and the studies' random draws.
 * Header-only because CMake builds each benchmark source as its own
 * program. */
#ifndef RB_BENCH_COMMON_H
#define RB_BENCH_COMMON_H

#include <stdio.h>
#include <time.h>
#include "rockbolt/record.h"

static inline double rb_bench_now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* Read a record and turn it into the floor motion of a 5 Hz, 5 % building.
 * Returns 0, or -1 after printing why. s is the caller's to free. */
static inline int rb_bench_floor_motion(const char *path, rb_series *s)
{
    rb_record_opts ro;
    rb_diag diag;
    rb_record_opts_init(&ro);
    if (rb_record_read(path, &ro, s, &diag) != RB_OK) {
        fprintf(stderr, "%s:%d:%d: error: %s\n", path, diag.line, diag.col, diag.msg);
        return -1;
    }
    if (rb_series_building_filter(s, 5.0, 0.05) != RB_OK) {
        fprintf(stderr, "%s: building filter failed\n", path);
        return -1;
    }
    return 0;
}

/* A draw in [lo, hi) from the 64-bit LCG state *s (a study's fixed seed
 * gives the same cabinets on every machine). */
static inline double rb_bench_uniform(unsigned long long *s, double lo, double hi)
{
    *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * (double)(*s >> 11) / 9007199254740992.0;
}

/* One of the shipped records as it is read: El Centro's AT2 file, or
 * (taft) Taft's one column in g at 0.01 s. 0, or -1. */
static inline int rb_bench_read_record(const char *path, int taft, rb_series *s)
{
    rb_record_opts ro;
    rb_diag diag;
    rb_record_opts_init(&ro);
    if (taft) {
        ro.format = RB_REC_ONE_COLUMN;
        ro.dt_s = 0.01;
        ro.units_to_mps2 = 9.80665;
    }
    return rb_record_read(path, &ro, s, &diag) == RB_OK ? 0 : -1;
}

/* The physical floor a solve is measured against: a plain linear SDOF
 * (the frame alone, at frequency f_hz and damping xi) through the same
 * floor series, by Newmark's average acceleration, one step a sample,
 * nothing tracked but the peak displacement. Returns it (m), so that the
 * loop is not optimised away. */
static inline double rb_bench_sdof_newmark(const rb_series *s, double scale, double f_hz,
                                           double xi)
{
    double w = 2 * 3.141592653589793 * f_hz, dt = s->dt_s;
    double k = w * w, c = 2 * xi * w;
    double khat = k + 2 * c / dt + 4 / (dt * dt);
    double u = 0, v = 0, a = -scale * s->accel_mps2[0], peak = 0;
    for (size_t i = 1; i < s->n; i++) {
        double p = -scale * s->accel_mps2[i];
        double un = (p + (4 / (dt * dt) + 2 * c / dt) * u + (4 / dt + c) * v + a) / khat;
        double vn = 2 * (un - u) / dt - v;
        a = p - c * vn - k * un;
        u = un;
        v = vn;
        peak = u > peak ? u : -u > peak ? -u : peak;
    }
    return peak;
}

#endif
