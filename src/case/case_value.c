/* Typed values of the case schema: quantities, booleans, whole numbers,
 * keywords and text, each checked against its node so that every message
 * names the dotted key, says what was expected and quotes what was found.
 * Also the unknown-key report with its "did you mean" hint. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "case_internal.h"
#include "rockbolt/datadir.h"
#include "util/nearest.h"

rb_ynode *rb_cv_get(rb_cctx *c, rb_ynode *map, const char *path,
                    const char *key, int required, const char *expected)
{
    rb_yentry *e = rb_ymap_find(map, key);
    if (e) {
        e->used = 1;
        return e->value;
    }
    if (required) {
        char k[RB_CASE_KEY_MAX];
        rb_case_keypath(k, path, key);
        rb_cctx_error(c, map, k, "missing required key '%s' (%s)", key, expected);
    }
    return NULL;
}

/* Error unless v is a non-null scalar. */
static int cv_scalar(rb_cctx *c, const rb_ynode *v, const char *key,
                        const char *expected)
{
    if (v->kind == RB_YNODE_SCALAR && !rb_ynode_is_null(v))
        return 1;
    rb_cctx_error(c, v, key, "expected %s, found %s", expected,
                  rb_ynode_kind_str(v));
    return 0;
}

int rb_cv_quantity(rb_cctx *c, const rb_ynode *v, const char *key, rb_dim dim,
                   rb_quantity *out)
{
    char expected[160], msg[300];
    snprintf(expected, sizeof expected, "%s (%s)", rb_dim_str(dim),
             rb_dim_units(dim));
    if (!cv_scalar(c, v, key, expected))
        return 0;
    if (rb_unit_parse(v->text, dim, out, msg, sizeof msg) != RB_OK) {
        rb_cctx_error(c, v, key, "%s", msg);
        return 0;
    }
    return 1;
}

/* A bound of a range message: a bare number for a ratio, a time or a
 * zero, else the quantity in the case's units. */
static rb_qtext cv_bound(const rb_cctx *c, rb_dim dim, double x)
{
    rb_qty q;
    rb_qtext t;
    if (x == 0 || !rb_dim_qty(dim, &q)) {
        snprintf(t.s, sizeof t.s, "%g", x);
        return t;
    }
    return rb_qty_str(c->units, q, x, 4);
}

/* "> 0", ">= 0 and < 1", ">= 1000 psi and <= 20000 psi" ... for a range
 * message. */
static void cv_range_str(const rb_cctx *c, rb_dim dim, char *buf, size_t size, double lo,
                         int lo_incl, double hi, int hi_incl)
{
    int n = 0;
    if (!isnan(lo))
        n = snprintf(buf, size, "%s %s", lo_incl ? ">=" : ">", cv_bound(c, dim, lo).s);
    if (!isnan(hi))
        snprintf(buf + n, size - (size_t)n, "%s%s %s", n ? " and " : "",
                 hi_incl ? "<=" : "<", cv_bound(c, dim, hi).s);
}

const rb_ynode *rb_cv_number(rb_cctx *c, rb_ynode *map, const char *path,
                             const char *key, int required, rb_dim dim,
                             double lo, int lo_incl, double hi, int hi_incl,
                             double *out)
{
    char k[RB_CASE_KEY_MAX], expected[200], range[120];
    rb_quantity q;
    if (dim == RB_DIM_RATIO)
        snprintf(expected, sizeof expected, "a dimensionless number such as "
                 "0.01 or 1 %%");
    else
        snprintf(expected, sizeof expected, "%s in %s", rb_dim_str(dim),
                 rb_dim_units(dim));
    rb_ynode *v = rb_cv_get(c, map, path, key, required, expected);
    if (!v)
        return NULL;
    rb_case_keypath(k, path, key);
    if (!rb_cv_quantity(c, v, k, dim, &q))
        return NULL;
    int bad = (!isnan(lo) && (lo_incl ? q.value < lo : q.value <= lo))
           || (!isnan(hi) && (hi_incl ? q.value > hi : q.value >= hi));
    if (bad) {
        range[0] = '\0';
        cv_range_str(c, dim, range, sizeof range, lo, lo_incl, hi, hi_incl);
        /* "damping: 5" meant 5 %: a bare damping ratio of 1 to 100, the
         * one ratio engineers say in percent (a z/h of 1.5 is no 1.5 %) */
        size_t kl = strlen(key);
        int percent = dim == RB_DIM_RATIO && kl >= 7 && strcmp(key + kl - 7, "damping") == 0
                      && !isnan(hi) && hi <= 1 && q.value >= 1 && q.value <= 100
                      && !strchr(v->text, '%');
        if (percent)
            rb_cctx_error(c, v, k, "must be %s (got '%s'; did you mean '%s %%'?)", range,
                          v->text, v->text);
        else
            rb_cctx_error(c, v, k, "must be %s (got '%s')", range, v->text);
        return NULL;
    }
    *out = q.value;
    return v;
}

