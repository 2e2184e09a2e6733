/* "rockbolt check CASE.yaml": load, solve every motion, judge, report;
 * "rockbolt design CASE.yaml" adds the design searches before reporting.
 *
 * Order matters for the exit-code contract: every output is planned and
 * checked (rockbolt/outplan.h) and the case and the template loaded before
 * any solving, so usage and input errors (exit 2) never leave files
 * behind; reports are rendered whole in memory, every output is written to
 * a temporary file and synced, and only then are they all renamed into
 * place. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "cli.h"
#include "util/pool.h"
#include "rockbolt/outplan.h"
#include "rockbolt/pdf.h"
#include "rockbolt/plot.h"
#include "rockbolt/run.h"
#include "rockbolt/template.h"
#include "rockbolt/textsafe.h"


typedef enum { OUT_JSON, OUT_TEXT, OUT_HISTORY, OUT_SWEEP, OUT_SVG, OUT_HTML, OUT_PDF } out_kind;

/* What one output of the plan holds; sweeps are numbered frequency sweeps
 * first, then each motion's amplitude sweeps, in case order; figures each
 * motion's history, then each sweep. */
typedef struct out_file {
    out_kind kind;
    size_t k;                /* SWEEP, SVG: which one */
} out_file;

typedef struct {
    rb_case c;
    rb_result *results;      /* n_motions, owned */
    rb_report_motion *rms;   /* n_motions, owned */
    rb_report rep;
    char *tmpl;              /* report template text, owned */
    const char *tmpl_origin;
    char *json, *text;       /* rendered reports, owned */
    rb_case_design design;   /* design only; owned */
    char **svgs;             /* figures: each motion's history, then each
                                sweep; n_svgs owned strings */
    size_t n_svgs;
    char *html;              /* owned */
    char *calc_tmpl;         /* --pdf: the package's template, owned */
    const char *calc_origin;
    char *pdf;               /* owned: pdf_len bytes */
    size_t pdf_len;
    rb_outplan plan;         /* every output, in the order of outs */
    struct out_file *outs;   /* owned, rb_outplan_count of them */
} check_run;

static void run_free(check_run *r)
{
    size_t i;
    if (r->results)
        for (i = 0; i < r->c.n_motions; i++)
            rb_result_free(&r->results[i]);
    free(r->results);
    free(r->rms);
    free(r->tmpl);
    free(r->json);
    free(r->text);
    rb_case_design_free(&r->design);
    for (i = 0; i < r->n_svgs; i++)
        free(r->svgs[i]);
    free(r->svgs);
    free(r->html);
    free(r->calc_tmpl);
    free(r->pdf);
    free(r->outs);
    rb_outplan_free(&r->plan);
    rb_case_free(&r->c);
}

static rb_exit load_case(const rb_cli_opts *o, check_run *r)
{
    rb_diag_list diags = {0};
    rb_status st = rb_cli_case_load(o, &r->c, &diags);
    size_t i;
    for (i = 0; i < diags.n; i++) {
        if (!diags.items[i].file[0])
            rb_diag_set_file(&diags.items[i], "%s",
                             o->case_path);
        rb_cli_diag_print(&diags.items[i]);
    }
    if (st != RB_OK && diags.n == 0)
        rb_cli_error(o->case_path, NULL, "cannot load the case: %s", rb_status_str(st));
    rb_diag_list_free(&diags);
    if (st == RB_OK)
        return RB_EXIT_PASS;
    return st == RB_ERR_NOMEM ? RB_EXIT_INTERNAL : RB_EXIT_USAGE;
}

/* The derived constants, and the template if a text report is wanted. */
static rb_exit prepare(const rb_cli_opts *o, check_run *r)
{
    rb_diag d;
    rb_status st;
    rb_diag_clear(&d);
    if (rb_model_derive(&r->c.model, &r->rep.derived, &d) != RB_OK) {
        rb_diag_set_file(&d, "%s", o->case_path);
        rb_cli_diag_print(&d);
        return RB_EXIT_USAGE;
    }
    r->results = calloc(r->c.n_motions, sizeof *r->results);
    r->rms = calloc(r->c.n_motions, sizeof *r->rms);
    if (!r->results || !r->rms) {
        rb_cli_error(NULL, NULL, "out of memory");
        return RB_EXIT_INTERNAL;
    }
    /* the PDF's template, before any solving: an unreadable one is exit 2 */
    if (o->pdf_path
        && (st = rb_template_load("calc.txt", &r->calc_tmpl, &r->calc_origin, &d)) != RB_OK) {
        rb_cli_diag_print(&d);
        return st == RB_ERR_IO ? RB_EXIT_USAGE : RB_EXIT_INTERNAL;
    }
    /* the HTML page carries the text report */
    if (!o->text_path && !o->html_path && o->quiet)
        return RB_EXIT_PASS;
    st = rb_template_load("report.txt", &r->tmpl, &r->tmpl_origin, &d);
    if (st != RB_OK) {
        rb_cli_diag_print(&d);
        return st == RB_ERR_IO ? RB_EXIT_USAGE : RB_EXIT_INTERNAL;
    }
    return RB_EXIT_PASS;
}

