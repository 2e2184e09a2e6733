/* A Markdown page of docs/ as a manual page, made at build time so that
 * the two cannot disagree (rockbolt-case(5) from docs/case-format.md).
 *
 *     rb_mdman IN.md OUT NAME SECTION VERSION DESCRIPTION
 *
 * It knows the Markdown the docs use, no more: the title "# ...", "## "
 * sections and "### " subsections, paragraphs, fenced and indented code,
 * "- " lists, tables (each row an entry headed by its first cell, the
 * other cells named by their column), `code`, **bold** and [links](...)
 * (the text kept). Anything else is text. roff's own characters are
 * escaped, so no line of the page can be read as a request. */
#include <ctype.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define LINE_MAX_LEN 4096
#define MAX_CELLS 16

static FILE *out;

/* Text as roff: backslashes and a leading dot or quote escaped. */
static void put_escaped(const char *s, size_t n, int *at_line_start)
{
    for (size_t i = 0; i < n; i++) {
        char ch = s[i];
        if (*at_line_start && (ch == '.' || ch == '\''))
            fputs("\\&", out);
        if (ch == '\\')
            fputs("\\e", out);
        else if (ch == '-')
            fputs("\\-", out);
        else
            fputc(ch, out);
        *at_line_start = ch == '\n';
    }
}

/* Whether a `code` or **bold** span is open: they may run over lines. */
static int in_code, in_bold;

/* One line of Markdown text, with its inline markup, as roff. */
static void put_inline(const char *s)
{
    int start = 1;
    while (*s) {
        const char *end;
        if (*s == '`') {
            in_code = !in_code;
            fputs(in_code || in_bold ? "\\fB" : "\\fR", out);
            s++;
        } else if (in_code) {
            put_escaped(s, 1, &start);
            s++;
        } else if (s[0] == '*' && s[1] == '*') {
            in_bold = !in_bold;
            fputs(in_bold ? "\\fB" : "\\fR", out);
            s += 2;
        } else if (*s == '[' && (end = strstr(s, "](")) && strchr(end, ')')
                   && !memchr(s, '`', (size_t)(end - s))) {
            put_escaped(s + 1, (size_t)(end - s - 1), &start);
            s = strchr(end, ')') + 1;
        } else if (s[0] == '\\' && s[1] && strchr("|*_`[]\\", s[1])) {
            /* a Markdown escape: the character itself */
            put_escaped(s + 1, 1, &start);
            s += 2;
        } else {
            put_escaped(s, 1, &start);
            s++;
        }
        start = 0;
    }
    fputc('\n', out);
}

/* A span left open ends with its paragraph. */
static void close_spans(void)
{
    if (in_code || in_bold)
        fputs("\\fR", out);
    in_code = in_bold = 0;
}

/* The cells of a table row "| a | b \| c |", trimmed, in place. */
static int split_cells(char *row, char *cells[MAX_CELLS])
{
    int n = 0;
    char *p = row;
    while (*p == ' ')
        p++;
    if (*p == '|')
        p++;
    while (*p && n < MAX_CELLS) {
        char *c = p;
        while (*p && !(*p == '|' && (p == c || p[-1] != '\\')))
            p++;
        char *e = p;
        if (*p)
            *p++ = '\0';
        while (*c == ' ')
            c++;
        while (e > c && e[-1] == ' ')
            *--e = '\0';
        if (!*p && !*c)
            break;
        cells[n++] = c;
    }
    return n;
}

static int is_separator(const char *s)
{
    for (; *s; s++)
        if (!strchr("|-: ", *s))
            return 0;
    return 1;
}

static void strip_newline(char *s)
{
    size_t n = strlen(s);
    while (n && (s[n - 1] == '\n' || s[n - 1] == '\r'))
        s[--n] = '\0';
}

