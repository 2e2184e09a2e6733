/* YAML case files to node trees, with the limits hostile input needs.
 *
 * libyaml's event API is walked once; every scalar is copied before its
 * event is deleted, and every node keeps the file name and the 1-based
 * line/column of its start mark so that later checks can point at the
 * offending value. The case schema needs only mappings, sequences and
 * scalars, so anchors and aliases are refused outright: that removes the
 * alias-expansion ("billion laughs") attack instead of metering it. Nesting
 * depth, scalar size and file size are capped (case_internal.h). Syntax and
 * limit errors stop the walk; duplicate keys are reported and the walk goes
 * on. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include <yaml.h>
#include "case_internal.h"

typedef struct {
    rb_cctx *c;
    yaml_parser_t parser;
    const char *file;                 /* borrowed from c->files */
    const unsigned char *buf;         /* the file's bytes, for offsets */
    size_t len;
    char path[RB_CASE_KEY_MAX];       /* key being parsed, for messages */
    int stop;                         /* a fatal error was reported */
    int case_like;                    /* a case key was met at the top: until
                                         then the file may be of another kind,
                                         and messages quote none of its text */
} rb_ywalk;

static const char *ywalk_key(const rb_ywalk *w)
{
    return w->path[0] && w->case_like ? w->path : "case";
}

static void ywalk_fatal(rb_ywalk *w, rb_status st, int line, int col,
                           const char *msg)
{
    rb_cctx_error_at(w->c, st, w->file, line, col, ywalk_key(w), "%s", msg);
    w->c->fatal = 1;
    w->stop = 1;
}

/* 1-based line and column of a byte offset (for reader errors, which carry
 * an offset but no mark). */
static void ywalk_locate(const rb_ywalk *w, size_t off, int *line, int *col)
{
    *line = 1;
    *col = 1;
    for (size_t i = 0; i < off && i < w->len; i++) {
        if (w->buf[i] == '\n') {
            (*line)++;
            *col = 1;
        } else if ((w->buf[i] & 0xC0) != 0x80) {
            (*col)++;
        }
    }
}

static void ywalk_syntax(rb_ywalk *w)
{
    yaml_parser_t *p = &w->parser;
    char msg[400];
    int line = (int)p->problem_mark.line + 1, col = (int)p->problem_mark.column + 1;
    if (p->error == YAML_MEMORY_ERROR) {
        w->c->nomem = 1;
        ywalk_fatal(w, RB_ERR_NOMEM, 0, 0, "out of memory while parsing");
        return;
    }
    if (p->error == YAML_READER_ERROR) {
        ywalk_locate(w, p->problem_offset, &line, &col);
        snprintf(msg, sizeof msg, "not a readable text file: %s",
                 p->problem ? p->problem : "bad byte");
    } else if (p->context) {
        snprintf(msg, sizeof msg, "YAML syntax error: %s (%s at line %d)",
                 p->problem ? p->problem : "unknown problem", p->context,
                 (int)p->context_mark.line + 1);
    } else {
        snprintf(msg, sizeof msg, "YAML syntax error: %s",
                 p->problem ? p->problem : "unknown problem");
    }
    ywalk_fatal(w, RB_ERR_PARSE, line, col, msg);
}

/* Next event into ev; 0 (after reporting) on a syntax error. */
static int ywalk_next(rb_ywalk *w, yaml_event_t *ev)
{
    if (!yaml_parser_parse(&w->parser, ev)) {
        ywalk_syntax(w);
        return 0;
    }
    return 1;
}

static rb_ynode *ynode_new(rb_ywalk *w, rb_ynode_kind kind, yaml_mark_t m)
{
    if (++w->c->n_nodes > RB_CASE_MAX_NODES) {
        char msg[160];
        snprintf(msg, sizeof msg, "more than %d keys, values and lists in the "
                 "case (the limit)", RB_CASE_MAX_NODES);
        ywalk_fatal(w, RB_ERR_LIMIT, (int)m.line + 1, (int)m.column + 1, msg);
        return NULL;
    }
    rb_ynode *n = calloc(1, sizeof *n);
    if (!n) {
        w->c->nomem = 1;
        ywalk_fatal(w, RB_ERR_NOMEM, 0, 0, "out of memory");
        return NULL;
    }
    n->kind = kind;
    n->file = w->file;
    n->line = (int)m.line + 1;
    n->col = (int)m.column + 1;
    return n;
}

