/* XML escaping of the renderers' text, and the hand-over of their buffer
 * (src/util/strbuf.h): rb_plot_finish turns a failed allocation into
 * RB_ERR_NOMEM once. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "plot_internal.h"
#include "rockbolt/textsafe.h"

/* The shared escaping of user text first (controls, format characters,
 * bytes that are not UTF-8, the characters XML 1.0 does not allow; tab and
 * newline kept for the preformatted report), then XML's own. */
void rb_plot_escape(rb_strbuf *b, const char *s)
{
    if (!s)
        return;
    char *t = rb_text_escape_lines(s);
    if (!t) {
        b->oom = 1;
        return;
    }
    const char *p = t;
    while (*p) {
        const char *run = p;
        while (*p && *p != '&' && *p != '<' && *p != '>' && *p != '"' && *p != '\'')
            p++;
        if (p > run)
            rb_strbuf_putn(b, run, (size_t)(p - run));
        switch (*p) {
        case '&': rb_strbuf_puts(b, "&amp;"); break;
        case '<': rb_strbuf_puts(b, "&lt;"); break;
        case '>': rb_strbuf_puts(b, "&gt;"); break;
        case '"': rb_strbuf_puts(b, "&quot;"); break;
        case '\'': rb_strbuf_puts(b, "&#39;"); break;
        default: continue;   /* the end */
        }
        p++;
    }
    free(t);
}

rb_status rb_plot_finish(rb_strbuf *b, char **out, rb_diag *diag)
{
    if (b->oom || !b->p) {
        rb_strbuf_free(b);
        *out = NULL;
        if (diag)
            rb_diag_set_msg(diag, "out of memory while drawing");
        return RB_ERR_NOMEM;
    }
    *out = b->p;
    b->p = NULL;
    b->n = b->cap = 0;
    return RB_OK;
}
