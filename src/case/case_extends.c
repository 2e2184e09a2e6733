/* `extends:` - case files built on a shared base file.
 *
 * A case may name one base file (path relative to the including file). The
 * base is read (and may itself extend another, up to 8 files in a chain,
 * without cycles) and deep-merged under the case: keys the case gives win,
 * mappings present in both are merged key by key, anything else (scalars,
 * sequences) is replaced whole. Two refinements keep merges meaningful:
 * keys that are alternatives of each other (height/cm_height, gap/gap_ratio,
 * ...) replace each other, and a mapping whose `type:` differs from the
 * base's replaces it instead of merging into it. Nodes keep the file they
 * were written in, so errors in inherited values point into the base. */
#define _POSIX_C_SOURCE 200809L
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "case_internal.h"
#include "rockbolt/sandbox.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

/* Keys of which a case gives at most one; the case's choice hides the
 * base's alternative. */
static const char *const key_alternatives[][2] = {
    {"height", "cm_height"}, {"diameter", "area"},
    {"lever_arm", "edge_distance"}, {"gap", "gap_ratio"},
    {"motion", "motions"},
};

static const char *alternative_of(const char *key)
{
    size_t n = sizeof key_alternatives / sizeof key_alternatives[0];
    for (size_t i = 0; i < n; i++) {
        if (strcmp(key, key_alternatives[i][0]) == 0)
            return key_alternatives[i][1];
        if (strcmp(key, key_alternatives[i][1]) == 0)
            return key_alternatives[i][0];
    }
    return NULL;
}

/* 1 if both maps have a scalar `type:` and they differ. */
static int types_differ(const rb_ynode *a, const rb_ynode *b)
{
    const rb_yentry *ta = rb_ymap_find(a, "type"), *tb = rb_ymap_find(b, "type");
    return ta && tb && ta->value->kind == RB_YNODE_SCALAR
        && tb->value->kind == RB_YNODE_SCALAR
        && strcmp(ta->value->text, tb->value->text) != 0;
}

static int ymap_append(rb_cctx *c, rb_ynode *map, rb_yentry *e)
{
    if (map->n == map->cap) {
        size_t cap = map->cap ? 2 * map->cap : 8;
        rb_yentry *p = realloc(map->entries, cap * sizeof *p);
        if (!p) {
            c->nomem = 1;
            return 0;
        }
        map->entries = p;
        map->cap = cap;
    }
    map->entries[map->n++] = *e;
    e->key = NULL;     /* moved: the base no longer owns it */
    e->value = NULL;
    return 1;
}

/* Merge base under dst (both mappings); moves nodes out of base. */
static void ymerge(rb_cctx *c, rb_ynode *dst, rb_ynode *base)
{
    for (size_t i = 0; i < base->n && !c->nomem; i++) {
        rb_yentry *e = &base->entries[i];
        if (strcmp(e->key, "extends") == 0)
            continue;
        rb_yentry *d = rb_ymap_find(dst, e->key);
        if (d) {
            if (d->value->kind == RB_YNODE_MAP && e->value->kind == RB_YNODE_MAP
                && !types_differ(d->value, e->value))
                ymerge(c, d->value, e->value);
            continue;
        }
        const char *alt = alternative_of(e->key);
        if (alt && rb_ymap_find(dst, alt))
            continue;
        ymap_append(c, dst, e);
    }
}

/* Values a base gives for its own bolt size, which do not hold for another:
 * under anchorage (A_se, A_brg, a pitch) and under design.code (A_se). */
static const char *const size_bound_keys[] = {
    "tensile_area", "head_bearing_area", "thread_pitch", "threads_per_inch", NULL};

/* The gross area a size entry (diameter or area) gives, or 0. */
static double size_area(const rb_yentry *e)
{
    rb_quantity q;
    char msg[200];
    int dia = strcmp(e->key, "diameter") == 0;
    if (e->value->kind != RB_YNODE_SCALAR
        || rb_unit_parse(e->value->text, dia ? RB_DIM_LENGTH : RB_DIM_AREA, &q, msg,
                         sizeof msg) != RB_OK || !(q.value > 0))
        return 0;
    return dia ? 0.78539816339744831 * q.value * q.value : q.value;
}

