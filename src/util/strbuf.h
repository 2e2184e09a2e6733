/* A growing string. A failed allocation only sets oom, so writers append
 * without checking each call and look once at the end. Internal to the
 * libraries (src/util). */
#ifndef RB_UTIL_STRBUF_H
#define RB_UTIL_STRBUF_H

#include <stddef.h>

typedef struct {
    char *p;        /* NUL-terminated once anything was appended */
    size_t n, cap;
    int oom;        /* sticky: an allocation failed */
} rb_strbuf;

void rb_strbuf_putn(rb_strbuf *b, const char *s, size_t n);
void rb_strbuf_puts(rb_strbuf *b, const char *s);
void rb_strbuf_printf(rb_strbuf *b, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 2, 3)))
#endif
    ;
/* The string, handed to the caller (free()); "" when nothing was appended;
 * NULL, with the buffer freed, after a failed allocation. b is empty after. */
char *rb_strbuf_take(rb_strbuf *b);
void rb_strbuf_free(rb_strbuf *b);

#endif
