/* "rockbolt check CASE.yaml": load, solve every motion, judge, report;
 * "rockbolt design CASE.yaml" adds the design searches before reporting.
 *
 * Order matters for the exit-code contract: output paths are checked and
 * the case and the template loaded before any solving, so usage and input
 * errors (exit 2) never leave files behind; reports are rendered whole in
 * memory, every output is written to a temporary file and synced, and only
 * then are they all renamed into place. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "cli.h"
#include "rockbolt/plot.h"
#include "rockbolt/textsafe.h"

#define RB_HISTORY_DT_DEFAULT_S 0.01

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
    rb_case_free(&r->c);
}

/* Every output's directory must exist and be writable before we start. */
static rb_exit check_output_paths(const rb_cli_opts *o)
{
    const char *paths[6] = { o->json_path, o->text_path, o->history_path,
                             o->sweep_csv_path, o->svg_path, o->html_path };
    static const char *const opts[6] = { "--json", "--text", "--history",
                                         "--sweep-csv", "--svg", "--html" };
    int i;
    for (i = 0; i < 6; i++) {
        rb_diag d;
        rb_diag_clear(&d);
        if (paths[i] && rb_outfile_check(paths[i], &d) != RB_OK) {
            snprintf(d.key, sizeof d.key, "%s", opts[i]);
            rb_cli_diag_print(&d);
            return RB_EXIT_USAGE;
        }
    }
    return RB_EXIT_PASS;
}

