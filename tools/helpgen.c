/* helpgen: turns src/cli/help.txt, the one source of rockbolt's help, into
 * the C text of --help (cli_help_text.c) and the rockbolt(1) man page, so
 * the two cannot disagree. Run by the build:
 *
 *   helpgen HELP.txt VERSION OUT.c OUT.1 OUT.bash OUT.zsh
 *
 * The last two are the bash and zsh completions, from the same options.
 * The format is described at the top of help.txt. Exit 1 with a message
 * naming the line on a malformed source. */
#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define MAX_LINES 2000
#define MAX_CMDS 16
#define MAX_ITEMS 40
#define MAX_SECTS 16

typedef struct {
    char *term;             /* option spec or item term */
    char *body[16];         /* description lines */
    int n_body;
} item;

typedef struct {
    char *name;
    char *usage[8];
    int n_usage;
    char *summary[8];
    int n_summary;
    char *text[64];         /* "" separates paragraphs */
    int n_text;
    item items[MAX_ITEMS];  /* options */
    int n_items;
} command;

typedef struct {
    char *title;
    item items[MAX_ITEMS];
    int n_items;
} section;

static char *name_line;
static char *intro[64];
static int n_intro;
static command cmds[MAX_CMDS];
static int n_cmds;
static section sects[MAX_SECTS];
static int n_sects;
static const char *src_path;
static int src_line;

static void die(const char *fmt, ...)
{
    va_list ap;
    fprintf(stderr, "%s:%d: error: ", src_path, src_line);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
    exit(1);
}

static char *dup(const char *s)
{
    char *p = malloc(strlen(s) + 1);
    if (!p)
        die("out of memory");
    strcpy(p, s);
    return p;
}

/* The text after "@word " or NULL when line is not that directive. */
static const char *directive(const char *line, const char *word)
{
    size_t n = strlen(word);
    if (line[0] != '@' || strncmp(line + 1, word, n) != 0)
        return NULL;
    if (line[n + 1] == '\0')
        return line + n + 1;
    if (line[n + 1] == ' ')
        return line + n + 2;
    return NULL;
}

enum { IN_NONE, IN_INTRO, IN_SUMMARY, IN_TEXT, IN_OPTION, IN_ITEM };

static void push(char **arr, int *n, int max, const char *s)
{
    if (*n >= max)
        die("too many lines in this block (at most %d)", max);
    arr[(*n)++] = dup(s);
}

static void parse(FILE *fp)
{
    char buf[512];
    int state = IN_NONE;
    command *c = NULL;
    section *s = NULL;
    item *it = NULL;
    const char *v;
    while (fgets(buf, sizeof buf, fp)) {
        size_t len = strlen(buf);
        src_line++;
        if (len && buf[len - 1] == '\n')
            buf[--len] = '\0';
        if (buf[0] == '#')
            continue;
        if (buf[0] == '@') {
            if ((v = directive(buf, "name"))) {
                name_line = dup(v);
                state = IN_NONE;
            } else if (directive(buf, "intro")) {
                state = IN_INTRO;
            } else if ((v = directive(buf, "command"))) {
                if (n_cmds >= MAX_CMDS)
                    die("too many commands");
                c = &cmds[n_cmds++];
                c->name = dup(v);
                s = NULL;
                state = IN_NONE;
            } else if ((v = directive(buf, "usage"))) {
                if (!c)
                    die("@usage outside a @command");
                push(c->usage, &c->n_usage, 8, v);
            } else if (directive(buf, "summary")) {
                if (!c)
                    die("@summary outside a @command");
                state = IN_SUMMARY;
            } else if (directive(buf, "text")) {
                if (!c)
                    die("@text outside a @command");
                state = IN_TEXT;
            } else if ((v = directive(buf, "option"))) {
                if (!c || s)
                    die("@option outside a @command");
                if (c->n_items >= MAX_ITEMS)
                    die("too many options");
                it = &c->items[c->n_items++];
                it->term = dup(v);
                state = IN_OPTION;
            } else if ((v = directive(buf, "section"))) {
                if (n_sects >= MAX_SECTS)
                    die("too many sections");
                s = &sects[n_sects++];
                s->title = dup(v);
                c = NULL;
                state = IN_NONE;
            } else if ((v = directive(buf, "item"))) {
                if (!s)
                    die("@item outside a @section");
                if (s->n_items >= MAX_ITEMS)
                    die("too many items");
                it = &s->items[s->n_items++];
                it->term = dup(v);
                state = IN_ITEM;
            } else {
                die("unknown directive '%s'", buf);
            }
            continue;
        }
        if (len > 76)
            die("line longer than 76 columns");
        switch (state) {
        case IN_INTRO:
            push(intro, &n_intro, 64, buf);
            break;
        case IN_SUMMARY:
            if (len)
                push(c->summary, &c->n_summary, 8, buf);
            break;
        case IN_TEXT:
            push(c->text, &c->n_text, 64, buf);
            break;
        case IN_OPTION:
        case IN_ITEM:
            if (len > 56)
                die("description line longer than 56 columns");
            if (len)
                push(it->body, &it->n_body, 16, buf);
            break;
        default:
            if (len)
                die("text outside a block");
        }
    }
    if (!name_line || !n_cmds)
        die("no @name or no @command");
    for (int i = 0; i < n_cmds; i++)
        if (!cmds[i].n_usage || !cmds[i].n_summary)
            die("command '%s' needs @usage and @summary", cmds[i].name);
}