/* The motions of a case solved side by side: each writes only its own
 * result, report entry and diagnostic. */
typedef struct {
    check_run *r;
    int figures;
    rb_diag *diags;
} motion_jobs;

static rb_status motion_job(void *v, size_t i)
{
    motion_jobs *m = v;
    rb_diag_clear(&m->diags[i]);
    return rb_run_motion(&m->r->c, i, m->figures, &m->r->results[i], &m->r->rms[i],
                         &m->diags[i]);
}

/* Solve and judge every motion; a solver failure is exit 3, reported for
 * the first motion that failed, as if they had been solved in order. */
static rb_exit solve_all(const rb_cli_opts *o, check_run *r)
{
    size_t n = r->c.n_motions;
    motion_jobs m = {r, o->history_path || o->svg_path || o->html_path || o->pdf_path, NULL};
    rb_status *sts = calloc(n ? n : 1, sizeof *sts);
    m.diags = calloc(n ? n : 1, sizeof *m.diags);
    rb_status st = sts && m.diags ? rb_pool_map(n, o->threads, motion_job, &m, sts)
                                  : RB_ERR_NOMEM;
    rb_exit e = RB_EXIT_PASS;
    if (st != RB_OK) {
        rb_cli_error(o->case_path, NULL, "%s", rb_status_str(st));
        e = RB_EXIT_INTERNAL;
    }
    for (size_t i = 0; i < n && e == RB_EXIT_PASS; i++)
        if (sts[i] != RB_OK) {
            const char *name = r->c.motions[i].name;
            char key[128];
            snprintf(key, sizeof key, "motion '%.100s'", name ? name : "?");
            rb_cli_error(o->case_path, key, "%s%s%s", rb_status_str(sts[i]),
                         m.diags[i].msg[0] ? ": " : "", m.diags[i].msg);
            e = RB_EXIT_INTERNAL;
        }
    free(sts);
    free(m.diags);
    if (e == RB_EXIT_PASS)
        rb_run_conclude(&r->c, r->rms, &r->rep);
    return e;
}

static rb_exit render_reports(const rb_cli_opts *o, check_run *r)
{
    rb_diag d;
    rb_status st = RB_OK;
    rb_diag_clear(&d);
    if (o->json_path)
        st = rb_report_render_json(&r->rep, &r->json, &d);
    if (st != RB_OK) {
        rb_diag_set_file(&d, "%s", o->json_path);
        rb_cli_diag_print(&d);
        return RB_EXIT_INTERNAL;
    }
    if (r->tmpl)
        st = rb_report_render_text(&r->rep, r->tmpl, &r->text, &d);
    if (st != RB_OK) {
        int user = strcmp(r->tmpl_origin, "RB_TEMPLATE_DIR") == 0;
        rb_diag_set_file(&d, "%s/report.txt",
                         user ? getenv("RB_TEMPLATE_DIR") : "templates");
        rb_cli_diag_print(&d);
        return user && st == RB_ERR_PARSE ? RB_EXIT_USAGE : RB_EXIT_INTERNAL;
    }
    return RB_EXIT_PASS;
}

static size_t count_sweeps(const rb_case_design *d)
{
    size_t i, n = d->n_sweeps;
    for (i = 0; i < d->n_motions; i++)
        n += d->motions[i].n_sweeps;
    return n;
}

static const rb_sweep *sweep_at(const rb_case_design *d, size_t k)
{
    size_t i;
    if (k < d->n_sweeps)
        return &d->sweeps[k];
    k -= d->n_sweeps;
    for (i = 0; i < d->n_motions; i++) {
        if (k < d->motions[i].n_sweeps)
            return &d->motions[i].sweeps[k];
        k -= d->motions[i].n_sweeps;
    }
    return NULL;
}

