/* What the files of src/pdf share: the body's markup parsed into blocks
 * (pdf_markup.c), which pdf_doc.c lays out on pages. Private to src/pdf. */
#ifndef RB_PDF_INTERNAL_H
#define RB_PDF_INTERNAL_H

#include <stddef.h>
#include "rockbolt/pdf.h"
#include "util/strbuf.h"

typedef enum {
    RB_PDF_TITLE,     /* "= " the document's title */
    RB_PDF_H1,        /* "# " */
    RB_PDF_H2,        /* "## " */
    RB_PDF_H3,        /* "!! " a check's heading */
    RB_PDF_EMPH,      /* "! " a paragraph in bold */
    RB_PDF_PARA,      /* any other line */
    RB_PDF_BULLET,    /* "- " */
    RB_PDF_EQ,        /* "> " an equation with its numbers */
    RB_PDF_TABLE,     /* "|" lines; "|=" a heading row */
    RB_PDF_PRE,       /* between "```" lines: text as printed */
    RB_PDF_FIGURES,   /* "@figures" */
    RB_PDF_NEWPAGE,   /* "@newpage" */
    RB_PDF_SPACE      /* a blank line */
} rb_pdf_kind;

typedef struct {
    char **cells;     /* owned, trimmed */
    size_t n;
    int head;
} rb_pdf_row;

typedef struct {
    rb_pdf_kind kind;
    char *text;       /* owned: the text; PRE: its lines joined by '\n' */
    rb_pdf_row *rows; /* TABLE: owned */
    size_t n_rows, cap_rows;
    size_t n_cols;    /* TABLE: the cells of its first row */
} rb_pdf_block;

typedef struct {
    rb_pdf_block *b;
    size_t n, cap;
} rb_pdf_blocks;

/* Parse markup (docs/pdf.md) into blocks. A table row with more cells
 * than the table's first row has the rest joined, with their "|", into
 * its last cell, so that text from a case (a name with a "|") cannot
 * shift a table's columns. RB_ERR_NOMEM. */
rb_status rb_pdf_parse(const char *markup, rb_pdf_blocks *out);
void rb_pdf_blocks_free(rb_pdf_blocks *b);

/* The cover block and the statement of what is not checked, as markup. */
void rb_pdf_cover_markup(rb_strbuf *b, const rb_pdf_cover *cv);
void rb_pdf_limits_markup(rb_strbuf *b);

#endif
