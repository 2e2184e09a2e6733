/* rb_record_read: check the arguments, open the file, settle its format
 * (guessing from the content first and the extension second, because
 * extensions like .V2 and .txt are shared by unrelated formats) and hand
 * it to the reader of that format. */
#include <math.h>
#include <string.h>
#include "record_internal.h"
#include "rockbolt/sandbox.h"

const rb_enum_name rb_record_format_names[] = {
    {"auto", RB_REC_AUTO}, {"at2", RB_REC_AT2}, {"cosmos", RB_REC_COSMOS_V2},
    {"two-column", RB_REC_TWO_COLUMN}, {"one-column", RB_REC_ONE_COLUMN}, {NULL, 0}};

/* How far to look for the first data row when guessing a column file. */
#define RB_REC_SNIFF_LINES 64

void rb_record_opts_init(rb_record_opts *o)
{
    if (!o)
        return;
    memset(o, 0, sizeof *o);
    o->format = RB_REC_AUTO;
}

static int record_ext_is(const char *path, const char *ext)
{
    size_t n = strlen(path), e = strlen(ext);
    return n >= e && rb_rec_find(path + n - e, e, ext) == 0;
}

/* A line that holds data for a column file: not blank, not a comment. */
static int record_is_data_line(const rb_rec_reader *r, size_t *ntok, rb_rec_token *first)
{
    size_t pos = 0, n = 0;
    rb_rec_token tok;
    while (rb_rec_token_next(r->line, &pos, 1, &tok)) {
        if (n == 0)
            *first = tok;
        n++;
    }
    *ntok = n;
    return n > 0 && first->s[0] != '#';
}

static rb_status record_guess_columns(const rb_rec_reader *r, size_t ntok,
                                         const rb_rec_token *first,
                                         rb_record_format *fmt)
{
    double x;
    if (rb_rec_number_parse(first->s, first->len, &x) == RB_ERR_PARSE)
        return rb_rec_fail(r, RB_ERR_PARSE, first->col, "cannot tell the format: "
                           "expected a PEER AT2 header (NPTS= in lines 1-4), a COSMOS "
                           "header or a column of numbers, found text that is none "
                           "of these");
    if (ntok > 2)
        return rb_rec_fail(r, RB_ERR_PARSE, first->col, "cannot tell the format: "
                           "expected one column (acceleration) or two (time, "
                           "acceleration), found %zu values on the line", ntok);
    *fmt = ntok == 1 ? RB_REC_ONE_COLUMN : RB_REC_TWO_COLUMN;
    return RB_OK;
}

/* A header format recognised from lines 1-4, or RB_REC_AUTO. */
static rb_status record_guess_header(rb_rec_reader *r, rb_record_format *fmt)
{
    int got = 0;
    rb_status st;
    *fmt = RB_REC_AUTO;
    while ((st = rb_rec_reader_next(r, &got)) == RB_OK && got && r->lineno <= 4) {
        if (r->lineno == 1 && rb_rec_find(r->line, r->len, "(format v") >= 0)
            *fmt = RB_REC_COSMOS_V2;
        else if (rb_rec_find(r->line, r->len, "npts") >= 0)
            *fmt = RB_REC_AT2;
        if (*fmt != RB_REC_AUTO)
            break;
    }
    if (st == RB_OK && r->lineno == 0)
        return rb_rec_fail_eof(r, RB_ERR_PARSE, "empty file: expected a "
                               "strong-motion record, found nothing");
    return st;
}

/* No header: the first data row tells one column from two. */
static rb_status record_guess_body(rb_rec_reader *r, rb_record_format *fmt)
{
    size_t ntok = 0;
    rb_rec_token first = {0};
    int got = 0;
    rb_status st;
    while ((st = rb_rec_reader_next(r, &got)) == RB_OK && got
           && r->lineno <= RB_REC_SNIFF_LINES)
        if (record_is_data_line(r, &ntok, &first))
            return record_guess_columns(r, ntok, &first, fmt);
    if (st != RB_OK)
        return st;
    if (got)
        return rb_rec_fail(r, RB_ERR_PARSE, 1, "cannot tell the format: no header "
                           "and no data in the first %d lines", RB_REC_SNIFF_LINES);
    return rb_rec_fail_eof(r, RB_ERR_PARSE, "expected a strong-motion record, "
                           "found no data");
}

