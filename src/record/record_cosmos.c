/* COSMOS strong-motion format, corrected acceleration (V2 and the .V2c
 * files of CESMD), first acceleration channel of the file.
 *
 * Layout (COSMOS Strong Motion Data Format v1.20): a text header whose
 * line 1 says how many lines it has ("(Format v01.20 with 13 text lines)")
 * and whose line 13 gives the null values; an integer header and a real
 * header, each introduced by "<n> ...-header values follow on <k> lines,
 * Format= (10I8)"; "<m> Comment line(s) follow"; then the data block,
 * "<npts> acceleration pts, approx <s> secs, units=cm/sec2 (04),
 * Format=(8F10.5)". Values are fixed-width Fortran fields and may touch
 * ("-123.45678-98.76543"), so fields are cut by the stated width, not at
 * blanks. Units come from integer-header entry 3 (physical units code),
 * else the data line; dt from real-header entry 62 (ms), else entry 34
 * (s, the recorder's interval, which processing may have changed). */
#include <math.h>
#include <string.h>
#include "rockbolt/model.h"
#include "record_internal.h"

#define RB_COSMOS_MAX_TEXT_LINES 1000
#define RB_COSMOS_MAX_HEADER_VALUES 100000
/* Header entries used, counted from 0 (the format counts from 1). */
#define RB_COSMOS_INT_UNITS 2
#define RB_COSMOS_REAL_DT_S 33
#define RB_COSMOS_REAL_DT_MS 61
#define RB_COSMOS_KEPT 100
#define RB_COSMOS_DT_REL_TOL 1e-6

typedef struct {
    size_t width;   /* characters per field; 0 -> split at blanks */
} rb_cosmos_fmt;

typedef struct {
    size_t text_lines;
    double int_null;
    double real_null;
    double ints[RB_COSMOS_KEPT];
    double reals[RB_COSMOS_KEPT];
    size_t n_ints, n_reals;
    size_t npts;
    double to_mps2;
    double dt_s;
    rb_cosmos_fmt data_fmt;
    long data_line;
} rb_cosmos;

static rb_status cosmos_next(rb_rec_reader *r, const char *what)
{
    int got = 0;
    rb_status st = rb_rec_reader_next(r, &got);
    if (st == RB_OK && !got)
        return rb_rec_fail_eof(r, RB_ERR_PARSE, "expected %s, found the end of the file",
                               what);
    return st;
}

/* Width of the fields of "Format= (8F10.5)" on the current line. */
static rb_cosmos_fmt cosmos_format(const rb_rec_reader *r)
{
    rb_cosmos_fmt f = {0};
    long at = rb_rec_find(r->line, r->len, "format");
    if (at < 0)
        return f;
    const char *p = strchr(r->line + at, '(');
    if (!p)
        return f;
    for (p++; *p >= '0' && *p <= '9'; p++)
        ;
    if (!strchr("IiFfEeDdGg", *p) || *p == '\0')
        return f;
    size_t w = 0;
    for (p++; *p >= '0' && *p <= '9' && w < 1000; p++)
        w = w * 10 + (size_t)(*p - '0');
    f.width = w;
    return f;
}

/* The next field of the current line; 0 at the end. A blank field with
 * more text after it comes back empty, so that parsing it fails. */
static int cosmos_field(const rb_rec_reader *r, const rb_cosmos_fmt *f, size_t *pos,
                           rb_rec_token *tok)
{
    if (f->width == 0)
        return rb_rec_token_next(r->line, pos, 0, tok);
    if (!rb_rec_token_field(r, *pos, f->width, tok))
        return 0;
    /* The last field of a line may be cut short: never step past its end,
     * where the search for more text below would read beyond the line. */
    *pos = *pos + f->width < r->len ? *pos + f->width : r->len;
    if (tok->len > 0)
        return 1;
    rb_rec_token later;
    size_t rest = *pos;
    return rb_rec_token_next(r->line, &rest, 0, &later);
}