static rb_yentry *size_entry(const rb_ynode *an)
{
    rb_yentry *e = an && an->kind == RB_YNODE_MAP ? rb_ymap_find(an, "diameter") : NULL;
    return e ? e : an && an->kind == RB_YNODE_MAP ? rb_ymap_find(an, "area") : NULL;
}

static rb_ynode *submap(const rb_ynode *m, const char *key)
{
    rb_yentry *e = m && m->kind == RB_YNODE_MAP ? rb_ymap_find(m, key) : NULL;
    return e && e->value->kind == RB_YNODE_MAP ? e->value : NULL;
}

static void drop_entry(rb_ynode *map, rb_yentry *e)
{
    size_t at = (size_t)(e - map->entries);
    free(e->key);
    rb_ynode_free(e->value);
    memmove(&map->entries[at], &map->entries[at + 1], (map->n - at - 1) * sizeof *e);
    map->n--;
}

/* One value of bmap (the base's section path) bound to the base's bolt
 * size, which the case (its section cmap) does not give while it changes
 * the size at sz: an error at sz, and the base's value dropped, so that
 * it is not also judged against the new size. */
static void size_conflict(rb_cctx *c, const rb_yentry *sz, const char *base_size,
                          rb_ynode *cmap, rb_ynode *bmap, const char *path, const char *key,
                          int row)
{
    rb_yentry *b = bmap ? rb_ymap_find(bmap, key) : NULL;
    if (!b || (cmap && rb_ymap_find(cmap, key)))
        return;
    const char *who = row ? "row" : "case";
    rb_cctx_error(c, sz->value, sz->key[0] == 'd' ? "anchorage.diameter" : "anchorage.area",
                  "changes the bolt's size from the base's %s, for which the base gives "
                  "%s.%s '%s' (%s:%d:%d): give this %s's %s.%s too, or take it out of the "
                  "base so that each size gets its own from the thread and head standards",
                  base_size, path, key, b->value->kind == RB_YNODE_SCALAR ? b->value->text
                                                                         : "...",
                  b->value->file, b->line, b->col, who, path, key);
    drop_entry(bmap, b);
}

/* A case that changes the bolt's size (diameter or area) keeps nothing the
 * base gives for its own size (docs/batch.md, "Values that follow the
 * size"): a value the base derives from its size is derived anew from the
 * case's, but one the base writes (a 1/2 in bolt's A_se of 0.142 in^2)
 * would silently hold for a 3/4 in bolt, whose A_se is 0.334 in^2, or fail
 * against a 3/8 in bolt's area pointing at the base; it is refused at the
 * new size. */
static void check_size_change(rb_cctx *c, rb_ynode *root, rb_ynode *base, int row)
{
    rb_ynode *ca = submap(root, "anchorage"), *ba = submap(base, "anchorage");
    rb_yentry *cs = size_entry(ca), *bs = size_entry(ba);
    if (!cs || !bs)
        return;
    double a = size_area(cs), b = size_area(bs);
    if (!(a > 0 && b > 0) || fabs(a - b) <= 1e-9 * b)
        return;
    char base_size[200];
    snprintf(base_size, sizeof base_size, "%s %.100s", bs->key,
             bs->value->kind == RB_YNODE_SCALAR ? bs->value->text : "");
    for (size_t k = 0; size_bound_keys[k]; k++)
        size_conflict(c, cs, base_size, ca, ba, "anchorage", size_bound_keys[k], row);
    size_conflict(c, cs, base_size, submap(submap(root, "design"), "code"),
                  submap(submap(base, "design"), "code"), "design.code", "ase", row);
}