void rb_ynode_free(rb_ynode *n)
{
    if (!n)
        return;
    free(n->text);
    for (size_t i = 0; n->kind == RB_YNODE_MAP && i < n->n; i++) {
        free(n->entries[i].key);
        rb_ynode_free(n->entries[i].value);
    }
    for (size_t i = 0; n->kind == RB_YNODE_SEQ && i < n->n; i++)
        rb_ynode_free(n->items[i]);
    free(n->entries);
    free(n->items);
    free(n);
}

/* Refuse anchors: see the file comment. */
static int ywalk_anchor(rb_ywalk *w, const yaml_char_t *anchor, yaml_mark_t m)
{
    char msg[300];
    if (!anchor)
        return 0;
    /* the anchor's name is not quoted: the file may not be a case at all */
    snprintf(msg, sizeof msg, "YAML anchors ('&') and aliases are not "
             "allowed in case files; use 'extends:' to share settings");
    ywalk_fatal(w, RB_ERR_PARSE, (int)m.line + 1, (int)m.column + 1, msg);
    return 1;
}

static rb_ynode *ywalk_scalar(rb_ywalk *w, yaml_event_t *ev)
{
    char msg[200];
    size_t len = ev->data.scalar.length;
    yaml_mark_t m = ev->start_mark;
    if (ywalk_anchor(w, ev->data.scalar.anchor, m))
        return NULL;
    if (len > RB_CASE_MAX_SCALAR) {
        snprintf(msg, sizeof msg, "value is %zu bytes long; the limit is %d "
                 "bytes per value", len, RB_CASE_MAX_SCALAR);
        ywalk_fatal(w, RB_ERR_LIMIT, (int)m.line + 1, (int)m.column + 1, msg);
        return NULL;
    }
    if (memchr(ev->data.scalar.value, '\0', len)) {
        ywalk_fatal(w, RB_ERR_PARSE, (int)m.line + 1, (int)m.column + 1,
                       "value contains a NUL character");
        return NULL;
    }
    rb_ynode *n = ynode_new(w, RB_YNODE_SCALAR, m);
    if (!n)
        return NULL;
    n->text = malloc(len + 1);
    if (!n->text) {
        free(n);
        w->c->nomem = 1;
        ywalk_fatal(w, RB_ERR_NOMEM, 0, 0, "out of memory");
        return NULL;
    }
    memcpy(n->text, ev->data.scalar.value, len);
    n->text[len] = '\0';
    n->plain = ev->data.scalar.style == YAML_PLAIN_SCALAR_STYLE;
    return n;
}

/* Grow a node's entries or items array to hold one more. */
static int ynode_grow(rb_ywalk *w, rb_ynode *n)
{
    if (n->n < n->cap)
        return 1;
    size_t cap = n->cap ? 2 * n->cap : 8;
    void *p = n->kind == RB_YNODE_MAP
        ? realloc(n->entries, cap * sizeof *n->entries)
        : realloc(n->items, cap * sizeof *n->items);
    if (!p) {
        w->c->nomem = 1;
        ywalk_fatal(w, RB_ERR_NOMEM, 0, 0, "out of memory");
        return 0;
    }
    if (n->kind == RB_YNODE_MAP)
        n->entries = p;
    else
        n->items = p;
    n->cap = cap;
    return 1;
}

static rb_ynode *ywalk_node(rb_ywalk *w, yaml_event_t *ev, int depth);

static int ywalk_seq_items(rb_ywalk *w, rb_ynode *seq, int depth)
{
    size_t base = strlen(w->path);
    for (;;) {
        yaml_event_t ev;
        if (!ywalk_next(w, &ev))
            return 0;
        if (ev.type == YAML_SEQUENCE_END_EVENT) {
            yaml_event_delete(&ev);
            return 1;
        }
        snprintf(w->path + base, sizeof w->path - base, "[%zu]", seq->n + 1);
        rb_ynode *item = ywalk_node(w, &ev, depth + 1);
        w->path[base] = '\0';
        if (!item || !ynode_grow(w, seq)) {
            rb_ynode_free(item);
            return 0;
        }
        seq->items[seq->n++] = item;
    }
}