static rb_status cosmos_text_header(rb_rec_reader *r, rb_cosmos *c)
{
    rb_status st = cosmos_next(r, "a COSMOS text header");
    if (st != RB_OK)
        return st;
    long at = rb_rec_find(r->line, r->len, "(format v");
    if (at < 0)
        return rb_rec_fail(r, RB_ERR_PARSE, 1, "expected a COSMOS header line "
                           "('... (Format v01.20 with 13 text lines) ...'), found none");
    long with = rb_rec_find(r->line, r->len, " with ");
    size_t pos = with < 0 ? r->len : (size_t)with + 6;
    rb_rec_token tok;
    c->text_lines = 13;
    if (rb_rec_token_next(r->line, &pos, 0, &tok)) {
        if ((st = rb_rec_token_count(r, &tok, "the number of text lines",
                                     RB_COSMOS_MAX_TEXT_LINES, &c->text_lines)) != RB_OK)
            return st;
        if (c->text_lines < 1 || c->text_lines > RB_COSMOS_MAX_TEXT_LINES)
            return rb_rec_fail(r, RB_ERR_PARSE, tok.col, "expected 1 to %d text lines, "
                               "found %zu", RB_COSMOS_MAX_TEXT_LINES, c->text_lines);
    }
    while ((size_t)r->lineno < c->text_lines) {
        if ((st = cosmos_next(r, "the rest of the COSMOS text header")) != RB_OK)
            return st;
        long colon = rb_rec_find(r->line, r->len, "unspecified:");
        pos = colon < 0 ? 0 : (size_t)colon + 12;
        if (colon >= 0 && rb_rec_token_next(r->line, &pos, 1, &tok)
            && rb_rec_number_parse(tok.s, tok.len, &c->int_null) == RB_OK
            && rb_rec_token_next(r->line, &pos, 1, &tok))
            (void)rb_rec_number_parse(tok.s, tok.len, &c->real_null);
    }
    return RB_OK;
}

/* "<n> <what> values follow on <k> lines, Format= (...)". */
static rb_status cosmos_block_head(rb_rec_reader *r, const char *what, size_t *n,
                                      size_t *lines, rb_cosmos_fmt *f)
{
    rb_rec_token tok;
    size_t pos = 0;
    rb_status st = cosmos_next(r, what);
    if (st != RB_OK)
        return st;
    long on = rb_rec_find(r->line, r->len, "follow on");
    if (rb_rec_find(r->line, r->len, what) < 0 || on < 0
        || !rb_rec_token_next(r->line, &pos, 0, &tok)) {
        return rb_rec_fail(r, RB_ERR_PARSE, 1, "expected '<n> %s values follow on "
                           "<k> lines, Format= (...)', found a line without it", what);
    }
    if ((st = rb_rec_token_count(r, &tok, "the number of header values",
                                 RB_COSMOS_MAX_HEADER_VALUES, n)) != RB_OK)
        return st;
    pos = (size_t)on + 9;
    if (!rb_rec_token_next(r->line, &pos, 1, &tok))
        return rb_rec_fail(r, RB_ERR_PARSE, (int)pos + 1, "expected the number of "
                           "lines after 'follow on', found the end of the line");
    if ((st = rb_rec_token_count(r, &tok, "the number of header lines",
                                 RB_COSMOS_MAX_HEADER_VALUES, lines)) != RB_OK)
        return st;
    if (*n > RB_COSMOS_MAX_HEADER_VALUES || *lines > RB_COSMOS_MAX_HEADER_VALUES)
        return rb_rec_fail(r, RB_ERR_LIMIT, 1, "more than %d header values or lines",
                           RB_COSMOS_MAX_HEADER_VALUES);
    *f = cosmos_format(r);
    return RB_OK;
}

/* An integer or real header; the first RB_COSMOS_KEPT values go to keep. */
static rb_status cosmos_header(rb_rec_reader *r, const char *what, double *keep,
                                  size_t *kept)
{
    size_t n = 0, lines = 0, seen = 0;
    rb_cosmos_fmt f;
    rb_status st = cosmos_block_head(r, what, &n, &lines, &f);
    for (size_t k = 0; st == RB_OK && k < lines; k++) {
        if ((st = cosmos_next(r, "header values")) != RB_OK)
            return st;
        size_t pos = 0;
        rb_rec_token tok;
        while (st == RB_OK && cosmos_field(r, &f, &pos, &tok)) {
            double x = 0.0;
            if ((st = rb_rec_token_number(r, &tok, "a header value", &x)) == RB_OK
                && seen < RB_COSMOS_KEPT)
                keep[seen] = x;
            seen++;
        }
    }
    if (st == RB_OK && seen != n)
        return rb_rec_fail(r, RB_ERR_PARSE, 0, "expected %zu %s values, found %zu",
                           n, what, seen);
    *kept = seen < RB_COSMOS_KEPT ? seen : RB_COSMOS_KEPT;
    return st;
}

