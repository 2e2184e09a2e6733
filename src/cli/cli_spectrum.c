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
} outputs;

static char *text_of(const void *ctx)
{
    const outputs *o = ctx;
    return rb_spectra_render_text(o->c, o->s);
}

static char *json_of(const void *ctx)
{
    const outputs *o = ctx;
    return rb_spectra_render_json(o->c, o->s);
}

static char *csv_of(const void *ctx)
{
    const outputs *o = ctx;
    return rb_spectra_render_csv(o->c, o->s);
}

static rb_status figure(const void *ctx, const char *title, char **out, rb_diag *d)
{
    const outputs *o = ctx;
    return rb_plot_spectra_svg(o->c, o->s, title, out, d);
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
        outputs out = {&c, &s};
        rb_cli_renders r = {&out, title, "spectra", text_of, json_of, csv_of, figure,
                           NULL, NULL, NULL, NULL};
        e = rb_cli_emit_case_outputs(o, &p, &r);
    }
    rb_case_spectra_free(&s);
    rb_case_free(&c);
    rb_outplan_free(&p);
    return e;
}
