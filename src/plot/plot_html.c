/* The HTML page of a check: the summary tables, the figures inline and the
 * text report, so the page can be mailed or archived as one file. It is written as XHTML-
 * compatible markup (closed empty elements, only the XML entities) so that
 * an XML parser accepts it as well as a browser. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "plot_internal.h"

/* Readable on a phone (the tables scroll sideways, the figures shrink)
 * and on paper: the summary is the first page, each figure stays whole. */
static const char style[] =
    "body{font-family:\"DejaVu Sans\",Helvetica,Arial,sans-serif;margin:24px;"
    "color:#222222;background:#ffffff}\n"
    "h1{font-size:20px}\nh2{font-size:16px;margin-top:28px}\n"
    "pre{font-family:\"DejaVu Sans Mono\",Menlo,Consolas,monospace;font-size:12px;"
    "background:#f7f7f7;border:1px solid #dddddd;padding:12px;overflow-x:auto}\n"
    "figure{margin:24px 0}\n"
    "svg{max-width:100%;height:auto;border:1px solid #eeeeee}\n"
    ".verdict{font-size:18px;font-weight:bold;padding:8px 12px;display:inline-block}\n"
    ".verdict.pass{background:#e3f4e3;color:#1b5e20}\n"
    ".verdict.fail{background:#fbe4e4;color:#b71c1c}\n"
    ".scroll{overflow-x:auto;margin:16px 0}\n"
    "table{border-collapse:collapse;font-size:13px}\n"
    "caption{text-align:left;font-weight:bold;padding:4px 0}\n"
    "th,td{border:1px solid #cccccc;padding:4px 8px;text-align:left;vertical-align:top}\n"
    "th{background:#f0f0f0;font-weight:normal}\n"
    "td.num{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}\n"
    "td.pass{color:#1b5e20;font-weight:bold}\ntd.fail{color:#b71c1c;font-weight:bold}\n"
    "td.warn{background:#fff4d6}\ntd.governs{font-weight:bold}\n"
    "@media (max-width:600px){body{margin:8px}table{font-size:11px}}\n"
    "@media print{body{margin:0}.scroll{overflow:visible}"
    "section.summary{page-break-after:always}"
    "figure{page-break-inside:avoid}pre{white-space:pre-wrap;border:none}}\n";

/* The <svg> element of a figure, past any XML declaration and whitespace. */
static const char *svg_start(const char *s)
{
    s += strspn(s, " \t\r\n");
    if (strncmp(s, "<?xml", 5) == 0) {
        const char *e = strstr(s, "?>");
        if (!e)
            return NULL;
        s = e + 2;
        s += strspn(s, " \t\r\n");
    }
    return strncmp(s, "<svg", 4) == 0 ? s : NULL;
}

rb_status rb_plot_html_page(const rb_report *rep, const char *title,
                            const char *text_report, const char *const *svgs,
                            size_t n_svgs, char **out, rb_diag *diag)
{
    rb_strbuf b = {0};
    size_t i;
    *out = NULL;
    for (i = 0; i < n_svgs; i++) {
        if (!svgs || !svgs[i] || !svg_start(svgs[i])) {
            if (diag)
                rb_diag_set_msg(diag, "figure %zu is not an <svg> element", i + 1);
            return RB_ERR_INVALID;
        }
    }
    if (!title)
        title = "rockbolt";
    rb_strbuf_puts(&b, "<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\" "
                 "lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n"
                 "<meta name=\"viewport\" content=\"width=device-width, "
                 "initial-scale=1\"/>\n<title>");
    rb_plot_escape(&b, title);
    rb_strbuf_puts(&b, "</title>\n<style>\n");
    rb_strbuf_puts(&b, style);
    rb_strbuf_puts(&b, "</style>\n</head>\n<body>\n<h1>");
    rb_plot_escape(&b, title);
    rb_strbuf_puts(&b, "</h1>\n");
    rb_plot_summary_tables(&b, rep);
    if (n_svgs && rep)
        rb_strbuf_puts(&b, "<h2>Figures</h2>\n");
    for (i = 0; i < n_svgs; i++) {
        rb_strbuf_printf(&b, "<figure class=\"figure\" data-figure=\"%zu\">\n", i + 1);
        rb_strbuf_puts(&b, svg_start(svgs[i]));
        rb_strbuf_puts(&b, "</figure>\n");
    }
    if (text_report) {
        if (rep)
            rb_strbuf_puts(&b, "<h2>Full report</h2>\n");
        rb_strbuf_puts(&b, "<pre class=\"report\">");
        rb_plot_escape(&b, text_report);
        rb_strbuf_puts(&b, "</pre>\n");
    }
    rb_strbuf_puts(&b, "</body>\n</html>\n");
    return rb_plot_finish(&b, out, diag);
}

rb_status rb_plot_report_html(const rb_report *rep, const char *text_report,
                              char **out, rb_diag *diag)
{
    char **svgs;
    char title[512];
    size_t i, n = 0;
    rb_status st = RB_OK;
    *out = NULL;
    if (!rep) {
        if (diag)
            rb_diag_set_msg(diag, "no report to draw");
        return RB_ERR_INVALID;
    }
    svgs = calloc(rep->n_motions ? rep->n_motions : 1, sizeof *svgs);
    if (!svgs) {
        if (diag)
            rb_diag_set_msg(diag, "out of memory while drawing");
        return RB_ERR_NOMEM;
    }
    for (i = 0; i < rep->n_motions && st == RB_OK; i++) {
        const rb_history *h = rep->motions[i].result ? rep->motions[i].result->history
                                                      : NULL;
        if (!h || h->n < 2)
            continue;       /* a motion without a history has no figure */
        st = rb_plot_history_svg(rep, i, &svgs[n], diag);
        if (st == RB_OK)
            n++;
    }
    if (st == RB_OK) {
        snprintf(title, sizeof title, "%s: %.200s", rep->headline,
                 rep->kase && rep->kase->name ? rep->kase->name : "rockbolt check");
        st = rb_plot_html_page(rep, title, text_report, (const char *const *)svgs, n, out,
                               diag);
    }
    for (i = 0; i < n; i++)
        free(svgs[i]);
    free(svgs);
    return st;
}
