/* Equipment lists: a CSV file, one row per cabinet, whose columns override
 * fields of a base case (docs/batch.md lists the columns).
 *
 * Fields are separated by commas and may be double-quoted ("" for a quote
 * inside), as RFC 4180 has them: a quoted field may hold line breaks (a
 * spreadsheet's multi-line cell), and its record then spans lines. Spaces
 * around unquoted fields are dropped; blank lines and lines starting with
 * '#' are skipped between records; the first other record is the header.
 * A column is a short name (mass, diameter, ...) or any case key by its
 * dotted path (concrete.strength), optionally with a unit in brackets
 * (embedment [in]) that a bare number in its cells takes. An empty cell
 * keeps the base's value. Every column must be a key of the case schema,
 * so that a misspelt header cannot silently leave a field at the base's
 * value. Each value keeps its line and column, and errors in it are
 * reported there.
 *
 * Encodings and separators (docs/batch.md): a list is UTF-8, with or
 * without a byte-order mark, unless the batch declares another encoding
 * (--encoding cp1252), which iconv turns into UTF-8 first. A row that is
 * not UTF-8 is unreadable at the first bad byte, with a hint, so no
 * output ever carries text that is not UTF-8. Fields are separated by
 * commas, or by semicolons when the header has ';' and no ',' outside
 * quotes (spreadsheets in locales with a decimal comma write those). */
#include <ctype.h>
#include <errno.h>
#include <iconv.h>
#include <search.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "batch_internal.h"
#include "rockbolt/datadir.h"
#include "rockbolt/sandbox.h"
#include "rockbolt/textsafe.h"
#include "rockbolt/units.h"
#include "util/nearest.h"

#define RB_CSV_MAX_FIELDS 64
#define RB_CSV_KEY_MAX 128      /* a column's dotted case key */
#define RB_CSV_UNIT_MAX 32      /* a column's [unit] */

typedef enum { COL_TAG, COL_BASE, COL_KEY, COL_MOTION } col_kind;

typedef struct {
    const char *name;
    col_kind kind;
    const char *key;   /* COL_KEY: the case key */
} col_def;

static const col_def csv_cols[] = {
    {"tag", COL_TAG, NULL},
    {"base", COL_BASE, NULL},
    {"description", COL_KEY, "description"},
    {"mass", COL_KEY, "equipment.mass"},
    {"height", COL_KEY, "equipment.height"},
    {"cm_height", COL_KEY, "equipment.cm_height"},
    {"base_width", COL_KEY, "equipment.base_width"},
    {"frequency", COL_KEY, "equipment.frequency"},
    {"damping", COL_KEY, "equipment.damping"},
    {"restitution", COL_KEY, "equipment.restitution"},
    {"bolt_model", COL_KEY, "anchorage.model"},
    {"bolts_per_row", COL_KEY, "anchorage.bolts_per_row"},
    {"diameter", COL_KEY, "anchorage.diameter"},
    {"area", COL_KEY, "anchorage.area"},
    {"yield_stress", COL_KEY, "anchorage.yield_stress"},
    {"toughness", COL_KEY, "anchorage.toughness"},
    {"deformable_length", COL_KEY, "anchorage.deformable_length"},
    {"edge_distance", COL_KEY, "anchorage.edge_distance"},
    {"lever_arm", COL_KEY, "anchorage.lever_arm"},
    {"anchor_type", COL_KEY, "anchorage.type"},
    {"embedment", COL_KEY, "anchorage.embedment"},
    {"spacing", COL_KEY, "anchorage.spacing"},
    {"ultimate_stress", COL_KEY, "anchorage.ultimate_stress"},
    {"tensile_area", COL_KEY, "anchorage.tensile_area"},
    {"head_bearing_area", COL_KEY, "anchorage.head_bearing_area"},
    {"gap", COL_KEY, "gap"},
    {"gap_ratio", COL_KEY, "gap_ratio"},
    {"motion", COL_MOTION, NULL},
    {"peak", COL_KEY, "motion.peak"},
    {"amplitude", COL_KEY, "motion.amplitude"},
    {"building_frequency", COL_KEY, "motion.building.frequency"},
    {"building_damping", COL_KEY, "motion.building.damping"},
    {"criterion", COL_KEY, "criteria.kind"},
    {"usage_limit", COL_KEY, "criteria.usage_limit"},
};
#define RB_CSV_NCOLS (sizeof csv_cols / sizeof csv_cols[0])

