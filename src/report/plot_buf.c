/* XML escaping of the renderers' text, and the hand-over of their buffer
 * (src/util/strbuf.h): rb_plot_finish turns a failed allocation into
 * RB_ERR_NOMEM once. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "plot_internal.h"
#include "rockbolt/textsafe.h"

/* Length of the valid UTF-8 sequence at s (1 to 4), or 0 if it is not one.
 * Overlong forms, surrogates and code points past U+10FFFF are invalid,
 * as are U+FFFE and U+FFFF, which XML does not allow either. */
static size_t utf8_len(const unsigned char *s)
{
    unsigned c = s[0];
    size_t n, i;
    unsigned long cp;
    if (c < 0x80)
        return 1;
    if (c >= 0xC2 && c <= 0xDF) {
        n = 2;
        cp = c & 0x1F;
    } else if (c >= 0xE0 && c <= 0xEF) {
        n = 3;
        cp = c & 0x0F;
    } else if (c >= 0xF0 && c <= 0xF4) {
        n = 4;
        cp = c & 0x07;
    } else {
        return 0;
    }
    for (i = 1; i < n; i++) {
        if ((s[i] & 0xC0) != 0x80)
            return 0;
        cp = (cp << 6) | (s[i] & 0x3F);
    }
    if ((n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000) || cp > 0x10FFFF
        || (cp >= 0xD800 && cp <= 0xDFFF) || cp == 0xFFFE || cp == 0xFFFF)
        return 0;
    return n;
}

void rb_plot_escape(rb_strbuf *b, const char *s)
{
    const unsigned char *p = (const unsigned char *)s;
    if (!s)
        return;
    while (*p) {
        const unsigned char *run = p;
        size_t k;
        /* copy plain bytes in one go: escaping is per character */
        while (*p >= 0x20 && *p < 0x80 && *p != '&' && *p != '<' && *p != '>'
               && *p != '"' && *p != '\'')
            p++;
        if (p > run)
            rb_strbuf_putn(b, (const char *)run, (size_t)(p - run));
        if (!*p)
            break;
        switch (*p) {
        case '&': rb_strbuf_puts(b, "&amp;"); p++; continue;
        case '<': rb_strbuf_puts(b, "&lt;"); p++; continue;
        case '>': rb_strbuf_puts(b, "&gt;"); p++; continue;
        case '"': rb_strbuf_puts(b, "&quot;"); p++; continue;
        case '\'': rb_strbuf_puts(b, "&#39;"); p++; continue;
        case '\t': case '\n': rb_strbuf_putn(b, (const char *)p, 1); p++; continue;
        default: break;
        }
        if (*p < 0x20 || *p == 0x7f) {
            /* not allowed in XML 1.0, even escaped: shown as the shared
             * escaping of user text shows it (\x1b) */
            char one[2] = {(char)*p, '\0'}, rep[8];
            rb_text_escape_to(rep, sizeof rep, one);
            rb_strbuf_puts(b, rep);
            p++;
            continue;
        }
        k = utf8_len(p);
        if (k) {
            rb_strbuf_putn(b, (const char *)p, k);
            p += k;
        } else {
            rb_strbuf_puts(b, "\xEF\xBF\xBD");
            p++;
        }
    }
}

rb_status rb_plot_finish(rb_strbuf *b, char **out, rb_diag *diag)
{
    if (b->oom || !b->p) {
        rb_strbuf_free(b);
        *out = NULL;
        if (diag)
            snprintf(diag->msg, sizeof diag->msg, "out of memory while drawing");
        return RB_ERR_NOMEM;
    }
    *out = b->p;
    b->p = NULL;
    b->n = b->cap = 0;
    return RB_OK;
}
