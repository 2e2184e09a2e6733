/* PEER AT2 records: four header lines, then the values in free format.
 *
 * Line 3 names the units ("ACCELERATION TIME HISTORY IN UNITS OF G", or
 * "The units are (g)" in hand-made copies). Line 4 holds the count and
 * the step, either keyed as in the legacy PEER ("NPTS=  4000, DT= .01000
 * SEC") and NGA-West2 ("NPTS=   5372, DT=   .0100 SEC,") headers, or
 * positionally as in early NGA files ("5372  0.0100  NPTS, DT"). The
 * count is checked against the values: a record cut short or run on is
 * the commonest corruption of these files. */
#include <math.h>
#include <string.h>
#include "record_internal.h"

/* Header dt and the options' dt_s must agree this closely: both are
 * typed numbers, not measurements. */
#define RB_AT2_DT_REL_TOL 1e-6

typedef struct {
    size_t npts;
    double dt_s;
    double to_mps2;
} rb_at2_header;

static size_t at2_skip_blanks(const char *s, size_t i)
{
    while (s[i] == ' ' || s[i] == '\t')
        i++;
    return i;
}

/* Past "UNITS", its joining word ("OF", "ARE", "IN", "=") and blanks. */
static size_t at2_units_start(const rb_rec_reader *r, size_t i)
{
    static const char *const joins[] = {"of ", "are ", "in ", "is "};
    for (int again = 1; again;) {
        again = 0;
        i = at2_skip_blanks(r->line, i);
        if (r->line[i] == '=' || r->line[i] == ':') {
            i++;
            again = 1;
        }
        for (size_t k = 0; k < sizeof joins / sizeof joins[0]; k++)
            if (rb_rec_find(r->line + i, strlen(joins[k]), joins[k]) == 0) {
                i += strlen(joins[k]);
                again = 1;
            }
    }
    return i;
}

static rb_status at2_units(const rb_rec_reader *r, const rb_record_opts *o,
                              double *to_mps2)
{
    static const char *const others[] = {"velocity", "displacement"};
    for (size_t k = 0; k < 2; k++) {
        long at = rb_rec_find(r->line, r->len, others[k]);
        if (at >= 0)
            return rb_rec_fail(r, RB_ERR_PARSE, (int)at + 1, "expected an "
                               "acceleration record, found a %s record", others[k]);
    }
    long at = rb_rec_find(r->line, r->len, "units");
    if (at < 0) {
        *to_mps2 = o->units_to_mps2;
        if (*to_mps2 > 0.0)
            return RB_OK;
        return rb_rec_fail(r, RB_ERR_INVALID, 1, "expected the units on line 3 "
                           "(e.g. 'UNITS OF G'), found none; give units_to_mps2");
    }
    size_t start = at2_units_start(r, (size_t)at + 5), end = start;
    while (r->line[end] && r->line[end] != ' ' && r->line[end] != '\t'
           && r->line[end] != ',' && r->line[end] != ';')
        end++;
    *to_mps2 = rb_rec_units_lookup(r->line + start, end - start);
    if (*to_mps2 > 0.0)
        return RB_OK;
    return rb_rec_fail(r, RB_ERR_PARSE, (int)start + 1, "expected acceleration units "
                       "(g, m/s^2, cm/s^2, mm/s^2, in/s^2) after 'UNITS', found "
                       "other text");
}

static rb_status at2_dt_value(const rb_rec_reader *r, const rb_rec_token *tok,
                                 double *dt)
{
    rb_status st = rb_rec_token_number(r, tok, "the time step DT in seconds", dt);
    if (st != RB_OK)
        return st;
    if (*dt > 0.0)
        return RB_OK;
    return rb_rec_fail(r, RB_ERR_INVALID, tok->col, "expected DT > 0 s, found a "
                       "number at or below zero");
}

/* The number of points from tok, within 1..limit. */
static rb_status at2_count(const rb_rec_reader *r, const rb_rec_token *tok,
                              size_t limit, rb_at2_header *h)
{
    rb_status st = rb_rec_token_count(r, tok, "the number of points NPTS", limit,
                                      &h->npts);
    if (st != RB_OK)
        return st;
    if (h->npts == 0)
        return rb_rec_fail(r, RB_ERR_INVALID, tok->col, "expected NPTS > 0, found 0");
    if (h->npts > limit)
        return rb_rec_fail(r, RB_ERR_LIMIT, tok->col, "NPTS is more than the point "
                           "limit of %zu", limit);
    return RB_OK;
}