typedef struct {
    char *text;    /* owned */
    int line;      /* 1-based line of the field's start (a record that holds
                      a multi-line cell spans lines) */
    int col;       /* 1-based byte column of the field's start */
} csv_field;

typedef struct {
    csv_field f[RB_CSV_MAX_FIELDS];
    size_t n;
} csv_row;

static void row_clear(csv_row *r)
{
    for (size_t i = 0; i < r->n; i++)
        free(r->f[i].text);
    r->n = 0;
}

/* Where a record stands in the buffer: pos and line of its next byte, and
 * the start of that line (for columns). */
typedef struct {
    const char *buf;
    size_t len, pos, line_start;
    int line;
} csv_cursor;

static int is_eol(const csv_cursor *cu, size_t i)
{
    return cu->buf[i] == '\n'
        || (cu->buf[i] == '\r' && (i + 1 == cu->len || cu->buf[i + 1] == '\n'));
}

/* Past the end of the current line (its newline included). */
static void skip_line(csv_cursor *cu)
{
    const char *nl = memchr(cu->buf + cu->pos, '\n', cu->len - cu->pos);
    cu->pos = nl ? (size_t)(nl - cu->buf) + 1 : cu->len;
    if (nl) {
        cu->line++;
        cu->line_start = cu->pos;
    }
}

/* A quoted field from the quote at cu->pos: its text with "" as one quote
 * and each line break (CRLF too) as LF, lines counted. NULL with msg on an
 * unterminated field, *oom when memory runs out. */
static char *quoted_field(csv_cursor *cu, char *msg, size_t msz, int *oom)
{
    const char *b = cu->buf;
    size_t i = cu->pos + 1, end = i;
    /* the closing quote first: the text is at most that long */
    while (end < cu->len && !(b[end] == '"' && (end + 1 >= cu->len || b[end + 1] != '"')))
        end += b[end] == '"' ? 2 : 1;
    if (end >= cu->len) {
        snprintf(msg, msz, "unterminated quoted field: its closing quote is missing, so "
                 "it would run to the end of the list");
        return NULL;
    }
    char *out = malloc(end - i + 1);
    size_t o = 0;
    if (!out) {
        *oom = 1;
        return NULL;
    }
    while (i < end) {
        if (b[i] == '"') {
            out[o++] = '"';
            i += 2;
        } else if (b[i] == '\r' && i + 1 < end && b[i + 1] == '\n') {
            i++;
        } else {
            if (b[i] == '\n') {
                cu->line++;
                cu->line_start = i + 1;
            }
            out[o++] = b[i++];
        }
    }
    out[o] = '\0';
    cu->pos = end + 1;
    return out;
}

/* Split the record at the cursor into fields, each with its line and
 * column, and move past it. Returns 1; 0 with msg, *bad_line and *bad_col
 * set on a malformed record (the cursor past its line); -1 on NOMEM. */
static int split_record(csv_cursor *cu, char sep, csv_row *r, char *msg, size_t msz,
                        int *bad_line, int *bad_col)
{
    const char *s = cu->buf;
    r->n = 0;
    for (;;) {
        while (cu->pos < cu->len && (s[cu->pos] == ' ' || s[cu->pos] == '\t'))
            cu->pos++;
        *bad_line = cu->line;
        *bad_col = (int)(cu->pos - cu->line_start) + 1;
        if (r->n == RB_CSV_MAX_FIELDS) {
            snprintf(msg, msz, "more than %d fields", RB_CSV_MAX_FIELDS);
            skip_line(cu);
            return 0;
        }
        csv_field *f = &r->f[r->n];
        f->line = *bad_line;
        f->col = *bad_col;
        char *out;
        if (cu->pos < cu->len && s[cu->pos] == '"') {
            int oom = 0;
            if (!(out = quoted_field(cu, msg, msz, &oom))) {
                if (oom)
                    return -1;
                cu->pos = cu->len;   /* nothing after it can be told apart */
                return 0;
            }
            while (cu->pos < cu->len && (s[cu->pos] == ' ' || s[cu->pos] == '\t'))
                cu->pos++;
            if (cu->pos < cu->len && s[cu->pos] != sep && !is_eol(cu, cu->pos)) {
                free(out);
                snprintf(msg, msz, "text after a quoted field");
                *bad_line = cu->line;
                *bad_col = (int)(cu->pos - cu->line_start) + 1;
                skip_line(cu);
                return 0;
            }
        } else {
            size_t i = cu->pos;
            while (i < cu->len && s[i] != sep && !is_eol(cu, i))
                i++;
            size_t o = i - cu->pos;
            while (o > 0 && (s[cu->pos + o - 1] == ' ' || s[cu->pos + o - 1] == '\t'))
                o--;
            if (!(out = malloc(o + 1)))
                return -1;
            memcpy(out, s + cu->pos, o);
            out[o] = '\0';
            cu->pos = i;
        }
        f->text = out;
        r->n++;
        if (cu->pos >= cu->len || is_eol(cu, cu->pos)) {
            skip_line(cu);
            return 1;
        }
        cu->pos++;   /* the separator */
    }
}