/* A deep copy of n (positions kept); NULL when memory runs out. */
static rb_ynode *ynode_copy(rb_cctx *c, const rb_ynode *n)
{
    rb_ynode *d = calloc(1, sizeof *d);
    if (!d) {
        c->nomem = 1;
        return NULL;
    }
    *d = *n;
    d->text = NULL;
    d->entries = NULL;
    d->items = NULL;
    d->n = d->cap = 0;
    if (n->text && !(d->text = strdup(n->text)))
        goto oom;
    if (n->kind == RB_YNODE_MAP && n->n) {
        if (!(d->entries = calloc(n->n, sizeof *d->entries)))
            goto oom;
        d->cap = n->n;
        for (; d->n < n->n; d->n++) {
            rb_yentry *e = &d->entries[d->n];
            *e = n->entries[d->n];
            e->key = strdup(e->key);
            e->value = e->key ? ynode_copy(c, n->entries[d->n].value) : NULL;
            if (!e->value) {
                free(e->key);
                goto oom;
            }
        }
    } else if (n->kind == RB_YNODE_SEQ && n->n) {
        if (!(d->items = calloc(n->n, sizeof *d->items)))
            goto oom;
        d->cap = n->n;
        for (; d->n < n->n; d->n++)
            if (!(d->items[d->n] = ynode_copy(c, n->items[d->n])))
                goto oom;
    }
    return d;
oom:
    c->nomem = 1;
    rb_ynode_free(d);
    return NULL;
}

static const char *motion_type(const rb_ynode *m)
{
    const rb_yentry *t = rb_ymap_find(m, "type");
    return t && t->value->kind == RB_YNODE_SCALAR ? t->value->text : "";
}

/* Whether every override key of a row's motion can apply to motion m of a
 * base's list (item k, 1-based); an error at the override if not. The
 * motion column (a `file`) picks one record, so it needs a list of one. */
static int row_motion_fits(rb_cctx *c, const rb_ynode *row, const rb_ynode *m, size_t k,
                              size_t n)
{
    const char *type = motion_type(m);
    int record = strcmp(type, "record") == 0;
    int ok = 1;
    for (size_t i = 0; i < row->n; i++) {
        const rb_yentry *e = &row->entries[i];
        if (strcmp(e->key, "file") == 0 && n != 1) {
            rb_cctx_error(c, e->value, "motion", "the base has %zu motions (a motions: "
                          "list), and a motion column cannot say which of them to "
                          "replace: give the row a base with one motion", n);
            return 0;
        }
        if (rb_ymap_find(row, "file"))
            continue;   /* the row's own record: it replaces m whole if m is not one */
        if ((strcmp(e->key, "peak") == 0 || strcmp(e->key, "building") == 0) && !record) {
            rb_cctx_error(c, e->value, e->key, "applies to record motions, but motions[%zu] "
                          "of the base is a %s motion", k, type[0] ? type : "untyped");
            ok = 0;
        }
        if (strcmp(e->key, "amplitude") == 0 && record) {
            rb_cctx_error(c, e->value, e->key, "applies to harmonic and pulse motions, but "
                          "motions[%zu] of the base is a record", k);
            ok = 0;
        }
    }
    return ok;
}

/* A row's `motion:` over a base's `motions:` list: the row's values apply
 * to each motion of the list, which keeps everything else (building,
 * window, polarity, run time, the other motions). Left alone, `motion`
 * would replace the whole list as its alternative. */
static void distribute_row_motion(rb_cctx *c, rb_ynode *root, rb_ynode *base)
{
    size_t at;
    rb_yentry *me = rb_ymap_find(root, "motion"), *se = rb_ymap_find(base, "motions");
    if (!me || !se || me->value->kind != RB_YNODE_MAP || se->value->kind != RB_YNODE_SEQ)
        return;
    rb_ynode *row = me->value, *list = se->value;
    int ok = 1;
    for (size_t k = 0; k < list->n; k++)
        if (list->items[k]->kind == RB_YNODE_MAP)
            ok &= row_motion_fits(c, row, list->items[k], k + 1, list->n);
    if (!ok) {
        c->fatal = 1;
        return;
    }
    for (size_t k = 0; k < list->n && !c->nomem; k++) {
        if (list->items[k]->kind != RB_YNODE_MAP)
            continue;
        rb_ynode *merged = ynode_copy(c, row);
        if (!merged)
            return;
        if (!types_differ(merged, list->items[k]))
            ymerge(c, merged, list->items[k]);
        rb_ynode_free(list->items[k]);
        list->items[k] = merged;
    }
    /* the row's mapping is spent: take it out so the list is inherited */
    at = (size_t)(me - root->entries);
    free(me->key);
    rb_ynode_free(me->value);
    memmove(&root->entries[at], &root->entries[at + 1],
            (root->n - at - 1) * sizeof *root->entries);
    root->n--;
}

