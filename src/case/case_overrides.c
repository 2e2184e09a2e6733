/* rb_case_load_overrides: a base case plus overriding values.
 *
 * The overrides become a small case document in memory that extends the
 * base (by absolute path, as are the records it names), loaded through
 * rb_case_load_text, which keeps every merge rule and check in one place:
 * nothing is written to disk. Diagnostics are then mapped back: positions
 * in the document become the origin's line and column of the value, and
 * the working-directory prefix the absolute paths brought in is removed, so
 * that paths read as they would in a normal load. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "rockbolt/case_overrides.h"
#include "util/strbuf.h"
#include "rockbolt/datadir.h"
#include "util/grow.h"

#define RB_OV_MAX_DEPTH 4
#define RB_OV_COMP_MAX 64

/* A double-quoted YAML scalar: no value can change the document's shape. */
static void sb_quoted(rb_strbuf *s, const char *v)
{
    rb_strbuf_putn(s, "\"", 1);
    for (const unsigned char *p = (const unsigned char *)v; *p; p++) {
        char esc[8];
        if (*p == '"' || *p == '\\') {
            esc[0] = '\\';
            esc[1] = (char)*p;
            rb_strbuf_putn(s, esc, 2);
        } else if (*p < 0x20 || *p == 0x7f) {
            snprintf(esc, sizeof esc, "\\x%02x", *p);
            rb_strbuf_puts(s, esc);
        } else {
            rb_strbuf_putn(s, (const char *)p, 1);
        }
    }
    rb_strbuf_putn(s, "\"", 1);
}

/* Component d of a dotted key into out; 0 when there is none. */
static int key_comp(const char *key, int d, char *out)
{
    const char *p = key;
    for (int i = 0; i < d; i++) {
        p = strchr(p, '.');
        if (!p)
            return 0;
        p++;
    }
    size_t n = strcspn(p, ".");
    if (n >= RB_OV_COMP_MAX)
        n = RB_OV_COMP_MAX - 1;
    memcpy(out, p, n);
    out[n] = '\0';
    return 1;
}

static int key_depth(const char *key)
{
    int d = 1;
    for (const char *p = key; *p; p++)
        d += *p == '.';
    return d;
}

/* Keys are lower-case words joined by dots, so they cannot smuggle YAML. */
static int key_ok(const char *key)
{
    if (!key[0] || key_depth(key) > RB_OV_MAX_DEPTH)
        return 0;
    for (const char *p = key; *p; p++) {
        int word = (*p >= 'a' && *p <= 'z') || (*p >= '0' && *p <= '9') || *p == '_';
        if (!word && !(*p == '.' && p != key && p[1] && p[1] != '.'))
            return 0;
    }
    return 1;
}

/* 1 if key starts with the first d components of prefix. */
static int same_prefix(const char *key, const char *prefix, int d)
{
    char a[RB_OV_COMP_MAX], b[RB_OV_COMP_MAX];
    for (int i = 0; i < d; i++) {
        if (!key_comp(key, i, a) || !key_comp(prefix, i, b) || strcmp(a, b) != 0)
            return 0;
    }
    return 1;
}

typedef struct {
    rb_strbuf sb;
    int line;          /* lines written so far */
    int *line_ov;      /* generated line (1-based) -> override index */
    size_t line_cap;
    const rb_case_override *ov;
    size_t n;
    const char *origin_dir; /* absolute, with a trailing '/' */
} rb_ovgen;

static void gen_line_end(rb_ovgen *g, int ov_index)
{
    rb_strbuf_putn(&g->sb, "\n", 1);
    g->line++;
    if ((size_t)g->line >= g->line_cap) {
        int *p = rb_grow(g->line_ov, &g->line_cap, sizeof *p, 32);
        if (!p) {
            g->sb.oom = 1;
            return;
        }
        g->line_ov = p;
    }
    g->line_ov[g->line] = ov_index;
}

static int is_path_key(const char *key)
{
    size_t n = strlen(key);
    return n >= 4 && strcmp(key + n - 4, "file") == 0;
}

/* Emit the mapping under the first d components of overrides[first].key,
 * taking, in input order, every override with that prefix. */
