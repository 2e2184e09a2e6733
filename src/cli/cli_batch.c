/* "rockbolt batch": a review of many cases with one summary.
 *
 * Order, as for check: usage errors, then output paths, then the work
 * list, then the runs. Cases that cannot be read are reported in the
 * summary like the others and decide the exit code; only a problem with
 * the command itself stops before any solving (exit 2, nothing written). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "cli_batch.h"

/* --reports DIR: created if missing (its parent must exist). */
static rb_exit check_reports_dir(const char *dir)
{
    struct stat sb;
    if (stat(dir, &sb) != 0) {
        if (errno == ENOENT && mkdir(dir, 0777) == 0)
            return RB_EXIT_PASS;
        rb_cli_error(dir, "--reports", "cannot create the directory: %s",
                     strerror(errno));
        return RB_EXIT_USAGE;
    }
    if (!S_ISDIR(sb.st_mode) || access(dir, W_OK | X_OK) != 0) {
        rb_cli_error(dir, "--reports", "not a writable directory");
        return RB_EXIT_USAGE;
    }
    return RB_EXIT_PASS;
}

static rb_exit check_base(const char *base)
{
    FILE *f = fopen(base, "rb");
    if (!f) {
        rb_cli_error(base, "--base", "cannot open the base case: %s", strerror(errno));
        return RB_EXIT_USAGE;
    }
    fclose(f);
    return RB_EXIT_PASS;
}

static rb_exit build_list(const rb_batch_cli *o, rb_batch_list *l)
{
    for (size_t i = 0; i < o->n_inputs; i++) {
        if (rb_batch_list_add(l, o->inputs[i], o->base) != RB_OK) {
            rb_cli_error(NULL, NULL, "out of memory");
            return RB_EXIT_INTERNAL;
        }
    }
    return RB_EXIT_PASS;
}

static rb_exit run(const rb_batch_cli *o, const rb_batch_list *l, rb_batch_summary *s)
{
    rb_batch_opts bo;
    rb_cli_progress prog;
    char *tmpl = NULL;
    rb_diag d;
    rb_diag_clear(&d);
    rb_batch_opts_init(&bo);
    if (o->reports_dir) {
        const char *origin;
        if (rb_template_load("report.txt", &tmpl, &origin, &d) != RB_OK) {
            rb_cli_diag_print(&d);
            return RB_EXIT_USAGE;
        }
    }
    bo.n_threads = o->threads;
    bo.design = o->design;
    bo.reports_dir = o->reports_dir;
    bo.report_template = tmpl;
    bo.shard = o->shard;
    bo.n_shards = o->n_shards;
    rb_cli_progress_start(&prog, o->quiet);
    bo.progress = rb_cli_progress_update;
    bo.progress_ctx = &prog;
    rb_status st = rb_batch_run(l, &bo, s, &d);
    free(tmpl);
    rb_cli_progress_end(&prog, s->n_cases);
    if (st != RB_OK) {
        rb_cli_error(NULL, NULL, "%s%s%s", rb_status_str(st), d.msg[0] ? ": " : "",
                     d.msg);
        return st == RB_ERR_INVALID ? RB_EXIT_USAGE : RB_EXIT_INTERNAL;
    }
    return RB_EXIT_PASS;
}

/* Each unreadable case also gets its diagnostic line on stderr, so that an
 * editor or a CI log can jump to it. */
static void print_errors(const rb_batch_summary *s)
{
    for (size_t i = 0; i < s->n_cases; i++) {
        const rb_batch_case *c = &s->cases[i];
        if (c->verdict == RB_BATCH_UNREADABLE || c->verdict == RB_BATCH_ERROR)
            rb_cli_diag_print(&c->error);
    }
}

rb_exit rb_cli_batch_main(int argc, char **argv)
{
    rb_batch_cli o;
    rb_batch_list l = {0};
    rb_batch_summary s;
    memset(&s, 0, sizeof s);
    int done;
    rb_exit e = rb_cli_batch_begin(argc, argv, 0, &o, &done);
    if (done)
        return RB_EXIT_PASS;
    if (e == RB_EXIT_PASS && o.base)
        e = check_base(o.base);
    if (e == RB_EXIT_PASS && o.reports_dir)
        e = check_reports_dir(o.reports_dir);
    if (e == RB_EXIT_PASS)
        e = build_list(&o, &l);
    if (e == RB_EXIT_PASS)
        e = run(&o, &l, &s);
    if (e == RB_EXIT_PASS) {
        print_errors(&s);
        e = rb_cli_batch_finish(&o, &s);
    }
    rb_batch_summary_free(&s);
    rb_batch_list_free(&l);
    rb_cli_batch_cli_free(&o);
    return e;
}
