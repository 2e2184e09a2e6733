/* The summary outputs of batch and merge: checked before any work, then
 * written whole (temporary files, synced, then all renamed), and the exit
 * code a summary calls for. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cli_batch.h"

rb_exit rb_cli_batch_begin(int argc, char **argv, int is_merge, rb_batch_cli *o,
                           int *done)
{
    rb_exit e = rb_cli_batch_parse(argc, argv, is_merge, o);
    *done = 0;
    if (e == RB_EXIT_PASS && o->help) {
        rb_cli_help_print();
        rb_cli_batch_cli_free(o);
        *done = 1;
        return RB_EXIT_PASS;
    }
    return e == RB_EXIT_PASS ? rb_cli_batch_check_outputs(o) : e;
}

rb_exit rb_cli_batch_check_outputs(const rb_batch_cli *o)
{
    const char *paths[3] = {o->json_path, o->csv_path, o->junit_path};
    static const char *const names[3] = {"--json", "--csv", "--junit"};
    for (int i = 0; i < 3; i++) {
        rb_diag d;
        rb_diag_clear(&d);
        if (paths[i] && rb_outfile_check(paths[i], &d) != RB_OK) {
            snprintf(d.key, sizeof d.key, "%s", names[i]);
            rb_cli_diag_print(&d);
            return RB_EXIT_USAGE;
        }
    }
    return RB_EXIT_PASS;
}

typedef char *(*render_fn)(const rb_batch_summary *s);

static rb_exit write_all(const rb_batch_cli *o, const rb_batch_summary *s)
{
    const char *paths[3] = {o->json_path, o->csv_path, o->junit_path};
    static const render_fn render[3] = {rb_batch_render_json, rb_batch_render_csv,
                                        rb_batch_render_junit};
    rb_outfile f[3];
    rb_status st = RB_OK;
    rb_diag d;
    memset(f, 0, sizeof f);
    rb_diag_clear(&d);
    for (int i = 0; i < 3 && st == RB_OK; i++) {
        if (!paths[i])
            continue;
        char *text = render[i](s);
        if (!text) {
            rb_cli_error(NULL, NULL, "out of memory");
            st = RB_ERR_NOMEM;
            break;
        }
        st = rb_outfile_open(&f[i], paths[i], 0, &d);
        if (st == RB_OK && fwrite(text, 1, strlen(text), f[i].fp) != strlen(text)) {
            snprintf(d.msg, sizeof d.msg, "cannot write");
            st = RB_ERR_IO;
        }
        if (st == RB_OK)
            st = rb_outfile_finish(&f[i], &d);
        if (st != RB_OK && !d.file[0])
            snprintf(d.file, sizeof d.file, "%s", paths[i]);
        free(text);
        if (st != RB_OK)
            rb_cli_diag_print(&d);
    }
    for (int i = 0; i < 3 && st == RB_OK; i++) {
        if (paths[i] && (st = rb_outfile_commit(&f[i], &d)) != RB_OK)
            rb_cli_diag_print(&d);
    }
    for (int i = 0; i < 3; i++)
        rb_outfile_abort(&f[i]);
    return st == RB_OK ? RB_EXIT_PASS : RB_EXIT_INTERNAL;
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

rb_exit rb_cli_batch_finish(const rb_batch_cli *o, const rb_batch_summary *s)
{
    rb_exit e = write_all(o, s);
    if (e != RB_EXIT_PASS)
        return e;
    if (!o->quiet) {
        char *text = rb_batch_render_text(s);
        if (!text) {
            rb_cli_error(NULL, NULL, "out of memory");
            return RB_EXIT_INTERNAL;
        }
        fputs(text, stdout);
        free(text);
        if (fflush(stdout) != 0 || ferror(stdout)) {
            rb_cli_error(NULL, NULL, "cannot write the summary to standard output");
            return RB_EXIT_INTERNAL;
        }
    }
    return exit_of(s);
}