/* A column of the list: what its cells set. */
typedef struct {
    col_kind kind;
    char key[RB_CSV_KEY_MAX];   /* COL_KEY: the dotted case key */
    char unit[RB_CSV_UNIT_MAX]; /* the header's [unit], for bare numbers; "" */
} csv_col;

typedef struct {
    const char *path;
    char *dir;            /* the list's directory with '/', or "" */
    const char *default_base;
    csv_col cols[RB_CSV_MAX_FIELDS];
    size_t n_cols;
    int tag_col, base_col;
    char sep;             /* ',' or ';', from the header */
    void *tags;           /* tag_entry tree (tsearch): the tags seen so far */
} csv_ctx;

/* A tag seen, and the line it was first given at. */
typedef struct {
    int line;
    char tag[];
} tag_entry;

static int tag_cmp(const void *a, const void *b)
{
    return strcmp(((const tag_entry *)a)->tag, ((const tag_entry *)b)->tag);
}

static rb_status add_ov(rb_batch_item *it, const char *key, const char *value,
                        int line, int col)
{
    rb_case_override *p = realloc(it->ov, (it->n_ov + 1) * sizeof *p);
    if (!p)
        return RB_ERR_NOMEM;
    it->ov = p;
    rb_case_override *o = &it->ov[it->n_ov];
    o->key = rb_batch_strdup(key);
    o->value = rb_batch_strdup(value);
    o->line = line;
    o->col = col;
    if (!o->key || !o->value) {
        free((char *)o->key);
        free((char *)o->value);
        return RB_ERR_NOMEM;
    }
    it->n_ov++;
    return RB_OK;
}

/* The motion column: a record file (relative to the list) or the name of a
 * shipped record. Returns RB_ERR_INVALID after marking the item bad. */
static rb_status add_motion(rb_batch_item *it, const char *v, int line, int col)
{
    rb_status st = RB_OK;
    if (strchr(v, '/') || strchr(v, '.')) {
        st = add_ov(it, "motion.type", "record", line, col);
        if (st == RB_OK)
            st = add_ov(it, "motion.file", v, line, col);
    } else {
        const rb_shipped_record *sr = rb_shipped_find(v);
        char file[4096];
        if (!sr || !rb_shipped_path(v, file, sizeof file)) {
            char msg[300];
            snprintf(msg, sizeof msg, "unknown motion '%.100s' (give a record "
                     "file, or one of: %s)", v, rb_shipped_names());
            rb_batch_item_bad(it, line, col, "motion", msg);
            return RB_ERR_INVALID;
        }
        st = add_ov(it, "motion.type", "record", line, col);
        if (st == RB_OK)
            st = add_ov(it, "motion.file", file, line, col);
        if (st == RB_OK)
            st = add_ov(it, "motion.format", sr->format, line, col);
        if (st == RB_OK && sr->dt)
            st = add_ov(it, "motion.dt", sr->dt, line, col);
        if (st == RB_OK && sr->units)
            st = add_ov(it, "motion.units", sr->units, line, col);
    }
    if (st == RB_OK)
        st = add_ov(it, "motion.name", v, line, col);
    return st;
}

static int find_col(const char *name)
{
    for (size_t k = 0; k < RB_CSV_NCOLS; k++)
        if (strcmp(csv_cols[k].name, name) == 0)
            return (int)k;
    return -1;
}