static void gen_map(rb_ovgen *g, size_t first, int d, char *done)
{
    char comp[RB_OV_COMP_MAX];
    for (size_t i = first; i < g->n; i++) {
        const char *key = g->ov[i].key;
        if (done[i] || !same_prefix(key, g->ov[first].key, d))
            continue;
        key_comp(key, d, comp);
        for (int k = 0; k < d; k++)
            rb_strbuf_puts(&g->sb, "  ");
        rb_strbuf_puts(&g->sb, comp);
        rb_strbuf_puts(&g->sb, ":");
        if (key_depth(key) == d + 1) {
            const char *v = g->ov[i].value;
            rb_strbuf_puts(&g->sb, " ");
            if (is_path_key(key) && v[0] && v[0] != '/'
                && strncmp(v, RB_SHIPPED_PREFIX, strlen(RB_SHIPPED_PREFIX)) != 0) {
                char *abs = malloc(strlen(g->origin_dir) + strlen(v) + 1);
                if (!abs) {
                    g->sb.oom = 1;
                    return;
                }
                strcpy(abs, g->origin_dir);
                strcat(abs, v);
                sb_quoted(&g->sb, abs);
                free(abs);
            } else {
                sb_quoted(&g->sb, v);
            }
            done[i] = 1;
            gen_line_end(g, (int)i);
            continue;
        }
        /* a leaf and a mapping of the same name come out as a duplicate
         * key, which the loader reports at the second */
        gen_line_end(g, (int)i);
        gen_map(g, i, d + 1, done);
    }
}

/* "/cwd/" (with the slash), or NULL. */
static char *cwd_prefix(void)
{
    size_t cap = 256;
    for (;;) {
        char *b = malloc(cap + 1);
        if (!b)
            return NULL;
        if (getcwd(b, cap)) {
            size_t n = strlen(b);
            if (n == 0 || b[n - 1] != '/')
                strcat(b, "/");
            return b;
        }
        free(b);
        if (errno != ERANGE || cap > 65536)
            return NULL;
        cap *= 2;
    }
}

/* prefix + path, unless path is absolute. */
static char *absolute(const char *prefix, const char *path, size_t path_len)
{
    size_t pl = path[0] == '/' ? 0 : strlen(prefix);
    char *p = malloc(pl + path_len + 1);
    if (!p)
        return NULL;
    memcpy(p, prefix, pl);
    memcpy(p + pl, path, path_len);
    p[pl + path_len] = '\0';
    return p;
}

static void strip_prefix(char *s, const char *prefix)
{
    size_t n = strlen(prefix);
    if (s && strncmp(s, prefix, n) == 0)
        memmove(s, s + n, strlen(s + n) + 1);
}

static char *dup_str(const char *s)
{
    size_t n = strlen(s) + 1;
    char *p = malloc(n);
    if (p)
        memcpy(p, s, n);
    return p;
}

static rb_status push_diag(rb_diag_list *l, const char *file, int line, int col,
                           const char *key, const char *msg)
{
    rb_diag *d = rb_diag_list_add(l);
    if (!d)
        return RB_ERR_NOMEM;
    rb_diag_set_file(d, "%s", file);
    d->line = line;
    d->col = col;
    rb_diag_set_key(d, "%s", key);
    rb_diag_set_msg(d, "%s", msg);
    return RB_ERR_INVALID;
}

/* Every occurrence of what in msg (of size n) replaced by with. */
static void replace_all(char *msg, size_t n, const char *what, const char *with)
{
    char *p = msg;
    size_t wl = strlen(what), rl = strlen(with);
    while (wl && (p = strstr(p, what)) != NULL) {
        char rest[sizeof ((rb_diag *)0)->msg];
        snprintf(rest, sizeof rest, "%s", p + wl);
        snprintf(p, n - (size_t)(p - msg), "%s%s", with, rest);
        if ((size_t)(p - msg) + rl >= n)
            break;
        p += rl;
    }
}

/* The override that sets key, or -1. */
static int override_of(const rb_ovgen *g, const char *key)
{
    for (size_t k = 0; k < g->n; k++)
        if (strcmp(g->ov[k].key, key) == 0)
            return (int)k;
    return -1;
}

/* Point diagnostics of the generated document at the overrides' origin.
 * An error of the row in another file (a value of the base that the
 * row's values make wrong, a record the row names) is the row's too: it
 * is reported at the row's cell for its key, else at the row's base cell,
 * and says where the value it is about was written. */
static void map_diags(rb_diag_list *l, size_t first, const char *tmp,
                      const rb_ovgen *g, const char *origin, int row_line,
                      int row_col, const char *cwd)
{
    for (size_t i = first; i < l->n; i++) {
        rb_diag *d = &l->items[i];
        if (strcmp(d->file, tmp) == 0) {
            int k = d->line >= 1 && d->line <= g->line ? g->line_ov[d->line] : -1;
            rb_diag_set_file(d, "%s", origin);
            d->line = k >= 0 ? g->ov[k].line : row_line;
            d->col = k >= 0 ? g->ov[k].col : row_col;
            /* the generated `extends:` is the row's base: say so */
            if (k < 0 && strcmp(d->key, "extends") == 0)
                rb_diag_set_key(d, "base");
        } else {
            char at[sizeof d->file + 40];
            int k = override_of(g, d->key);
            strip_prefix(d->file, cwd);
            if (d->file[0] && d->line > 0)
                snprintf(at, sizeof at, " (the value at %s:%d:%d)", d->file, d->line,
                         d->col);
            else
                snprintf(at, sizeof at, " (in %s)", d->file);
            if (d->file[0] && strlen(d->msg) + strlen(at) < sizeof d->msg)
                rb_diag_set_msg(d, "%s%s", d->msg, at);
            rb_diag_set_file(d, "%s", origin);
            d->line = k >= 0 ? g->ov[k].line : row_line;
            d->col = k >= 0 ? g->ov[k].col : row_col;
        }
        /* messages quoting the generated document: name the origin */
        replace_all(d->msg, sizeof d->msg, tmp, origin);
        replace_all(d->msg, sizeof d->msg, cwd, "");
    }
}

