/* Status phrases and diag helpers. The switch has no default so that a new
 * status without a phrase is a compiler warning, not a silent "unknown". */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include "rockbolt/status.h"

const char *rb_status_str(rb_status status)
{
    switch (status) {
    case RB_OK: return "ok";
    case RB_ERR_NOMEM: return "out of memory";
    case RB_ERR_IO: return "input/output error";
    case RB_ERR_PARSE: return "parse error";
    case RB_ERR_INVALID: return "invalid value";
    case RB_ERR_LIMIT: return "limit exceeded";
    case RB_ERR_STEP_TOO_SMALL: return "integrator step too small";
    case RB_ERR_NONFINITE: return "non-finite value in the state";
    case RB_ERR_WORK_LIMIT: return "too many events per simulated second";
    }
    return "unknown status";
}

void rb_diag_clear(rb_diag *diag)
{
    if (diag)
        memset(diag, 0, sizeof *diag);
}

rb_status rb_diag_set(rb_diag *diag, rb_status st, const char *file, int line, int col,
                      const char *key, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    rb_diag_vset(diag, st, file, line, col, key, fmt, ap);
    va_end(ap);
    return st;
}

rb_status rb_diag_vset(rb_diag *diag, rb_status st, const char *file, int line, int col,
                       const char *key, const char *fmt, va_list ap)
{
    if (!diag)
        return st;
    /* the reason may quote the diag's own fields: format it first */
    char msg[sizeof diag->msg];
    vsnprintf(msg, sizeof msg, fmt, ap);
    snprintf(diag->file, sizeof diag->file, "%s", file ? file : "");
    diag->line = line;
    diag->col = col;
    snprintf(diag->key, sizeof diag->key, "%s", key ? key : "");
    memcpy(diag->msg, msg, sizeof msg);
    return st;
}

/* fmt into field (of size n), through a copy: the text may quote field */
static void set_field(char *field, size_t n, const char *fmt, va_list ap)
{
    char text[sizeof ((rb_diag *)0)->msg];
    vsnprintf(text, sizeof text, fmt, ap);
    snprintf(field, n, "%s", text);
}

void rb_diag_set_file(rb_diag *diag, const char *fmt, ...)
{
    va_list ap;
    if (!diag)
        return;
    va_start(ap, fmt);
    set_field(diag->file, sizeof diag->file, fmt, ap);
    va_end(ap);
}

void rb_diag_set_key(rb_diag *diag, const char *fmt, ...)
{
    va_list ap;
    if (!diag)
        return;
    va_start(ap, fmt);
    set_field(diag->key, sizeof diag->key, fmt, ap);
    va_end(ap);
}

void rb_diag_set_msg(rb_diag *diag, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    rb_diag_vset_msg(diag, fmt, ap);
    va_end(ap);
}

void rb_diag_vset_msg(rb_diag *diag, const char *fmt, va_list ap)
{
    if (diag)
        set_field(diag->msg, sizeof diag->msg, fmt, ap);
}