/* dir of including + "/" + rel, unless rel is absolute or including has no
 * directory part. */
static char *extends_path(const char *including, const char *rel)
{
    const char *slash = strrchr(including, '/');
    size_t dlen = (rel[0] == '/' || !slash) ? 0 : (size_t)(slash - including + 1);
    size_t rlen = strlen(rel);
    char *p = malloc(dlen + rlen + 1);
    if (!p)
        return NULL;
    memcpy(p, including, dlen);
    memcpy(p + dlen, rel, rlen + 1);
    return p;
}

typedef struct {
    char *ids[RB_CASE_MAX_EXTENDS + 1];  /* canonical paths, owned */
    const char *names[RB_CASE_MAX_EXTENDS + 1]; /* as in messages, borrowed */
    size_t n;
} rb_chain;

/* "a.yaml -> b.yaml -> a.yaml" from chain entry first on, then last. */
static void chain_str(const rb_chain *chain, size_t first, const char *last,
                         char *buf, size_t size)
{
    size_t n = 0;
    buf[0] = '\0';
    for (size_t i = first; i < chain->n && n < size; i++)
        n += (size_t)snprintf(buf + n, size - n, "%s -> ", chain->names[i]);
    if (n < size)
        snprintf(buf + n, size - n, "%s", last);
}

static char *canonical_key(const char *path)
{
    char buf[PATH_MAX];
    const char *src = realpath(path, buf) ? buf : path;
    size_t len = strlen(src) + 1;
    char *p = malloc(len);
    if (p)
        memcpy(p, src, len);
    return p;
}

static rb_status read_chain(rb_cctx *c, const char *file, const rb_ynode *where,
                               rb_chain *chain, rb_ynode **root);

/* A YAML file is taken for a case only if at least one of its top-level
 * keys is a case key (the list of rb_top_keys in case_schema.c). Any other
 * YAML file (a CI configuration, a secret) gets one diagnostic that quotes
 * none of its keys or values, instead of one "unknown key 'password'" per
 * key in artefacts that may be published. */
static int plausible_case(const rb_ynode *root)
{
    if (!root || root->kind != RB_YNODE_MAP || root->n == 0)
        return 1;   /* the schema says what is wrong, quoting nothing */
    for (size_t i = 0; i < root->n; i++)
        if (rb_case_top_key(root->entries[i].key))
            return 1;
    return 0;
}

/* Follow root's `extends:` (if any) and merge the base under root. */
static void follow_extends(rb_cctx *c, const char *file, rb_ynode *root,
                              rb_chain *chain)
{
    rb_yentry *e = rb_ymap_find(root, "extends");
    if (!e)
        return;
    e->used = 1;
    const rb_ynode *v = e->value;
    if (v->kind != RB_YNODE_SCALAR || rb_ynode_is_null(v) || !v->text[0]) {
        rb_cctx_error(c, v, "extends", "expected the path of a base case file, "
                      "found %s", rb_ynode_kind_str(v));
        c->fatal = 1;
        return;
    }
    char *path = extends_path(file, v->text);
    if (!path) {
        c->nomem = 1;
        return;
    }
    rb_ynode *base = NULL;
    /* Without its base a case is missing so much that listing each missing
     * key would bury the one real problem: stop here. */
    if (read_chain(c, path, v, chain, &base) == RB_OK && base) {
        if (c->overrides && chain->n == 1)
            distribute_row_motion(c, root, base);
        if (!c->fatal) {
            check_size_change(c, root, base, c->overrides && chain->n == 1);
            ymerge(c, root, base);
        }
    }
    else
        c->fatal = 1;
    rb_ynode_free(base);
    free(path);
}

