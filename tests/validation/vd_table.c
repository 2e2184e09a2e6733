/* Reader of cases/thesis/expected.csv.
 *
 * Comma-separated, one header line, '#' lines are comments. A field may be
 * double-quoted so that it can hold commas; "" inside quotes is a quote.
 * Columns: section, case, motion, quantity, label, thesis, source,
 * tolerance, expect, reason. tolerance is a number (absolute), a number
 * followed by % (relative), an interval "lo..hi" (either end may be left
 * open) or "exact" (words); expect is "agree" or
 * "differs N" (a known difference explained in note N). */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "vd.h"

#define VD_COLS 10
#define VD_LINE_MAX 4096

static const char *const vd_header[VD_COLS] = {
    "section", "case", "motion", "quantity", "label", "thesis", "source",
    "tolerance", "expect", "reason"};

/* Split line into at most VD_COLS fields, in place. Returns the field count,
 * or -1 for an unterminated quote. */
static int split_csv(char *line, char *field[VD_COLS])
{
    int n = 0;
    char *p = line;
    for (;;) {
        if (n == VD_COLS)
            return n + 1;   /* too many */
        char *out = p;
        field[n++] = out;
        if (*p == '"') {
            p++;
            for (;;) {
                if (*p == '\0')
                    return -1;
                if (*p == '"' && p[1] == '"') {
                    *out++ = '"';
                    p += 2;
                } else if (*p == '"') {
                    p++;
                    break;
                } else {
                    *out++ = *p++;
                }
            }
        } else {
            while (*p && *p != ',')
                *out++ = *p++;
        }
        int more = *p == ',';
        if (*p)
            p++;
        *out = '\0';
        if (!more)
            return n;
    }
}

static char *dup(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = malloc(n);
    if (d)
        memcpy(d, s, n);
    return d;
}

static int parse_row(char *f[VD_COLS], vd_row *r, const char *path, int line)
{
    char *end;
    r->line = line;
    r->motion = 1;
    if (f[2][0]) {
        errno = 0;
        long m = strtol(f[2], &end, 10);
        if (*end || m < 1 || m > 1000 || errno) {
            fprintf(stderr, "%s:%d: motion must be a number from 1 (got '%s')\n",
                    path, line, f[2]);
            return 0;
        }
        r->motion = (int)m;
    }
    char *dots = strstr(f[7], "..");
    if (strcmp(f[7], "exact") == 0) {
        r->tol_kind = VD_TOL_EXACT;
        r->tol = 0;
    } else if (dots) {
        r->tol_kind = VD_TOL_RANGE;
        /* cut at the dots so that "14." is not read as the lower end */
        *dots = '\0';
        r->lo = dots == f[7] ? -HUGE_VAL : strtod(f[7], &end);
        int ok = dots == f[7] || !*end;
        r->hi = dots[2] ? strtod(dots + 2, &end) : HUGE_VAL;
        ok = ok && (!dots[2] || (end != dots + 2 && !*end)) && r->lo <= r->hi;
        *dots = '.';
        if (!ok) {
            fprintf(stderr, "%s:%d: an interval is 'lo..hi' with lo <= hi (got '%s')\n",
                    path, line, f[7]);
            return 0;
        }
    } else {
        r->tol = strtod(f[7], &end);
        r->tol_kind = VD_TOL_ABS;
        if (end != f[7] && *end == '%') {
            r->tol_kind = VD_TOL_REL;
            r->tol /= 100.0;
            end++;
        }
        if (end == f[7] || *end || !(r->tol >= 0)) {
            fprintf(stderr, "%s:%d: tolerance must be a number, a percentage or "
                    "'exact' (got '%s')\n", path, line, f[7]);
            return 0;
        }
    }
    if (strcmp(f[8], "agree") == 0) {
        r->differs_note = 0;
    } else if (strncmp(f[8], "differs ", 8) == 0
               && (r->differs_note = atoi(f[8] + 8)) > 0) {
        /* note number parsed */
    } else {
        fprintf(stderr, "%s:%d: expect must be 'agree' or 'differs N' (got '%s')\n",
                path, line, f[8]);
        return 0;
    }
    if (!f[0][0] || !f[1][0] || !f[3][0] || !f[5][0] || !f[6][0] || !f[9][0]) {
        fprintf(stderr, "%s:%d: section, case, quantity, thesis, source and "
                "reason must not be empty\n", path, line);
        return 0;
    }
    r->section = dup(f[0]);
    r->kase = dup(f[1]);
    r->quantity = dup(f[3]);
    r->label = dup(f[4]);
    r->thesis = dup(f[5]);
    r->source = dup(f[6]);
    r->tol_text = dup(f[7]);
    r->reason = dup(f[9]);
    if (!r->section || !r->kase || !r->quantity || !r->label || !r->thesis
        || !r->source || !r->tol_text || !r->reason) {
        fprintf(stderr, "%s:%d: out of memory\n", path, line);
        return 0;
    }
    if (r->tol_kind != VD_TOL_EXACT) {
        strtod(r->thesis, &end);
        if (end == r->thesis || *end) {
            fprintf(stderr, "%s:%d: a numeric tolerance needs a numeric thesis "
                    "value (got '%s')\n", path, line, r->thesis);
            return 0;
        }
    }
    return 1;
}