/* The short column name nearest a misspelt one, or NULL. */
static const char *nearest_col(const char *name)
{
    const char *best = NULL;
    int bestd = 9;
    for (size_t k = 0; k < RB_CSV_NCOLS; k++) {
        int d = rb_edit_distance(name, csv_cols[k].name);
        if (d < bestd) {
            bestd = d;
            best = csv_cols[k].name;
        }
    }
    return bestd <= rb_typo_limit(strlen(name)) ? best : NULL;
}

/* A unit some quantity of a case can be written in ("in", "kip", "%"). */
static int known_unit(const char *unit)
{
    char text[RB_CSV_UNIT_MAX + 4], msg[200];
    rb_quantity q;
    snprintf(text, sizeof text, "1 %s", unit);
    for (int d = 0; d < RB_DIM_COUNT; d++)
        if (rb_unit_parse(text, (rb_dim)d, &q, msg, sizeof msg) == RB_OK)
            return 1;
    return 0;
}

/* A header cell: "mass", "concrete.strength", "embedment [in]". Returns 1
 * with *col filled, 0 with msg saying why the column is not known. */
static int parse_column(const char *cell, csv_col *col, char *msg, size_t msz)
{
    char name[RB_CSV_KEY_MAX];
    const char *br = strchr(cell, '[');
    size_t n = br ? (size_t)(br - cell) : strlen(cell);
    while (n > 0 && isspace((unsigned char)cell[n - 1]))
        n--;
    memset(col, 0, sizeof *col);
    if (n >= sizeof name) {
        snprintf(msg, msz, "unknown column '%.60s...' (longer than any case key)", cell);
        return 0;
    }
    memcpy(name, cell, n);
    name[n] = '\0';
    if (br) {
        const char *u = br + 1, *close = strchr(u, ']');
        while (isspace((unsigned char)*u))
            u++;
        size_t un = close ? (size_t)(close - u) : 0;
        while (un > 0 && isspace((unsigned char)u[un - 1]))
            un--;
        if (!close || close[1] || un == 0 || un >= sizeof col->unit) {
            snprintf(msg, msz, "column '%.60s': expected a name and a unit in brackets "
                     "at its end, such as 'embedment [in]'", cell);
            return 0;
        }
        memcpy(col->unit, u, un);
        col->unit[un] = '\0';
        if (!known_unit(col->unit)) {
            snprintf(msg, msz, "column '%.60s': unknown unit '%s' (units as a case file "
                     "writes them: in, mm, lb, kip, psi, ksi, g, %%, ...)", cell, col->unit);
            return 0;
        }
    }
    int k = find_col(name);
    if (k >= 0) {
        col->kind = csv_cols[k].kind;
        snprintf(col->key, sizeof col->key, "%s", csv_cols[k].key ? csv_cols[k].key
                                                                  : csv_cols[k].name);
    } else {
        char why[300];
        if (!rb_case_key_settable(name, why, sizeof why)) {
            /* a misspelt short name: the nearest short name, unless the
             * schema knows the key and says why it cannot be a column */
            const char *near = strchr(name, '.') || strncmp(why, "unknown key", 11) != 0
                             ? NULL : nearest_col(name);
            if (near)
                snprintf(why, sizeof why, "did you mean '%s'?", near);
            snprintf(msg, msz, "unknown column '%.60s': %s (a column is tag, base, motion, a "
                     "short name such as mass, or a dotted case key such as "
                     "anchorage.embedment)",
                     name, why);
            return 0;
        }
        col->kind = COL_KEY;
        snprintf(col->key, sizeof col->key, "%s", name);
    }
    if (col->unit[0] && col->kind != COL_KEY) {
        snprintf(msg, msz, "column '%.60s' takes no unit", name);
        return 0;
    }
    return 1;
}

