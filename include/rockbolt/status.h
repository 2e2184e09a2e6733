/* Status codes shared by every rockbolt library call.
 *
 * Library calls never print: they return an rb_status and, where a caller
 * passes one, fill an rb_diag with the place and the reason. Only the CLI
 * turns these into messages and exit codes. */
#ifndef ROCKBOLT_STATUS_H
#define ROCKBOLT_STATUS_H

#include <stdarg.h>
#include <stddef.h>

typedef enum {
    RB_OK = 0,
    RB_ERR_NOMEM,          /* an allocation failed */
    RB_ERR_IO,             /* a file could not be read or written */
    RB_ERR_PARSE,          /* a file is not of the expected form */
    RB_ERR_INVALID,        /* a value is out of range or inconsistent */
    RB_ERR_LIMIT,          /* a resource limit of the tool was reached */
    RB_ERR_STEP_TOO_SMALL, /* the integrator could not meet its tolerance */
    RB_ERR_NONFINITE,      /* NaN or infinity appeared in the state */
    RB_ERR_WORK_LIMIT      /* too many events per simulated second */
} rb_status;

/* A short, fixed English phrase for a status; never NULL. */
const char *rb_status_str(rb_status status);

/* Where and why a call failed. line and col count from 1; 0 means unknown.
 * The caller owns the struct; nothing in it needs freeing. */
typedef struct {
    char file[512];
    int line;
    int col;
    char key[128];
    char msg[512];
} rb_diag;

#if defined(__GNUC__)
#define RB_DIAG_FORMAT(f, a) __attribute__((format(printf, f, a)))
#else
#define RB_DIAG_FORMAT(f, a)
#endif

/* Clear a diag to "no error". Accepts NULL. */
void rb_diag_clear(rb_diag *diag);

/* The one way a library call reports a failure: fill diag (may be NULL)
 * with the place (file and key may be NULL, line and col 0) and the
 * formatted reason, and return st. */
rb_status rb_diag_set(rb_diag *diag, rb_status st, const char *file, int line, int col,
                      const char *key, const char *fmt, ...) RB_DIAG_FORMAT(7, 8);
/* The same with a va_list, for callers that take a format themselves. */
rb_status rb_diag_vset(rb_diag *diag, rb_status st, const char *file, int line, int col,
                       const char *key, const char *fmt, va_list ap) RB_DIAG_FORMAT(7, 0);

/* One field of a diag changed, for a caller that adds where or why to a
 * diag filled below it: the text is formatted first, so it may quote the
 * diag's own fields. With rb_diag_set these are the only writers of an
 * rb_diag's text (tests/layers/diag_writes.sh). diag may be NULL. */
void rb_diag_set_file(rb_diag *diag, const char *fmt, ...) RB_DIAG_FORMAT(2, 3);
void rb_diag_set_key(rb_diag *diag, const char *fmt, ...) RB_DIAG_FORMAT(2, 3);
void rb_diag_set_msg(rb_diag *diag, const char *fmt, ...) RB_DIAG_FORMAT(2, 3);
void rb_diag_vset_msg(rb_diag *diag, const char *fmt, va_list ap) RB_DIAG_FORMAT(2, 0);

#endif
