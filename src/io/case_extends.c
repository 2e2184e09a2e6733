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
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "case_internal.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

/* Keys of which a case gives at most one; the case's choice hides the
 * base's alternative. */
static const char *const rb_alternatives[][2] = {
    {"height", "cm_height"}, {"diameter", "area"},
    {"lever_arm", "edge_distance"}, {"gap", "gap_ratio"},
    {"motion", "motions"},
};

static const char *rb_alternative_of(const char *key)
{
    size_t n = sizeof rb_alternatives / sizeof rb_alternatives[0];
    for (size_t i = 0; i < n; i++) {
        if (strcmp(key, rb_alternatives[i][0]) == 0)
            return rb_alternatives[i][1];
        if (strcmp(key, rb_alternatives[i][1]) == 0)
            return rb_alternatives[i][0];
    }
    return NULL;
}

/* 1 if both maps have a scalar `type:` and they differ. */
static int rb_types_differ(const rb_ynode *a, const rb_ynode *b)
{
    const rb_yentry *ta = rb_ymap_find(a, "type"), *tb = rb_ymap_find(b, "type");
    return ta && tb && ta->value->kind == RB_YNODE_SCALAR
        && tb->value->kind == RB_YNODE_SCALAR
        && strcmp(ta->value->text, tb->value->text) != 0;
}

static int rb_ymap_append(rb_cctx *c, rb_ynode *map, rb_yentry *e)
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
static void rb_ymerge(rb_cctx *c, rb_ynode *dst, rb_ynode *base)
{
    for (size_t i = 0; i < base->n && !c->nomem; i++) {
        rb_yentry *e = &base->entries[i];
        if (strcmp(e->key, "extends") == 0)
            continue;
        rb_yentry *d = rb_ymap_find(dst, e->key);
        if (d) {
            if (d->value->kind == RB_YNODE_MAP && e->value->kind == RB_YNODE_MAP
                && !rb_types_differ(d->value, e->value))
                rb_ymerge(c, d->value, e->value);
            continue;
        }
        const char *alt = rb_alternative_of(e->key);
        if (alt && rb_ymap_find(dst, alt))
            continue;
        rb_ymap_append(c, dst, e);
    }
}

/* dir of including + "/" + rel, unless rel is absolute or including has no
 * directory part. */
static char *rb_extends_path(const char *including, const char *rel)
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
static void rb_chain_str(const rb_chain *chain, size_t first, const char *last,
                         char *buf, size_t size)
{
    size_t n = 0;
    buf[0] = '\0';
    for (size_t i = first; i < chain->n && n < size; i++)
        n += (size_t)snprintf(buf + n, size - n, "%s -> ", chain->names[i]);
    if (n < size)
        snprintf(buf + n, size - n, "%s", last);
}

static char *rb_canonical(const char *path)
{
    char buf[PATH_MAX];
    const char *src = realpath(path, buf) ? buf : path;
    size_t len = strlen(src) + 1;
    char *p = malloc(len);
    if (p)
        memcpy(p, src, len);
    return p;
}

static rb_status rb_read_chain(rb_cctx *c, const char *file, const rb_ynode *where,
                               rb_chain *chain, rb_ynode **root);

/* Follow root's `extends:` (if any) and merge the base under root. */
static void rb_follow_extends(rb_cctx *c, const char *file, rb_ynode *root,
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
    char *path = rb_extends_path(file, v->text);
    if (!path) {
        c->nomem = 1;
        return;
    }
    rb_ynode *base = NULL;
    /* Without its base a case is missing so much that listing each missing
     * key would bury the one real problem: stop here. */
    if (rb_read_chain(c, path, v, chain, &base) == RB_OK && base)
        rb_ymerge(c, root, base);
    else
        c->fatal = 1;
    rb_ynode_free(base);
    free(path);
}

static rb_status rb_read_chain(rb_cctx *c, const char *file, const rb_ynode *where,
                               rb_chain *chain, rb_ynode **root)
{
    *root = NULL;
    char *id = rb_canonical(file);
    if (!id) {
        c->nomem = 1;
        return RB_ERR_NOMEM;
    }
    for (size_t i = 0; i < chain->n; i++) {
        if (strcmp(chain->ids[i], id) == 0) {
            char cycle[400];
            rb_chain_str(chain, i, file, cycle, sizeof cycle);
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
    chain->names[chain->n] = file;
    chain->ids[chain->n++] = id;
    rb_status st = rb_yaml_read_tree(c, file, where, "extends", root);
    if (st == RB_OK)
        rb_follow_extends(c, file, *root, chain);
    free(chain->ids[--chain->n]);
    return st;
}

rb_status rb_case_read_merged(rb_cctx *c, const char *file, rb_ynode **root)
{
    rb_chain chain;
    memset(&chain, 0, sizeof chain);
    rb_status st = rb_read_chain(c, file, NULL, &chain, root);
    if (st == RB_OK && c->fatal)
        st = RB_ERR_PARSE;
    return st;
}
