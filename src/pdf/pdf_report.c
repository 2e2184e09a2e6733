/* The calculation packages of the commands: check and design from the
 * template calc.txt filled with the text report's variables (one set of
 * numbers, in the case's units, for both); fragility and the batch
 * summary from the table they print. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "pdf_internal.h"

rb_status rb_report_render_pdf(const rb_report *r, const char *command, const char *tmpl,
                               const char *const *svgs, size_t n_svgs,
                               char **out, size_t *len, rb_diag *diag)
{
    char *body = NULL, title[64], verdict[RB_HEADLINE_MAX + 400];
    rb_strbuf b = {0};
    *out = NULL;
    *len = 0;
    rb_status st = rb_report_render_text(r, tmpl, &body, diag);
    if (st != RB_OK)
        return st;
    if (n_svgs) {
        rb_strbuf_puts(&b, body);
        rb_strbuf_puts(&b, "\n# Figures\n@figures\n");
        free(body);
        if (!(body = rb_strbuf_take(&b)))
            return RB_ERR_NOMEM;
    }
    snprintf(title, sizeof title, "Seismic anchorage %s", strcmp(command, "design") == 0
             ? "design" : "check");
    snprintf(verdict, sizeof verdict, "%s: %s", r->headline, r->reason);
    rb_pdf_cover cv = {title, &r->kase->project, r->kase->name, r->kase->path, verdict,
                       r->kase->output_units};
    st = rb_pdf_render(&cv, body, svgs, n_svgs, out, len, diag);
    free(body);
    return st;
}

rb_status rb_table_render_pdf(const rb_pdf_cover *cv, const char *heading, const char *text,
                              const char *const *svgs, size_t n_svgs,
                              char **out, size_t *len, rb_diag *diag)
{
    rb_strbuf b = {0};
    *out = NULL;
    *len = 0;
    rb_strbuf_printf(&b, "# %s\n```\n", heading);
    /* the text's own "```" lines would end the block early: none of the
     * tool's tables has one, and a case's name cannot start a line */
    rb_strbuf_puts(&b, text);
    rb_strbuf_puts(&b, "\n```\n");
    if (n_svgs)
        rb_strbuf_puts(&b, "# Figures\n@figures\n");
    char *body = rb_strbuf_take(&b);
    if (!body)
        return RB_ERR_NOMEM;
    rb_status st = rb_pdf_render(cv, body, svgs, n_svgs, out, len, diag);
    free(body);
    return st;
}