/* Add key -> value to map, or report a duplicate (and drop the value). */
static int ywalk_add(rb_ywalk *w, rb_ynode *map, rb_ynode *key, rb_ynode *val)
{
    if (map->n == RB_CASE_MAX_KEYS) {
        char msg[160];
        snprintf(msg, sizeof msg, "more than %d keys in one mapping (the limit)",
                 RB_CASE_MAX_KEYS);
        ywalk_fatal(w, RB_ERR_LIMIT, key->line, key->col, msg);
        rb_ynode_free(key);
        rb_ynode_free(val);
        return 0;
    }
    rb_yentry *old = rb_ymap_find(map, key->text);
    if (old && !w->case_like) {
        rb_cctx_error(w->c, key, "case", "duplicate key (first given at line %d)",
                      old->line);
        rb_ynode_free(key);
        rb_ynode_free(val);
        return 1;
    }
    if (old) {
        rb_cctx_error(w->c, key, w->path, "duplicate key '%s' (first given at "
                      "line %d)", key->text, old->line);
        rb_ynode_free(key);
        rb_ynode_free(val);
        return 1;
    }
    if (!ynode_grow(w, map)) {
        rb_ynode_free(key);
        rb_ynode_free(val);
        return 0;
    }
    rb_yentry *e = &map->entries[map->n++];
    e->key = key->text;
    e->line = key->line;
    e->col = key->col;
    e->value = val;
    e->used = 0;
    key->text = NULL;
    rb_ynode_free(key);
    return 1;
}

static int ywalk_map_entries(rb_ywalk *w, rb_ynode *map, int depth)
{
    size_t base = strlen(w->path);
    for (;;) {
        yaml_event_t ev;
        if (!ywalk_next(w, &ev))
            return 0;
        if (ev.type == YAML_MAPPING_END_EVENT) {
            yaml_event_delete(&ev);
            return 1;
        }
        if (ev.type != YAML_SCALAR_EVENT) {
            yaml_mark_t m = ev.start_mark;
            yaml_event_delete(&ev);
            ywalk_fatal(w, RB_ERR_PARSE, (int)m.line + 1, (int)m.column + 1,
                           "a key must be a plain word, not a mapping, "
                           "sequence or alias");
            return 0;
        }
        rb_ynode *key = ywalk_scalar(w, &ev);
        yaml_event_delete(&ev);
        if (!key)
            return 0;
        /* An empty key ("? " or '""') has no dotted name to report
         * anything against, and no key of the schema is empty. */
        if (!key->text[0]) {
            ywalk_fatal(w, RB_ERR_PARSE, key->line, key->col, "a key must be "
                           "a plain word, found an empty key");
            rb_ynode_free(key);
            return 0;
        }
        if (!base && rb_case_top_key(key->text))
            w->case_like = 1;
        snprintf(w->path + base, sizeof w->path - base, "%s%s",
                 base ? "." : "", key->text);
        rb_ynode *val = NULL;
        if (ywalk_next(w, &ev))
            val = ywalk_node(w, &ev, depth + 1);
        if (!val) {
            rb_ynode_free(key);
            return 0;
        }
        int ok = ywalk_add(w, map, key, val);
        w->path[base] = '\0';
        if (!ok)
            return 0;
    }
}

/* Build the node that starts with ev, consuming ev and everything up to the
 * node's end. Returns NULL after a fatal error. */
static rb_ynode *ywalk_node(rb_ywalk *w, yaml_event_t *ev, int depth)
{
    rb_ynode *n = NULL;
    yaml_mark_t m = ev->start_mark;
    char msg[120];
    if (ev->type == YAML_SCALAR_EVENT) {
        n = ywalk_scalar(w, ev);
        yaml_event_delete(ev);
        return n;
    }
    if (ev->type == YAML_ALIAS_EVENT) {
        yaml_event_delete(ev);
        ywalk_fatal(w, RB_ERR_PARSE, (int)m.line + 1, (int)m.column + 1,
                       "YAML aliases ('*name') are not allowed in case files; "
                       "use 'extends:' to share settings");
        return NULL;
    }
    int is_map = ev->type == YAML_MAPPING_START_EVENT;
    const yaml_char_t *anchor = is_map ? ev->data.mapping_start.anchor
                                       : ev->data.sequence_start.anchor;
    int bad = ywalk_anchor(w, anchor, m);
    yaml_event_delete(ev);
    if (bad)
        return NULL;
    if (depth > RB_CASE_MAX_DEPTH) {
        snprintf(msg, sizeof msg, "nesting is deeper than %d levels",
                 RB_CASE_MAX_DEPTH);
        ywalk_fatal(w, RB_ERR_LIMIT, (int)m.line + 1, (int)m.column + 1, msg);
        return NULL;
    }
    n = ynode_new(w, is_map ? RB_YNODE_MAP : RB_YNODE_SEQ, m);
    if (!n)
        return NULL;
    int ok = is_map ? ywalk_map_entries(w, n, depth)
                    : ywalk_seq_items(w, n, depth);
    if (!ok) {
        rb_ynode_free(n);
        return NULL;
    }
    return n;
}

