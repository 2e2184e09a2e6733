/* Reading record files as text: lines with their numbers, tokens with
 * their columns, numbers without locale or strtod's extensions, and
 * diagnostics that say where a file went wrong.
 *
 * Record files come from many programs and some are hostile: lines are
 * capped, NUL bytes stop the read, and every number is checked against a
 * plain decimal grammar before strtod sees it (strtod alone would accept
 * hex, "nan" and "infinity"). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "record_internal.h"

/* Longest number token: 7-digit Fortran E fields are 15 wide; anything
 * much longer is not a number a record would hold. */
#define RB_REC_NUMBER_MAX 64

static int rec_is_blank(int c)
{
    return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

static int rec_is_digit(int c)
{
    return c >= '0' && c <= '9';
}

static int rec_lower(int c)
{
    return (c >= 'A' && c <= 'Z') ? c - 'A' + 'a' : c;
}

rb_status rb_rec_reader_open(rb_rec_reader *r, const char *path, rb_diag *diag)
{
    memset(r, 0, sizeof *r);
    r->path = path;
    r->diag = diag;
    /* Only regular files: a case from elsewhere could name /dev/stdin, a
     * terminal or a FIFO and stall the run, and the format guess needs to
     * rewind. O_NONBLOCK keeps the open from waiting on a FIFO; it is
     * cleared before reading. */
    errno = 0;
    int fd = open(path, O_RDONLY | O_NONBLOCK);
    if (fd < 0) {
        const char *why = errno ? strerror(errno) : "unknown reason";
        return rb_rec_fail_at(r, RB_ERR_IO, 0, 0, "cannot open the file: %s", why);
    }
    struct stat sb;
    int flags = fcntl(fd, F_GETFL);
    if (fstat(fd, &sb) != 0 || !S_ISREG(sb.st_mode)) {
        close(fd);
        return rb_rec_fail_at(r, RB_ERR_IO, 0, 0, "cannot use the file: expected a "
                              "regular file (not a directory, device or pipe)");
    }
    if ((unsigned long long)sb.st_size > RB_REC_MAX_BYTES) {
        close(fd);
        return rb_rec_fail_at(r, RB_ERR_LIMIT, 0, 0, "the file holds %lld bytes, "
                              "over the %llu MiB a record may hold (the limit)",
                              (long long)sb.st_size, RB_REC_MAX_BYTES >> 20);
    }
    if (flags < 0 || fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) != 0
        || !(r->fp = fdopen(fd, "rb"))) {
        const char *why = errno ? strerror(errno) : "unknown reason";
        close(fd);
        return rb_rec_fail_at(r, RB_ERR_IO, 0, 0, "cannot open the file: %s", why);
    }
    return RB_OK;
}

void rb_rec_reader_close(rb_rec_reader *r)
{
    if (r->fp)
        fclose(r->fp);
    free(r->line);
    r->fp = NULL;
    r->line = NULL;
    r->len = r->cap = 0;
}

rb_status rb_rec_reader_rewind(rb_rec_reader *r)
{
    if (fseek(r->fp, 0L, SEEK_SET) != 0)
        return rb_rec_fail_at(r, RB_ERR_IO, 0, 0, "cannot go back to the start of the file");
    clearerr(r->fp);
    r->lineno = 0;
    r->nread = 0;
    r->len = 0;
    if (r->line)
        r->line[0] = '\0';
    return RB_OK;
}

/* Room for one more character and the terminating NUL. */
static rb_status rec_reader_grow(rb_rec_reader *r)
{
    if (r->len + 2 <= r->cap)
        return RB_OK;
    size_t cap = r->cap ? r->cap * 2 : 256;
    if (cap > RB_REC_LINE_MAX + 2)
        cap = RB_REC_LINE_MAX + 2;
    char *p = realloc(r->line, cap);
    if (!p)
        return rb_rec_fail(r, RB_ERR_NOMEM, 0, "out of memory reading a line");
    r->line = p;
    r->cap = cap;
    return RB_OK;
}