/* Figures per motion: its time history, and with bolts its hysteresis. */
static size_t figures_per_motion(const rb_case *c)
{
    return c->model.bolt_model == RB_BOLT_NONE ? 1 : 2;
}

/* The figures (--svg, --html): every motion's time history (and
 * hysteresis), then every sweep, so the numbering of --svg files follows
 * the report's order. */
static rb_exit render_figures(const rb_cli_opts *o, check_run *r)
{
    size_t per = figures_per_motion(&r->c), n_mf = r->c.n_motions * per;
    size_t n_sw = count_sweeps(&r->design), n = n_mf + n_sw, i;
    rb_status st = RB_OK;
    rb_diag d;
    char title[320];
    if (!o->svg_path && !o->html_path && !o->pdf_path)
        return RB_EXIT_PASS;
    if (!(r->svgs = calloc(n ? n : 1, sizeof *r->svgs))) {
        rb_cli_error(NULL, NULL, "out of memory");
        return RB_EXIT_INTERNAL;
    }
    rb_diag_clear(&d);
    for (i = 0; i < n && st == RB_OK; i++, r->n_svgs++) {
        if (i < n_mf) {
            st = i % per == 0 ? rb_plot_history_svg(&r->rep, i / per, &r->svgs[i], &d)
                              : rb_plot_hysteresis_svg(&r->rep, i / per, &r->svgs[i], &d);
            continue;
        }
        const rb_sweep *sw = sweep_at(&r->design, i - n_mf);
        snprintf(title, sizeof title, "%.150s: %s sweep", r->c.name ? r->c.name : "case",
                 sw->kind == RB_SWEEP_FREQUENCY ? "frequency" : "amplitude");
        st = rb_plot_sweep_svg(sw, title, &r->svgs[i], &d);
    }
    if (st == RB_OK && o->html_path) {
        snprintf(title, sizeof title, "rockbolt %s: %.150s, %s",
                 o->command == RB_CMD_DESIGN ? "design" : "check",
                 r->c.name ? r->c.name : "case", r->rep.headline);
        st = rb_plot_html_page(&r->rep, title, r->text, (const char *const *)r->svgs,
                               r->n_svgs, &r->html, &d);
    }
    if (st == RB_OK && o->pdf_path) {
        st = rb_report_render_pdf(&r->rep, o->command == RB_CMD_DESIGN ? "design" : "check",
                                  r->calc_tmpl, (const char *const *)r->svgs, r->n_svgs,
                                  &r->pdf, &r->pdf_len, &d);
        if (st == RB_ERR_PARSE) {
            /* an error of the template, at its line and column */
            int user = strcmp(r->calc_origin, "RB_TEMPLATE_DIR") == 0;
            rb_diag_set_file(&d, "%s/calc.txt",
                             user ? getenv("RB_TEMPLATE_DIR") : "templates");
            rb_cli_diag_print(&d);
            return user ? RB_EXIT_USAGE : RB_EXIT_INTERNAL;
        }
    }
    if (st != RB_OK) {
        rb_cli_error(NULL, d.key[0] ? d.key : NULL, "cannot draw the figures: %s%s%s",
                     rb_status_str(st), d.msg[0] ? ": " : "", d.msg);
        return RB_EXIT_INTERNAL;
    }
    return RB_EXIT_PASS;
}

/* Add one output to the plan (and its kind to r->outs); print on error. */
static rb_exit plan_add(check_run *r, const char *opt, const char *path, out_kind kind,
                        size_t k)
{
    rb_diag d;
    rb_status st;
    out_file *n = realloc(r->outs, (rb_outplan_count(&r->plan) + 1) * sizeof *n);
    if (!n) {
        rb_cli_error(NULL, NULL, "out of memory");
        return RB_EXIT_INTERNAL;
    }
    r->outs = n;
    rb_diag_clear(&d);
    st = rb_outplan_add(&r->plan, opt, path, &d);
    if (st != RB_OK) {
        if (st == RB_ERR_NOMEM)
            rb_cli_error(NULL, NULL, "out of memory");
        else
            rb_cli_diag_print(&d);
        return st == RB_ERR_NOMEM ? RB_EXIT_INTERNAL : RB_EXIT_USAGE;
    }
    r->outs[rb_outplan_count(&r->plan) - 1].kind = kind;
    r->outs[rb_outplan_count(&r->plan) - 1].k = k;
    return RB_EXIT_PASS;
}