static rb_exit load_case(const rb_cli_opts *o, check_run *r)
{
    rb_diag_list diags = {0};
    rb_status st = rb_case_load(o->case_path, &r->c, &diags);
    size_t i;
    for (i = 0; i < diags.n; i++) {
        if (!diags.items[i].file[0])
            snprintf(diags.items[i].file, sizeof diags.items[i].file, "%s",
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

/* Is output the same file as input? By device and inode when both exist
 * (two spellings of one path, links), else by the path text. */
static int same_file(const char *output, const char *input)
{
    struct stat a, b;
    if (stat(output, &a) == 0 && stat(input, &b) == 0)
        return a.st_dev == b.st_dev && a.st_ino == b.st_ino;
    return strcmp(output, input) == 0;
}

/* No output may replace a file the case was read from: its bases and
 * records are named only inside the case, so the command line check of
 * the case path alone does not see them. Sweep and figure files get
 * numbered names, so their base names are what is compared. */
static rb_exit check_outputs_not_inputs(const rb_cli_opts *o, const rb_case *c)
{
    const char *paths[6] = { o->json_path, o->text_path, o->history_path,
                             o->sweep_csv_path, o->svg_path, o->html_path };
    static const char *const opts[6] = { "--json", "--text", "--history",
                                         "--sweep-csv", "--svg", "--html" };
    size_t i, k;
    for (i = 0; i < 6; i++)
        for (k = 0; paths[i] && k < c->n_input_files; k++)
            if (same_file(paths[i], c->input_files[k])) {
                rb_cli_error(paths[i], opts[i], "is an input of the case (%s); "
                             "refusing to overwrite it", c->input_files[k]);
                return RB_EXIT_USAGE;
            }
    return RB_EXIT_PASS;
}

/* The derived constants, and the template if a text report is wanted. */
static rb_exit prepare(const rb_cli_opts *o, check_run *r)
{
    rb_diag d;
    rb_status st;
    rb_diag_clear(&d);
    if (rb_model_derive(&r->c.model, &r->rep.derived, &d) != RB_OK) {
        snprintf(d.file, sizeof d.file, "%s", o->case_path);
        rb_cli_diag_print(&d);
        return RB_EXIT_USAGE;
    }
    r->results = calloc(r->c.n_motions, sizeof *r->results);
    r->rms = calloc(r->c.n_motions, sizeof *r->rms);
    if (!r->results || !r->rms) {
        rb_cli_error(NULL, NULL, "out of memory");
        return RB_EXIT_INTERNAL;
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

/* Solve and judge every motion; a solver failure is exit 3. */
static rb_exit solve_all(const rb_cli_opts *o, check_run *r)
{
    rb_solve_opts so = r->c.solve;
    size_t i;
    if (r->c.write_history || o->history_path || o->svg_path || o->html_path) {
        if (!(so.history_dt_s > 0))
            so.history_dt_s = RB_HISTORY_DT_DEFAULT_S;
    }
    for (i = 0; i < r->c.n_motions; i++) {
        const rb_case_motion *cm = &r->c.motions[i];
        rb_report_motion *rm = &r->rms[i];
        rb_diag d;
        rb_status st;
        rb_diag_clear(&d);
        st = rb_solve_run(&r->c.model, &cm->motion, &so, &r->results[i], &d);
        if (st != RB_OK) {
            char key[128];
            snprintf(key, sizeof key, "motion '%.100s'", cm->name ? cm->name : "?");
            rb_cli_error(o->case_path, key, "%s%s%s", rb_status_str(st),
                         d.msg[0] ? ": " : "", d.msg);
            return RB_EXIT_INTERNAL;
        }
        rm->motion = cm;
        rm->result = &r->results[i];
        rm->pass = rb_criteria_judge(&r->c.criteria, &r->results[i], rm->reason,
                                     sizeof rm->reason);
    }
    r->rep.kase = &r->c;
    r->rep.motions = r->rms;
    r->rep.n_motions = r->c.n_motions;
    r->rep.with_history = r->c.write_history;
    rb_report_conclude(&r->rep);
    return RB_EXIT_PASS;
}

static rb_exit render_reports(const rb_cli_opts *o, check_run *r)
{
    rb_diag d;
    rb_status st = RB_OK;
    rb_diag_clear(&d);
    if (o->json_path)
        st = rb_report_json_render(&r->rep, &r->json, &d);
    if (st != RB_OK) {
        snprintf(d.file, sizeof d.file, "%s", o->json_path);
        rb_cli_diag_print(&d);
        return RB_EXIT_INTERNAL;
    }
    if (r->tmpl)
        st = rb_report_text_render(&r->rep, r->tmpl, &r->text, &d);
    if (st != RB_OK) {
        int user = strcmp(r->tmpl_origin, "RB_TEMPLATE_DIR") == 0;
        snprintf(d.file, sizeof d.file, "%s/report.txt",
                 user ? getenv("RB_TEMPLATE_DIR") : "templates");
        rb_cli_diag_print(&d);
        return user && st == RB_ERR_PARSE ? RB_EXIT_USAGE : RB_EXIT_INTERNAL;
    }
    return RB_EXIT_PASS;
}

typedef enum { OUT_JSON, OUT_TEXT, OUT_HISTORY, OUT_SWEEP, OUT_SVG, OUT_HTML } out_kind;

/* One output file of the run; sweeps are numbered frequency sweeps first,
 * then each motion's amplitude sweeps, in case order. */
typedef struct {
    out_kind kind;
    const char *path;
    char name[4096];         /* path storage for derived sweep names */
    const rb_sweep *sweep;
    const char *data;        /* SVG and HTML: the rendered text */
} out_file;

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

/* The figures (--svg, --html): every motion's time history, then every
 * sweep, so the numbering of --svg files follows the report's order. */
static rb_exit render_figures(const rb_cli_opts *o, check_run *r)
{
    size_t n_sw = count_sweeps(&r->design), n = r->c.n_motions + n_sw, i;
    rb_status st = RB_OK;
    rb_diag d;
    char title[256];
    if (!o->svg_path && !o->html_path)
        return RB_EXIT_PASS;
    if (!(r->svgs = calloc(n ? n : 1, sizeof *r->svgs))) {
        rb_cli_error(NULL, NULL, "out of memory");
        return RB_EXIT_INTERNAL;
    }
    rb_diag_clear(&d);
    for (i = 0; i < n && st == RB_OK; i++, r->n_svgs++) {
        if (i < r->c.n_motions) {
            st = rb_plot_history_svg(&r->rep, i, &r->svgs[i], &d);
            continue;
        }
        const rb_sweep *sw = sweep_at(&r->design, i - r->c.n_motions);
        snprintf(title, sizeof title, "%.150s: %s sweep", r->c.name ? r->c.name : "case",
                 sw->kind == RB_SWEEP_FREQUENCY ? "frequency" : "amplitude");
        st = rb_plot_sweep_svg(sw, title, &r->svgs[i], &d);
    }
    if (st == RB_OK && o->html_path) {
        snprintf(title, sizeof title, "rockbolt %s: %.150s, %s",
                 o->command == RB_CMD_DESIGN ? "design" : "check",
                 r->c.name ? r->c.name : "case", r->rep.pass ? "PASS" : "FAIL");
        st = rb_plot_html_page(title, r->text, (const char *const *)r->svgs, r->n_svgs,
                               &r->html, &d);
    }
    if (st != RB_OK) {
        rb_cli_error(NULL, d.key[0] ? d.key : NULL, "cannot draw the figures: %s%s%s",
                     rb_status_str(st), d.msg[0] ? ": " : "", d.msg);
        return RB_EXIT_INTERNAL;
    }
    return RB_EXIT_PASS;
}

/* The list of outputs asked for; *n_out set. NULL (after printing) if the
 * list cannot be made. */
static out_file *list_outputs(const rb_cli_opts *o, const check_run *r, size_t *n_out)
{
    size_t n_sw = o->sweep_csv_path ? count_sweeps(&r->design) : 0, n = 0, k;
    size_t n_fig = o->svg_path ? r->n_svgs : 0;
    out_file *f = calloc(4 + n_sw + n_fig, sizeof *f);
    if (!f) {
        rb_cli_error(NULL, NULL, "out of memory");
        return NULL;
    }
    if (o->json_path)
        f[n].kind = OUT_JSON, f[n++].path = o->json_path;
    if (o->text_path)
        f[n].kind = OUT_TEXT, f[n++].path = o->text_path;
    if (o->history_path)
        f[n].kind = OUT_HISTORY, f[n++].path = o->history_path;
    for (k = 0; k < n_sw; k++, n++) {
        f[n].kind = OUT_SWEEP;
        f[n].sweep = sweep_at(&r->design, k);
        f[n].path = rb_cli_numbered_name(o->sweep_csv_path, k, n_sw, f[n].name,
                                          sizeof f[n].name);
        if (!f[n].path) {
            rb_cli_error(o->sweep_csv_path, "--sweep-csv", "file name too long");
            free(f);
            return NULL;
        }
    }
    if (o->html_path)
        f[n].kind = OUT_HTML, f[n].data = r->html, f[n++].path = o->html_path;
    for (k = 0; k < n_fig; k++, n++) {
        f[n].kind = OUT_SVG;
        f[n].data = r->svgs[k];
        f[n].path = rb_cli_numbered_name(o->svg_path, k, n_fig, f[n].name,
                                         sizeof f[n].name);
        if (!f[n].path) {
            rb_cli_error(o->svg_path, "--svg", "file name too long");
            free(f);
            return NULL;
        }
    }
    *n_out = n;
    return f;
}

static rb_status fill_output(const out_file *of, FILE *fp, const check_run *r, rb_diag *d)
{
    const char *s = of->kind == OUT_JSON ? r->json : of->kind == OUT_TEXT ? r->text
                                                                       : of->data;
    if (of->kind == OUT_HISTORY)
        return rb_history_write_csv(fp, &r->rep, d);
    if (of->kind == OUT_SWEEP)
        return rb_sweep_write_csv(of->sweep, fp);
    if (fwrite(s, 1, strlen(s), fp) != strlen(s)) {
        snprintf(d->msg, sizeof d->msg, "cannot write");
        return RB_ERR_IO;
    }
    return RB_OK;
}

/* Write all outputs to temporary files, sync them all, then rename them
 * all: an error before the renames leaves no output touched. */
static rb_exit write_outputs(const rb_cli_opts *o, check_run *r)
{
    size_t n = 0, i;
    out_file *of = list_outputs(o, r, &n);
    rb_outfile *f;
    rb_status st = RB_OK;
    rb_diag d;
    if (!of)
        return RB_EXIT_INTERNAL;
    if (!(f = calloc(n ? n : 1, sizeof *f))) {
        free(of);
        rb_cli_error(NULL, NULL, "out of memory");
        return RB_EXIT_INTERNAL;
    }
    rb_diag_clear(&d);
    for (i = 0; i < n && st == RB_OK; i++) {
        st = rb_outfile_open(&f[i], of[i].path, 0, &d);
        if (st == RB_OK)
            st = fill_output(&of[i], f[i].fp, r, &d);
        if (st == RB_OK)
            st = rb_outfile_finish(&f[i], &d);
        if (st != RB_OK && !d.file[0])
            snprintf(d.file, sizeof d.file, "%s", of[i].path);
    }
    for (i = 0; i < n && st == RB_OK; i++)
        st = rb_outfile_commit(&f[i], &d);
    for (i = 0; i < n; i++)
        rb_outfile_abort(&f[i]);
    free(f);
    free(of);
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
    e = check_output_paths(o);
    if (e == RB_EXIT_PASS)
        e = load_case(o, &r);
    if (e == RB_EXIT_PASS)
        e = check_outputs_not_inputs(o, &r.c);
    if (e == RB_EXIT_PASS)
        e = prepare(o, &r);
    if (e == RB_EXIT_PASS)
        e = solve_all(o, &r);
    if (e == RB_EXIT_PASS && o->command == RB_CMD_DESIGN) {
        e = rb_cli_design_step(o, &r.c, &r.design);
        r.rep.design = &r.design;
    }
    if (e == RB_EXIT_PASS)
        e = render_reports(o, &r);
    if (e == RB_EXIT_PASS)
        e = render_figures(o, &r);
    if (e == RB_EXIT_PASS)
        e = write_outputs(o, &r);
    if (e == RB_EXIT_PASS && !o->quiet) {
        if (o->text_path) {
            char reason[2048];
            printf("%s: %s\n", r.rep.pass ? "PASS" : "FAIL",
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