rb_status rb_rec_reader_next(rb_rec_reader *r, int *got)
{
    int c;
    *got = 0;
    if (!r->line && rec_reader_grow(r) != RB_OK)
        return RB_ERR_NOMEM;
    c = getc(r->fp);
    /* At the end the last line stays, so that an error can point just
     * after its last character. */
    if (c == EOF) {
        if (ferror(r->fp))
            return rb_rec_fail_at(r, RB_ERR_IO, r->lineno + 1, 0,
                                  "read error: %s", strerror(errno));
        return RB_OK;
    }
    r->len = 0;
    r->lineno++;
    *got = 1;
    /* a file that grew past the limit after it was opened */
    if (++r->nread > RB_REC_MAX_BYTES)
        return rb_rec_fail_at(r, RB_ERR_LIMIT, r->lineno, 0, "the file holds more "
                              "than the %llu MiB a record may hold (the limit)",
                              RB_REC_MAX_BYTES >> 20);
    for (; c != EOF && c != '\n'; c = getc(r->fp)) {
        r->nread++;
        if (c == '\0')
            return rb_rec_fail_at(r, RB_ERR_PARSE, r->lineno, (int)r->len + 1,
                                  "expected text, found a NUL byte (binary file?)");
        if (r->len >= RB_REC_LINE_MAX)
            return rb_rec_fail_at(r, RB_ERR_LIMIT, r->lineno, RB_REC_LINE_MAX + 1,
                                  "line longer than %d characters (the limit)",
                                  RB_REC_LINE_MAX);
        if (rec_reader_grow(r) != RB_OK)
            return RB_ERR_NOMEM;
        r->line[r->len++] = (char)c;
    }
    if (ferror(r->fp))
        return rb_rec_fail(r, RB_ERR_IO, 0, "read error: %s", strerror(errno));
    if (r->len > 0 && r->line[r->len - 1] == '\r')
        r->len--;
    r->line[r->len] = '\0';
    return RB_OK;
}

static rb_status rec_vfail(const rb_rec_reader *r, rb_status status, long line,
                              int col, const char *fmt, va_list ap)
    RB_REC_PRINTF(5, 0);

static rb_status rec_vfail(const rb_rec_reader *r, rb_status status, long line,
                              int col, const char *fmt, va_list ap)
{
    return rb_diag_vset(r->diag, status, r->path, line > 0 && line <= 0x7fffffffL
                        ? (int)line : 0, col > 0 ? col : 0, "", fmt, ap);
}

rb_status rb_rec_fail_at(const rb_rec_reader *r, rb_status status, long line,
                         int col, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    rec_vfail(r, status, line, col, fmt, ap);
    va_end(ap);
    return status;
}

rb_status rb_rec_fail(const rb_rec_reader *r, rb_status status, int col,
                      const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    rec_vfail(r, status, r->lineno, col, fmt, ap);
    va_end(ap);
    return status;
}

rb_status rb_rec_fail_eof(const rb_rec_reader *r, rb_status status,
                          const char *fmt, ...)
{
    va_list ap;
    long line = r->lineno > 0 ? r->lineno : 1;
    int col = r->lineno > 0 ? (int)r->len + 1 : 1;
    va_start(ap, fmt);
    rec_vfail(r, status, line, col, fmt, ap);
    va_end(ap);
    return status;
}

int rb_rec_token_next(const char *line, size_t *pos, int commas, rb_rec_token *tok)
{
    size_t i = *pos;
    while (line[i] && (rec_is_blank((unsigned char)line[i])
                       || (commas && line[i] == ',')))
        i++;
    if (!line[i]) {
        *pos = i;
        return 0;
    }
    size_t start = i;
    while (line[i] && !rec_is_blank((unsigned char)line[i])
           && !(commas && line[i] == ','))
        i++;
    tok->s = line + start;
    tok->len = i - start;
    tok->col = (int)start + 1;
    *pos = i;
    return 1;
}

int rb_rec_token_field(const rb_rec_reader *r, size_t start, size_t width,
                       rb_rec_token *tok)
{
    if (start >= r->len)
        return 0;
    size_t end = start + width < r->len ? start + width : r->len, field = start;
    while (start < end && rec_is_blank((unsigned char)r->line[start]))
        start++;
    while (end > start && rec_is_blank((unsigned char)r->line[end - 1]))
        end--;
    tok->s = r->line + start;
    tok->len = end - start;
    tok->col = (int)(tok->len ? start : field) + 1;
    return 1;
}

