/* Escaping of user text for every output (include/rockbolt/textsafe.h):
 * one function for terminals and text files, one CSV field writer built on
 * it. Everything that prints a name, tag, path or message from an input
 * goes through these two. */
#include <stdlib.h>
#include <string.h>
#include "rockbolt/textsafe.h"

/* Length of a valid UTF-8 sequence at p (1 to 4), or 0 if invalid. */
static size_t utf8_len(const unsigned char *p, unsigned *cp_out)
{
    unsigned cp;
    size_t n;
    if (p[0] < 0x80) {
        *cp_out = p[0];
        return 1;
    }
    if (p[0] >= 0xC2 && p[0] <= 0xDF) {
        n = 2;
        cp = p[0] & 0x1Fu;
    } else if (p[0] >= 0xE0 && p[0] <= 0xEF) {
        n = 3;
        cp = p[0] & 0x0Fu;
    } else if (p[0] >= 0xF0 && p[0] <= 0xF4) {
        n = 4;
        cp = p[0] & 0x07u;
    } else {
        return 0;
    }
    for (size_t i = 1; i < n; i++) {
        if ((p[i] & 0xC0) != 0x80)   /* also stops at the NUL */
            return 0;
        cp = (cp << 6) | (p[i] & 0x3Fu);
    }
    if ((n == 3 && cp < 0x800) || (n == 4 && cp < 0x10000) || cp > 0x10FFFF
        || (cp >= 0xD800 && cp <= 0xDFFF))
        return 0;
    *cp_out = cp;
    return n;
}

/* Characters shown as \uXXXX though they are valid UTF-8: XML 1.0 allows
 * neither U+FFFE nor U+FFFF, even as references, so one in a tag made the
 * whole JUnit file unreadable; and the bidirectional and invisible format
 * characters reorder or hide the text around them (an RLO tag reversed
 * the rest of its table line): the embeddings, overrides and isolates, the
 * marks, the zero-width characters, the line and paragraph separators and
 * the byte-order mark, which have no place in a name. */
static int shown_as_code(unsigned cp)
{
    return cp == 0x061c || cp == 0x180e || (cp >= 0x200b && cp <= 0x200f)
           || (cp >= 0x2028 && cp <= 0x202e) || (cp >= 0x2060 && cp <= 0x2064)
           || (cp >= 0x2066 && cp <= 0x206f) || cp == 0xfeff
           || (cp >= 0xfff9 && cp <= 0xfffb) || cp == 0xfffe || cp == 0xffff;
}

/* C1 controls (CSI is 0x9b) and the characters above: the one set every
 * output escapes as \uXXXX, for people and in JSON alike. */
static int escaped_as_code(unsigned cp)
{
    return (cp >= 0x80 && cp <= 0x9f) || shown_as_code(cp);
}

/* \uXXXX of a character of the Basic Multilingual Plane, into rep. */
static size_t code_of(unsigned cp, char rep[8])
{
    static const char hex[] = "0123456789abcdef";
    rep[0] = '\\';
    rep[1] = 'u';
    rep[2] = hex[cp >> 12];
    rep[3] = hex[(cp >> 8) & 15];
    rep[4] = hex[(cp >> 4) & 15];
    rep[5] = hex[cp & 15];
    return 6;
}

/* The next character of s at *p: its shown form in rep (escaped or not)
 * and its length there; advances *p. keep_lines keeps tab and newline as
 * they are (preformatted text). */
static size_t next_char(const unsigned char **p, char rep[8], int keep_lines)
{
    static const char hex[] = "0123456789abcdef";
    const unsigned char *s = *p;
    unsigned cp = 0;
    size_t n = utf8_len(s, &cp);
    if (n == 0) {                        /* not UTF-8: the byte in hex */
        rep[0] = '\\';
        rep[1] = 'x';
        rep[2] = hex[s[0] >> 4];
        rep[3] = hex[s[0] & 15];
        *p = s + 1;
        return 4;
    }
    *p = s + n;
    if (keep_lines && (cp == '\t' || cp == '\n')) {
        rep[0] = (char)cp;
        return 1;
    }
    if (cp == '\t' || cp == '\n' || cp == '\r') {
        rep[0] = '\\';
        rep[1] = cp == '\t' ? 't' : cp == '\n' ? 'n' : 'r';
        return 2;
    }
    if (cp < 0x20 || cp == 0x7f) {
        rep[0] = '\\';
        rep[1] = 'x';
        rep[2] = hex[cp >> 4];
        rep[3] = hex[cp & 15];
        return 4;
    }
    if (escaped_as_code(cp))
        return code_of(cp, rep);
    memcpy(rep, s, n);
    return n;
}

static size_t escape_to(char *out, size_t size, const char *s, int keep_lines)
{
    const unsigned char *p = (const unsigned char *)(s ? s : "");
    size_t need = 0;
    int full = size == 0;
    char rep[8];
    while (*p) {
        size_t k = next_char(&p, rep, keep_lines);
        if (!full && need + k < size)
            memcpy(out + need, rep, k);
        else if (!full) {
            out[need] = '\0';
            full = 1;
        }
        need += k;
    }
    if (!full)
        out[need] = '\0';
    return need;
}

size_t rb_text_escape_to(char *out, size_t size, const char *s)
{
    return escape_to(out, size, s, 0);
}

const char *rb_text_escape_buf(const char *s, char *out, size_t size)
{
    rb_text_escape_to(out, size, s);
    return out;
}