static rb_status record_guess(rb_rec_reader *r, rb_record_format *fmt)
{
    rb_status st = record_guess_header(r, fmt);
    if (st == RB_OK && *fmt == RB_REC_AUTO) {
        if (record_ext_is(r->path, ".at2"))
            *fmt = RB_REC_AT2;
        else if (record_ext_is(r->path, ".v2") || record_ext_is(r->path, ".v2c"))
            *fmt = RB_REC_COSMOS_V2;
    }
    if (st == RB_OK && *fmt == RB_REC_AUTO && (st = rb_rec_reader_rewind(r)) == RB_OK)
        st = record_guess_body(r, fmt);
    if (st != RB_OK)
        return st;
    return rb_rec_reader_rewind(r);
}

static rb_status record_check_opts(const rb_rec_reader *r, const rb_record_opts *o)
{
    if (o->format < RB_REC_AUTO || o->format > RB_REC_ONE_COLUMN)
        return rb_rec_fail_at(r, RB_ERR_INVALID, 0, 0, "unknown record format %d",
                              (int)o->format);
    if (!isfinite(o->units_to_mps2) || o->units_to_mps2 < 0.0)
        return rb_rec_fail_at(r, RB_ERR_INVALID, 0, 0, "expected units_to_mps2 > 0 "
                              "or 0 (from the file), found %g", o->units_to_mps2);
    if (!isfinite(o->dt_s) || o->dt_s < 0.0)
        return rb_rec_fail_at(r, RB_ERR_INVALID, 0, 0, "expected dt_s > 0 s or 0 "
                              "(from the file), found %g", o->dt_s);
    return RB_OK;
}

static rb_status record_dispatch(rb_rec_reader *r, const rb_record_opts *o,
                                    rb_series *out)
{
    rb_record_format fmt = o->format;
    rb_status st = RB_OK;
    if (fmt == RB_REC_AUTO)
        st = record_guess(r, &fmt);
    if (st != RB_OK)
        return st;
    switch (fmt) {
    case RB_REC_AT2: return rb_record_read_at2(r, o, out);
    case RB_REC_COSMOS_V2: return rb_record_read_cosmos(r, o, out);
    case RB_REC_TWO_COLUMN: return rb_record_read_two_column(r, o, out);
    case RB_REC_ONE_COLUMN: return rb_record_read_one_column(r, o, out);
    case RB_REC_AUTO: break;
    }
    return rb_rec_fail_at(r, RB_ERR_INVALID, 0, 0, "no record format");
}

rb_status rb_record_read(const char *path, const rb_record_opts *opts,
                         rb_series *out, rb_diag *diag)
{
    rb_record_opts defaults;
    rb_rec_reader r;
    rb_diag_clear(diag);
    if (out)
        memset(out, 0, sizeof *out);
    if (!opts) {
        rb_record_opts_init(&defaults);
        opts = &defaults;
    }
    memset(&r, 0, sizeof r);
    r.path = path;
    r.diag = diag;
    if (!path || !out)
        return rb_rec_fail_at(&r, RB_ERR_INVALID, 0, 0, "no file name or no output");
    rb_status st = record_check_opts(&r, opts);
    char why[600];
    if (st == RB_OK && !rb_sandbox_allows(opts->sandbox, path, why, sizeof why))
        st = rb_rec_fail_at(&r, RB_ERR_IO, 0, 0, "it lies outside the sandbox '%s' "
                            "(%s)", rb_sandbox_dir(opts->sandbox), why);
    if (st == RB_OK)
        st = rb_rec_reader_open(&r, path, diag);
    if (st == RB_OK)
        st = record_dispatch(&r, opts, out);
    rb_rec_reader_close(&r);
    if (st != RB_OK)
        rb_series_free(out);
    return st;
}