/* ---- the C text ---- */

static FILE *out;

static void c_str(const char *s)
{
    fputc('"', out);
    for (; *s; s++) {
        if (*s == '"' || *s == '\\')
            fputc('\\', out);
        fputc(*s, out);
    }
    fputc('"', out);
}

/* One line of the help text, printf-style. */
static void c_line(const char *fmt, ...)
{
    char buf[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    fputs("    ", out);
    c_str(buf);
    fputs(",\n", out);
}

/* Blocks of text with trailing blank lines dropped. */
static int trimmed(char **lines, int n)
{
    while (n > 0 && !lines[n - 1][0])
        n--;
    return n;
}

static void c_items(const item *items, int n, int width)
{
    for (int i = 0; i < n; i++) {
        const item *it = &items[i];
        int w = (int)strlen(it->term);
        if (w > width) {
            c_line("  %s", it->term);
            for (int k = 0; k < it->n_body; k++)
                c_line("  %*s  %s", width, "", it->body[k]);
            continue;
        }
        c_line("  %-*s  %s", width, it->term, it->n_body ? it->body[0] : "");
        for (int k = 1; k < it->n_body; k++)
            c_line("  %*s  %s", width, "", it->body[k]);
    }
}

static int items_width(const item *items, int n, int cap)
{
    int w = 0;
    for (int i = 0; i < n; i++) {
        int l = (int)strlen(items[i].term);
        if (l > w && l <= cap)
            w = l;
    }
    return w;
}

/* The long and short names an option spec declares: "-q, --quiet",
 * "--json FILE" -> "-q" "--quiet", "--json". */
static void c_option_names(const char *spec)
{
    char buf[128];
    snprintf(buf, sizeof buf, "%s", spec);
    for (char *tok = strtok(buf, ", "); tok; tok = strtok(NULL, ", "))
        if (tok[0] == '-') {
            fputs("    ", out);
            c_str(tok);
            fputs(",\n", out);
        }
}

static void write_c(const char *path)
{
    if (!(out = fopen(path, "w")))
        die("cannot write %s", path);
    fprintf(out, "/* Generated by tools/helpgen.c from src/cli/help.txt; do not edit. */\n");
    fprintf(out, "#include <stddef.h>\n#include \"cli_help.h\"\n\n");
    for (int i = 0; i < n_cmds; i++) {
        command *c = &cmds[i];
        fprintf(out, "static const char *const help_%s[] = {\n", c->name);
        for (int k = 0; k < c->n_usage; k++)
            c_line("%s%s", k ? "       " : "usage: ", c->usage[k]);
        c_line("");
        int nt = trimmed(c->text, c->n_text);
        for (int k = 0; k < nt; k++)
            c_line("%s", c->text[k]);
        if (c->n_items) {
            c_line("");
            c_line("options:");
            c_items(c->items, c->n_items, items_width(c->items, c->n_items, 18));
        }
        fputs("    NULL\n};\n\n", out);
        fprintf(out, "static const char *const opts_%s[] = {\n", c->name);
        for (int k = 0; k < c->n_items; k++)
            c_option_names(c->items[k].term);
        fputs("    NULL\n};\n\n", out);
    }
    fputs("const rb_help_command rb_help_commands[] = {\n", out);
    for (int i = 0; i < n_cmds; i++) {
        fputs("    {", out);
        c_str(cmds[i].name);
        fprintf(out, ", help_%s, opts_%s},\n", cmds[i].name, cmds[i].name);
    }
    fputs("    {NULL, NULL, NULL}\n};\n\n", out);

    fputs("const char *const rb_help_overview[] = {\n", out);
    int first = 1;
    for (int i = 0; i < n_cmds; i++)
        for (int k = 0; k < cmds[i].n_usage; k++) {
            c_line("%s%s", first ? "usage: " : "       ", cmds[i].usage[k]);
            first = 0;
        }
    c_line("       rockbolt --help | --version");
    c_line("");
    int ni = trimmed(intro, n_intro);
    for (int k = 0; k < ni; k++)
        c_line("%s", intro[k]);
    c_line("");
    c_line("commands:");
    for (int i = 0; i < n_cmds; i++) {
        command *c = &cmds[i];
        const char *u = c->usage[0] + strlen("rockbolt ");
        char term[64];
        /* the command and its positional arguments, up to the options */
        size_t n = strcspn(u, "[");
        if (u[n] == '[' && isupper((unsigned char)u[n + 1]))
            n += strcspn(u + n, "]") + 1;
        snprintf(term, sizeof term, "%.*s", (int)n, u);
        for (size_t l = strlen(term); l && term[l - 1] == ' '; l--)
            term[l - 1] = '\0';
        if (strlen(term) > 17) {
            c_line("  %s", term);
            c_line("  %-17s %s", "", c->summary[0]);
        } else {
            c_line("  %-17s %s", term, c->summary[0]);
        }
        for (int k = 1; k < c->n_summary; k++)
            c_line("  %-17s %s", "", c->summary[k]);
    }
    c_line("");
    c_line("Each command's usage and options: rockbolt help COMMAND, or");
    c_line("rockbolt COMMAND --help. The manual: man rockbolt.");
    for (int i = 0; i < n_sects; i++) {
        c_line("");
        c_line("%s:", sects[i].title);
        c_items(sects[i].items, sects[i].n_items,
                items_width(sects[i].items, sects[i].n_items, 18));
    }
    fputs("    NULL\n};\n", out);
    if (fclose(out) != 0)
        die("cannot write %s", path);
}

/* ---- the man page ---- */

/* Text with roff's specials escaped; a leading '.' or '\'' guarded. */
static void roff(const char *s)
{
    if (*s == '.' || *s == '\'')
        fputs("\\&", out);
    for (; *s; s++) {
        if (*s == '\\')
            fputs("\\e", out);
        else if (*s == '-')
            fputs("\\-", out);
        else
            fputc(*s, out);
    }
}

/* An option spec in bold with its argument in italics. */
static void roff_term(const char *spec)
{
    fputs(".TP\n", out);
    const char *p = spec;
    while (*p) {
        size_t n = strcspn(p, " ,");
        char word[128];
        snprintf(word, sizeof word, "%.*s", (int)n, p);
        int arg = word[0] && word[0] != '-' && isupper((unsigned char)word[0])
                  && strchr(spec, '-') == spec;
        fputs(arg ? "\\fI" : "\\fB", out);
        roff(word);
        fputs("\\fR", out);
        p += n;
        while (*p == ' ' || *p == ',') {
            fputc(*p, out);
            p++;
        }
    }
    fputc('\n', out);
}

static void roff_paragraphs(char **lines, int n)
{
    int open = 0;
    for (int k = 0; k < n; k++) {
        if (!lines[k][0]) {
            open = 0;
            continue;
        }
        if (!open)
            fputs(".PP\n", out);
        open = 1;
        roff(lines[k]);
        fputc('\n', out);
    }
}

static void roff_items(const item *items, int n)
{
    for (int i = 0; i < n; i++) {
        roff_term(items[i].term);
        for (int k = 0; k < items[i].n_body; k++) {
            roff(items[i].body[k]);
            fputc('\n', out);
        }
    }
}

static void upper(char *dst, size_t size, const char *s)
{
    size_t i;
    for (i = 0; s[i] && i + 1 < size; i++)
        dst[i] = (char)toupper((unsigned char)s[i]);
    dst[i] = '\0';
}

static void write_man(const char *path, const char *version)
{
    char title[128];
    if (!(out = fopen(path, "w")))
        die("cannot write %s", path);
    fputs(".\\\" Generated by tools/helpgen.c from src/cli/help.txt; do not edit.\n", out);
    fprintf(out, ".TH ROCKBOLT 1 \"\" \"rockbolt %s\" \"User Commands\"\n", version);
    fputs(".SH NAME\nrockbolt \\- ", out);
    roff(name_line);
    fputs("\n.SH SYNOPSIS\n.nf\n", out);
    for (int i = 0; i < n_cmds; i++)
        for (int k = 0; k < cmds[i].n_usage; k++) {
            roff(cmds[i].usage[k]);
            fputc('\n', out);
        }
    fputs("rockbolt \\-\\-help | \\-\\-version\n.fi\n.SH DESCRIPTION\n", out);
    roff_paragraphs(intro, n_intro);
    fputs(".PP\nOne section below describes each command and every option it "
          "takes; \\fBrockbolt help\\fR \\fICOMMAND\\fR prints the same.\n", out);
    for (int i = 0; i < n_cmds; i++) {
        command *c = &cmds[i];
        upper(title, sizeof title, c->name);
        fprintf(out, ".SH \"ROCKBOLT %s\"\n.nf\n", title);
        for (int k = 0; k < c->n_usage; k++) {
            roff(c->usage[k]);
            fputc('\n', out);
        }
        fputs(".fi\n", out);
        roff_paragraphs(c->text, c->n_text);
        if (c->n_items) {
            fputs(".SS Options\n", out);
            roff_items(c->items, c->n_items);
        }
    }
    for (int i = 0; i < n_sects; i++) {
        upper(title, sizeof title, sects[i].title);
        fprintf(out, ".SH \"%s\"\n", title);
        roff_items(sects[i].items, sects[i].n_items);
    }
    fputs(".SH \"SEE ALSO\"\nThe documentation in the source distribution: "
          "README.md and docs/ (the case file, the reports, batch review, "
          "design, the solver).\n", out);
    if (fclose(out) != 0)
        die("cannot write %s", path);
}

/* ---- completions ---- */

/* The option names of a spec and the kind of value it takes: 0 none, 'f'
 * a file, 'd' a directory, 'x' something else. */
static int spec_names(const char *spec, char names[4][64], int *n)
{
    char buf[128];
    int kind = 0;
    *n = 0;
    snprintf(buf, sizeof buf, "%s", spec);
    for (char *tok = strtok(buf, ", "); tok; tok = strtok(NULL, ", ")) {
        if (tok[0] == '-' && *n < 4)
            snprintf(names[(*n)++], 64, "%s", tok);
        else if (!strcmp(tok, "DIR"))
            kind = 'd';
        else if (!strcmp(tok, "FILE") || !strcmp(tok, "CASE"))
            kind = 'f';
        else
            kind = 'x';
    }
    return kind;
}

static void write_bash(const char *path)
{
    char names[4][64];
    int n;
    if (!(out = fopen(path, "w")))
        die("cannot write %s", path);
    fputs("# bash completion for rockbolt. Generated by tools/helpgen.c from\n"
          "# src/cli/help.txt; do not edit.\n"
          "_rockbolt() {\n"
          "    local cur prev cmd opts\n"
          "    cur=${COMP_WORDS[COMP_CWORD]}\n"
          "    prev=${COMP_WORDS[COMP_CWORD-1]}\n"
          "    if [ \"$COMP_CWORD\" -eq 1 ]; then\n"
          "        COMPREPLY=($(compgen -W \"", out);
    for (int i = 0; i < n_cmds; i++)
        fprintf(out, "%s ", cmds[i].name);
    fputs("--help --version\" -- \"$cur\"))\n        return\n    fi\n"
          "    cmd=${COMP_WORDS[1]}\n    case \"$cmd $prev\" in\n", out);
    for (int i = 0; i < n_cmds; i++)
        for (int k = 0; k < cmds[i].n_items; k++) {
            int kind = spec_names(cmds[i].items[k].term, names, &n);
            if (!kind)
                continue;
            fputs("        ", out);
            for (int j = 0; j < n; j++)
                fprintf(out, "%s\"%s %s\"", j ? "|" : "", cmds[i].name, names[j]);
            fprintf(out, ")\n            %s\n            return ;;\n",
                    kind == 'f' ? "COMPREPLY=($(compgen -f -- \"$cur\"))"
                    : kind == 'd' ? "COMPREPLY=($(compgen -d -- \"$cur\"))"
                    : "COMPREPLY=()");
        }
    fputs("    esac\n    case \"$cmd\" in\n", out);
    for (int i = 0; i < n_cmds; i++) {
        fprintf(out, "        %s) opts=\"", cmds[i].name);
        for (int k = 0; k < cmds[i].n_items; k++) {
            spec_names(cmds[i].items[k].term, names, &n);
            for (int j = 0; j < n; j++)
                fprintf(out, "%s%s", k || j ? " " : "", names[j]);
        }
        fputs("\" ;;\n", out);
    }
    fputs("        *) return ;;\n    esac\n"
          "    if [ \"$cmd\" = help ]; then\n"
          "        COMPREPLY=($(compgen -W \"", out);
    for (int i = 0; i < n_cmds; i++)
        fprintf(out, "%s%s", i ? " " : "", cmds[i].name);
    fputs("\" -- \"$cur\"))\n"
          "    elif [[ $cur == -* ]]; then\n"
          "        COMPREPLY=($(compgen -W \"$opts\" -- \"$cur\"))\n"
          "    else\n"
          "        COMPREPLY=($(compgen -f -- \"$cur\"))\n"
          "    fi\n}\n"
          "complete -o filenames -F _rockbolt rockbolt\n", out);
    if (fclose(out) != 0)
        die("cannot write %s", path);
}

/* A description for zsh: the lines joined, brackets and colons made
 * harmless, quotes escaped. */
static void zsh_desc(char *const *lines, int n)
{
    for (int k = 0; k < n; k++) {
        if (k)
            fputc(' ', out);
        for (const char *s = lines[k]; *s; s++)
            if (*s == '\'')
                fputs("'\\''", out);
            else if (*s == '[')
                fputc('(', out);
            else if (*s == ']')
                fputc(')', out);
            else if (*s == ':')
                fputc(',', out);
            else
                fputc(*s, out);
    }
}

static void write_zsh(const char *path)
{
    char names[4][64];
    int n;
    if (!(out = fopen(path, "w")))
        die("cannot write %s", path);
    fputs("#compdef rockbolt\n# zsh completion for rockbolt. Generated by "
          "tools/helpgen.c from\n# src/cli/help.txt; do not edit.\n\n"
          "_rockbolt() {\n    local -a commands\n    commands=(\n", out);
    for (int i = 0; i < n_cmds; i++) {
        fprintf(out, "        '%s:", cmds[i].name);
        zsh_desc(cmds[i].summary, cmds[i].n_summary);
        fputs("'\n", out);
    }
    fputs("    )\n    if (( CURRENT == 2 )); then\n"
          "        _describe 'command' commands\n        return\n    fi\n"
          "    local cmd=$words[2]\n    shift words\n    (( CURRENT-- ))\n"
          "    case $cmd in\n", out);
    for (int i = 0; i < n_cmds; i++) {
        command *c = &cmds[i];
        fprintf(out, "        %s)\n", c->name);
        if (!strcmp(c->name, "help")) {
            fputs("            _describe 'command' commands ;;\n", out);
            continue;
        }
        fputs("            _arguments -s \\\n", out);
        for (int k = 0; k < c->n_items; k++) {
            int kind = spec_names(c->items[k].term, names, &n);
            for (int j = 0; j < n; j++) {
                fprintf(out, "                '%s[", names[j]);
                zsh_desc(c->items[k].body, c->items[k].n_body);
                fputs("]", out);
                if (kind == 'f')
                    fputs(":file:_files", out);
                else if (kind == 'd')
                    fputs(":directory:_files -/", out);
                else if (kind)
                    fputs(":value: ", out);
                fputs("' \\\n", out);
            }
        }
        fputs("                '*:file:_files' ;;\n", out);
    }
    fputs("    esac\n}\n\n_rockbolt \"$@\"\n", out);
    if (fclose(out) != 0)
        die("cannot write %s", path);
}

int main(int argc, char **argv)
{
    if (argc != 7) {
        fprintf(stderr, "usage: helpgen HELP.txt VERSION OUT.c OUT.1 OUT.bash OUT.zsh\n");
        return 2;
    }
    src_path = argv[1];
    FILE *fp = fopen(argv[1], "r");
    if (!fp) {
        perror(argv[1]);
        return 1;
    }
    parse(fp);
    fclose(fp);
    src_line = 0;
    write_c(argv[3]);
    write_man(argv[4], argv[2]);
    write_bash(argv[5]);
    write_zsh(argv[6]);
    return 0;
}