int main(int argc, char **argv)
{
    if (argc != 7) {
        fprintf(stderr, "usage: rb_mdman IN.md OUT NAME SECTION VERSION DESCRIPTION\n");
        return 2;
    }
    FILE *in = fopen(argv[1], "r");
    out = fopen(argv[2], "w");
    if (!in || !out) {
        fprintf(stderr, "rb_mdman: cannot open %s\n", in ? argv[2] : argv[1]);
        return 1;
    }
    char upper[128];
    size_t k;
    for (k = 0; argv[3][k] && k + 1 < sizeof upper; k++)
        upper[k] = (char)toupper((unsigned char)argv[3][k]);
    upper[k] = '\0';
    fprintf(out, ".\\\" Made from %s by rb_mdman: edit that file, not this one.\n",
            strrchr(argv[1], '/') ? strrchr(argv[1], '/') + 1 : argv[1]);
    fprintf(out, ".TH \"%s\" \"%s\" \"\" \"rockbolt %s\" \"rockbolt manual\"\n", upper,
            argv[4], argv[5]);
    fprintf(out, ".SH NAME\n%s \\- ", argv[3]);
    put_inline(argv[6]);
    /* left-aligned and unhyphenated: keys and units are copied from it */
    fputs(".nh\n.ad l\n.SH DESCRIPTION\n", out);

    char line[LINE_MAX_LEN], header[LINE_MAX_LEN];
    char *heads[MAX_CELLS];
    int n_heads = 0, in_fence = 0, in_table = 0, in_list = 0, para = 0, in_indent = 0;
    int lineno = 0;
    while (fgets(line, sizeof line, in)) {
        lineno++;
        strip_newline(line);
        if (lineno == 1 && line[0] == '#' && line[1] == ' ')
            continue;  /* the title is the NAME line */
        if (strncmp(line, "```", 3) == 0) {
            fputs(in_fence ? ".fi\n.RE\n" : ".PP\n.RS 4\n.nf\n", out);
            in_fence = !in_fence;
            para = 1;
            continue;
        }
        if (in_fence) {
            int start = 1;
            put_escaped(line, strlen(line), &start);
            fputc('\n', out);
            continue;
        }
        if (line[0] == '|') {
            char *cells[MAX_CELLS];
            if (!in_table) {
                /* the header row: its cells name the columns */
                memcpy(header, line, sizeof header);
                n_heads = split_cells(header, heads);
                in_table = 1;
                continue;
            }
            if (is_separator(line))
                continue;
            int n = split_cells(line, cells);
            close_spans();
            fputs(".TP\n", out);
            put_inline(n ? cells[0] : "");
            int first = 1;
            for (int i = 1; i < n; i++) {
                if (!cells[i][0])
                    continue;
                if (!first)
                    fputs(".br\n", out);
                first = 0;
                fputs("\\fI", out);
                int start = 0;
                const char *h = i < n_heads ? heads[i] : "";
                /* a header in backticks is a key name: shown plain */
                char hb[256];
                snprintf(hb, sizeof hb, "%s", h);
                for (char *q = hb; *q; q++)
                    if (*q == '`')
                        memmove(q, q + 1, strlen(q));
                put_escaped(hb, strlen(hb), &start);
                fputs("\\fR: ", out);
                put_inline(cells[i]);
            }
            continue;
        }
        if (in_table) {
            in_table = 0;
            para = 1;
        }
        if (line[0] == '\0') {
            close_spans();
            if (in_indent) {
                fputs(".fi\n.RE\n", out);
                in_indent = 0;
            }
            in_list = 0;
            para = 1;
            continue;
        }
        if (line[0] == '#')  /* code spans in headings: plain */
            for (char *q = line; *q; q++)
                if (*q == '`')
                    memmove(q, q + 1, strlen(q));
        if (strncmp(line, "### ", 4) == 0) {
            fputs(".SS \"", out);
            int start = 0;
            put_escaped(line + 4, strlen(line + 4), &start);
            fputs("\"\n", out);
            para = 0;
            continue;
        }
        if (strncmp(line, "## ", 3) == 0) {
            fputs(".SH \"", out);
            int start = 0;
            for (char *q = line + 3; *q; q++)
                *q = (char)toupper((unsigned char)*q);
            put_escaped(line + 3, strlen(line + 3), &start);
            fputs("\"\n", out);
            para = 0;
            continue;
        }
        if (strncmp(line, "    ", 4) == 0 && !in_list && (para || in_indent)) {
            if (!in_indent)
                fputs(".PP\n.RS 4\n.nf\n", out);
            in_indent = 1;
            para = 0;
            int start = 1;
            put_escaped(line + 4, strlen(line + 4), &start);
            fputc('\n', out);
            continue;
        }
        if (line[0] == '-' && line[1] == ' ') {
            fputs(".IP \\(bu 2\n", out);
            put_inline(line + 2);
            in_list = 1;
            para = 0;
            continue;
        }
        if (para) {
            fputs(".PP\n", out);
            para = 0;
        }
        const char *t = line;
        while (*t == ' ')
            t++;
        put_inline(t);
    }
    if (in_fence || in_indent)
        fputs(".fi\n.RE\n", out);
    fputs(".SH SEE ALSO\n.BR rockbolt (1)\n", out);
    int bad = ferror(in) || ferror(out);
    fclose(in);
    if (fclose(out) != 0 || bad) {
        fprintf(stderr, "rb_mdman: cannot write %s\n", argv[2]);
        return 1;
    }
    return 0;
}