static int cosmos_known(const rb_cosmos *c, double x, double null)
{
    return x != null && x != c->int_null && x != c->real_null;
}

/* Skip "<m> Comment line(s) follow ..." and its lines, if present, and
 * leave the data line current. */
static rb_status cosmos_skip_comments(rb_rec_reader *r)
{
    rb_status st = cosmos_next(r, "the comment or data line");
    if (st != RB_OK || rb_rec_find(r->line, r->len, "comment") < 0)
        return st;
    size_t pos = 0, n = 0;
    rb_rec_token tok;
    if (!rb_rec_token_next(r->line, &pos, 0, &tok))
        return rb_rec_fail(r, RB_ERR_PARSE, 1, "expected the number of comment lines");
    if ((st = rb_rec_token_count(r, &tok, "the number of comment lines",
                                 RB_COSMOS_MAX_HEADER_VALUES, &n)) != RB_OK)
        return st;
    for (size_t k = 0; k < n; k++)
        if ((st = cosmos_next(r, "a comment line")) != RB_OK)
            return st;
    return cosmos_next(r, "the data line ('<n> acceleration pts, ...')");
}

/* "<npts> acceleration pts, approx <s> secs, units=<u> (<code>), Format=(...)" */
static rb_status cosmos_data_line(rb_rec_reader *r, const rb_record_opts *o,
                                     rb_cosmos *c, double *text_units)
{
    rb_rec_token tok;
    size_t pos = 0;
    int first = rb_rec_token_next(r->line, &pos, 0, &tok);
    if (!first || rb_rec_find(r->line, r->len, "acceleration pts") < 0)
        return rb_rec_fail(r, RB_ERR_PARSE, 1, "expected an acceleration data block "
                           "('<n> acceleration pts, ...'), found a line without it");
    size_t limit = rb_rec_max_points(o);
    rb_status st = rb_rec_token_count(r, &tok, "the number of points", limit, &c->npts);
    if (st != RB_OK)
        return st;
    if (c->npts == 0)
        return rb_rec_fail(r, RB_ERR_INVALID, tok.col, "expected at least one point, "
                           "found 0");
    if (c->npts > limit)
        return rb_rec_fail(r, RB_ERR_LIMIT, tok.col, "more points than the point limit "
                           "of %zu", limit);
    long u = rb_rec_find(r->line, r->len, "units=");
    *text_units = 0.0;
    if (u >= 0) {
        size_t start = (size_t)u + 6, end = start;
        while (end < r->len && !strchr("(, \t", r->line[end]))
            end++;
        *text_units = rb_rec_units_lookup(r->line + start, end - start);
    }
    c->data_fmt = cosmos_format(r);
    c->data_line = r->lineno;
    return RB_OK;
}

/* Physical-units codes of COSMOS Table 2 that are accelerations. */
static double cosmos_units_code(double code)
{
    static const struct { int code; double to_mps2; } table[] = {
        {2, RB_G0}, {4, 1e-2}, {7, 0.0254}, {10, 1e-2}, {11, 1e-3 * RB_G0}};
    for (size_t i = 0; i < sizeof table / sizeof table[0]; i++)
        if (code == (double)table[i].code)
            return table[i].to_mps2;
    return 0.0;
}

