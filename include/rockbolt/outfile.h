/* Atomic output files: the data reach their path whole or not at all
 * (written to a temporary file beside it, synced, then renamed). The
 * output plan (rockbolt/outplan.h) writes every command's outputs by them. */
#ifndef ROCKBOLT_OUTFILE_H
#define ROCKBOLT_OUTFILE_H

#include <stddef.h>
#include <stdio.h>
#include "rockbolt/status.h"

/* A file being written: the data go to a temporary file next to path and
 * only appear under path at rb_outfile_commit. */
typedef struct {
    FILE *fp;          /* write here between open and commit */
    char *path;        /* owned */
    char *tmp_path;    /* owned; ".rb-XXXXXX" in the directory of path */
    int no_clobber;    /* refuse to replace an existing file */
    int finished;      /* data flushed, synced and the file closed */
} rb_outfile;

/* Check, before any work, that path can be written: its directory exists
 * and is writable, and path is not itself a directory. RB_ERR_IO with the
 * reason in diag (diag->file = path) if not. */
rb_status rb_outfile_check(const char *path, rb_diag *diag);

/* Create the temporary file (mkstemp in the directory of path). With
 * no_clobber, commit fails with RB_ERR_INVALID if path exists by then, and
 * open fails early if it already does. On error f holds nothing to free. */
rb_status rb_outfile_open(rb_outfile *f, const char *path, int no_clobber,
                          rb_diag *diag);

/* Flush, fsync and close the temporary file, leaving it unpublished, so
 * that several outputs can all be made durable before any is renamed. On
 * error the temporary file is removed and f freed. */
rb_status rb_outfile_finish(rb_outfile *f, rb_diag *diag);

/* Finish (if not yet done) and rename (or, with no_clobber, link) the
 * temporary file to path. On any error the temporary file is removed and
 * path is left as it was. f is freed either way. */
rb_status rb_outfile_commit(rb_outfile *f, rb_diag *diag);

/* Close and remove the temporary file; path is untouched. Accepts a closed
 * or zeroed f. */
void rb_outfile_abort(rb_outfile *f);

/* Write len bytes of data to path atomically (open, write, commit). */
rb_status rb_outfile_write_all(const char *path, const char *data, size_t len,
                               int no_clobber, rb_diag *diag);

#endif
