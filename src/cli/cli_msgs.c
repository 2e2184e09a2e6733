/* Diagnostics of the CLI: one line per problem on stderr, in the form
 * compilers use, "FILE:LINE:COL: error: KEY: MESSAGE", so editors can jump
 * to the place. Everything the library reports arrives as an rb_diag. */
#include <stdarg.h>
#include <stdio.h>
#include "cli.h"
#include "rockbolt/textsafe.h"

void rb_cli_diag_print(const rb_diag *d)
{
    rb_cli_diag_fprint(stderr, d);
}

void rb_cli_diag_fprint(FILE *out, const rb_diag *d)
{
    /* file, key and message may hold text from an input: shown escaped */
    char file[2048], key[512], msg[2048];
    rb_text_escape_buf(d->file[0] ? d->file : "rockbolt", file, sizeof file);
    rb_text_escape_buf(d->key, key, sizeof key);
    rb_text_escape_buf(d->msg[0] ? d->msg : "unspecified error", msg, sizeof msg);
    if (d->line > 0 && d->col > 0)
        fprintf(out, "%s:%d:%d: error: ", file, d->line, d->col);
    else if (d->line > 0)
        fprintf(out, "%s:%d: error: ", file, d->line);
    else
        fprintf(out, "%s: error: ", file);
    if (key[0])
        fprintf(out, "%s: ", key);
    fprintf(out, "%s\n", msg);
}

void rb_cli_error(const char *file, const char *key, const char *fmt, ...)
{
    rb_diag d;
    va_list ap;
    va_start(ap, fmt);
    rb_diag_vset(&d, RB_ERR_INVALID, file ? file : "rockbolt", 0, 0, key, fmt, ap);
    va_end(ap);
    rb_cli_diag_print(&d);
}
