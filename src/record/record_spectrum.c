/* Target spectrum tables: frequency and acceleration in two columns. */
#include <stdlib.h>
#include <string.h>
#include "record_internal.h"
#include "rockbolt/sandbox.h"
#include "rockbolt/spectrum.h"
#include "rockbolt/units.h"

static rb_status table_row(const rb_rec_reader *r, double units, rb_rec_values *f,
                           rb_rec_values *a, int *header_ok)
{
    size_t pos = 0;
    rb_rec_token tok[2], extra;
    if (!rb_rec_token_next(r->line, &pos, 1, &tok[0]) || tok[0].s[0] == '#')
        return RB_OK;
    double x;
    int first_row = *header_ok;
    *header_ok = 0;
    if (first_row && rb_rec_number_parse(tok[0].s, tok[0].len, &x) == RB_ERR_PARSE)
        return RB_OK;   /* the header line */
    if (!rb_rec_token_next(r->line, &pos, 1, &tok[1]))
        return rb_rec_fail(r, RB_ERR_PARSE, (int)r->len + 1, "expected two values per row "
                           "(frequency in Hz, spectral acceleration), found one");
    if (rb_rec_token_next(r->line, &pos, 1, &extra))
        return rb_rec_fail(r, RB_ERR_PARSE, extra.col, "expected two values per row "
                           "(frequency in Hz, spectral acceleration), found more");
    double fv, av;
    rb_status st = rb_rec_token_number(r, &tok[0], "a frequency in Hz", &fv);
    if (st == RB_OK)
        st = rb_rec_token_number(r, &tok[1], "a spectral acceleration", &av);
    if (st != RB_OK)
        return st;
    /* a row at 1e-6 Hz made the generator step a free period of 11 days
     * per oscillator per pass: checked against the spectrum's own range */
    if (!(fv >= RB_SPECTRUM_MIN_HZ && fv <= RB_SPECTRUM_MAX_HZ))
        return rb_rec_fail(r, RB_ERR_INVALID, tok[0].col, "expected a frequency from %g "
                           "to %g Hz, found %g", RB_SPECTRUM_MIN_HZ, RB_SPECTRUM_MAX_HZ, fv);
    if (f->n > 0 && !(fv > f->v[f->n - 1]))
        return rb_rec_fail(r, RB_ERR_INVALID, tok[0].col, "expected frequencies to "
                           "increase, found %g Hz after %g Hz", fv, f->v[f->n - 1]);
    if (!(av > 0))
        return rb_rec_fail(r, RB_ERR_INVALID, tok[1].col, "expected a spectral "
                           "acceleration > 0, found %g", av);
    if (!(av * units <= RB_SPECTRUM_MAX_ACCEL_MPS2))
        return rb_rec_fail(r, RB_ERR_INVALID, tok[1].col, "expected a spectral "
                           "acceleration of at most 1000 g, found %g (%g g)", av,
                           av * units / RB_UNIT_G_MPS2);
    st = rb_rec_values_push(f, r, &tok[0], fv, 1.0);
    if (st == RB_OK)
        st = rb_rec_values_push(a, r, &tok[1], av, units);
    return st;
}

rb_status rb_spectrum_table_read(const char *path, const rb_sandbox *sandbox,
                                 double units_to_mps2, size_t max_points,
                                 double **freq_hz, double **accel_mps2, size_t *n,
                                 rb_diag *diag)
{
    *freq_hz = *accel_mps2 = NULL;
    *n = 0;
    rb_rec_reader r;
    char why[600];
    memset(&r, 0, sizeof r);
    r.path = path;
    r.diag = diag;
    if (!rb_sandbox_allows(sandbox, path, why, sizeof why))
        return rb_rec_fail_at(&r, RB_ERR_IO, 0, 0, "it lies outside the sandbox '%s' (%s)",
                              rb_sandbox_dir(sandbox), why);
    rb_status st = rb_rec_reader_open(&r, path, diag);
    if (st != RB_OK)
        return st;
    rb_rec_values f, a;
    rb_rec_values_init(&f, max_points);
    rb_rec_values_init(&a, max_points);
    int got = 1, header_ok = 1;
    while (st == RB_OK) {
        st = rb_rec_reader_next(&r, &got);
        if (st != RB_OK || !got)
            break;
        st = table_row(&r, units_to_mps2, &f, &a, &header_ok);
    }
    if (st == RB_OK && f.n < 2)
        st = rb_rec_fail_eof(&r, RB_ERR_PARSE, "expected at least two rows of frequency "
                             "and spectral acceleration, found %zu", f.n);
    rb_rec_reader_close(&r);
    if (st != RB_OK) {
        rb_rec_values_free(&f);
        rb_rec_values_free(&a);
        return st;
    }
    *freq_hz = f.v;
    *accel_mps2 = a.v;
    *n = f.n;
    return RB_OK;
}