/* Check the header; on a problem the whole list becomes one bad item. */
static rb_status read_header(csv_ctx *cx, rb_batch_list *l, const csv_row *r, int line)
{
    char msg[700];
    cx->tag_col = cx->base_col = -1;
    /* A header without one known column is not a list's (a CSV of another
     * kind, a system file named *.csv): say so without quoting it, since
     * the error goes into published summaries. */
    size_t known = 0;
    for (size_t i = 0; i < r->n; i++)
        known += parse_column(r->f[i].text, &cx->cols[i], msg, sizeof msg);
    if (known == 0) {
        rb_batch_item *it = rb_batch_list_push(l, cx->path);
        if (!it)
            return RB_ERR_NOMEM;
        rb_batch_item_bad(it, line, 1, "header", "not an equipment list: none of the "
                          "header's columns is a known column (tag, base, mass, ...)");
        return RB_ERR_INVALID;
    }
    for (size_t i = 0; i < r->n; i++) {
        int ok = parse_column(r->f[i].text, &cx->cols[i], msg, sizeof msg);
        for (size_t j = 0; j < i && ok; j++)
            if (strcmp(cx->cols[j].key, cx->cols[i].key) == 0) {
                snprintf(msg, sizeof msg, "duplicate column '%.60s' (column %zu sets "
                         "%s too)", r->f[i].text, j + 1, cx->cols[i].key);
                ok = 0;
            }
        if (!ok) {
            rb_batch_item *it = rb_batch_list_push(l, cx->path);
            if (!it)
                return RB_ERR_NOMEM;
            rb_batch_item_bad(it, r->f[i].line, r->f[i].col, "header", msg);
            return RB_ERR_INVALID;
        }
        if (cx->cols[i].kind == COL_TAG)
            cx->tag_col = (int)i;
        if (cx->cols[i].kind == COL_BASE)
            cx->base_col = (int)i;
    }
    cx->n_cols = r->n;
    const char *missing = cx->tag_col < 0 ? "no 'tag' column"
        : (cx->base_col < 0 && !cx->default_base)
          ? "no 'base' column and no --base case" : NULL;
    if (missing) {
        rb_batch_item *it = rb_batch_list_push(l, cx->path);
        if (!it)
            return RB_ERR_NOMEM;
        rb_batch_item_bad(it, line, 1, "header", missing);
        return RB_ERR_INVALID;
    }
    return RB_OK;
}

static char *join(const char *a, const char *b)
{
    char *p = malloc(strlen(a) + strlen(b) + 1);
    if (p) {
        strcpy(p, a);
        strcat(p, b);
    }
    return p;
}

/* 0 if tag is new, else the line it was first given at; -1 on NOMEM. */
static int tag_seen(csv_ctx *cx, const char *tag, int line)
{
    /* a tree, not a scan: a list of 100 000 rows would compare 5e9 tags */
    size_t n = strlen(tag) + 1;
    tag_entry *e = malloc(sizeof *e + n);
    if (!e)
        return -1;
    e->line = line;
    memcpy(e->tag, tag, n);
    tag_entry **found = tsearch(e, &cx->tags, tag_cmp);
    if (!found) {
        free(e);
        return -1;
    }
    if (*found != e) {
        free(e);
        return (*found)->line;
    }
    return 0;
}

/* The row's tag column; "" where it has none. */
static const char *row_tag(const csv_ctx *cx, const csv_row *r)
{
    return (size_t)cx->tag_col < r->n ? r->f[cx->tag_col].text : "";
}

/* A new item for the row at line, tagged by its tag or, where that is
 * empty, by "line N"; copy makes the tag's string (a plain copy, or one
 * that shows bytes that are not UTF-8 escaped). NULL when out of memory. */
static rb_batch_item *row_item(const csv_ctx *cx, rb_batch_list *l, const char *tag,
                               int line, char *(*copy)(const char *))
{
    char name[32];
    rb_batch_item *it = rb_batch_list_push(l, cx->path);
    if (!it)
        return NULL;
    it->line = line;
    snprintf(name, sizeof name, "line %d", line);
    return (it->tag = copy(tag[0] ? tag : name)) ? it : NULL;
}

/* A cell that is a number without its unit ("4", "0.75", "3/4"): it
 * takes its column's [unit]. One with a unit of its own keeps that. */
static int bare_number(const char *v)
{
    size_t n = strlen(v);
    return n > 0 && (isdigit((unsigned char)v[n - 1]) || v[n - 1] == '.');
}