static rb_status generate(rb_ovgen *g, const char *base_abs, const char *name,
                          char *done)
{
    rb_strbuf_puts(&g->sb, "extends: ");
    sb_quoted(&g->sb, base_abs);
    gen_line_end(g, -1);
    if (name) {
        rb_strbuf_puts(&g->sb, "name: ");
        sb_quoted(&g->sb, name);
        gen_line_end(g, -1);
    }
    for (size_t i = 0; i < g->n && !g->sb.oom; i++)
        if (!done[i])
            gen_map(g, i, 0, done);
    return g->sb.oom ? RB_ERR_NOMEM : RB_OK;
}

rb_status rb_case_load_overrides(const char *base_path, const char *origin,
                                 const char *name, const rb_case_override *ov,
                                 size_t n, struct rb_record_cache *cache,
                                 const struct rb_sandbox *sandbox, rb_case *out,
                                 rb_diag_list *diags)
{
    return rb_case_load_overrides_at(base_path, n ? ov[0].line : 0, 1, origin, name, ov,
                                     n, cache, sandbox, out, diags);
}

rb_status rb_case_load_overrides_at(const char *base_path, int row_line, int row_col,
                                    const char *origin, const char *name,
                                    const rb_case_override *ov, size_t n,
                                    struct rb_record_cache *cache,
                                    const struct rb_sandbox *sandbox, rb_case *out,
                                    rb_diag_list *diags)
{
    rb_ovgen g;
    char doc[600];
    rb_status st = RB_OK;
    if (row_col < 1)
        row_col = 1;
    memset(out, 0, sizeof *out);
    memset(&g, 0, sizeof g);
    for (size_t i = 0; i < n; i++) {
        if (!key_ok(ov[i].key) || !strcmp(ov[i].key, "extends")
            || !strcmp(ov[i].key, "name")) {
            char msg[200];
            snprintf(msg, sizeof msg, "'%.100s' cannot be overridden (expected a "
                     "dotted case key such as 'equipment.mass')", ov[i].key);
            st = push_diag(diags, origin, ov[i].line, ov[i].col, ov[i].key, msg);
        }
    }
    if (st != RB_OK)
        return st;
    char *cwd = cwd_prefix();
    const char *slash = strrchr(origin, '/');
    char *odir = cwd ? absolute(cwd, origin, slash ? (size_t)(slash - origin + 1) : 0)
                     : NULL;
    char *base_abs = cwd ? absolute(cwd, base_path, strlen(base_path)) : NULL;
    char *done = calloc(n ? n : 1, 1);
    if (!cwd || !odir || !base_abs || !done) {
        st = cwd ? RB_ERR_NOMEM : RB_ERR_IO;
        if (st == RB_ERR_IO)
            push_diag(diags, origin, row_line, row_col, "base",
                      "cannot find the working directory");
        goto done;
    }
    g.ov = ov;
    g.n = n;
    g.origin_dir = odir;
    st = generate(&g, base_abs, name, done);
    if (st != RB_OK)
        goto done;
    /* the document's name in diagnostics until they are mapped to the row */
    snprintf(doc, sizeof doc, "%.500s (row at line %d)", origin, row_line);
    size_t first = diags->n;
    st = rb_case_load_text(doc, g.sb.p, g.sb.n, cache, sandbox, out, diags);
    map_diags(diags, first, doc, &g, origin, row_line, row_col, cwd);
    if (st == RB_OK) {
        char *p = dup_str(origin);
        if (!p) {
            rb_case_free(out);
            st = RB_ERR_NOMEM;
            goto done;
        }
        free(out->path);
        out->path = p;
        for (size_t i = 0; i < out->n_motions; i++)
            strip_prefix(out->motions[i].source, cwd);
    }
done:
    free(g.sb.p);
    free(g.line_ov);
    free(done);
    free(base_abs);
    free(odir);
    free(cwd);
    return st;
}