static rb_exit plan_input(check_run *r, const char *path)
{
    rb_diag d;
    rb_status st;
    rb_diag_clear(&d);
    st = rb_outplan_add_input(&r->plan, path, &d);
    if (st == RB_OK)
        return RB_EXIT_PASS;
    if (st == RB_ERR_NOMEM)
        rb_cli_error(NULL, NULL, "out of memory");
    else
        rb_cli_diag_print(&d);
    return st == RB_ERR_NOMEM ? RB_EXIT_INTERNAL : RB_EXIT_USAGE;
}

/* Before the case is loaded: the case file and the outputs whose names
 * do not depend on it. */
static rb_exit plan_fixed(const rb_cli_opts *o, check_run *r)
{
    rb_exit e = plan_input(r, o->case_path);
    if (e == RB_EXIT_PASS && o->json_path)
        e = plan_add(r, "--json", o->json_path, OUT_JSON, 0);
    if (e == RB_EXIT_PASS && o->text_path)
        e = plan_add(r, "--text", o->text_path, OUT_TEXT, 0);
    if (e == RB_EXIT_PASS && o->history_path)
        e = plan_add(r, "--history", o->history_path, OUT_HISTORY, 0);
    if (e == RB_EXIT_PASS && o->html_path)
        e = plan_add(r, "--html", o->html_path, OUT_HTML, 0);
    if (e == RB_EXIT_PASS && o->pdf_path)
        e = plan_add(r, "--pdf", o->pdf_path, OUT_PDF, 0);
    return e;
}

/* How many sweeps design will make: known from the case before solving. */
static size_t planned_sweeps(const rb_cli_opts *o, const rb_case *c)
{
    size_t i, n_freq = 0, n_amp = 0;
    if (o->command != RB_CMD_DESIGN)
        return 0;
    for (i = 0; i < c->n_sweeps; i++) {
        n_freq += c->sweeps[i].kind == RB_SWEEP_FREQUENCY;
        n_amp += c->sweeps[i].kind == RB_SWEEP_AMPLITUDE;
    }
    return n_freq + c->n_motions * n_amp;
}

/* A numbered series of n files cannot be one stream ("-", /dev/stdout, a
 * device): its names would be "--1", "/dev/stdout-1". Refused, naming how
 * many files the run makes, unless there is one. */
static rb_exit refuse_stream_series(const char *opt, const char *path, size_t n,
                                    const char *what)
{
    if (n <= 1 || (strcmp(path, "-") != 0 && strncmp(path, "/dev/", 5) != 0))
        return RB_EXIT_PASS;
    rb_cli_error(path, opt, "this run writes %zu %s, as FILE-1 to FILE-%zu, and '%s' "
                 "takes one; give a file name%s", n, what, n, path,
                 strcmp(opt, "--svg") == 0 ? ", or --html - for every figure in one page"
                                           : "");
    return RB_EXIT_USAGE;
}

/* After loading: every file the case was read from, and the numbered
 * sweep and figure files, whose count the case fixes. All before solving. */
static rb_exit plan_loaded(const rb_cli_opts *o, check_run *r)
{
    size_t n_sw = planned_sweeps(o, &r->c), k;
    size_t n_fig = r->c.n_motions * figures_per_motion(&r->c) + n_sw;
    char name[4096];
    rb_exit e = RB_EXIT_PASS;
    for (k = 0; k < r->c.n_input_files && e == RB_EXIT_PASS; k++)
        e = plan_input(r, r->c.input_files[k]);
    if (e == RB_EXIT_PASS && o->sweep_csv_path)
        e = refuse_stream_series("--sweep-csv", o->sweep_csv_path, n_sw, "sweep tables");
    if (e == RB_EXIT_PASS && o->svg_path)
        e = refuse_stream_series("--svg", o->svg_path, n_fig, "figures");
    for (k = 0; o->sweep_csv_path && k < n_sw && e == RB_EXIT_PASS; k++) {
        const char *p = rb_cli_numbered_name(o->sweep_csv_path, k, n_sw, name, sizeof name);
        if (!p) {
            rb_cli_error(o->sweep_csv_path, "--sweep-csv", "file name too long");
            return RB_EXIT_USAGE;
        }
        e = plan_add(r, "--sweep-csv", p, OUT_SWEEP, k);
    }
    for (k = 0; o->svg_path && k < n_fig && e == RB_EXIT_PASS; k++) {
        const char *p = rb_cli_numbered_name(o->svg_path, k, n_fig, name, sizeof name);
        if (!p) {
            rb_cli_error(o->svg_path, "--svg", "file name too long");
            return RB_EXIT_USAGE;
        }
        e = plan_add(r, "--svg", p, OUT_SVG, k);
    }
    return e;
}