static rb_status read_row(csv_ctx *cx, rb_batch_list *l, const csv_row *r, int line)
{
    char msg[300];
    const char *tag = row_tag(cx, r);
    rb_batch_item *it = row_item(cx, l, tag, line, rb_batch_strdup);
    if (!it)
        return RB_ERR_NOMEM;
    if (r->n != cx->n_cols) {
        snprintf(msg, sizeof msg, "the row has %zu fields; the header has %zu",
                 r->n, cx->n_cols);
        rb_batch_item_bad(it, line, 1, "row", msg);
        return RB_OK;
    }
    if (!tag[0]) {
        rb_batch_item_bad(it, r->f[cx->tag_col].line, r->f[cx->tag_col].col, "tag",
                          "the tag is empty");
        return RB_OK;
    }
    int first = tag_seen(cx, tag, line);
    if (first < 0)
        return RB_ERR_NOMEM;
    if (first > 0) {
        snprintf(msg, sizeof msg, "duplicate tag '%.100s' (first given at line %d)",
                 tag, first);
        rb_batch_item_bad(it, r->f[cx->tag_col].line, r->f[cx->tag_col].col, "tag", msg);
        return RB_OK;
    }
    const char *base = cx->base_col >= 0 ? r->f[cx->base_col].text : "";
    if (base[0]) {
        it->base = base[0] == '/' ? rb_batch_strdup(base) : join(cx->dir, base);
        it->base_line = r->f[cx->base_col].line;
        it->base_col = r->f[cx->base_col].col;
    }
    else if (cx->default_base)
        it->base = rb_batch_strdup(cx->default_base);
    else {
        rb_batch_item_bad(it, r->f[cx->base_col].line, r->f[cx->base_col].col, "base",
                          "no base case: the cell is empty and no --base was given");
        return RB_OK;
    }
    if (!it->base)
        return RB_ERR_NOMEM;
    for (size_t i = 0; i < r->n; i++) {
        const csv_col *c = &cx->cols[i];
        const char *v = r->f[i].text;
        rb_status st = RB_OK;
        if (!v[0] || c->kind == COL_TAG || c->kind == COL_BASE)
            continue;
        if (c->kind == COL_MOTION) {
            st = add_motion(it, v, r->f[i].line, r->f[i].col);
        } else if (c->unit[0] && bare_number(v)) {
            char *q = malloc(strlen(v) + strlen(c->unit) + 2);
            if (!q)
                return RB_ERR_NOMEM;
            sprintf(q, "%s %s", v, c->unit);
            st = add_ov(it, c->key, q, r->f[i].line, r->f[i].col);
            free(q);
        } else {
            st = add_ov(it, c->key, v, r->f[i].line, r->f[i].col);
        }
        if (st == RB_ERR_INVALID)
            return RB_OK;
        if (st != RB_OK)
            return st;
    }
    return RB_OK;
}

/* The whole list; NUL bytes refused unless an encoding (UTF-16) may have
 * them: its text is checked after transcoding. */
static char *slurp(const char *path, size_t *len, int allow_nul, char *msg, size_t msz)
{
    FILE *f = fopen(path, "rb");
    if (!f) {
        snprintf(msg, msz, "cannot open the list");
        return NULL;
    }
    char *buf = malloc(RB_CSV_MAX_BYTES + 1);
    if (!buf) {
        fclose(f);
        snprintf(msg, msz, "out of memory");
        return NULL;
    }
    *len = fread(buf, 1, RB_CSV_MAX_BYTES + 1, f);
    int err = ferror(f);
    fclose(f);
    if (err || *len > RB_CSV_MAX_BYTES) {
        free(buf);
        snprintf(msg, msz, err ? "cannot read the list"
                               : "the list is larger than 64 MiB");
        return NULL;
    }
    buf[*len] = '\0';
    if (!allow_nul && memchr(buf, '\0', *len)) {
        free(buf);
        snprintf(msg, msz, "the list holds NUL bytes: not a text file (or saved "
                 "as UTF-16: pass --encoding utf-16, or save it as UTF-8)");
        return NULL;
    }
    return buf;
}

/* The separator the header record uses: ';' when it has one and no comma
 * outside quotes, else ','. */
static char header_sep(const char *s, size_t n)
{
    int quoted = 0, comma = 0, semi = 0;
    for (size_t i = 0; i < n && (quoted || s[i] != '\n'); i++) {
        if (s[i] == '"')
            quoted = !quoted;
        else if (!quoted && s[i] == ',')
            comma = 1;
        else if (!quoted && s[i] == ';')
            semi = 1;
    }
    return semi && !comma ? ';' : ',';
}

#define RB_CSV_HINT "the list is not UTF-8; save it as UTF-8 or pass --encoding " \
                    "cp1252 (or the encoding it was saved in)"

