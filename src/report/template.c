/* A small text template engine for the reports (see report.h for the
 * syntax).
 *
 * Why not a general engine: the text report needs placeholders with a
 * fixed printf precision (so output is byte-stable), one repeated section
 * per motion and a few conditional lines, nothing more. A template is
 * tokenised once, section tags are matched, tags alone on their line are
 * made to vanish with that line, and the token list is rendered
 * recursively. Formats are parsed here and applied through fixed literal
 * format strings, so a template can never inject a conversion into printf.
 * Templates are a few kilobytes: simplicity wins over speed. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "util/strbuf.h"
#include "rockbolt/report.h"
#include "rockbolt/template.h"
#include "rockbolt/textsafe.h"
#include "util/grow.h"

#define TMPL_MAX_DEPTH 8   /* nested sections; the report needs two */
#define TMPL_MAX_WIDTH 64
#define TMPL_MAX_PREC 30

typedef enum { TOK_TEXT, TOK_VAR, TOK_OPEN, TOK_INVERT, TOK_CLOSE,
               TOK_COMMENT } tok_kind;

/* Parsed "%[-+][width][.prec]conv". */
typedef struct {
    int left, plus, width, prec; /* prec -1: not given */
    char conv;                   /* 0: default for the value's kind */
} fspec;

typedef struct {
    tok_kind kind;
    const char *s;    /* TEXT: the text; tags: the name */
    size_t len;
    fspec fmt;
    int line, col;    /* where the tag starts, from 1 */
    size_t match;     /* OPEN/INVERT: index of the CLOSE */
    int standalone;
} tok;

typedef struct {
    tok *v;
    size_t n, cap;
} toklist;


static rb_status fail(rb_diag *diag, const tok *t, const char *msg)
{
    char key[128] = "";
    if (t && t->kind != TOK_TEXT)
        snprintf(key, sizeof key, "%.*s", (int)(t->len < 100 ? t->len : 100), t->s);
    return rb_diag_set(diag, RB_ERR_PARSE, diag ? diag->file : NULL, t ? t->line : 0,
                       t ? t->col : 0, key, "%s", msg);
}

static tok *toks_push(toklist *l)
{
    if (l->n == l->cap) {
        tok *v = rb_grow(l->v, &l->cap, sizeof *v, 64);
        if (!v)
            return NULL;
        l->v = v;
    }
    memset(&l->v[l->n], 0, sizeof l->v[0]);
    return &l->v[l->n++];
}

/* Parse a format after the ':' of a tag; returns 0 if it is not one we
 * accept. */
static int parse_fspec(const char *s, size_t n, fspec *f)
{
    size_t i = 0;
    memset(f, 0, sizeof *f);
    f->prec = -1;
    if (n < 2 || s[i++] != '%')
        return 0;
    for (; i < n && (s[i] == '-' || s[i] == '+'); i++)
        *(s[i] == '-' ? &f->left : &f->plus) = 1;
    for (; i < n && s[i] >= '0' && s[i] <= '9'; i++)
        if ((f->width = f->width * 10 + (s[i] - '0')) > TMPL_MAX_WIDTH)
            return 0;
    if (i < n && s[i] == '.') {
        f->prec = 0;
        for (i++; i < n && s[i] >= '0' && s[i] <= '9'; i++)
            if ((f->prec = f->prec * 10 + (s[i] - '0')) > TMPL_MAX_PREC)
                return 0;
    }
    if (i + 1 != n || !strchr("fegds", s[i]))
        return 0;
    f->conv = s[i];
    return 1;
}

static int is_name(const char *s, size_t n)
{
    size_t i;
    if (n == 0)
        return 0;
    for (i = 0; i < n; i++)
        if (!(s[i] == '_' || s[i] == '.' || (s[i] >= 'a' && s[i] <= 'z') ||
              (s[i] >= 'A' && s[i] <= 'Z') || (s[i] >= '0' && s[i] <= '9')))
            return 0;
    return 1;
}

/* Advance (line, col) from p to q. */
static void track(const char *p, const char *q, int *line, int *col)
{
    for (; p < q; p++) {
        if (*p == '\n') {
            ++*line;
            *col = 1;
        } else {
            ++*col;
        }
    }
}

