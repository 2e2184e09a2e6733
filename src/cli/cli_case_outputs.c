/* What the commands that read one case and write figures and tables from
 * it (fragility, spectrum, motion) share: planning --json, --csv, --svg,
 * --html and --pdf against the case (and creating motion's and batch's
 * output directories), loading the case with its own files added to the
 * plan's inputs, so that no output can replace one, and writing the
 * outputs and the table on stdout from the command's renderers. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "cli.h"
#include "cli_batch.h"
#include "rockbolt/pdf.h"
#include "rockbolt/plot.h"

rb_exit rb_cli_plan_case_outputs(const rb_cli_opts *o, rb_outplan *p)
{
    const char *paths[6] = {o->json_path, o->csv_path, o->svg_path, o->html_path,
                            o->p58_path, o->pdf_path};
    static const char *const opts[6] = {"--json", "--csv", "--svg", "--html", "--p58",
                                        "--pdf"};
    rb_diag d;
    rb_diag_clear(&d);
    rb_status st = rb_outplan_add_input(p, o->case_path, &d);
    for (int k = 0; k < 6 && st == RB_OK; k++)
        if (paths[k])
            st = rb_outplan_add(p, opts[k], paths[k], &d);
    return st == RB_OK ? RB_EXIT_PASS : rb_cli_plan_error(st, &d);
}

rb_exit rb_cli_output_dir(const char *dir, const char *opt, int *created)
{
    struct stat sb;
    *created = 0;
    if (stat(dir, &sb) != 0) {
        if (errno == ENOENT && mkdir(dir, 0777) == 0) {
            *created = 1;
            return RB_EXIT_PASS;
        }
        rb_cli_error(dir, opt, "cannot create the directory: %s", strerror(errno));
        return RB_EXIT_USAGE;
    }
    if (!S_ISDIR(sb.st_mode) || access(dir, W_OK | X_OK) != 0) {
        rb_cli_error(dir, opt, "not a writable directory");
        return RB_EXIT_USAGE;
    }
    return RB_EXIT_PASS;
}

rb_status rb_cli_case_load(const rb_cli_opts *o, rb_case *c, rb_diag_list *diags)
{
    rb_cli_progress line;
    rb_cli_progress_start(&line, o->quiet);
    if (line.enabled)
        rb_case_set_generate_progress(rb_cli_progress_generate, &line);
    rb_status st = rb_case_load_cached(o->case_path, NULL, &o->sandbox, c, diags);
    rb_case_set_generate_progress(NULL, NULL);
    rb_cli_progress_clear(&line);
    return st;
}

rb_exit rb_cli_load_case_planned(const rb_cli_opts *o, rb_case *c, rb_outplan *p)
{
    rb_diag_list diags = {0};
    rb_status st = rb_cli_case_load(o, c, &diags);
    for (size_t i = 0; i < diags.n; i++)
        rb_cli_diag_print(&diags.items[i]);
    if (st != RB_OK && diags.n == 0)
        rb_cli_error(o->case_path, NULL, "cannot load the case: %s", rb_status_str(st));
    rb_diag_list_free(&diags);
    if (st != RB_OK)
        return st == RB_ERR_NOMEM ? RB_EXIT_INTERNAL : RB_EXIT_USAGE;
    /* the records, bases and tables it read are inputs too */
    rb_diag d;
    rb_diag_clear(&d);
    for (size_t i = 0; i < c->n_input_files && st == RB_OK; i++)
        st = rb_outplan_add_input(p, c->input_files[i], &d);
    return st == RB_OK ? RB_EXIT_PASS : rb_cli_plan_error(st, &d);
}

/* --html: the table and the figure in one page */
static rb_status page(const rb_cli_renders *r, char **out, rb_diag *d)
{
    char *svg = NULL, *text = r->text(r->ctx);
    rb_status st = text ? r->figure(r->ctx, r->title, &svg, d) : RB_ERR_NOMEM;
    if (st == RB_OK) {
        const char *svgs[1] = {svg};
        st = rb_plot_html_page(NULL, r->title, text, svgs, 1, out, d);
    }
    free(svg);
    free(text);
    return st;
}

/* --pdf: the cover from the case, the table as printed and the figure */
static rb_status pdf(const rb_cli_renders *r, FILE *fp, rb_diag *d)
{
    char *svg = NULL, *text = r->text(r->ctx), *doc = NULL;
    size_t len = 0;
    rb_status st = text && r->kase ? r->figure(r->ctx, r->title, &svg, d) : RB_ERR_NOMEM;
    if (st == RB_OK) {
        const char *svgs[1] = {svg};
        rb_pdf_cover cv = {r->title, &r->kase->project, r->kase->name, r->kase->path, NULL,
                           r->kase->output_units};
        st = rb_table_render_pdf(&cv, r->title, text, svgs, 1, &doc, &len, d);
    }
    if (st == RB_OK && fwrite(doc, 1, len, fp) != len)
        st = RB_ERR_IO;
    free(doc);
    free(svg);
    free(text);
    return st;
}

static rb_status fill(void *ctx, size_t i, FILE *fp, rb_diag *d)
{
    const void *const *cx = ctx;
    const rb_outplan *plan = cx[0];
    const rb_cli_renders *r = cx[1];
    const char *opt = rb_outplan_opt(plan, i);
    char *text = NULL;
    rb_status st = RB_OK;
    if (r->other_opt && strcmp(opt, r->other_opt) == 0) {
        st = r->other(r->ctx, i, fp, d);
        if (st != RB_OK && !d->msg[0])
            rb_diag_set_msg(d, "%s", rb_status_str(st));
        return st;
    }
    if (strcmp(opt, "--pdf") == 0) {
        st = pdf(r, fp, d);
        if (st != RB_OK && !d->msg[0])
            rb_diag_set_msg(d, "%s", rb_status_str(st));
        return st;
    }
    if (strcmp(opt, "--json") == 0)
        text = r->json(r->ctx);
    else if (strcmp(opt, "--csv") == 0)
        text = r->csv(r->ctx);
    else if (strcmp(opt, "--p58") == 0 && r->p58)
        text = r->p58(r->ctx);
    else if (strcmp(opt, "--svg") == 0)
        st = r->figure(r->ctx, r->title, &text, d);
    else
        st = page(r, &text, d);
    if (st == RB_OK && !text)
        st = RB_ERR_NOMEM;
    if (st == RB_OK && fputs(text, fp) == EOF)
        st = RB_ERR_IO;
    if (st != RB_OK && !d->msg[0])
        rb_diag_set_msg(d, "%s", rb_status_str(st));
    free(text);
    return st;
}

rb_exit rb_cli_emit_case_outputs(const rb_cli_opts *o, rb_outplan *p, const rb_cli_renders *r)
{
    const void *cx[2] = {p, r};
    rb_diag d;
    rb_diag_clear(&d);
    if (rb_outplan_write(p, fill, (void *)cx, &d) != RB_OK) {
        rb_cli_diag_print(&d);
        return RB_EXIT_INTERNAL;
    }
    if (o->quiet || rb_outplan_uses_stdout(p))
        return RB_EXIT_PASS;
    char *text = r->text(r->ctx);
    rb_exit e = RB_EXIT_PASS;
    if (!text || fputs(text, stdout) == EOF || fflush(stdout) != 0) {
        rb_cli_error(NULL, NULL, "cannot write the %s to standard output", r->what);
        e = RB_EXIT_INTERNAL;
    }
    free(text);
    return e;
}
