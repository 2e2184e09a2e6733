/* The values of a record as they are read: a buffer that grows by doubling
 * up to the caller's point limit, so a file can never make us hold more
 * than that, and the hand-over to an rb_series. Also the two option rules
 * every reader shares (point limit, dt agreement). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include "record_internal.h"

#define RB_REC_FIRST_CAPACITY 1024

void rb_rec_values_init(rb_rec_values *b, size_t max)
{
    memset(b, 0, sizeof *b);
    b->max = max;
}

void rb_rec_values_free(rb_rec_values *b)
{
    free(b->v);
    memset(b, 0, sizeof *b);
}

static rb_status rec_values_grow(rb_rec_values *b, const rb_rec_reader *r, int col)
{
    size_t cap = b->cap ? b->cap * 2 : RB_REC_FIRST_CAPACITY;
    if (cap > b->max)
        cap = b->max;
    double *p = realloc(b->v, cap * sizeof *p);
    if (!p)
        return rb_rec_fail(r, RB_ERR_NOMEM, col, "out of memory holding %zu values",
                           cap);
    b->v = p;
    b->cap = cap;
    return RB_OK;
}

rb_status rb_rec_values_push(rb_rec_values *b, const rb_rec_reader *r,
                             const rb_rec_token *tok, double raw, double factor)
{
    if (b->n >= b->max)
        return rb_rec_fail(r, RB_ERR_LIMIT, tok->col,
                           "more than %zu values (the point limit)", b->max);
    if (b->n == b->cap && rec_values_grow(b, r, tok->col) != RB_OK)
        return RB_ERR_NOMEM;
    double x = raw * factor;
    if (!isfinite(x)) {
        return rb_rec_fail(r, RB_ERR_INVALID, tok->col, "expected an acceleration "
                           "that fits in m/s^2, found one that overflows once "
                           "converted");
    }
    b->v[b->n++] = x;
    return RB_OK;
}

void rb_rec_values_move(rb_rec_values *b, double dt_s, double t0_s, rb_series *out)
{
    /* Trimming the slack is optional; a refused realloc keeps the block. */
    double *p = b->n ? realloc(b->v, b->n * sizeof *p) : NULL;
    memset(out, 0, sizeof *out);
    out->accel_mps2 = p ? p : b->v;
    out->n = b->n;
    out->dt_s = dt_s;
    out->t0_s = t0_s;
    memset(b, 0, sizeof *b);
}

size_t rb_rec_max_points(const rb_record_opts *o)
{
    size_t hard = SIZE_MAX / sizeof(double) / 16;
    size_t m = o->max_points ? o->max_points : RB_REC_DEFAULT_MAX_POINTS;
    return m < hard ? m : hard;
}

rb_status rb_rec_check_dt(const rb_rec_reader *r, const rb_record_opts *o,
                          double file_dt, double rel_tol, long line, int col)
{
    if (o->dt_s == 0.0)
        return RB_OK;
    if (!isfinite(o->dt_s) || o->dt_s < 0.0)
        return rb_rec_fail_at(r, RB_ERR_INVALID, 0, 0, "expected dt_s > 0 s or 0 "
                              "(take dt from the file) in the options, found %g",
                              o->dt_s);
    if (fabs(o->dt_s - file_dt) > rel_tol * file_dt)
        return rb_rec_fail_at(r, RB_ERR_INVALID, line, col, "the file gives dt = %.9g s "
                              "but the options say dt = %.9g s", file_dt, o->dt_s);
    return RB_OK;
}
