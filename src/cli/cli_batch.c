/* "rockbolt batch": a review of many cases with one summary.
 *
 * Order, as for check: usage errors, then output paths, then the work
 * list, then the runs. Cases that cannot be read are reported in the
 * summary like the others and decide the exit code; only a problem with
 * the command itself stops before any solving (exit 2, nothing written). */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "cli_batch.h"
#include "rockbolt/record_cache.h"
#include "rockbolt/template.h"

/* --base must be a regular file it can open: a FIFO would block the open
 * (and every row's load) for ever, so it is opened without waiting and
 * looked at before anything is read. */
static rb_exit check_base(const char *base)
{
    struct stat sb;
    int fd = open(base, O_RDONLY | O_NONBLOCK);
    if (fd < 0) {
        rb_cli_error(base, "--base", "cannot open the base case: %s", strerror(errno));
        return RB_EXIT_USAGE;
    }
    int regular = fstat(fd, &sb) == 0 && S_ISREG(sb.st_mode);
    close(fd);
    if (!regular) {
        rb_cli_error(base, "--base", "the base case is not a regular file (a "
                     "directory, FIFO or device)");
        return RB_EXIT_USAGE;
    }
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

/* What decides the files a row reads: its list, its base and the values
 * of its path overrides (keys ending in "file"); other overrides change
 * numbers only. NULL for a case file, which is loaded on its own. */
static char *inputs_key(const rb_batch_item *it)
{
    size_t n = strlen(it->source) + strlen(it->base ? it->base : "") + 3;
    for (size_t k = 0; k < it->n_ov; k++)
        n += strlen(it->ov[k].key) + strlen(it->ov[k].value) + 2;
    char *key = it->tag ? malloc(n) : NULL;
    if (!key)
        return NULL;
    int w = snprintf(key, n, "%s\n%s", it->source, it->base ? it->base : "");
    for (size_t k = 0; k < it->n_ov; k++) {
        size_t kl = strlen(it->ov[k].key);
        if (kl >= 4 && strcmp(it->ov[k].key + kl - 4, "file") == 0)
            w += snprintf(key + w, n - (size_t)w, "\n%s=%s", it->ov[k].key,
                          it->ov[k].value);
    }
    return key;
}

#define RB_SEEN_KEYS 64

/* Every file the work list reads and every report it will write, before
 * any solving: each item of this shard is loaded as the run will load it
 * (an item that does not load is reported by the run and writes no
 * report). Rows whose inputs are those of a row already loaded (same list,
 * base and path overrides: usually all of a list's) are not loaded again. */
static rb_exit plan_items(rb_batch_cli *o, const rb_batch_list *l)
{
    rb_record_cache *cache = rb_record_cache_new(0);
    rb_status st = cache ? RB_OK : RB_ERR_NOMEM;
    char *seen[RB_SEEN_KEYS] = {0};
    size_t n_seen = 0;
    rb_diag d;
    rb_diag_clear(&d);
    for (size_t i = 0; i < l->n && st == RB_OK; i++) {
        const rb_batch_item *it = &l->items[i];
        rb_diag_list diags = {0};
        rb_case c;
        if (!rb_batch_in_shard(i, o->shard, o->n_shards))
            continue;
        st = rb_outplan_add_input(&o->plan, it->source, &d);
        if (st == RB_OK && it->base)
            st = rb_outplan_add_input(&o->plan, it->base, &d);
        if (st != RB_OK || it->bad)
            continue;
        char *key = inputs_key(it);
        int known = 0;
        for (size_t k = 0; key && k < n_seen && k < RB_SEEN_KEYS && !known; k++)
            known = strcmp(seen[k], key) == 0;
        if (known && !o->reports_dir) {
            free(key);
            continue;
        }
        if (known) {
            /* a row's report is named by its tag: no need to load it */
            char stem[200], path[4600];
            free(key);
            rb_batch_report_stem(i, it->tag, l->n, stem, sizeof stem);
            snprintf(path, sizeof path, "%s/%s.json", o->reports_dir, stem);
            st = rb_outplan_reserve(&o->plan, "--reports", path, &d);
            snprintf(path, sizeof path, "%s/%s.txt", o->reports_dir, stem);
            if (st == RB_OK)
                st = rb_outplan_reserve(&o->plan, "--reports", path, &d);
            continue;
        }
        memset(&c, 0, sizeof c);
        rb_status ls = it->tag
            ? rb_case_load_overrides_at(it->base, it->base_line ? it->base_line : it->line,
                                        it->base_col, it->source,
                                        it->tag, it->ov, it->n_ov, cache, l->sandbox, &c, &diags)
            : rb_case_load_cached(it->source, cache, l->sandbox, &c, &diags);
        rb_diag_list_free(&diags);
        if (ls == RB_ERR_NOMEM)
            st = ls;
        if (ls != RB_OK) {
            free(key);
            continue;
        }
        if (key) {
            /* remembered once loaded: a row that fails leaves its inputs
             * to the next row with the same key */
            free(seen[n_seen % RB_SEEN_KEYS]);
            seen[n_seen++ % RB_SEEN_KEYS] = key;
            if (n_seen == 2 * RB_SEEN_KEYS)
                n_seen = RB_SEEN_KEYS;
        }
        for (size_t k = 0; k < c.n_input_files && st == RB_OK; k++)
            st = rb_outplan_add_input(&o->plan, c.input_files[k], &d);
        if (st == RB_OK && o->reports_dir) {
            char stem[200], path[4600];
            const char *tag = it->tag ? it->tag : c.name ? c.name : it->source;
            rb_batch_report_stem(i, tag, l->n, stem, sizeof stem);
            snprintf(path, sizeof path, "%s/%s.json", o->reports_dir, stem);
            st = rb_outplan_reserve(&o->plan, "--reports", path, &d);
            snprintf(path, sizeof path, "%s/%s.txt", o->reports_dir, stem);
            if (st == RB_OK)
                st = rb_outplan_reserve(&o->plan, "--reports", path, &d);
        }
        rb_case_free(&c);
    }
    rb_record_cache_free(cache);
    for (size_t k = 0; k < RB_SEEN_KEYS; k++)
        free(seen[k]);
    return st == RB_OK ? RB_EXIT_PASS : rb_cli_plan_error(st, &d);
}

static rb_exit run(rb_batch_cli *o, const rb_batch_list *l, rb_batch_summary *s)
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
    bo.fragility = o->fragility;
    bo.seed = o->seed;
    bo.intensity = o->intensity;
    bo.reports_dir = o->reports_dir;
    bo.report_template = tmpl;
    bo.report_stage = &o->plan;
    bo.shard = o->shard;
    bo.n_shards = o->n_shards;
    rb_cli_progress_start(&prog, o->quiet);
    bo.progress = rb_cli_progress_update;
    bo.progress_ctx = &prog;
    bo.sink = rb_cli_stream_sink;
    bo.sink_ctx = o;
    rb_status st = rb_batch_run(l, &bo, s, &d);
    free(tmpl);
    rb_cli_progress_end(&prog, s->n_cases);
    if (st != RB_OK && o->spool_failed)
        return rb_cli_stream_error(o);
    if (st != RB_OK) {
        rb_cli_error(NULL, NULL, "%s%s%s", rb_status_str(st), d.msg[0] ? ": " : "",
                     d.msg);
        return st == RB_ERR_INVALID ? RB_EXIT_USAGE : RB_EXIT_INTERNAL;
    }
    return RB_EXIT_PASS;
}