int rb_cv_time_range(rb_cctx *c, const rb_ynode *v, const char *key, double t,
                     int zero_ok)
{
    if ((zero_ok && t == 0) || (t >= RB_CASE_MIN_TIME_S && t <= RB_CASE_MAX_RUN_S))
        return 1;
    if (t > RB_CASE_MAX_RUN_S)
        rb_cctx_error_at(c, RB_ERR_LIMIT, v->file, v->line, v->col, key,
                         "must be at most %g s, one simulated hour (the limit; "
                         "got '%s')", RB_CASE_MAX_RUN_S, v->text);
    else
        rb_cctx_error(c, v, key, "must be %sat least %g ms (got '%s'): shorter "
                      "times are below what the solver can step through",
                      zero_ok ? "0 or " : "", RB_CASE_MIN_TIME_S * 1e3, v->text);
    return 0;
}

int rb_cv_bool(rb_cctx *c, const rb_ynode *v, const char *key, int *out)
{
    static const char *const yes[] = {"true", "True", "TRUE"};
    static const char *const no[] = {"false", "False", "FALSE"};
    if (!cv_scalar(c, v, key, "true or false"))
        return 0;
    for (int i = 0; i < 3; i++) {
        if (strcmp(v->text, yes[i]) == 0) {
            *out = 1;
            return 1;
        }
        if (strcmp(v->text, no[i]) == 0) {
            *out = 0;
            return 1;
        }
    }
    rb_cctx_error(c, v, key, "expected true or false, found '%s'", v->text);
    return 0;
}

int rb_cv_int(rb_cctx *c, const rb_ynode *v, const char *key, long lo,
              long hi, long *out)
{
    char expected[80], *end;
    snprintf(expected, sizeof expected, "a whole number from %ld to %ld", lo, hi);
    if (!cv_scalar(c, v, key, expected))
        return 0;
    errno = 0;
    long x = strtol(v->text, &end, 10);
    int digits = end != v->text && isdigit((unsigned char)end[-1]);
    if (errno || !digits || *end || x < lo || x > hi) {
        rb_cctx_error(c, v, key, "expected %s, found '%s'", expected, v->text);
        return 0;
    }
    *out = x;
    return 1;
}

/* The candidate closest to word when close enough to be a likely typo. */
static const char *cv_nearest(const char *word, const char *const cand[])
{
    const char *best = NULL;
    int bestd = 9;
    for (size_t i = 0; cand[i]; i++) {
        int d = rb_edit_distance(word, cand[i]);
        if (d < bestd) {
            bestd = d;
            best = cand[i];
        }
    }
    return bestd <= rb_typo_limit(strlen(word)) ? best : NULL;
}

/* "a, b, c" from a NULL-terminated list. */
static void cv_join(char *buf, size_t size, const char *const names[])
{
    size_t n = 0;
    buf[0] = '\0';
    for (size_t i = 0; names[i] && n < size; i++)
        n += (size_t)snprintf(buf + n, size - n, "%s%s", i ? ", " : "", names[i]);
}

