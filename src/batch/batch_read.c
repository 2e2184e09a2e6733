/* Reading a JSON summary one case at a time (rockbolt/batch.h): the head,
 * the members before "cases", then each element of "cases" on demand. A
 * small scanner finds where each value ends (strings, escapes, nesting) and
 * cJSON parses that value alone, so that what is held is one case's text
 * and tree, never the file's: a 100 000-row summary read whole took 490 MB.
 * Each piece has a limit of its own (docs/robustness.md); the summary as a
 * whole has none. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cjson/cJSON.h>
#include "batch_summary.h"

#define NONE (-2)

struct rb_batch_reader {
    FILE *fp;
    char name[512];
    int line, col;            /* of the next byte */
    int ahead;                /* the byte peeked at, EOF, or NONE */
    int vline, vcol;          /* where the value in buf began */
    char *buf;                /* the value being read */
    size_t len, cap;
    rb_batch_summary head;    /* what the cases are read with */
    int state;                /* 0: before the first case, 1: after one, 2: done */
    size_t n_cases;
};

static int peek(rb_batch_reader *r)
{
    if (r->ahead == NONE)
        r->ahead = getc(r->fp);
    return r->ahead;
}

static int take(rb_batch_reader *r)
{
    int c = peek(r);
    r->ahead = NONE;
    if (c == '\n') {
        r->line++;
        r->col = 1;
    } else if (c != EOF) {
        r->col++;
    }
    return c;
}

static void skip_ws(rb_batch_reader *r)
{
    int c;
    while ((c = peek(r)) == ' ' || c == '\t' || c == '\n' || c == '\r')
        take(r);
}

#if defined(__GNUC__)
__attribute__((format(printf, 7, 8)))
#endif
static rb_status fail_at(rb_batch_reader *r, rb_diag *d, rb_status st, int line, int col,
                         const char *key, const char *fmt, ...)
{
    char msg[sizeof d->msg];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(msg, sizeof msg, fmt, ap);
    va_end(ap);
    return rb_diag_set(d, st, r->name, line, col, key, "%s", msg);
}

/* At the byte just read or about to be. */
#define FAIL(r, d, st, key, ...) fail_at(r, d, st, (r)->line, (r)->col, key, __VA_ARGS__)

/* A diagnostic made without a place (the head's or a case's fields): at
 * the value read last. */
static rb_status place(rb_batch_reader *r, rb_diag *d, rb_status st)
{
    rb_diag_set_file(d, "%s", r->name);
    d->line = r->vline;
    d->col = r->vcol;
    return st;
}

/* The end of the file where more was expected: a read error, or the file
 * cut short. */
static rb_status ended(rb_batch_reader *r, rb_diag *d, const char *key)
{
    if (ferror(r->fp))
        return rb_diag_set(d, RB_ERR_IO, r->name, 0, 0, key, "cannot read: %s",
                           strerror(errno ? errno : EIO));
    if (r->line == 1 && r->col == 1)
        return FAIL(r, d, RB_ERR_PARSE, key, "the file is empty");
    return FAIL(r, d, RB_ERR_PARSE, key, "the summary ends early (cut short?)");
}

static int put(rb_batch_reader *r, int c)
{
    if (r->len + 1 >= r->cap) {
        size_t cap = r->cap ? 2 * r->cap : 4096;
        char *p = realloc(r->buf, cap);
        if (!p)
            return 0;
        r->buf = p;
        r->cap = cap;
    }
    r->buf[r->len++] = (char)c;
    return 1;
}

/* The text of the next value into buf (NUL-terminated), no more than
 * limit bytes; what names the piece and named its limit in the message (a
 * head's values share one). Only where it
 * ends is found here: cJSON judges the rest. */
static rb_status scan(rb_batch_reader *r, size_t limit, size_t named, const char *key,
                      const char *what, rb_diag *d)
{
    char stack[RB_BATCH_READ_DEPTH];
    int depth = 0, in_str = 0, esc = 0, c;
    r->len = 0;
    r->vline = r->line;
    r->vcol = r->col;
    c = peek(r);
    int scalar = c != '{' && c != '[' && c != '"';
    for (;;) {
        c = peek(r);
        if (c == EOF) {
            if (scalar && r->len > 0 && !ferror(r->fp))
                break;
            return ended(r, d, key);
        }
        if (scalar && (c == ',' || c == ']' || c == '}' || c == ':' || c == ' '
                       || c == '\t' || c == '\n' || c == '\r'))
            break;
        if (r->len >= limit)
            return fail_at(r, d, RB_ERR_LIMIT, r->vline, r->vcol, key, "%s is longer than the "
                           "limit of %zu KiB: rockbolt batch writes none so long; check "
                           "that this is a summary from batch --json", what, named >> 10);
        if (!put(r, take(r)))
            return RB_ERR_NOMEM;
        if (scalar)
            continue;
        if (in_str) {
            if (esc)
                esc = 0;
            else if (c == '\\')
                esc = 1;
            else if (c == '"')
                in_str = 0;
            if (!in_str && depth == 0)  /* the string was the value */
                break;
        } else if (c == '"') {
            in_str = 1;
        } else if (c == '{' || c == '[') {
            if (depth == RB_BATCH_READ_DEPTH)
                return FAIL(r, d, RB_ERR_LIMIT, key, "nested deeper than %d levels",
                            RB_BATCH_READ_DEPTH);
            stack[depth++] = c == '{' ? '}' : ']';
        } else if (c == '}' || c == ']') {
            if (depth == 0 || stack[--depth] != c)
                return FAIL(r, d, RB_ERR_PARSE, key, "not JSON: a '%c' that closes nothing "
                            "open", c);
            if (depth == 0)
                break;
        }
    }
    if (r->len == 0)
        return FAIL(r, d, RB_ERR_PARSE, key, "not JSON: expected a value");
    r->buf[r->len] = '\0';
    return RB_OK;
}