/* A row with a byte that is not UTF-8 at column col: unreadable there. Its
 * tag is shown with that byte as \xHH, so no output carries it raw. */
static rb_status bad_encoding_row(csv_ctx *cx, rb_batch_list *l, const csv_row *r,
                                  int line, int byte_line, int col, unsigned char byte)
{
    char msg[300];
    rb_batch_item *it = row_item(cx, l, row_tag(cx, r), line, rb_utf8_fix);
    if (!it)
        return RB_ERR_NOMEM;
    snprintf(msg, sizeof msg, "byte 0x%02X is not UTF-8: " RB_CSV_HINT, byte);
    rb_batch_item_bad(it, byte_line, col, "encoding", msg);
    return RB_OK;
}

/* Line and column of byte at in buf, from the record's start (line,
 * line_start). */
static void where_in(const char *buf, size_t line_start, int line, size_t at, int *out_line,
                     int *out_col)
{
    for (size_t i = line_start; i < at; i++)
        if (buf[i] == '\n') {
            line++;
            line_start = i + 1;
        }
    *out_line = line;
    *out_col = (int)(at - line_start) + 1;
}

static rb_status read_lines(csv_ctx *cx, rb_batch_list *l, const char *buf, size_t len,
                            size_t n_before)
{
    csv_row r;
    char msg[200];
    int have_header = 0;
    csv_cursor cu = {buf, len, 0, 0, 1};
    rb_status st = RB_OK;
    memset(&r, 0, sizeof r);
    if (len >= 3 && memcmp(buf, "\xEF\xBB\xBF", 3) == 0)
        cu.pos = cu.line_start = 3;   /* a byte-order mark, as spreadsheets write */
    while (cu.pos < len && st == RB_OK) {
        size_t k = cu.pos;
        while (k < len && (buf[k] == ' ' || buf[k] == '\t'))
            k++;
        if (k == len || buf[k] == '#' || is_eol(&cu, k)) {
            skip_line(&cu);   /* blank lines and comments, between records only */
            continue;
        }
        int line = cu.line, bad_line = line, bad_col = 1;
        size_t start = cu.pos, line_start = cu.line_start;
        if (!have_header)
            cx->sep = header_sep(buf + start, len - start);
        int ok = split_record(&cu, cx->sep, &r, msg, sizeof msg, &bad_line, &bad_col);
        size_t bad_at = ok > 0 ? rb_utf8_invalid_at(buf + start, cu.pos - start) : 0;
        if (ok > 0 && bad_at < cu.pos - start) {
            int bl, bc;
            where_in(buf, line_start, line, start + bad_at, &bl, &bc);
            if (have_header) {
                st = bad_encoding_row(cx, l, &r, line, bl, bc,
                                      (unsigned char)buf[start + bad_at]);
                row_clear(&r);
                continue;
            }
            ok = 0;
            bad_line = bl;
            bad_col = bc;
            snprintf(msg, sizeof msg, "byte 0x%02X is not UTF-8: " RB_CSV_HINT,
                     (unsigned char)buf[start + bad_at]);
        }
        if (ok < 0) {
            st = RB_ERR_NOMEM;
        } else if (!ok || !have_header) {
            if (!ok) {
                rb_batch_item *it = rb_batch_list_push(l, cx->path);
                if (!it)
                    st = RB_ERR_NOMEM;
                else {
                    it->line = line;
                    rb_batch_item_bad(it, bad_line, bad_col,
                                      have_header ? "row" : "header", msg);
                }
                if (!have_header) {
                    row_clear(&r);
                    return st;
                }
            } else {
                st = read_header(cx, l, &r, line);
                have_header = 1;
                if (st == RB_ERR_INVALID) {
                    row_clear(&r);
                    return RB_OK;
                }
            }
        } else {
            st = read_row(cx, l, &r, line);
        }
        row_clear(&r);
    }
    if (st == RB_OK && l->n == n_before) {
        rb_batch_item *it = rb_batch_list_push(l, cx->path);
        if (!it)
            return RB_ERR_NOMEM;
        rb_batch_item_bad(it, cu.line > 1 ? cu.line - 1 : 1, 1, "header",
                          have_header ? "the list has no rows" : "the list is empty");
    }
    return st;
}

/* buf[0..*len) in encoding enc, as UTF-8 in a new buffer (buf is freed).
 * NULL with msg set and *line, *col at the first byte that is not a
 * character of enc (or 0 when the whole list is at fault). A list that
 * starts with a UTF-8 byte-order mark says it is UTF-8, and is kept. */
