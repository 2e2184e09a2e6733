/* The summary as JUnit XML, so that CI systems show each case as a test:
 * a case that fails its criteria is a <failure>, one that cannot be read
 * or solved an <error>. No timings: the file is as deterministic as the
 * other summaries.
 *
 * One testcase per case, named by its tag alone (classname: its source),
 * so that a CI's test history follows a cabinet when rows are inserted
 * or its motions change; a list's line is a property, not part of the
 * name. The motions of a case are lines of its <failure>. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "batch_summary.h"
#include "rockbolt/names.h"
#include "rockbolt/report.h"
#include "rockbolt/textsafe.h"

/* Text for XML content and attributes: first the shared escaping of
 * control characters (XML 1.0 allows none but tab and newline, and a
 * reader should see them as \x1b, \r), then XML's own. Newlines that
 * the summary itself puts between lines go through xml_raw. */
static void xml_raw(rb_strbuf *b, const char *s)
{
    for (const unsigned char *p = (const unsigned char *)s; *p; p++) {
        switch (*p) {
        case '&': rb_strbuf_puts(b, "&amp;"); break;
        case '<': rb_strbuf_puts(b, "&lt;"); break;
        case '>': rb_strbuf_puts(b, "&gt;"); break;
        case '"': rb_strbuf_puts(b, "&quot;"); break;
        case '\'': rb_strbuf_puts(b, "&apos;"); break;
        case '\n': rb_strbuf_puts(b, "&#10;"); break;
        default:
            if (*p < 0x20 || *p == 0x7f)
                rb_strbuf_puts(b, "?");   /* unreachable after rb_text_escape */
            else
                rb_strbuf_putn(b, (const char *)p, 1);
        }
    }
}

static void xml_text(rb_strbuf *b, const char *s)
{
    char *t = rb_text_escape(s);
    if (!t) {
        b->oom = 1;
        return;
    }
    xml_raw(b, t);
    free(t);
}

static void property(rb_strbuf *b, const char *name, const char *value)
{
    rb_strbuf_puts(b, "<property name=\"");
    xml_text(b, name);
    rb_strbuf_puts(b, "\" value=\"");
    xml_text(b, value);
    rb_strbuf_puts(b, "\"/>");
}

static void number(rb_strbuf *b, const char *state, const char *what, double v)
{
    char name[64], value[32];
    snprintf(name, sizeof name, "fragility.%s.%s", state, what);
    if (isfinite(v))
        snprintf(value, sizeof value, "%.6g", v);
    else
        value[0] = '\0';
    property(b, name, value);
}

/* The case's fragility as properties, in g, as the CSV has it: a CI can
 * chart them per cabinet. */
static void fragility_properties(rb_strbuf *b, const rb_batch_fragility *f)
{
    char v[32];
    if (f->error) {
        property(b, "fragility.error", f->error);
        return;
    }
    double g = f->g_mps2;
    if (f->im_freq_hz > 0) {
        /* the level and medians are the spectral acceleration there */
        snprintf(v, sizeof v, "%.6g", f->im_freq_hz);
        property(b, "fragility.intensity_freq_hz", v);
    }
    snprintf(v, sizeof v, "%.6g", f->level_mps2 / g);
    property(b, "fragility.level_g", v);
    property(b, "fragility.governing", f->governing >= 0
             ? rb_enum_str(rb_limit_state_names, f->governing) : "none");
    for (int k = 0; k < RB_N_LIMITS; k++) {
        const rb_batch_limit *l = &f->limits[k];
        const char *st = rb_enum_str(rb_limit_state_names, k);
        if (!l->present)
            continue;
        if (l->fitted) {
            number(b, st, "median_g", l->median_mps2 / g);
            number(b, st, "beta", l->beta);
            number(b, st, "median_lo_g", l->median_lo_mps2 / g);
            number(b, st, "median_hi_g", l->median_hi_mps2 / g);
            number(b, st, "p_at_level", l->p_at_level);
        }
        number(b, st, "reached", (double)l->reached);
        number(b, st, "confirmed", l->confirmed != 0);
        number(b, st, "model_limited", (double)l->model_limited);
    }
}

/* A run's numbers in its failure line: ", usage 0.123, ..." for the columns
 * JUnit shows, 3 decimals, n/a where it has none. */
static void run_numbers(rb_strbuf *b, const rb_batch_result *r)
{
    for (size_t k = 0; k < rb_batch_n_columns; k++) {
        const rb_batch_column *col = &rb_batch_columns[k];
        char num[64];
        if (!col->junit)
            continue;
        if (isnan(r->value[k]))
            snprintf(num, sizeof num, ", %s n/a", col->junit);
        else
            snprintf(num, sizeof num, ", %s %.3f", col->junit, r->value[k]);
        xml_raw(b, num);
    }
}