/* The value scanned, parsed; NULL with d set when it is not JSON, at the
 * line and column where cJSON stopped. */
static cJSON *parse(rb_batch_reader *r, const char *key, rb_diag *d, rb_status *st)
{
    const char *end = NULL;
    cJSON *v = cJSON_ParseWithLengthOpts(r->buf, r->len, &end, 0);
    if (v && end == r->buf + r->len)
        return v;
    cJSON_Delete(v);
    if (!end || end < r->buf || end > r->buf + r->len)
        end = cJSON_GetErrorPtr();
    int line = r->vline, col = r->vcol;
    for (const char *p = r->buf; end && p < end && p < r->buf + r->len; p++) {
        if (*p == '\n') {
            line++;
            col = 1;
        } else {
            col++;
        }
    }
    *st = rb_diag_set(d, RB_ERR_PARSE, r->name, line, col, key, "not JSON");
    return NULL;
}

void rb_batch_reader_close(rb_batch_reader *r)
{
    if (!r)
        return;
    free(r->buf);
    free(r);
}

/* The members before "cases" into head; the reader then stands at the
 * list's first element. */
static rb_status read_head(rb_batch_reader *r, cJSON *root, rb_diag *d)
{
    rb_status st = RB_OK;
    size_t used = 0;
    int c, has_cases = 0;
    if (peek(r) == 0xEF) {           /* a byte-order mark, as cJSON allowed */
        take(r);
        if (take(r) != 0xBB || take(r) != 0xBF)
            return FAIL(r, d, RB_ERR_PARSE, "summary", "not JSON");
    }
    skip_ws(r);
    if (peek(r) != '{')
        return peek(r) == EOF ? ended(r, d, "summary")
                              : FAIL(r, d, RB_ERR_PARSE, "summary", "not JSON: a summary "
                                     "is a JSON object, which begins with '{'");
    take(r);
    for (;;) {
        skip_ws(r);
        if (peek(r) == '}')
            break;
        if (peek(r) != '"')
            return peek(r) == EOF ? ended(r, d, "summary")
                                  : FAIL(r, d, RB_ERR_PARSE, "summary", "not JSON: "
                                         "expected a key in double quotes");
        st = scan(r, RB_BATCH_READ_KEY_MAX, RB_BATCH_READ_KEY_MAX, "summary", "a key", d);
        if (st != RB_OK)
            return st;
        cJSON *k = parse(r, "summary", d, &st);
        if (!k)
            return st;
        char key[RB_BATCH_READ_KEY_MAX + 1];
        snprintf(key, sizeof key, "%s", k->valuestring);
        cJSON_Delete(k);
        skip_ws(r);
        if ((c = take(r)) != ':')
            return c == EOF ? ended(r, d, key)
                            : FAIL(r, d, RB_ERR_PARSE, key, "not JSON: expected ':'");
        skip_ws(r);
        if (strcmp(key, "cases") == 0) {
            has_cases = 1;
            break;
        }
        if ((st = scan(r, RB_BATCH_READ_HEAD_MAX - used, RB_BATCH_READ_HEAD_MAX, key,
                       "the summary's head (what comes before \"cases\")", d)) != RB_OK)
            return st;
        used += r->len;
        cJSON *v = parse(r, key, d, &st);
        if (!v)
            return st;
        if (!cJSON_AddItemToObject(root, key, v)) {
            cJSON_Delete(v);
            return RB_ERR_NOMEM;
        }
        skip_ws(r);
        if ((c = take(r)) == '}')
            break;
        if (c != ',')
            return c == EOF ? ended(r, d, key)
                            : FAIL(r, d, RB_ERR_PARSE, key, "not JSON: expected ',' or '}'");
    }
    /* the head's own errors first, as when the summary was read whole */
    int line = r->line, col = r->col;
    if ((st = rb_batch_read_json_head(root, &r->head, d)) != RB_OK) {
        r->vline = r->vcol = 0;   /* the head as a whole, as before */
        return place(r, d, st);
    }
    if (!has_cases || peek(r) != '[')
        return fail_at(r, d, RB_ERR_PARSE, line, col, "cases",
                           "expected a list%s", has_cases ? ""
                           : " (a summary's cases come last, as batch writes them)");
    take(r);
    return RB_OK;
}