/* Fill t (kind, name, format) from the text between "{{" and "}}". */
static rb_status parse_tag(tok *t, const char *s, size_t n, rb_diag *diag)
{
    const char *colon;
    t->kind = TOK_VAR;
    t->fmt.prec = -1;
    if (n > 0 && strchr("#^/!", s[0])) {
        t->kind = s[0] == '#' ? TOK_OPEN : s[0] == '^' ? TOK_INVERT
                : s[0] == '/' ? TOK_CLOSE : TOK_COMMENT;
        s++;
        n--;
    }
    if (t->kind == TOK_COMMENT)
        return RB_OK;
    while (n > 0 && s[0] == ' ')
        s++, n--;
    while (n > 0 && s[n - 1] == ' ')
        n--;
    colon = memchr(s, ':', n);
    t->s = s;
    t->len = colon ? (size_t)(colon - s) : n;
    if (!is_name(t->s, t->len))
        return fail(diag, t, "a tag name is letters, digits, '_' and '.'");
    if (colon && t->kind != TOK_VAR)
        return fail(diag, t, "only a value tag takes a format");
    if (colon && !parse_fspec(colon + 1, n - t->len - 1, &t->fmt))
        return fail(diag, t, "format must be %[-+][width][.precision] with "
                    "one of f e g d s (width <= 64, precision <= 30)");
    return RB_OK;
}

static rb_status tokenize(const char *tmpl, toklist *l, rb_diag *diag)
{
    const char *p = tmpl, *mark = tmpl;
    int line = 1, col = 1;
    while (*p) {
        const char *open = strstr(p, "{{"), *close;
        tok *t;
        if (!open)
            open = p + strlen(p);
        if (open > p) {
            if (!(t = toks_push(l)))
                return RB_ERR_NOMEM;
            t->kind = TOK_TEXT;
            t->s = p;
            t->len = (size_t)(open - p);
        }
        if (!*open)
            break;
        if (!(t = toks_push(l)))
            return RB_ERR_NOMEM;
        track(mark, open, &line, &col);
        mark = open;
        t->line = line;
        t->col = col;
        t->s = open;
        t->len = 2;
        if (!(close = strstr(open + 2, "}}")))
            return fail(diag, t, "tag is not closed by '}}'");
        if (parse_tag(t, open + 2, (size_t)(close - open - 2), diag) != RB_OK)
            return RB_ERR_PARSE;
        p = close + 2;
    }
    return RB_OK;
}

/* Pair every section opening with its closing tag. */
static rb_status match_sections(toklist *l, rb_diag *diag)
{
    size_t stack[TMPL_MAX_DEPTH], depth = 0, i;
    for (i = 0; i < l->n; i++) {
        tok *t = &l->v[i];
        if (t->kind == TOK_OPEN || t->kind == TOK_INVERT) {
            if (depth == TMPL_MAX_DEPTH)
                return fail(diag, t, "sections nested too deeply");
            stack[depth++] = i;
        } else if (t->kind == TOK_CLOSE) {
            tok *o;
            if (depth == 0)
                return fail(diag, t, "closing tag without an opening one");
            o = &l->v[stack[--depth]];
            if (o->len != t->len || memcmp(o->s, t->s, t->len) != 0)
                return fail(diag, t, "closing tag does not match the open section");
            o->match = i;
        }
    }
    if (depth > 0)
        return fail(diag, &l->v[stack[depth - 1]], "section is not closed");
    return RB_OK;
}

static int is_blank(const char *s, size_t n)
{
    size_t i;
    for (i = 0; i < n; i++)
        if (s[i] != ' ' && s[i] != '\t' && s[i] != '\r')
            return 0;
    return 1;
}

/* Does the text before tag i, back to the start of its line, hold only
 * blanks? (And after it, up to the end of the line?) */
static int blank_before(const toklist *l, size_t i)
{
    const tok *p;
    const char *nl;
    if (i == 0)
        return 1;
    p = &l->v[i - 1];
    if (p->kind != TOK_TEXT)
        return 0;
    for (nl = p->s + p->len; nl > p->s && nl[-1] != '\n'; nl--)
        ;
    if (nl == p->s && i - 1 != 0)
        return 0;
    return is_blank(nl, (size_t)(p->s + p->len - nl));
}

