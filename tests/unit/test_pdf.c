/* The PDF writer (src/pdf): the body's markup parsed into blocks (tables
 * that text from a case cannot shift, text as printed, every prefix), and
 * documents whose page count is known from the markup: one page per
 * @newpage more, each a /Type /Page object of the file; a figure librsvg
 * cannot read is an error naming it, with nothing returned. */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>
#include "harness.h"
#include "pdf/pdf_internal.h"

static void test_parse(void)
{
    rb_pdf_blocks bs;
    const char *mk = "= Title\n# One\n## One.one\n!! 17.6.1 steel\n! bold\n- item\n"
                     "> N = 1 x 2\n|= a | b | c\n| 1 | 2 | x|y|z\n| 3\n\n```\n  col  \n"
                     "| not a table\n```\n@figures\n@newpage\nplain text\n";
    CHECK(rb_pdf_parse(mk, &bs) == RB_OK);
    static const rb_pdf_kind want[] = {
        RB_PDF_TITLE, RB_PDF_H1, RB_PDF_H2, RB_PDF_H3, RB_PDF_EMPH, RB_PDF_BULLET,
        RB_PDF_EQ, RB_PDF_TABLE, RB_PDF_SPACE, RB_PDF_PRE, RB_PDF_FIGURES,
        RB_PDF_NEWPAGE, RB_PDF_PARA};
    CHECK(bs.n == sizeof want / sizeof want[0]);
    for (size_t i = 0; i < bs.n && i < sizeof want / sizeof want[0]; i++)
        CHECK(bs.b[i].kind == want[i]);
    CHECK(strcmp(bs.b[0].text, "Title") == 0);
    CHECK(strcmp(bs.b[3].text, "17.6.1 steel") == 0);
    CHECK(strcmp(bs.b[6].text, "N = 1 x 2") == 0);
    const rb_pdf_block *t = &bs.b[7];
    CHECK(t->n_rows == 3 && t->n_cols == 3);
    CHECK(t->rows[0].head && !t->rows[1].head);
    CHECK(strcmp(t->rows[0].cells[2], "c") == 0);
    /* the extra cells, bars and all, stay in the last one */
    CHECK(t->rows[1].n == 3 && strcmp(t->rows[1].cells[2], "x|y|z") == 0);
    CHECK(t->rows[2].n == 1 && strcmp(t->rows[2].cells[0], "3") == 0);
    /* text as printed keeps its spaces and its bars */
    CHECK(strcmp(bs.b[9].text, "  col  \n| not a table") == 0);
    CHECK(strcmp(bs.b[12].text, "plain text") == 0);
    rb_pdf_blocks_free(&bs);
}

/* Page objects in a PDF as cairo writes them ("/Type /Page", not
 * "/Type /Pages"). */
static int count_pages(const char *doc, size_t len)
{
    int n = 0;
    const char *key = "/Type /Page";
    size_t k = strlen(key);
    for (size_t i = 0; i + k < len; i++)
        if (memcmp(doc + i, key, k) == 0 && doc[i + k] != 's')
            n++;
    return n;
}

static void test_pages(void)
{
    rb_case_project pr = {0};
    pr.project = "Hospital";
    pr.given = 1;
    rb_pdf_cover cv = {"Test", &pr, "case", "case.yaml", "PASS", RB_UNITS_SI};
    char *doc = NULL;
    size_t len = 0;
    rb_diag d;
    int one = 0;
    for (int n_new = 0; n_new <= 3; n_new++) {
        char body[256] = "# A\ntext\n";
        for (int k = 0; k < n_new; k++)
            strcat(body, "@newpage\n# More\ntext\n");
        rb_diag_clear(&d);
        CHECK(rb_pdf_render(&cv, body, NULL, 0, &doc, &len, &d) == RB_OK);
        CHECK(doc && len > 5 && memcmp(doc, "%PDF-", 5) == 0);
        int pages = doc ? count_pages(doc, len) : 0;
        if (n_new == 0)
            one = pages;
        CHECK(one >= 1 && pages == one + n_new);
        free(doc);
        doc = NULL;
    }
    /* a figure that is not SVG: named, nothing returned */
    const char *svgs[2] = {"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"10\" "
                           "height=\"10\"><rect width=\"5\" height=\"5\"/></svg>",
                           "not svg at all"};
    rb_diag_clear(&d);
    CHECK(rb_pdf_render(&cv, "@figures\n", svgs, 2, &doc, &len, &d) == RB_ERR_INVALID);
    CHECK(doc == NULL && len == 0);
    CHECK(strstr(d.msg, "figure 2") != NULL);
    rb_diag_clear(&d);
    CHECK(rb_pdf_render(&cv, "@figures\n", svgs, 1, &doc, &len, &d) == RB_OK);
    free(doc);
}

int main(void)
{
    test_parse();
    test_pages();
    TEST_MAIN_END();
}