static rb_status cosmos_resolve(const rb_rec_reader *r, const rb_record_opts *o,
                                   rb_cosmos *c, double text_units)
{
    if (c->n_ints > RB_COSMOS_INT_UNITS)
        c->to_mps2 = cosmos_units_code(c->ints[RB_COSMOS_INT_UNITS]);
    if (c->to_mps2 == 0.0)
        c->to_mps2 = text_units > 0.0 ? text_units : o->units_to_mps2;
    if (!(c->to_mps2 > 0.0))
        return rb_rec_fail_at(r, RB_ERR_INVALID, c->data_line, 1, "expected the units "
                              "in integer-header entry 3 or 'units=' on the data line, "
                              "found neither; give units_to_mps2");
    c->dt_s = 0.0;
    if (c->n_reals > RB_COSMOS_REAL_DT_MS
        && cosmos_known(c, c->reals[RB_COSMOS_REAL_DT_MS], -999.0))
        c->dt_s = c->reals[RB_COSMOS_REAL_DT_MS] * 1e-3;
    else if (c->n_reals > RB_COSMOS_REAL_DT_S
             && cosmos_known(c, c->reals[RB_COSMOS_REAL_DT_S], -999.0))
        c->dt_s = c->reals[RB_COSMOS_REAL_DT_S];
    if (!(c->dt_s > 0.0))
        return rb_rec_fail_at(r, RB_ERR_INVALID, c->data_line, 1, "expected the time "
                              "step in real-header entry 62 (ms) or 34 (s) as a "
                              "positive number, found none");
    return rb_rec_check_dt(r, o, c->dt_s, RB_COSMOS_DT_REL_TOL, c->data_line, 1);
}

/* After the last value: the rest of the line and the next line must not
 * hold more values (the next line is "End-of-data ..." or another block). */
static rb_status cosmos_no_more(rb_rec_reader *r, const rb_cosmos *c, size_t pos)
{
    rb_rec_token tok;
    double x;
    int got = 0;
    if (cosmos_field(r, &c->data_fmt, &pos, &tok))
        return rb_rec_fail(r, RB_ERR_PARSE, tok.col, "the data line says %zu points, "
                           "found more values than that", c->npts);
    rb_status st = rb_rec_reader_next(r, &got);
    pos = 0;
    if (st != RB_OK || !got || !rb_rec_token_next(r->line, &pos, 0, &tok))
        return st;
    if (rb_rec_number_parse(tok.s, tok.len, &x) == RB_OK)
        return rb_rec_fail(r, RB_ERR_PARSE, tok.col, "the data line says %zu points, "
                           "found more values than that", c->npts);
    return RB_OK;
}

static rb_status cosmos_values(rb_rec_reader *r, const rb_cosmos *c, rb_rec_values *b)
{
    rb_status st = RB_OK;
    while (b->n < c->npts) {
        int got = 0;
        if ((st = rb_rec_reader_next(r, &got)) != RB_OK)
            return st;
        if (!got)
            return rb_rec_fail_eof(r, RB_ERR_PARSE, "the data line says %zu points, "
                                   "found the end of the file after %zu", c->npts, b->n);
        if (rb_rec_find(r->line, r->len, "end-of-data") >= 0
            || rb_rec_find(r->line, r->len, " pts") >= 0)
            return rb_rec_fail(r, RB_ERR_PARSE, 1, "the data line says %zu points, "
                               "found the end of the block after %zu", c->npts, b->n);
        size_t pos = 0;
        rb_rec_token tok;
        while (b->n < c->npts && cosmos_field(r, &c->data_fmt, &pos, &tok)) {
            double x;
            if ((st = rb_rec_token_number(r, &tok, "an acceleration value", &x)) != RB_OK
                || (st = rb_rec_values_push(b, r, &tok, x, c->to_mps2)) != RB_OK)
                return st;
        }
        if (b->n == c->npts)
            return cosmos_no_more(r, c, pos);
    }
    return st;
}

rb_status rb_record_read_cosmos(rb_rec_reader *r, const rb_record_opts *o, rb_series *out)
{
    rb_cosmos c;
    double text_units = 0.0;
    memset(&c, 0, sizeof c);
    c.int_null = -999.0;
    c.real_null = -999.0;
    rb_status st = cosmos_text_header(r, &c);
    if (st == RB_OK)
        st = cosmos_header(r, "Integer-header", c.ints, &c.n_ints);
    if (st == RB_OK)
        st = cosmos_header(r, "Real-header", c.reals, &c.n_reals);
    if (st == RB_OK)
        st = cosmos_skip_comments(r);
    if (st == RB_OK)
        st = cosmos_data_line(r, o, &c, &text_units);
    if (st == RB_OK)
        st = cosmos_resolve(r, o, &c, text_units);
    if (st != RB_OK)
        return st;
    rb_rec_values b;
    rb_rec_values_init(&b, c.npts);
    st = cosmos_values(r, &c, &b);
    if (st == RB_OK)
        rb_rec_values_move(&b, c.dt_s, 0.0, out);
    rb_rec_values_free(&b);
    return st;
}
