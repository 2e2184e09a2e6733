/* The PDF calculation package (library rb_pdf, docs/pdf.md): what a
 * reviewer files. Pages are laid out with pango and drawn with cairo; the
 * figures are the commands' own SVGs, drawn by librsvg as vectors.
 *
 * A package is a cover block (the case's project: section, the case, the
 * tool and the verdict), a body in a light markup (docs/pdf.md; for check
 * and design the template calc.txt, filled with the text report's
 * variables so that both give the same numbers in the same units), the
 * figures, and the statement of what the tool does not check. Every page
 * says "Page n of m". Nothing here prints or writes files: the renderers
 * return the document's bytes. */
#ifndef ROCKBOLT_PDF_H
#define ROCKBOLT_PDF_H

#include <stddef.h>
#include "rockbolt/case.h"
#include "rockbolt/report.h"
#include "rockbolt/status.h"

/* What the cover block and the page footers say. */
typedef struct {
    const char *title;              /* "Seismic anchorage check" */
    const rb_case_project *project; /* NULL: none given */
    const char *case_name;          /* NULL: no case (a batch) */
    const char *case_path;
    const char *verdict;            /* one line; NULL: none */
    rb_unit_system units;           /* US customary: Letter paper, else A4 */
} rb_pdf_cover;

/* The document of cover, body (markup) and figures (n SVG documents,
 * drawn where the body says "@figures"). *out is a new buffer of *len
 * bytes the caller frees. RB_ERR_INVALID when a figure cannot be read
 * (diag says which), RB_ERR_NOMEM, RB_ERR_IO when cairo fails. */
rb_status rb_pdf_render(const rb_pdf_cover *cv, const char *body,
                        const char *const *svgs, size_t n_svgs,
                        char **out, size_t *len, rb_diag *diag);

/* check and design: the body is tmpl (calc.txt, rb_template_load) filled
 * with r's variables; command is "check" or "design". Template errors are
 * RB_ERR_PARSE with the template's line and column in diag. */
rb_status rb_report_render_pdf(const rb_report *r, const char *command, const char *tmpl,
                               const char *const *svgs, size_t n_svgs,
                               char **out, size_t *len, rb_diag *diag);

/* A command's table printed as it is on the terminal (fragility, the
 * batch summary), under a heading, then its figures. */
rb_status rb_table_render_pdf(const rb_pdf_cover *cv, const char *heading, const char *text,
                              const char *const *svgs, size_t n_svgs,
                              char **out, size_t *len, rb_diag *diag);

#endif