int rb_cv_enum(rb_cctx *c, const rb_ynode *v, const char *key,
               const char *const names[], int *out)
{
    char list[300], expected[340];
    cv_join(list, sizeof list, names);
    snprintf(expected, sizeof expected, "one of %s", list);
    if (!cv_scalar(c, v, key, expected))
        return 0;
    for (int i = 0; names[i]; i++) {
        if (strcmp(v->text, names[i]) == 0) {
            *out = i;
            return 1;
        }
    }
    const char *near = cv_nearest(v->text, names);
    if (near)
        rb_cctx_error(c, v, key, "unknown value '%s' (did you mean '%s'?)",
                      v->text, near);
    else
        rb_cctx_error(c, v, key, "expected %s, found '%s'", expected, v->text);
    return 0;
}

int rb_cv_enum_table(rb_cctx *c, const rb_ynode *v, const char *key,
                     const rb_enum_name *table, size_t n_parse, int *out)
{
    const char *names[RB_CV_ENUM_MAX + 1];
    size_t n = 0;
    for (; table[n].name && n < RB_CV_ENUM_MAX && (n_parse == 0 || n < n_parse); n++)
        names[n] = table[n].name;
    names[n] = NULL;
    int i;
    if (!rb_cv_enum(c, v, key, names, &i))
        return 0;
    *out = table[i].value;
    return 1;
}

int rb_cv_string(rb_cctx *c, const rb_ynode *v, const char *key, char **out)
{
    if (!cv_scalar(c, v, key, "text"))
        return 0;
    size_t len = strlen(v->text) + 1;
    char *p = malloc(len);
    if (!p) {
        c->nomem = 1;
        return 0;
    }
    memcpy(p, v->text, len);
    free(*out);
    *out = p;
    return 1;
}

int rb_cv_map(rb_cctx *c, const rb_ynode *v, const char *key)
{
    if (v->kind == RB_YNODE_MAP)
        return 1;
    rb_cctx_error(c, v, key, "expected a mapping of keys, found %s",
                  rb_ynode_kind_str(v));
    return 0;
}

void rb_cv_unknown_keys(rb_cctx *c, const rb_ynode *map, const char *path,
                        const char *const valid[])
{
    char k[RB_CASE_KEY_MAX], list[400];
    for (size_t i = 0; i < map->n; i++) {
        const rb_yentry *e = &map->entries[i];
        if (e->used)
            continue;
        rb_case_keypath(k, path, e->key);
        const char *near = cv_nearest(e->key, valid);
        if (near) {
            rb_cctx_error_at(c, RB_ERR_INVALID, e->value->file, e->line, e->col,
                             k, "unknown key '%s' (did you mean '%s'?)",
                             e->key, near);
        } else {
            cv_join(list, sizeof list, valid);
            rb_cctx_error_at(c, RB_ERR_INVALID, e->value->file, e->line, e->col,
                             k, "unknown key '%s' (expected one of: %s)",
                             e->key, list);
        }
    }
}

void rb_cv_note_field(rb_cctx *c, const char *field, const char *key,
                      const rb_ynode *node)
{
    if (c->n_fields == RB_CASE_MAX_FIELDS)
        return;
    rb_cfield *f = &c->fields[c->n_fields++];
    f->field = field;
    snprintf(f->key, sizeof f->key, "%s", key);
    f->node = node;
}

char *rb_case_input_path(const rb_ynode *v)
{
    size_t sl = strlen(RB_SHIPPED_PREFIX);
    if (strncmp(v->text, RB_SHIPPED_PREFIX, sl) == 0) {
        char buf[4096];
        const char *sp = rb_shipped_path(v->text + sl, buf, sizeof buf);
        char *copy = sp ? malloc(strlen(sp) + 1) : NULL;
        if (copy)
            memcpy(copy, sp, strlen(sp) + 1);
        return copy;
    }
    const char *slash = strrchr(v->file, '/');
    size_t dlen = (v->text[0] == '/' || !slash) ? 0 : (size_t)(slash - v->file + 1);
    size_t rlen = strlen(v->text);
    char *p = malloc(dlen + rlen + 1);
    if (p) {
        memcpy(p, v->file, dlen);
        memcpy(p + dlen, v->text, rlen + 1);
    }
    return p;
}

char *rb_case_strdup(rb_cctx *c, const char *s)
{
    size_t len = strlen(s) + 1;
    char *p = malloc(len);
    if (p)
        memcpy(p, s, len);
    else
        c->nomem = 1;
    return p;
}