int vd_table_read(const char *path, vd_table *t)
{
    memset(t, 0, sizeof *t);
    FILE *fp = fopen(path, "r");
    if (!fp) {
        fprintf(stderr, "%s: %s\n", path, strerror(errno));
        return 0;
    }
    char line[VD_LINE_MAX];
    int lineno = 0, ok = 1, header = 0;
    while (ok && fgets(line, sizeof line, fp)) {
        lineno++;
        size_t len = strlen(line);
        if (len && line[len - 1] != '\n' && !feof(fp)) {
            fprintf(stderr, "%s:%d: line longer than %d bytes\n", path, lineno,
                    VD_LINE_MAX - 2);
            ok = 0;
            break;
        }
        while (len && (line[len - 1] == '\n' || line[len - 1] == '\r'))
            line[--len] = '\0';
        if (len == 0 || line[0] == '#')
            continue;
        char *f[VD_COLS];
        int n = split_csv(line, f);
        if (n != VD_COLS) {
            fprintf(stderr, "%s:%d: expected %d fields, found %s%d\n", path,
                    lineno, VD_COLS, n > VD_COLS ? "more than " : "",
                    n > VD_COLS ? VD_COLS : n);
            ok = 0;
            break;
        }
        if (!header) {
            for (int i = 0; i < VD_COLS; i++)
                if (strcmp(f[i], vd_header[i]) != 0) {
                    fprintf(stderr, "%s:%d: column %d must be '%s'\n", path,
                            lineno, i + 1, vd_header[i]);
                    ok = 0;
                }
            header = 1;
            continue;
        }
        if (t->n == t->cap) {
            size_t cap = t->cap ? 2 * t->cap : 64;
            vd_row *rows = realloc(t->rows, cap * sizeof *rows);
            if (!rows) {
                fprintf(stderr, "%s: out of memory\n", path);
                ok = 0;
                break;
            }
            t->rows = rows;
            t->cap = cap;
        }
        vd_row *r = &t->rows[t->n++];
        memset(r, 0, sizeof *r);
        ok = parse_row(f, r, path, lineno);
    }
    if (ok && ferror(fp)) {
        fprintf(stderr, "%s: read error\n", path);
        ok = 0;
    }
    fclose(fp);
    if (ok && !header) {
        fprintf(stderr, "%s: no header line\n", path);
        ok = 0;
    }
    if (!ok)
        vd_table_free(t);
    return ok;
}

void vd_table_free(vd_table *t)
{
    if (!t)
        return;
    for (size_t i = 0; i < t->n; i++) {
        vd_row *r = &t->rows[i];
        free(r->section);
        free(r->kase);
        free(r->quantity);
        free(r->label);
        free(r->thesis);
        free(r->source);
        free(r->tol_text);
        free(r->reason);
    }
    free(t->rows);
    memset(t, 0, sizeof *t);
}