/* Stream start, document start, the root node, document end, stream end. */
static rb_ynode *ywalk_stream(rb_ywalk *w)
{
    yaml_event_t ev;
    rb_ynode *root = NULL;
    while (!w->stop && ywalk_next(w, &ev)) {
        yaml_event_type_t t = ev.type;
        yaml_mark_t m = ev.start_mark;
        if (t == YAML_STREAM_END_EVENT) {
            yaml_event_delete(&ev);
            break;
        }
        if (t == YAML_DOCUMENT_START_EVENT && root) {
            yaml_event_delete(&ev);
            ywalk_fatal(w, RB_ERR_PARSE, (int)m.line + 1, (int)m.column + 1,
                           "a case file holds one YAML document; found a "
                           "second one");
            break;
        }
        if (t == YAML_STREAM_START_EVENT || t == YAML_DOCUMENT_START_EVENT
            || t == YAML_DOCUMENT_END_EVENT) {
            yaml_event_delete(&ev);
            continue;
        }
        root = ywalk_node(w, &ev, 1);
    }
    if (w->stop) {
        rb_ynode_free(root);
        return NULL;
    }
    return root;
}

/* Open a base file named by `extends:`, refusing anything but a regular
 * file: a case from elsewhere could name /dev/stdin, a terminal or a FIFO
 * and stall the run. O_NONBLOCK keeps the open itself from waiting on a
 * FIFO; it is cleared again before reading. NULL with errno, or with
 * *not_regular set. */
static FILE *yaml_open_base(const char *file, int *not_regular)
{
    struct stat sb;
    *not_regular = 0;
    int fd = open(file, O_RDONLY | O_NONBLOCK);
    if (fd < 0)
        return NULL;
    int flags = fcntl(fd, F_GETFL);
    if (fstat(fd, &sb) != 0 || !S_ISREG(sb.st_mode)
        || flags < 0 || fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) != 0) {
        *not_regular = 1;
        close(fd);
        return NULL;
    }
    FILE *f = fdopen(fd, "rb");
    if (!f)
        close(fd);
    return f;
}

/* Open the case file itself. It may be a pipe (`rockbolt check
 * <(gen-case)`), but the open must not wait: opening a FIFO that no
 * process writes to would block for ever. O_NONBLOCK makes the open return
 * at once and is cleared before reading, so a pipe with a writer is read
 * to its end and one without reads as empty. NULL with errno. */
static FILE *yaml_open_case(const char *file)
{
    int fd = open(file, O_RDONLY | O_NONBLOCK);
    if (fd < 0)
        return NULL;
    int flags = fcntl(fd, F_GETFL);
    if (flags < 0 || fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) != 0) {
        int e = errno;
        close(fd);
        errno = e;
        return NULL;
    }
    FILE *f = fdopen(fd, "rb");
    if (!f) {
        int e = errno;
        close(fd);
        errno = e;
    }
    return f;
}

/* Read the whole file, refusing more than the size limit. The case file
 * itself may be anything readable (`rockbolt check <(gen-case)`); bases
 * must be regular files. */
