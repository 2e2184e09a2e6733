/* Column records: one value per row (dt given by the caller) or two
 * (time, acceleration). Blanks or commas separate the values; blank lines
 * and lines starting with '#' are skipped. Neither form states its units,
 * so the caller must.
 *
 * The solver assumes equal steps, so a time column must be uniform. Each
 * step is compared with the mean step of the rows before it, which flags
 * the very row where a sample is missing or doubled while letting the
 * rounding of printed times (a few digits) pass. */
#include <math.h>
#include "record_internal.h"

/* A step may differ from the mean of the steps before it by this
 * fraction; a missing sample makes it differ by 100 %. */
#define RB_COLS_DT_REL_TOL 0.01

typedef struct {
    double t0;
    double t_prev;
    size_t rows;
} rb_cols_clock;

static rb_status cols_need_units(const rb_rec_reader *r, const rb_record_opts *o)
{
    if (o->units_to_mps2 > 0.0)
        return RB_OK;
    return rb_rec_fail_at(r, RB_ERR_INVALID, 0, 0, "column records do not state their "
                          "units: give units_to_mps2 (e.g. 9.80665 for g)");
}

/* The values of a data row into tok[]; *n is 0 for a blank or comment line.
 * More than want values is an error at the first extra one. */
static rb_status cols_split(const rb_rec_reader *r, size_t want, rb_rec_token *tok,
                               size_t *n)
{
    size_t pos = 0;
    rb_rec_token extra;
    *n = 0;
    while (*n < want && rb_rec_token_next(r->line, &pos, 1, &tok[*n])) {
        if (*n == 0 && tok[0].s[0] == '#')
            return RB_OK;
        (*n)++;
    }
    if (*n == 0)
        return RB_OK;
    if (rb_rec_token_next(r->line, &pos, 1, &extra))
        return rb_rec_fail(r, RB_ERR_PARSE, extra.col, want == 1
                           ? "expected one value per row (acceleration), found more"
                           : "expected two values per row (time, acceleration), "
                           "found more");
    if (*n < want)
        return rb_rec_fail(r, RB_ERR_PARSE, (int)r->len + 1, "expected two values per "
                           "row (time, acceleration), found one");
    return RB_OK;
}

static rb_status cols_tick(const rb_rec_reader *r, rb_cols_clock *c,
                              const rb_rec_token *tok, double t)
{
    if (c->rows == 0) {
        c->t0 = t;
    } else if (c->rows == 1 && !(t > c->t0)) {
        return rb_rec_fail(r, RB_ERR_INVALID, tok->col, "expected times to increase, "
                           "found t = %.9g s after t = %.9g s", t, c->t0);
    } else if (c->rows > 1) {
        double mean = (c->t_prev - c->t0) / (double)(c->rows - 1);
        double step = t - c->t_prev;
        if (!(fabs(step - mean) <= RB_COLS_DT_REL_TOL * mean))
            return rb_rec_fail(r, RB_ERR_INVALID, tok->col, "expected a uniform time "
                               "step of %.9g s (the mean so far), found a step of "
                               "%.9g s to t = %.9g s", mean, step, t);
    }
    c->t_prev = t;
    c->rows++;
    return RB_OK;
}

/* Every data row of the file; clock is NULL for one-column records. */
static rb_status cols_rows(rb_rec_reader *r, double to_mps2, rb_cols_clock *clock,
                              rb_rec_values *b)
{
    size_t want = clock ? 2 : 1, n = 0;
    rb_rec_token tok[2];
    int got = 0;
    rb_status st;
    while ((st = rb_rec_reader_next(r, &got)) == RB_OK && got) {
        double t = 0.0, a = 0.0;
        if ((st = cols_split(r, want, tok, &n)) != RB_OK)
            return st;
        if (n == 0)
            continue;
        if (clock && ((st = rb_rec_token_number(r, &tok[0], "a time in seconds", &t))
                      != RB_OK || (st = cols_tick(r, clock, &tok[0], t)) != RB_OK))
            return st;
        if ((st = rb_rec_token_number(r, &tok[want - 1], "an acceleration value", &a))
            != RB_OK || (st = rb_rec_values_push(b, r, &tok[want - 1], a, to_mps2)) != RB_OK)
            return st;
    }
    if (st == RB_OK && b->n == 0)
        return rb_rec_fail_eof(r, RB_ERR_PARSE, "expected rows of numbers, found none");
    return st;
}

rb_status rb_record_read_two_column(rb_rec_reader *r, const rb_record_opts *o,
                                    rb_series *out)
{
    rb_cols_clock clock = {0.0, 0.0, 0};
    rb_rec_values b;
    rb_status st = cols_need_units(r, o);
    if (st != RB_OK)
        return st;
    rb_rec_values_init(&b, rb_rec_max_points(o));
    st = cols_rows(r, o->units_to_mps2, &clock, &b);
    double dt = o->dt_s;
    if (st == RB_OK && clock.rows > 1) {
        dt = (clock.t_prev - clock.t0) / (double)(clock.rows - 1);
        st = rb_rec_check_dt(r, o, dt, RB_COLS_DT_REL_TOL, 0, 0);
    } else if (st == RB_OK && !(dt > 0.0)) {
        st = rb_rec_fail(r, RB_ERR_INVALID, 0, "expected at least two rows to define "
                         "the time step (or dt_s in the options), found one");
    }
    if (st == RB_OK)
        rb_rec_values_move(&b, dt, clock.t0, out);
    rb_rec_values_free(&b);
    return st;
}

rb_status rb_record_read_one_column(rb_rec_reader *r, const rb_record_opts *o,
                                    rb_series *out)
{
    rb_rec_values b;
    if (!(o->dt_s > 0.0))
        return rb_rec_fail_at(r, RB_ERR_INVALID, 0, 0, "one-column records do not "
                              "state their time step: give dt_s > 0");
    rb_status st = cols_need_units(r, o);
    if (st != RB_OK)
        return st;
    rb_rec_values_init(&b, rb_rec_max_points(o));
    st = cols_rows(r, o->units_to_mps2, NULL, &b);
    if (st == RB_OK)
        rb_rec_values_move(&b, o->dt_s, 0.0, out);
    rb_rec_values_free(&b);
    return st;
}