long rb_rec_find(const char *s, size_t len, const char *word)
{
    size_t w = strlen(word);
    for (size_t i = 0; w <= len && i <= len - w; i++) {
        size_t k = 0;
        while (k < w && rec_lower((unsigned char)s[i + k])
                            == rec_lower((unsigned char)word[k]))
            k++;
        if (k == w)
            return (long)i;
    }
    return -1;
}

/* Length of the decimal number at the start of s (len bytes): sign,
 * digits, point, exponent with E or D; 0 when s does not start with one. */
static size_t rec_scan_number(const char *s, size_t len)
{
    size_t i = 0, digits = 0;
    if (i < len && (s[i] == '+' || s[i] == '-'))
        i++;
    for (; i < len && rec_is_digit((unsigned char)s[i]); i++)
        digits++;
    if (i < len && s[i] == '.')
        for (i++; i < len && rec_is_digit((unsigned char)s[i]); i++)
            digits++;
    if (digits == 0)
        return 0;
    if (i < len && (rec_lower((unsigned char)s[i]) == 'e'
                    || rec_lower((unsigned char)s[i]) == 'd')) {
        size_t j = i + 1;
        if (j < len && (s[j] == '+' || s[j] == '-'))
            j++;
        if (j < len && rec_is_digit((unsigned char)s[j])) {
            while (j < len && rec_is_digit((unsigned char)s[j]))
                j++;
            i = j;
        }
    }
    return i;
}

static int rec_is_nonfinite_word(const char *s, size_t len)
{
    if (len > 0 && (*s == '+' || *s == '-')) {
        s++;
        len--;
    }
    return (len >= 3 && rb_rec_find(s, 3, "nan") == 0)
        || (len >= 3 && rb_rec_find(s, 3, "inf") == 0);
}

rb_status rb_rec_number_parse(const char *s, size_t len, double *out)
{
    char buf[RB_REC_NUMBER_MAX + 1];
    if (rec_is_nonfinite_word(s, len))
        return RB_ERR_INVALID;
    if (len == 0 || len > RB_REC_NUMBER_MAX || rec_scan_number(s, len) != len)
        return RB_ERR_PARSE;
    for (size_t i = 0; i < len; i++)
        buf[i] = (s[i] == 'd' || s[i] == 'D') ? 'e' : s[i];
    buf[len] = '\0';
    char *end = NULL;
    double x = strtod(buf, &end);
    /* A decimal point other than '.' (a foreign locale) stops strtod
     * early; treat it as not a number rather than misread it. */
    if (end != buf + len)
        return RB_ERR_PARSE;
    if (!isfinite(x))
        return RB_ERR_INVALID;
    *out = x;
    return RB_OK;
}

rb_status rb_rec_token_number(const rb_rec_reader *r, const rb_rec_token *tok,
                              const char *what, double *out)
{
    rb_status st = rb_rec_number_parse(tok->s, tok->len, out);
    if (st == RB_OK)
        return RB_OK;
    if (st == RB_ERR_INVALID)
        return rb_rec_fail(r, st, tok->col, "expected %s as a finite number, found "
                           "NaN, infinity, a hexadecimal number or one out of range",
                           what);
    return rb_rec_fail(r, st, tok->col, "expected %s (a number), found text that is "
                       "not a number", what);
}

static rb_status rec_count_fail(const rb_rec_reader *r, const rb_rec_token *tok,
                                   const char *what)
{
    return rb_rec_fail(r, RB_ERR_PARSE, tok->col,
                       "expected %s (a whole number), found text that is not one", what);
}

rb_status rb_rec_token_count(const rb_rec_reader *r, const rb_rec_token *tok,
                             const char *what, size_t limit, size_t *out)
{
    size_t n = 0, i = (tok->len > 0 && tok->s[0] == '+') ? 1 : 0;
    if (i == tok->len)
        return rec_count_fail(r, tok, what);
    for (; i < tok->len; i++) {
        if (!rec_is_digit((unsigned char)tok->s[i]))
            return rec_count_fail(r, tok, what);
        /* limit is far below SIZE_MAX / 10, so this cannot wrap. */
        if (n <= limit)
            n = n * 10 + (size_t)(tok->s[i] - '0');
    }
    *out = n > limit ? limit + 1 : n;
    return RB_OK;
}