static rb_status yaml_slurp(rb_cctx *c, const char *file, const rb_ynode *where,
                               const char *where_key, unsigned char **buf,
                               size_t *len)
{
    int not_regular = 0;
    errno = 0;
    FILE *f = where ? yaml_open_base(file, &not_regular) : yaml_open_case(file);
    const char *dfile = where ? where->file : file;
    int line = where ? where->line : 0, col = where ? where->col : 0;
    const char *key = where ? where_key : "case";
    if (!f) {
        if (not_regular)
            rb_cctx_error_at(c, RB_ERR_IO, dfile, line, col, key, "cannot use "
                             "'%s': expected a regular file (not a directory, "
                             "device or pipe)", file);
        else
            rb_cctx_error_at(c, RB_ERR_IO, dfile, line, col, key,
                             "cannot open '%s': %s", file, strerror(errno));
        return RB_ERR_IO;
    }
    *buf = malloc(RB_CASE_MAX_FILE_BYTES + 1);
    if (!*buf) {
        fclose(f);
        c->nomem = 1;
        return RB_ERR_NOMEM;
    }
    errno = 0;
    *len = fread(*buf, 1, RB_CASE_MAX_FILE_BYTES + 1, f);
    int err = ferror(f), eno = errno;
    fclose(f);
    if (err || *len > RB_CASE_MAX_FILE_BYTES) {
        free(*buf);
        *buf = NULL;
        if (err)
            rb_cctx_error_at(c, RB_ERR_IO, dfile, line, col, key,
                             "cannot read '%s': %s", file,
                             eno == EISDIR ? "it is a directory, not a case file"
                             : strerror(eno ? eno : EIO));
        else
            rb_cctx_error_at(c, RB_ERR_LIMIT, dfile, line, col, key,
                             "'%s' is larger than the limit of 4 MiB for a "
                             "case file", file);
        return err ? RB_ERR_IO : RB_ERR_LIMIT;
    }
    return RB_OK;
}

rb_status rb_yaml_read_tree(rb_cctx *c, const char *file, const rb_ynode *where,
                            const char *where_key, rb_ynode **root)
{
    unsigned char *buf = NULL;
    size_t len = 0;
    *root = NULL;
    rb_status st = yaml_slurp(c, file, where, where_key, &buf, &len);
    if (st != RB_OK)
        return st;
    return rb_yaml_parse_text(c, file, buf, len, root);
}

rb_status rb_yaml_parse_text(rb_cctx *c, const char *file, unsigned char *buf, size_t len,
                             rb_ynode **root)
{
    *root = NULL;
    rb_ywalk w;
    memset(&w, 0, sizeof w);
    w.c = c;
    w.buf = buf;
    w.len = len;
    w.file = rb_cctx_file(c, file);
    if (!w.file || !yaml_parser_initialize(&w.parser)) {
        free(buf);
        c->nomem = 1;
        return RB_ERR_NOMEM;
    }
    yaml_parser_set_input_string(&w.parser, buf, len);
    rb_ynode *n = ywalk_stream(&w);
    yaml_parser_delete(&w.parser);
    free(buf);
    if (w.stop)
        return RB_ERR_PARSE;
    if (!n || rb_ynode_is_null(n)) {
        rb_cctx_error_at(c, RB_ERR_PARSE, w.file, 1, 1, "case", "the file is "
                         "empty (expected a mapping with 'equipment:', "
                         "'anchorage:' and 'motion:')");
        rb_ynode_free(n);
        return RB_ERR_PARSE;
    }
    if (n->kind != RB_YNODE_MAP) {
        rb_cctx_error(c, n, "case", "expected a mapping of keys at the top "
                      "level, found %s", rb_ynode_kind_str(n));
        rb_ynode_free(n);
        return RB_ERR_PARSE;
    }
    *root = n;
    return RB_OK;
}

rb_yentry *rb_ymap_find(const rb_ynode *map, const char *key)
{
    if (!map || map->kind != RB_YNODE_MAP)
        return NULL;
    for (size_t i = 0; i < map->n; i++)
        if (strcmp(map->entries[i].key, key) == 0)
            return &map->entries[i];
    return NULL;
}

int rb_ynode_is_null(const rb_ynode *n)
{
    return n && n->kind == RB_YNODE_SCALAR && n->plain
        && (n->text[0] == '\0' || strcmp(n->text, "~") == 0
            || strcmp(n->text, "null") == 0 || strcmp(n->text, "Null") == 0
            || strcmp(n->text, "NULL") == 0);
}

const char *rb_ynode_kind_str(const rb_ynode *n)
{
    if (!n)
        return "nothing";
    if (n->kind == RB_YNODE_MAP)
        return "a mapping";
    if (n->kind == RB_YNODE_SEQ)
        return "a sequence";
    return rb_ynode_is_null(n) ? "nothing (null)" : "a single value";
}