/* "NPTS= n, DT= dt": returns RB_OK with found = 0 if the line is not keyed. */
static rb_status at2_keyed(const rb_rec_reader *r, size_t limit, rb_at2_header *h,
                              int *found)
{
    rb_rec_token tok;
    long at = rb_rec_find(r->line, r->len, "npts");
    size_t pos = at < 0 ? 0 : at2_skip_blanks(r->line, (size_t)at + 4);
    *found = at >= 0 && (r->line[pos] == '=' || r->line[pos] == ':');
    if (!*found)
        return RB_OK;
    pos++;
    if (!rb_rec_token_next(r->line, &pos, 1, &tok))
        return rb_rec_fail(r, RB_ERR_PARSE, (int)pos + 1, "expected the number of "
                           "points after 'NPTS=', found the end of the line");
    rb_status st = at2_count(r, &tok, limit, h);
    if (st != RB_OK)
        return st;
    long dt_at = rb_rec_find(r->line + pos, r->len - pos, "dt");
    size_t dpos = dt_at < 0 ? r->len : at2_skip_blanks(r->line, pos + (size_t)dt_at + 2);
    if (dt_at < 0 || (r->line[dpos] != '=' && r->line[dpos] != ':'))
        return rb_rec_fail(r, RB_ERR_PARSE, (int)pos + 1, "expected 'DT= <step> SEC' "
                           "after the number of points, found none");
    dpos++;
    if (!rb_rec_token_next(r->line, &dpos, 1, &tok))
        return rb_rec_fail(r, RB_ERR_PARSE, (int)dpos + 1, "expected the time step "
                           "after 'DT=', found the end of the line");
    return at2_dt_value(r, &tok, &h->dt_s);
}

/* "n dt ..." as the first two tokens. */
static rb_status at2_positional(const rb_rec_reader *r, size_t limit, rb_at2_header *h)
{
    rb_rec_token tok;
    size_t pos = 0;
    if (!rb_rec_token_next(r->line, &pos, 1, &tok))
        return rb_rec_fail(r, RB_ERR_PARSE, 1, "expected 'NPTS= <n>, DT= <step> SEC' "
                           "on line 4, found an empty line");
    double x;
    if (rb_rec_number_parse(tok.s, tok.len, &x) != RB_OK) {
        return rb_rec_fail(r, RB_ERR_PARSE, tok.col, "expected 'NPTS= <n>, DT= <step> "
                           "SEC' on line 4, found other text");
    }
    rb_status st = at2_count(r, &tok, limit, h);
    if (st != RB_OK)
        return st;
    if (!rb_rec_token_next(r->line, &pos, 1, &tok))
        return rb_rec_fail(r, RB_ERR_PARSE, (int)pos + 1, "expected the time step "
                           "after the number of points, found the end of the line");
    return at2_dt_value(r, &tok, &h->dt_s);
}

static rb_status at2_npts_dt(const rb_rec_reader *r, const rb_record_opts *o,
                                rb_at2_header *h)
{
    size_t limit = rb_rec_max_points(o);
    int keyed = 0;
    rb_status st = at2_keyed(r, limit, h, &keyed);
    if (st == RB_OK && !keyed)
        st = at2_positional(r, limit, h);
    if (st != RB_OK)
        return st;
    return rb_rec_check_dt(r, o, h->dt_s, RB_AT2_DT_REL_TOL, r->lineno, 1);
}

static rb_status at2_header_read(rb_rec_reader *r, const rb_record_opts *o,
                                    rb_at2_header *h)
{
    for (long k = 1; k <= 4; k++) {
        int got = 0;
        rb_status st = rb_rec_reader_next(r, &got);
        if (st != RB_OK)
            return st;
        if (!got)
            return rb_rec_fail_eof(r, RB_ERR_PARSE, "expected the 4 header lines of "
                                   "a PEER AT2 record, found the end of the file");
        if (k == 3 && (st = at2_units(r, o, &h->to_mps2)) != RB_OK)
            return st;
        if (k == 4 && (st = at2_npts_dt(r, o, h)) != RB_OK)
            return st;
    }
    return RB_OK;
}

static rb_status at2_values(rb_rec_reader *r, const rb_at2_header *h, rb_rec_values *b)
{
    int got = 0;
    rb_status st;
    while ((st = rb_rec_reader_next(r, &got)) == RB_OK && got) {
        size_t pos = 0;
        rb_rec_token tok;
        while (rb_rec_token_next(r->line, &pos, 0, &tok)) {
            double x;
            if (b->n == h->npts)
                return rb_rec_fail(r, RB_ERR_PARSE, tok.col, "line 4 says NPTS = %zu, "
                                   "found more values than that", h->npts);
            if ((st = rb_rec_token_number(r, &tok, "an acceleration value", &x)) != RB_OK
                || (st = rb_rec_values_push(b, r, &tok, x, h->to_mps2)) != RB_OK)
                return st;
        }
    }
    if (st == RB_OK && b->n < h->npts)
        return rb_rec_fail_eof(r, RB_ERR_PARSE, "line 4 says NPTS = %zu, found the end "
                               "of the file after %zu values", h->npts, b->n);
    return st;
}

rb_status rb_record_read_at2(rb_rec_reader *r, const rb_record_opts *o, rb_series *out)
{
    rb_at2_header h = {0, 0.0, 0.0};
    rb_rec_values b;
    rb_status st = at2_header_read(r, o, &h);
    if (st != RB_OK)
        return st;
    rb_rec_values_init(&b, h.npts);
    st = at2_values(r, &h, &b);
    if (st == RB_OK)
        rb_rec_values_move(&b, h.dt_s, 0.0, out);
    rb_rec_values_free(&b);
    return st;
}