static char *transcode(char *buf, size_t *len, const char *enc, char *msg, size_t msz,
                       int *line, int *col)
{
    *line = *col = 0;
    if (*len >= 3 && memcmp(buf, "\xEF\xBB\xBF", 3) == 0)
        return buf;
    iconv_t cd = iconv_open("UTF-8", enc);
    if (cd == (iconv_t)-1) {
        snprintf(msg, msz, "unknown encoding '%.60s' (iconv knows no such name; "
                 "'iconv -l' lists them)", enc);
        free(buf);
        return NULL;
    }
    /* at most 4 bytes of UTF-8 for each input byte (UTF-16 gives at most
     * 3 per 2, single-byte encodings at most 3 per 1) */
    size_t cap = 4 * *len + 1;
    char *out = *len <= RB_CSV_MAX_BYTES ? malloc(cap) : NULL;
    if (!out) {
        iconv_close(cd);
        free(buf);
        snprintf(msg, msz, "out of memory");
        return NULL;
    }
    char *in = buf, *o = out;
    size_t inleft = *len, outleft = cap - 1;
    size_t r = iconv(cd, &in, &inleft, &o, &outleft);
    if (r != (size_t)-1)
        r = iconv(cd, NULL, NULL, &o, &outleft);
    iconv_close(cd);
    if (r == (size_t)-1) {
        size_t at = (size_t)(in - buf);
        int ln = 1;
        size_t start = 0;
        for (size_t i = 0; i < at; i++)
            if (buf[i] == '\n') {
                ln++;
                start = i + 1;
            }
        *line = ln;
        *col = (int)(at - start) + 1;
        if (errno == EILSEQ)
            snprintf(msg, msz, "byte 0x%02X is not a character of the encoding "
                     "'%.60s' given by --encoding", (unsigned char)buf[at], enc);
        else
            snprintf(msg, msz, "the list ends inside a character of the encoding "
                     "'%.60s'", enc);
        free(out);
        free(buf);
        return NULL;
    }
    free(buf);
    *len = (size_t)(o - out);
    out[*len] = '\0';
    if (memchr(out, '\0', *len)) {
        free(out);
        snprintf(msg, msz, "the list holds NUL characters in the encoding '%.60s': "
                 "not a text file, or not in that encoding", enc);
        return NULL;
    }
    return out;
}

rb_status rb_batch_list_read_csv(rb_batch_list *l, const char *path, const char *default_base)
{
    csv_ctx cx;
    char msg[700];
    size_t len = 0, n_before = l->n;
    memset(&cx, 0, sizeof cx);
    cx.path = path;
    cx.default_base = default_base;
    const char *slash = strrchr(path, '/');
    size_t dl = slash ? (size_t)(slash - path + 1) : 0;
    if (!(cx.dir = malloc(dl + 1)))
        return RB_ERR_NOMEM;
    memcpy(cx.dir, path, dl);
    cx.dir[dl] = '\0';
    char why[600];
    char *buf = NULL;
    if (!rb_sandbox_allows(l->sandbox, path, why, sizeof why))
        snprintf(msg, sizeof msg, "the list lies outside the sandbox '%.*s' (%.*s)",
                 300, rb_sandbox_dir(l->sandbox), 300, why);
    else
        buf = slurp(path, &len, l->encoding != NULL, msg, sizeof msg);
    int bad_line = 0, bad_col = 0;
    if (buf && l->encoding)
        buf = transcode(buf, &len, l->encoding, msg, sizeof msg, &bad_line, &bad_col);
    rb_status st = RB_OK;
    if (!buf) {
        rb_batch_item *it = rb_batch_list_push(l, path);
        if (!it)
            st = RB_ERR_NOMEM;
        else
            rb_batch_item_bad(it, bad_line, bad_col, bad_line ? "encoding" : "list",
                              msg);
    } else {
        st = read_lines(&cx, l, buf, len, n_before);
    }
    while (cx.tags) {
        /* POSIX has no tdestroy: take the root until none is left */
        tag_entry *e = *(tag_entry **)cx.tags;
        tdelete(e, &cx.tags, tag_cmp);
        free(e);
    }
    free(cx.dir);
    free(buf);
    return st;
}
