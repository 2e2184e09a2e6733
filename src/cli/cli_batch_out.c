/* The summary outputs of batch and merge: planned and checked against each
 * other and the inputs before any work (rockbolt/outplan.h), then written
 * whole (temporary files, synced, then all renamed, with batch's staged
 * reports), and the exit code a summary calls for. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cli_batch.h"
#include "rockbolt/pdf.h"

rb_exit rb_cli_batch_begin(int argc, char **argv, int is_merge, rb_batch_cli *o,
                           int *done)
{
    rb_exit e = rb_cli_batch_parse(argc, argv, is_merge, o);
    *done = 0;
    if (e == RB_EXIT_PASS && o->help) {
        rb_cli_help_command_print(is_merge ? "merge" : "batch");
        rb_cli_batch_cli_free(o);
        *done = 1;
        return RB_EXIT_PASS;
    }
    return e == RB_EXIT_PASS ? rb_cli_batch_check_outputs(o) : e;
}

rb_exit rb_cli_plan_error(rb_status st, const rb_diag *d)
{
    if (st == RB_ERR_NOMEM) {
        rb_cli_error(NULL, NULL, "out of memory");
        return RB_EXIT_INTERNAL;
    }
    rb_cli_diag_print(d);
    return RB_EXIT_USAGE;
}

rb_exit rb_cli_batch_check_outputs(rb_batch_cli *o)
{
    const char *paths[5] = {o->json_path, o->csv_path, o->junit_path, o->p58_path,
                            o->pdf_path};
    static const char *const names[5] = {"--json", "--csv", "--junit", "--p58", "--pdf"};
    rb_status st = RB_OK;
    rb_diag d;
    rb_diag_clear(&d);
    /* lists, case files and shards named here; what they name is added
     * once the work list is made (cli_batch.c) */
    for (size_t i = 0; i < o->n_inputs && st == RB_OK; i++)
        st = rb_outplan_add_input(&o->plan, o->inputs[i], &d);
    if (st == RB_OK && o->base)
        st = rb_outplan_add_input(&o->plan, o->base, &d);
    for (int i = 0; i < 5 && st == RB_OK; i++)
        if (paths[i])
            st = rb_outplan_add(&o->plan, names[i], paths[i], &d);
    return st == RB_OK ? RB_EXIT_PASS : rb_cli_plan_error(st, &d);
}

/* --pdf: the summary table as printed, in a calculation package */
static rb_status pdf(rb_batch_cli *o, const rb_batch_summary *s, FILE *fp, rb_diag *d)
{
    char *text = NULL, *doc = NULL;
    size_t n = 0, len = 0;
    FILE *mem = open_memstream(&text, &n);
    if (!mem)
        return RB_ERR_NOMEM;
    rb_status st = rb_cli_stream_copy(o, RB_BATCH_TEXT, s, mem);
    if (fclose(mem) != 0 && st == RB_OK)
        st = RB_ERR_NOMEM;
    /* The rows of a list share --base, so its project: and units are the
     * package's cover and paper; a base that does not load (its rows
     * reported that already) leaves the cover without them. */
    rb_case base;
    int have_base = 0;
    if (st == RB_OK && o->base) {
        rb_diag_list dl = {NULL, 0, 0};
        have_base = rb_case_load_cached(o->base, NULL, &o->sandbox, &base, &dl) == RB_OK;
        rb_diag_list_free(&dl);
    }
    if (st == RB_OK) {
        rb_pdf_cover cv = {"Seismic anchorage batch summary",
                           have_base && base.project.given ? &base.project : NULL, NULL,
                           NULL, NULL, have_base ? base.output_units : RB_UNITS_SI};
        st = rb_table_render_pdf(&cv, "Summary", text, NULL, 0, &doc, &len, d);
    }
    if (have_base)
        rb_case_free(&base);
    if (st == RB_OK && fwrite(doc, 1, len, fp) != len)
        st = RB_ERR_IO;
    free(doc);
    free(text);
    return st;
}