static int blank_after(const toklist *l, size_t i)
{
    const tok *nx;
    const char *nl;
    if (i + 1 == l->n)
        return 1;
    nx = &l->v[i + 1];
    if (nx->kind != TOK_TEXT)
        return 0;
    nl = memchr(nx->s, '\n', nx->len);
    if (!nl && i + 2 != l->n)
        return 0;
    return is_blank(nx->s, nl ? (size_t)(nl - nx->s) : nx->len);
}

/* Section and comment tags alone on a line take the line with them. The
 * conditions are decided on the untouched tokens first, then applied. */
static void strip_standalone(toklist *l)
{
    size_t i;
    for (i = 0; i < l->n; i++) {
        tok_kind k = l->v[i].kind;
        if (k != TOK_TEXT && k != TOK_VAR)
            l->v[i].standalone = blank_before(l, i) && blank_after(l, i);
    }
    for (i = 0; i < l->n; i++) {
        tok *t = &l->v[i];
        size_t cut_start = 0, cut_end = 0;
        const char *nl;
        if (t->kind != TOK_TEXT)
            continue;
        if (i + 1 < l->n && l->v[i + 1].standalone) {
            for (nl = t->s + t->len; nl > t->s && nl[-1] != '\n'; nl--)
                ;
            cut_end = (size_t)(t->s + t->len - nl);
        }
        if (i > 0 && l->v[i - 1].standalone) {
            nl = memchr(t->s, '\n', t->len);
            cut_start = nl ? (size_t)(nl - t->s) + 1 : t->len;
        }
        if (cut_start + cut_end >= t->len) {
            t->len = 0;
        } else {
            t->s += cut_start;
            t->len -= cut_start + cut_end;
        }
    }
}

static const rb_tvar *find_var(const rb_tscope *sc, const char *s, size_t n)
{
    size_t i;
    for (; sc; sc = sc->parent)
        for (i = 0; i < sc->n_vars; i++)
            if (strlen(sc->vars[i].name) == n && !memcmp(sc->vars[i].name, s, n))
                return &sc->vars[i];
    return NULL;
}

static const rb_tlist *find_list(const rb_tscope *sc, const char *s, size_t n)
{
    size_t i;
    for (; sc; sc = sc->parent)
        for (i = 0; i < sc->n_lists; i++)
            if (strlen(sc->lists[i].name) == n && !memcmp(sc->lists[i].name, s, n))
                return &sc->lists[i];
    return NULL;
}

/* snprintf one value by its spec through literal formats only. Returns
 * the length needed, or -1 if the spec does not fit the value's kind. */
static int format_value(char *dst, size_t cap, const fspec *f, const rb_tvar *v)
{
    int w = f->left ? -f->width : f->width, p = f->prec;
    char conv = f->conv;
    double x = v->kind == RB_TVAL_INT ? (double)v->integer : v->num;
    if (v->kind == RB_TVAL_NONE ||
        (v->kind == RB_TVAL_NUM && !isfinite(v->num)))
        return snprintf(dst, cap, "%*s", w, "n/a");
    if (!conv)
        conv = v->kind == RB_TVAL_STR ? 's' : v->kind == RB_TVAL_INT ? 'd' : 'g';
    if ((conv == 's') != (v->kind == RB_TVAL_STR) ||
        (conv == 'd' && v->kind != RB_TVAL_INT))
        return -1;
    switch (conv) {
    case 's': return snprintf(dst, cap, "%*.*s", w, p, v->str ? v->str : "");
    case 'd': return f->plus ? snprintf(dst, cap, "%+*ld", w, v->integer)
                             : snprintf(dst, cap, "%*ld", w, v->integer);
    case 'f':
        /* no "-0.00": a value that rounds to zero prints as zero */
        if (fabs(x) < 0.5 * pow(10.0, -(p < 0 ? 6 : p)))
            x = 0.0;
        return f->plus ? snprintf(dst, cap, "%+*.*f", w, p, x)
                       : snprintf(dst, cap, "%*.*f", w, p, x);
    case 'e': return f->plus ? snprintf(dst, cap, "%+*.*e", w, p, x)
                             : snprintf(dst, cap, "%*.*e", w, p, x);
    default: return f->plus ? snprintf(dst, cap, "%+*.*g", w, p, x)
                            : snprintf(dst, cap, "%*.*g", w, p, x);
    }
}

/* Strings (names, descriptions, reasons) can carry control characters
 * from the case's YAML escapes: they are shown escaped, never sent. */