static void junit_case(rb_strbuf *b, const rb_batch_case *c)
{
    rb_strbuf_puts(b, "    <testcase classname=\"");
    xml_text(b, c->source);
    rb_strbuf_puts(b, "\" name=\"");
    xml_text(b, c->tag);
    rb_strbuf_puts(b, "\"");
    unsigned warnings = 0;
    for (size_t m = 0; m < c->n_runs; m++)
        warnings |= c->runs[m].warnings;
    if (c->verdict == RB_BATCH_PASS && !warnings && c->line <= 0 && !c->fragility) {
        rb_strbuf_puts(b, "/>\n");
        return;
    }
    rb_strbuf_puts(b, ">\n");
    /* JUnit has no warning element: a property a CI can gate on, and the
     * headline in the output where people read it */
    char w[80], head[RB_HEADLINE_MAX];
    rb_warnings_names(warnings, w, sizeof w);
    rb_report_headline(c->verdict == RB_BATCH_PASS, warnings, head, sizeof head);
    if (c->line > 0 || warnings || c->fragility) {
        rb_strbuf_puts(b, "      <properties>");
        if (c->line > 0)
            rb_strbuf_printf(b, "<property name=\"line\" value=\"%d\"/>", c->line);
        if (warnings) {
            rb_strbuf_puts(b, "<property name=\"validity_warnings\" value=\"");
            xml_text(b, w);
            rb_strbuf_puts(b, "\"/>");
        }
        if (c->fragility)
            fragility_properties(b, c->fragility);
        rb_strbuf_puts(b, "</properties>\n");
    }
    if (c->verdict == RB_BATCH_PASS) {
        /* only warnings: no failure */
    } else if (c->verdict == RB_BATCH_FAIL) {
        rb_strbuf_puts(b, "      <failure type=\"criteria\" message=\"");
        xml_text(b, c->reason ? c->reason : "");
        rb_strbuf_puts(b, "\">");
        for (size_t m = 0; m < c->n_runs; m++) {
            const rb_batch_result *r = &c->runs[m];
            xml_text(b, r->motion);
            xml_raw(b, r->pass ? ": pass" : ": FAIL");
            run_numbers(b, r);
            xml_raw(b, r->pass ? "\n" : ": ");
            if (!r->pass) {   /* why it fails, as its verdict line says */
                xml_text(b, r->reason ? r->reason : "");
                xml_raw(b, "\n");
            }
        }
        rb_strbuf_puts(b, "</failure>\n");
    } else {
        const rb_diag *e = rb_batch_case_error(c);
        char msg[1400];
        if (e->line > 0)
            snprintf(msg, sizeof msg, "%s:%d:%d: error: %s: %s", e->file, e->line,
                     e->col, e->key, e->msg);
        else
            snprintf(msg, sizeof msg, "%s: error: %s: %s", e->file, e->key, e->msg);
        rb_strbuf_printf(b, "      <error type=\"%s\" message=\"",
                       c->verdict == RB_BATCH_UNREADABLE ? "unreadable" : "error");
        xml_text(b, msg);
        rb_strbuf_printf(b, "\">%zu error%s reported</error>\n", c->n_errors,
                       c->n_errors == 1 ? "" : "s");
    }
    if (warnings) {
        rb_strbuf_puts(b, "      <system-out>");
        xml_text(b, head);
        rb_strbuf_puts(b, "</system-out>\n");
    }
    rb_strbuf_puts(b, "    </testcase>\n");
}

void rb_batch_render_junit_head(rb_strbuf *b, const rb_batch_summary *s,
                                const rb_batch_counts *n)
{
    (void)s;
    size_t errors = n->unreadable + n->errors;
    rb_strbuf_puts(b, "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    rb_strbuf_printf(b, "<testsuites name=\"rockbolt batch\" tests=\"%zu\" failures=\"%zu\""
                   " errors=\"%zu\">\n", n->cases, n->failed, errors);
    rb_strbuf_printf(b, "  <testsuite name=\"rockbolt\" tests=\"%zu\" failures=\"%zu\" "
                   "errors=\"%zu\" skipped=\"0\">\n", n->cases, n->failed, errors);
}

void rb_batch_render_junit_case(rb_strbuf *b, const rb_batch_summary *s, const rb_batch_case *c,
                                size_t pos)
{
    (void)s, (void)pos;
    junit_case(b, c);
}

void rb_batch_render_junit_tail(rb_strbuf *b, const rb_batch_summary *s,
                                const rb_batch_counts *n)
{
    (void)s, (void)n;
    rb_strbuf_puts(b, "  </testsuite>\n</testsuites>\n");
}