static rb_status fill(void *ctx, size_t i, FILE *fp, rb_diag *d)
{
    const void *const *cx = ctx;
    rb_batch_cli *o = (rb_batch_cli *)cx[0];
    const rb_batch_summary *s = cx[1];
    const char *opt = rb_outplan_opt(&o->plan, i);
    if (strcmp(opt, "--pdf") == 0) {
        rb_status st = pdf(o, s, fp, d);
        if (st != RB_OK && o->spool_failed)
            return rb_diag_set(d, RB_ERR_IO, o->spool_failed, 0, 0, "",
                               "cannot read back the summary's temporary file: %.200s",
                               strerror(o->spool_errno));
        if (st != RB_OK && !d->msg[0])
            rb_diag_set_msg(d, "%s", rb_status_str(st));
        return st;
    }
    rb_batch_format f = strcmp(opt, "--json") == 0 ? RB_BATCH_JSON
                      : strcmp(opt, "--csv") == 0 ? RB_BATCH_CSV
                      : strcmp(opt, "--p58") == 0 ? RB_BATCH_P58
                      : RB_BATCH_JUNIT;
    rb_status st = rb_cli_stream_copy(o, f, s, fp);
    if (st != RB_OK && o->spool_failed)
        /* the summary's own temporary file, not this output, failed */
        return rb_diag_set(d, RB_ERR_IO, o->spool_failed, 0, 0, "",
                           "cannot read back the summary's temporary file: %.200s",
                           strerror(o->spool_errno));
    if (st != RB_OK)
        rb_diag_set_msg(d, "%s", st == RB_ERR_NOMEM ? "out of memory"
                        : "cannot write");
    return st;
}

/* Every summary output and every staged report: all renamed at the end. */
static rb_exit write_all(rb_batch_cli *o, const rb_batch_summary *s)
{
    const void *cx[2] = {o, s};
    rb_diag d;
    rb_diag_clear(&d);
    rb_status st = rb_outplan_write(&o->plan, fill, (void *)cx, &d);
    if (st != RB_OK && o->spool_failed)
        return rb_cli_stream_error(o);
    if (st != RB_OK) {
        rb_cli_diag_print(&d);
        return RB_EXIT_INTERNAL;
    }
    return RB_EXIT_PASS;
}

/* An error (solver, reports) outranks an unreadable case, which outranks a
 * failing one: the worst problem decides. */
static rb_exit exit_of(const rb_batch_summary *s)
{
    rb_batch_counts n;
    rb_batch_count(s, &n);
    if (n.errors)
        return RB_EXIT_INTERNAL;
    if (n.unreadable)
        return RB_EXIT_USAGE;
    return n.failed ? RB_EXIT_FAIL : RB_EXIT_PASS;
}

rb_exit rb_cli_batch_finish(rb_batch_cli *o, const rb_batch_summary *s)
{
    if (!o->error_spool) {
        rb_exit e = rb_cli_stream_open(o);
        if (e != RB_EXIT_PASS)
            return e;
    }
    if (!s->streamed && rb_cli_stream_sink(o, s, s->cases, 0, s->n_cases) != RB_OK) {
        if (o->spool_failed)
            return rb_cli_stream_error(o);
        rb_cli_error(NULL, NULL, "out of memory");
        return RB_EXIT_INTERNAL;
    }
    rb_exit e = write_all(o, s);
    if (e != RB_EXIT_PASS)
        return e;
    /* the text is spooled for --pdf too, and printed only when asked */
    if (o->spool[RB_BATCH_TEXT] && !o->quiet && !rb_outplan_uses_stdout(&o->plan)) {
        rb_status st = rb_cli_stream_copy(o, RB_BATCH_TEXT, s, stdout);
        if (st != RB_OK && o->spool_failed)
            return rb_cli_stream_error(o);
        if (st != RB_OK || fflush(stdout) != 0 || ferror(stdout)) {
            rb_cli_error(NULL, NULL, "cannot write the summary to standard output");
            return RB_EXIT_INTERNAL;
        }
    }
    return exit_of(s);
}