static rb_status emit_var(rb_strbuf *b, const tok *t, const rb_tscope *sc, rb_diag *diag)
{
    const rb_tvar *v = find_var(sc, t->s, t->len);
    rb_tvar esc;
    char *shown = NULL;
    int n;
    if (!v)
        return fail(diag, t, "unknown name");
    if (v->kind == RB_TVAL_STR && v->str && rb_text_needs_escape(v->str)) {
        if (!(shown = rb_text_escape(v->str)))
            return RB_ERR_NOMEM;
        esc = *v;
        esc.str = shown;
        v = &esc;
    }
    n = format_value(NULL, 0, &t->fmt, v);
    if (n < 0) {
        free(shown);
        return fail(diag, t, "format does not fit the kind of value");
    }
    char *text = malloc((size_t)n + 1);
    if (text) {
        format_value(text, (size_t)n + 1, &t->fmt, v);
        rb_strbuf_putn(b, text, (size_t)n);
    }
    free(text);
    free(shown);
    return text && !b->oom ? RB_OK : RB_ERR_NOMEM;
}

/* A section over a plain value renders once if the value is "true": a
 * non-zero number, a non-empty string. */
static int var_truthy(const rb_tvar *v)
{
    switch (v->kind) {
    case RB_TVAL_NONE: return 0;
    case RB_TVAL_NUM: return isfinite(v->num) && v->num != 0;
    case RB_TVAL_INT: return v->integer != 0;
    case RB_TVAL_STR: return v->str && v->str[0];
    }
    return 0;
}

static rb_status render(rb_strbuf *b, const toklist *l, size_t from, size_t to,
                        const rb_tscope *sc, rb_diag *diag);

static rb_status render_section(rb_strbuf *b, const toklist *l, size_t i,
                                const rb_tscope *sc, rb_diag *diag)
{
    const tok *t = &l->v[i];
    const rb_tlist *list = find_list(sc, t->s, t->len);
    const rb_tvar *v = list ? NULL : find_var(sc, t->s, t->len);
    size_t k;
    rb_status st = RB_OK;
    if (!list && !v)
        return fail(diag, t, "unknown name");
    if (t->kind == TOK_INVERT) {
        int empty = list ? list->n == 0 : !var_truthy(v);
        return empty ? render(b, l, i + 1, t->match, sc, diag) : RB_OK;
    }
    if (v)
        return var_truthy(v) ? render(b, l, i + 1, t->match, sc, diag) : RB_OK;
    for (k = 0; k < list->n && st == RB_OK; k++) {
        rb_tscope item = list->items[k];
        item.parent = sc;
        st = render(b, l, i + 1, t->match, &item, diag);
    }
    return st;
}

static rb_status render(rb_strbuf *b, const toklist *l, size_t from, size_t to,
                        const rb_tscope *sc, rb_diag *diag)
{
    size_t i;
    rb_status st = RB_OK;
    for (i = from; i < to && st == RB_OK; i++) {
        const tok *t = &l->v[i];
        switch (t->kind) {
        case TOK_TEXT:
            rb_strbuf_putn(b, t->s, t->len);
            if (b->oom)
                st = RB_ERR_NOMEM;
            break;
        case TOK_VAR:
            st = emit_var(b, t, sc, diag);
            break;
        case TOK_OPEN:
        case TOK_INVERT:
            st = render_section(b, l, i, sc, diag);
            i = t->match;
            break;
        case TOK_CLOSE:
        case TOK_COMMENT:
            break;
        }
    }
    return st;
}

rb_status rb_template_render(const char *tmpl, const rb_tscope *scope,
                             char **out, rb_diag *diag)
{
    toklist l = {0};
    rb_strbuf b = {0};
    rb_status st;
    *out = NULL;
    st = tokenize(tmpl, &l, diag);
    if (st == RB_OK)
        st = match_sections(&l, diag);
    if (st == RB_OK) {
        strip_standalone(&l);
    }
    if (st == RB_OK)
        st = render(&b, &l, 0, l.n, scope, diag);
    free(l.v);
    if (st != RB_OK) {
        rb_strbuf_free(&b);
        return st;
    }
    *out = rb_strbuf_take(&b);
    return *out ? RB_OK : RB_ERR_NOMEM;
}
