/* Reading strong-motion record files into an rb_series (io layer).
 *
 * Formats: PEER AT2 (NGA-West2 header and the older "NPTS= n, DT= dt SEC"
 * one), COSMOS V2 (.V2 corrected acceleration), two columns (time, accel),
 * one column with dt given. Units are read from the header where the format
 * has them, else given by the caller. The result is in m/s^2. */
#ifndef ROCKBOLT_RECORD_H
#define ROCKBOLT_RECORD_H

#include "rockbolt/motion.h"

typedef enum {
    RB_REC_AUTO = 0,    /* guess from the extension and the first lines */
    RB_REC_AT2,
    RB_REC_COSMOS_V2,
    RB_REC_TWO_COLUMN,
    RB_REC_ONE_COLUMN
} rb_record_format;

typedef struct {
    rb_record_format format;
    double units_to_mps2;  /* factor to m/s^2 when the file does not say; 0 -> from header, else error */
    double dt_s;           /* one-column files: required; others: 0 -> from the file */
    size_t max_points;     /* refuse longer records (RB_ERR_LIMIT); 0 -> 10 000 000 */
} rb_record_opts;

void rb_record_opts_init(rb_record_opts *o);

/* Read a record. On error, diag names the file, line, column and problem.
 * out is owned by the caller (rb_series_free). */
rb_status rb_record_read(const char *path, const rb_record_opts *opts,
                         rb_series *out, rb_diag *diag);

#endif