static char *escape_new(const char *s, int keep_lines)
{
    size_t n = escape_to(NULL, 0, s, keep_lines);
    char *out = malloc(n + 1);
    if (out)
        escape_to(out, n + 1, s, keep_lines);
    return out;
}

char *rb_text_escape(const char *s)
{
    return escape_new(s, 0);
}

char *rb_text_escape_lines(const char *s)
{
    return escape_new(s, 1);
}

int rb_text_needs_escape(const char *s)
{
    const unsigned char *p = (const unsigned char *)(s ? s : "");
    char rep[8];
    while (*p) {
        const unsigned char *at = p;
        size_t k = next_char(&p, rep, 0);
        if (k != (size_t)(p - at) || memcmp(rep, at, k) != 0)
            return 1;
    }
    return 0;
}

/* Characters that make a spreadsheet read a cell as a formula (OWASP,
 * "CSV injection"). */
static int formula_start(char c)
{
    return c == '=' || c == '+' || c == '-' || c == '@' || c == '\t' || c == '\r';
}

/* The first character a spreadsheet keeps: those that trim on import
 * drop leading blanks, so " =1+1" is a formula there too. */
static const char *after_blanks(const char *s)
{
    for (;;) {
        if (*s == ' ' || *s == '\t' || *s == '\r' || *s == '\n' || *s == '\v' || *s == '\f')
            s++;
        else if ((unsigned char)s[0] == 0xc2 && (unsigned char)s[1] == 0xa0)
            s += 2;   /* no-break space */
        else
            return s;
    }
}

char *rb_csv_field(const char *s, int always_quote)
{
    const char *raw = s ? s : "";
    char *t = rb_text_escape(raw);
    if (!t)
        return NULL;
    int guard = formula_start(raw[0]) || formula_start(t[0])
                || formula_start(*after_blanks(raw));
    int quote = always_quote || guard || strpbrk(t, ",\"") != NULL;
    if (!quote)
        return t;
    size_t n = 0;
    for (const char *p = t; *p; p++)
        n += *p == '"' ? 2 : 1;
    char *out = malloc(n + (size_t)guard + 3);
    if (!out) {
        free(t);
        return NULL;
    }
    char *o = out;
    *o++ = '"';
    if (guard)
        *o++ = '\'';
    for (const char *p = t; *p; p++) {
        if (*p == '"')
            *o++ = '"';
        *o++ = *p;
    }
    *o++ = '"';
    *o = '\0';
    free(t);
    return out;
}

int rb_csv_field_write(FILE *fp, const char *s, int always_quote)
{
    char *f = rb_csv_field(s, always_quote);
    if (!f)
        return -1;
    int bad = fputs(f, fp) == EOF;
    free(f);
    return bad ? -1 : 0;
}

size_t rb_text_width(const char *s)
{
    const unsigned char *p = (const unsigned char *)s;
    size_t w = 0;
    unsigned cp;
    while (*p) {
        size_t n = utf8_len(p, &cp);
        p += n ? n : 1;
        w++;
    }
    return w;
}

size_t rb_utf8_invalid_at(const char *s, size_t len)
{
    const unsigned char *p = (const unsigned char *)s;
    size_t i = 0;
    while (i < len) {
        unsigned cp;
        size_t n = p[i] < 0x80 ? 1 : (len - i >= 4 ? utf8_len(p + i, &cp) : 0);
        if (n == 0 && p[i] >= 0x80) {
            /* near the end: check on a copy padded with NULs */
            unsigned char t[5] = {0};
            memcpy(t, p + i, len - i < 4 ? len - i : 4);
            n = utf8_len(t, &cp);
        }
        if (n == 0)
            return i;
        i += n;
    }
    return len;
}

char *rb_utf8_fix(const char *s)
{
    static const char hex[] = "0123456789abcdef";
    if (!s)
        s = "";
    size_t len = strlen(s), bad = 0;
    for (size_t i = rb_utf8_invalid_at(s, len); i < len;
         i += 1 + rb_utf8_invalid_at(s + i + 1, len - i - 1))
        bad++;
    char *out = malloc(len + 3 * bad + 1), *o = out;
    if (!out)
        return NULL;
    for (size_t i = 0; i < len;) {
        size_t ok = rb_utf8_invalid_at(s + i, len - i);
        memcpy(o, s + i, ok);
        o += ok;
        i += ok;
        if (i < len) {
            unsigned char c = (unsigned char)s[i++];
            *o++ = '\\';
            *o++ = 'x';
            *o++ = hex[c >> 4];
            *o++ = hex[c & 15];
        }
    }
    *o = '\0';
    return out;
}

char *rb_json_escape_format(const char *json)
{
    const unsigned char *p = (const unsigned char *)json;
    size_t len = strlen(json), extra = 0;
    unsigned cp;
    /* each such character is 2 or 3 bytes of UTF-8 and 6 escaped */
    for (size_t i = 0, n; i < len; i += n ? n : 1)
        if ((n = utf8_len(p + i, &cp)) > 1 && escaped_as_code(cp))
            extra += 6 - n;
    char *out = malloc(len + extra + 1), *o = out;
    if (!out)
        return NULL;
    for (size_t i = 0, n; i < len; i += n) {
        n = utf8_len(p + i, &cp);
        if (n > 1 && escaped_as_code(cp)) {
            o += code_of(cp, o);
        } else {
            n = n ? n : 1;
            memcpy(o, p + i, n);
            o += n;
        }
    }
    *o = '\0';
    return out;
}