rb_status rb_batch_reader_open(FILE *fp, const char *name, rb_batch_summary *head,
                               rb_batch_reader **out, rb_diag *diag)
{
    rb_diag scratch;
    rb_diag *d = diag ? diag : &scratch;
    memset(head, 0, sizeof *head);
    *out = NULL;
    rb_batch_reader *r = calloc(1, sizeof *r);
    cJSON *root = cJSON_CreateObject();
    if (!r || !root) {
        free(r);
        cJSON_Delete(root);
        return RB_ERR_NOMEM;
    }
    r->fp = fp;
    snprintf(r->name, sizeof r->name, "%s", name ? name : "");
    r->line = r->col = 1;
    r->ahead = NONE;
    rb_status st = read_head(r, root, d);
    cJSON_Delete(root);
    if (st != RB_OK) {
        rb_batch_reader_close(r);
        return st;
    }
    *head = r->head;
    head->name = name;
    *out = r;
    return RB_OK;
}

/* After the list: the object's end, then nothing but blanks. */
static rb_status finish(rb_batch_reader *r, rb_diag *d)
{
    int c;
    r->vline = r->line;
    r->vcol = r->col;
    skip_ws(r);
    if ((c = take(r)) != '}')
        return c == EOF ? ended(r, d, "summary")
                        : FAIL(r, d, RB_ERR_PARSE, "summary", c == ','
                               ? "members after \"cases\": a summary's cases come last, as "
                                 "batch writes them"
                               : "not JSON: expected '}' after the list of cases");
    skip_ws(r);
    if (peek(r) != EOF)
        return FAIL(r, d, RB_ERR_PARSE, "summary", "text after the summary's end");
    if (ferror(r->fp))
        return ended(r, d, "summary");
    r->state = 2;
    return RB_OK;
}

rb_status rb_batch_reader_next(rb_batch_reader *r, rb_batch_case *c, int *got,
                               rb_diag *diag)
{
    rb_diag scratch;
    rb_diag *d = diag ? diag : &scratch;
    rb_status st = RB_OK;
    int ch;
    memset(c, 0, sizeof *c);
    *got = 0;
    if (r->state == 2)
        return RB_OK;
    skip_ws(r);
    if (r->state == 1) {
        if ((ch = take(r)) == ']')
            return finish(r, d);
        if (ch != ',')
            return ch == EOF ? ended(r, d, "cases")
                             : FAIL(r, d, RB_ERR_PARSE, "cases", "not JSON: expected ',' "
                                    "or ']' after case %zu", r->n_cases);
        skip_ws(r);
    } else if (peek(r) == ']') {
        take(r);
        return finish(r, d);
    }
    r->state = 1;
    char what[64];
    snprintf(what, sizeof what, "case %zu of the list", r->n_cases + 1);
    st = scan(r, RB_BATCH_READ_CASE_MAX, RB_BATCH_READ_CASE_MAX, "cases", what, d);
    if (st != RB_OK)
        return st;
    cJSON *o = parse(r, "cases", d, &st);
    /* one long case must not keep its buffer for the rest of the file */
    if (r->cap > RB_BATCH_READ_KEEP) {
        free(r->buf);
        r->buf = NULL;
        r->cap = 0;
    }
    if (!o)
        return st;
    if (!cJSON_IsObject(o))
        st = fail_at(r, d, RB_ERR_PARSE, r->vline, r->vcol, "cases", "expected an object "
                     "for each case");
    else if ((st = rb_batch_read_json_case(o, &r->head, c, d)) != RB_OK)
        place(r, d, st);
    cJSON_Delete(o);
    if (st != RB_OK)
        return st;
    r->n_cases++;
    *got = 1;
    return RB_OK;
}

rb_status rb_batch_summary_parse(const char *text, rb_batch_summary *out, rb_diag *diag)
{
    memset(out, 0, sizeof *out);
    /* fmemopen wants a size of at least one */
    FILE *fp = fmemopen((void *)(text[0] ? text : " "), text[0] ? strlen(text) : 1, "r");
    if (!fp)
        return RB_ERR_NOMEM;
    rb_batch_reader *r = NULL;
    rb_status st = rb_batch_reader_open(fp, "", out, &r, diag);
    size_t cap = 0;
    while (st == RB_OK) {
        rb_batch_case c;
        int got = 0;
        if ((st = rb_batch_reader_next(r, &c, &got, diag)) != RB_OK || !got)
            break;
        if (out->n_cases == cap) {
            size_t ncap = cap ? 2 * cap : 16;
            rb_batch_case *p = realloc(out->cases, ncap * sizeof *p);
            if (!p) {
                rb_batch_case_free(&c);
                st = RB_ERR_NOMEM;
                break;
            }
            out->cases = p;
            cap = ncap;
        }
        out->cases[out->n_cases++] = c;
    }
    rb_batch_reader_close(r);
    fclose(fp);
    if (st != RB_OK)
        rb_batch_summary_free(out);
    return st;
}
