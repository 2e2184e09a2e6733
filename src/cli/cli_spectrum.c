/* "rockbolt spectrum CASE.yaml": the response spectra of the case's
 * motions (rb_run_spectra), as a table on stdout and, when asked, JSON,
 * CSV, an SVG figure and an HTML page, all planned and checked before the
 * work and written all or none. Exit 0 when they are computed (a spectrum
 * is not a verdict). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "cli_batch.h"
#include "rockbolt/outplan.h"
#include "rockbolt/plot.h"
#include "rockbolt/run.h"

typedef struct {
    const rb_case *c;
    const rb_case_spectra *s;
    const char *title;
} outputs;

static rb_status page(const outputs *o, char **out, rb_diag *d)
{
    char *svg = NULL, *text = rb_spectra_render_text(o->c, o->s);
    rb_status st = text ? rb_plot_spectra_svg(o->c, o->s, o->title, &svg, d) : RB_ERR_NOMEM;
    if (st == RB_OK) {
        const char *svgs[1] = {svg};
        st = rb_plot_html_page(NULL, o->title, text, svgs, 1, out, d);
    }
    free(svg);
    free(text);
    return st;
}

static rb_status fill(void *ctx, size_t i, FILE *fp, rb_diag *d)
{
    const void *const *cx = ctx;
    const rb_outplan *plan = cx[0];
    const outputs *o = cx[1];
    const char *opt = plan->outs[i].opt;
    char *text = NULL;
    rb_status st = RB_OK;
    if (strcmp(opt, "--json") == 0)
        text = rb_spectra_render_json(o->c, o->s);
    else if (strcmp(opt, "--csv") == 0)
        text = rb_spectra_render_csv(o->c, o->s);
    else if (strcmp(opt, "--svg") == 0)
        st = rb_plot_spectra_svg(o->c, o->s, o->title, &text, d);
    else
        st = page(o, &text, d);
    if (st == RB_OK && !text)
        st = RB_ERR_NOMEM;
    if (st == RB_OK && fputs(text, fp) == EOF)
        st = RB_ERR_IO;
    if (st != RB_OK && !d->msg[0])
        snprintf(d->msg, sizeof d->msg, "%s", rb_status_str(st));
    free(text);
    return st;
}

rb_exit rb_cli_spectrum_run(const rb_cli_opts *o)
{
    rb_outplan p;
    rb_case c;
    rb_case_spectra s;
    char title[256];
    memset(&c, 0, sizeof c);
    memset(&s, 0, sizeof s);
    rb_outplan_init(&p);
    rb_exit e = rb_cli_plan_case_outputs(o, &p);
    if (e == RB_EXIT_PASS)
        e = rb_cli_load_case_planned(o, &c, &p);
    if (e == RB_EXIT_PASS) {
        rb_diag d;
        rb_diag_clear(&d);
        rb_status st = rb_run_spectra(&c, &o->spectrum, &s, &d);
        if (st != RB_OK) {
            rb_cli_error(o->case_path, d.key[0] ? d.key : NULL, "%s", d.msg[0] ? d.msg
                         : rb_status_str(st));
            e = st == RB_ERR_INVALID || st == RB_ERR_LIMIT ? RB_EXIT_USAGE : RB_EXIT_INTERNAL;
        }
    }
    if (e == RB_EXIT_PASS) {
        snprintf(title, sizeof title, "Response spectra of %.200s",
                 c.name ? c.name : "the case");
        outputs out = {&c, &s, title};
        const void *cx[2] = {&p, &out};
        rb_diag d;
        rb_diag_clear(&d);
        if (rb_outplan_write(&p, fill, (void *)cx, &d) != RB_OK) {
            rb_cli_diag_print(&d);
            e = RB_EXIT_INTERNAL;
        }
    }
    if (e == RB_EXIT_PASS && !o->quiet && !rb_outplan_uses_stdout(&p)) {
        char *text = rb_spectra_render_text(&c, &s);
        if (!text || fputs(text, stdout) == EOF || fflush(stdout) != 0) {
            rb_cli_error(NULL, NULL, "cannot write the spectra to standard output");
            e = RB_EXIT_INTERNAL;
        }
        free(text);
    }
    rb_case_spectra_free(&s);
    rb_case_free(&c);
    rb_outplan_free(&p);
    return e;
}
