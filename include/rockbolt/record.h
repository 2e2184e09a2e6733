/* Reading strong-motion record files into an rb_series (library rb_record).
 *
 * Formats: PEER AT2 (NGA-West2 header and the older "NPTS= n, DT= dt SEC"
 * one), COSMOS V2 (.V2 corrected acceleration), two columns (time, accel),
 * one column with dt given. Units are read from the header where the format
 * has them, else given by the caller. The result is in m/s^2. */
#ifndef ROCKBOLT_RECORD_H
#define ROCKBOLT_RECORD_H

#include "rockbolt/motion.h"
#include "rockbolt/names.h"

typedef enum {
    RB_REC_AUTO = 0,    /* guess from the extension and the first lines */
    RB_REC_AT2,
    RB_REC_COSMOS_V2,
    RB_REC_TWO_COLUMN,
    RB_REC_ONE_COLUMN
} rb_record_format;
extern const rb_enum_name rb_record_format_names[]; /* rb_record_format */

typedef struct {
    rb_record_format format;
    double units_to_mps2;  /* factor to m/s^2 when the file does not say; 0 -> from header, else error */
    double dt_s;           /* one-column files: required; others: 0 -> from the file */
    size_t max_points;     /* refuse longer records (RB_ERR_LIMIT); 0 -> 10 000 000 */
    const struct rb_sandbox *sandbox; /* borrowed: refuse a file outside it
                                         (RB_ERR_IO); NULL -> any file */
} rb_record_opts;

void rb_record_opts_init(rb_record_opts *o);

/* Read a record. On error, diag names the file, line, column and problem.
 * out is owned by the caller (rb_series_free). */
rb_status rb_record_read(const char *path, const rb_record_opts *opts,
                         rb_series *out, rb_diag *diag);

/* How rb_record_read treats the options and the file:
 * - Units: a header that states them (AT2 line 3, COSMOS headers) wins;
 *   otherwise units_to_mps2 must be set (column files always need it).
 * - dt: taken from the header, or from the time column of a two-column
 *   file (uniform to 1 % of a step). A nonzero dt_s must then agree with
 *   the file; one-column files need it.
 * - t0: the first time of a two-column file, else 0.
 * Errors: RB_ERR_IO (cannot open or read), RB_ERR_PARSE (not of the
 * expected form: non-numeric token, missing or bad header, fewer or more
 * values than the header announces, empty file), RB_ERR_INVALID (dt <= 0,
 * NaN or infinite values, non-uniform time column, missing units,
 * conflicting options), RB_ERR_LIMIT (more than max_points values, or a
 * line over 65536 characters), RB_ERR_NOMEM. On error out is empty.
 * out is overwritten, not freed: free a series before reading into it. */

/* Factor to m/s^2 of an acceleration unit as records spell it: g, mg,
 * m/s^2, cm/s^2, gal, mm/s^2, in/s^2, ft/s^2; any case, "sec" for "s",
 * s2, s/s or s^2 for the square. RB_ERR_PARSE if unknown. */
rb_status rb_record_units_parse(const char *name, double *to_mps2);

/* A target spectrum table: rows of frequency (Hz) and spectral
 * acceleration (times units_to_mps2), separated by blanks or a comma;
 * blank lines, lines starting with '#' and one header line before the
 * first row are skipped. Frequencies strictly increasing, from
 * RB_SPECTRUM_MIN_HZ to RB_SPECTRUM_MAX_HZ, accelerations > 0 and at most
 * RB_SPECTRUM_MAX_ACCEL_MPS2 once converted, 2 to max_points rows. *freq_hz and *accel_mps2 are
 * the caller's (free); on error they are NULL and diag names the file,
 * line and column; a file outside sandbox (may be NULL) is RB_ERR_IO.
 * RB_ERR_IO, RB_ERR_PARSE, RB_ERR_INVALID, RB_ERR_LIMIT,
 * RB_ERR_NOMEM. */
rb_status rb_spectrum_table_read(const char *path, const struct rb_sandbox *sandbox,
                                 double units_to_mps2, size_t max_points,
                                 double **freq_hz, double **accel_mps2, size_t *n,
                                 rb_diag *diag);

#endif
