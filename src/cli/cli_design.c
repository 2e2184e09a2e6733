/* The searches of `rockbolt design` and the names of its sweep files. */
#include <stdio.h>
#include <string.h>
#include "cli.h"
#include "cli_batch.h"
#include "rockbolt/run.h"

/* The progress line, and the number of searches for its closing line. */
typedef struct {
    rb_cli_progress line;
    size_t total;
} design_progress;

static void on_progress(void *ctx, size_t done, size_t total, const char *what)
{
    design_progress *p = ctx;
    p->total = total;
    rb_cli_progress_design(&p->line, done, total, what);
}

rb_exit rb_cli_design_step(const rb_cli_opts *o, const rb_case *c, const rb_result *checked,
                           rb_case_design *d)
{
    rb_diag diag;
    rb_status st;
    rb_diag_clear(&diag);
    /* on a terminal, unless --quiet: the search under way on stderr; the
     * outputs are the same with it or without */
    design_progress p = {0};
    rb_cli_progress_start(&p.line, o->quiet);
    st = rb_run_design_checked(c, checked, o->threads, d, &diag,
                               p.line.enabled ? on_progress : NULL, &p);
    if (p.line.enabled && p.line.shown && st != RB_OK)
        fputs("\r\033[K", stderr);
    else if (st == RB_OK)
        rb_cli_progress_design_end(&p.line, p.total);
    if (st == RB_OK)
        return RB_EXIT_PASS;
    rb_cli_error(o->case_path, diag.key, "%s%s%s", rb_status_str(st),
                 diag.msg[0] ? ": " : "", diag.msg);
    return st == RB_ERR_INVALID ? RB_EXIT_USAGE : RB_EXIT_INTERNAL;
}

const char *rb_cli_numbered_name(const char *base, size_t i, size_t n, char *buf,
                                  size_t size)
{
    const char *slash = strrchr(base, '/');
    const char *dot = strrchr(base, '.');
    size_t stem;
    int w;
    if (n == 1)
        return base;
    /* a dot in a directory name, or a leading dot, is not an extension */
    if (!dot || (slash && dot < slash) || dot == (slash ? slash + 1 : base))
        dot = base + strlen(base);
    stem = (size_t)(dot - base);
    w = snprintf(buf, size, "%.*s-%zu%s", (int)stem, base, i + 1, dot);
    return w > 0 && (size_t)w < size ? buf : NULL;
}