static rb_status read_chain(rb_cctx *c, const char *file, const rb_ynode *where,
                               rb_chain *chain, rb_ynode **root)
{
    *root = NULL;
    char *id = canonical_key(file);
    if (!id) {
        c->nomem = 1;
        return RB_ERR_NOMEM;
    }
    for (size_t i = 0; i < chain->n; i++) {
        if (strcmp(chain->ids[i], id) == 0) {
            char cycle[400];
            chain_str(chain, i, file, cycle, sizeof cycle);
            rb_cctx_error(c, where, "extends", "extends cycle: %s", cycle);
            free(id);
            return RB_ERR_INVALID;
        }
    }
    if (chain->n == RB_CASE_MAX_EXTENDS) {
        rb_cctx_error(c, where, "extends", "more than %d files in the extends "
                      "chain", RB_CASE_MAX_EXTENDS);
        free(id);
        return RB_ERR_LIMIT;
    }
    char why[600];
    if (where && !rb_sandbox_allows(c->sandbox, file, why, sizeof why)) {
        rb_cctx_error(c, where, "extends", "cannot use '%s': it lies outside the "
                      "sandbox '%s' (%s)", file, rb_sandbox_dir(c->sandbox), why);
        free(id);
        return RB_ERR_IO;
    }
    chain->names[chain->n] = file;
    chain->ids[chain->n++] = id;
    size_t diags_before = c->diags->n, errors_before = c->n_errors,
           dropped_before = c->n_dropped;
    rb_status st = rb_yaml_read_tree(c, file, where, "extends", root);
    if (st == RB_OK && !plausible_case(*root)) {
        /* what the walk said about a file that is no case (a duplicate
         * key, say) would quote its text: only the verdict below stays */
        c->diags->n = diags_before;
        c->n_errors = errors_before;
        c->n_dropped = dropped_before;
        if (where)
            rb_cctx_error(c, where, "extends", "'%s' is not a rockbolt case: none of "
                          "its top-level keys is a case key (name, equipment, "
                          "anchorage, motion, ...)", file);
        else
            rb_cctx_error_at(c, RB_ERR_PARSE, file, (*root)->line, (*root)->col,
                             "case", "not a rockbolt case: none of the file's "
                             "top-level keys is a case key (name, equipment, "
                             "anchorage, motion, ...)");
        rb_ynode_free(*root);
        *root = NULL;
        c->fatal = 1;
        st = RB_ERR_PARSE;
    }
    if (st == RB_OK)
        follow_extends(c, file, *root, chain);
    free(chain->ids[--chain->n]);
    return st;
}

rb_status rb_case_read_merged_text(rb_cctx *c, const char *name, unsigned char *text,
                                   size_t len, rb_ynode **root)
{
    rb_chain chain;
    memset(&chain, 0, sizeof chain);
    rb_status st = rb_yaml_parse_text(c, name, text, len, root);
    char *id = st == RB_OK ? strdup(name) : NULL;
    if (st == RB_OK && !id) {
        c->nomem = 1;
        st = RB_ERR_NOMEM;
    }
    if (st == RB_OK) {
        chain.names[0] = name;
        chain.ids[0] = id;
        chain.n = 1;
        follow_extends(c, name, *root, &chain);
        free(id);
    }
    if (st == RB_OK && c->fatal)
        st = RB_ERR_PARSE;
    return st;
}

rb_status rb_case_read_merged(rb_cctx *c, const char *file, rb_ynode **root)
{
    rb_chain chain;
    memset(&chain, 0, sizeof chain);
    rb_status st = read_chain(c, file, NULL, &chain, root);
    if (st == RB_OK && c->fatal)
        st = RB_ERR_PARSE;
    return st;
}