/* Each unreadable case also gets its diagnostic line on stderr, so that an
 * editor or a CI log can jump to it; after the progress line is gone. */
static rb_exit print_errors(rb_batch_cli *o)
{
    char buf[4096];
    size_t n;
    errno = 0;
    if (fflush(o->error_spool) != 0 || fseek(o->error_spool, 0, SEEK_SET) != 0)
        goto failed;
    while ((n = fread(buf, 1, sizeof buf, o->error_spool)) > 0)
        fwrite(buf, 1, n, stderr);
    if (!ferror(o->error_spool))
        return RB_EXIT_PASS;
failed:
    o->spool_failed = o->spool_path[RB_BATCH_N_FORMATS];
    o->spool_errno = errno ? errno : EIO;
    return rb_cli_stream_error(o);
}

rb_exit rb_cli_batch_main(int argc, char **argv)
{
    rb_batch_cli o;
    rb_batch_list l = {0};
    rb_batch_summary s;
    memset(&s, 0, sizeof s);
    int done, made_dir = 0;
    rb_exit e = rb_cli_batch_begin(argc, argv, 0, &o, &done);
    if (done)
        return RB_EXIT_PASS;
    if (e == RB_EXIT_PASS && o.base)
        e = check_base(o.base);
    if (e == RB_EXIT_PASS && o.reports_dir)
        e = rb_cli_output_dir(o.reports_dir, "--reports", &made_dir);
    l.encoding = o.encoding;
    l.sandbox = &o.sandbox;
    if (e == RB_EXIT_PASS)
        e = build_list(&o, &l);
    if (e == RB_EXIT_PASS)
        e = plan_items(&o, &l);
    if (e == RB_EXIT_PASS)
        e = rb_cli_stream_open(&o);
    if (e == RB_EXIT_PASS)
        e = run(&o, &l, &s);
    /* refused before any work: not even the reports directory is left */
    if (made_dir && e != RB_EXIT_PASS && s.n_cases == 0)
        rmdir(o.reports_dir);
    if (e == RB_EXIT_PASS) {
        e = print_errors(&o);
    if (e == RB_EXIT_PASS)
        e = rb_cli_batch_finish(&o, &s);
    }
    rb_batch_summary_free(&s);
    rb_batch_list_free(&l);
    rb_cli_batch_cli_free(&o);
    return e;
}