static rb_status fill_output(void *ctx, size_t i, FILE *fp, rb_diag *d)
{
    const check_run *r = ctx;
    const out_file *of = &r->outs[i];
    const char *s = NULL;
    switch (of->kind) {
    case OUT_HISTORY:
        return rb_history_write_csv(fp, &r->rep, d);
    case OUT_SWEEP:
        if (!sweep_at(&r->design, of->k))
            break;
        return rb_sweep_write_csv(sweep_at(&r->design, of->k), fp);
    case OUT_JSON:
        s = r->json;
        break;
    case OUT_TEXT:
        s = r->text;
        break;
    case OUT_HTML:
        s = r->html;
        break;
    case OUT_SVG:
        s = of->k < r->n_svgs ? r->svgs[of->k] : NULL;
        break;
    case OUT_PDF:
        if (!r->pdf)
            break;
        if (fwrite(r->pdf, 1, r->pdf_len, fp) != r->pdf_len) {
            rb_diag_set_msg(d, "cannot write");
            return RB_ERR_IO;
        }
        return RB_OK;
    }
    if (!s) {
        /* the plan counted more sweeps or figures than were made */
        rb_diag_set_msg(d, "nothing to write here (a bug)");
        return RB_ERR_INVALID;
    }
    if (fwrite(s, 1, strlen(s), fp) != strlen(s)) {
        rb_diag_set_msg(d, "cannot write");
        return RB_ERR_IO;
    }
    return RB_OK;
}

/* Write all outputs to temporary files, sync them all, then rename them
 * all: an error before the renames leaves no output touched. */
static rb_exit write_outputs(const rb_cli_opts *o, check_run *r)
{
    rb_diag d;
    rb_status st;
    size_t k, n_sw = 0, n_fig = 0;
    for (k = 0; k < rb_outplan_count(&r->plan); k++) {
        n_sw += r->outs[k].kind == OUT_SWEEP;
        n_fig += r->outs[k].kind == OUT_SVG;
    }
    if ((o->sweep_csv_path && n_sw != count_sweeps(&r->design))
        || (o->svg_path && n_fig != r->n_svgs)) {
        rb_cli_error(NULL, NULL, "the planned sweep or figure files do not match "
                     "what was made (a bug); nothing written");
        return RB_EXIT_INTERNAL;
    }
    rb_diag_clear(&d);
    st = rb_outplan_write(&r->plan, fill_output, r, &d);
    if (st != RB_OK) {
        rb_cli_diag_print(&d);
        return RB_EXIT_INTERNAL;
    }
    return RB_EXIT_PASS;
}

rb_exit rb_cli_check_run(const rb_cli_opts *o)
{
    check_run r;
    rb_exit e;
    memset(&r, 0, sizeof r);
    rb_outplan_init(&r.plan);
    e = plan_fixed(o, &r);
    if (e == RB_EXIT_PASS)
        e = load_case(o, &r);
    if (e == RB_EXIT_PASS)
        e = plan_loaded(o, &r);
    if (e == RB_EXIT_PASS)
        e = prepare(o, &r);
    if (e == RB_EXIT_PASS)
        e = solve_all(o, &r);
    if (e == RB_EXIT_PASS && o->command == RB_CMD_DESIGN) {
        e = rb_cli_design_step(o, &r.c, r.results, &r.design);
        r.rep.design = &r.design;
    }
    if (e == RB_EXIT_PASS)
        e = render_reports(o, &r);
    if (e == RB_EXIT_PASS)
        e = render_figures(o, &r);
    if (e == RB_EXIT_PASS)
        e = write_outputs(o, &r);
    /* an output on standard output is all that goes there */
    if (e == RB_EXIT_PASS && !o->quiet && !rb_outplan_uses_stdout(&r.plan)) {
        if (o->text_path) {
            char reason[2048];
            printf("%s: %s\n", r.rep.headline,
                   rb_text_escape_buf(r.rep.reason, reason, sizeof reason));
        } else {
            fputs(r.text, stdout);
        }
        if (fflush(stdout) != 0 || ferror(stdout)) {
            rb_cli_error(NULL, NULL, "cannot write the report to standard output");
            e = RB_EXIT_INTERNAL;
        }
    }
    if (e == RB_EXIT_PASS)
        e = r.rep.pass ? RB_EXIT_PASS : RB_EXIT_FAIL;
    run_free(&r);
    return e;
}
