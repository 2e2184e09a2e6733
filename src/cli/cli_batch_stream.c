/* The summary outputs of batch written as the cases are done: each case is
 * rendered into an anonymous temporary file per format as soon as its
 * chunk is finished, and freed. The head, which holds the counts, is
 * known only at the end; then head, spool and tail go out together (into
 * the staged outputs, which are renamed into place all or none). So the
 * memory of a batch does not grow with the summary, only its disk. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cli_batch.h"

/* An anonymous file in TMPDIR (else /tmp), gone when closed or when the
 * process ends: glibc's tmpfile() does not look at TMPDIR, which is where
 * CI systems put their scratch space. */
static FILE *spool_open(void)
{
    const char *dir = getenv("TMPDIR");
    char path[4096];
    if (!dir || !*dir)
        dir = "/tmp";
    FILE *f = NULL;
    if (snprintf(path, sizeof path, "%s/rockbolt-summary-XXXXXX", dir) < (int)sizeof path) {
        int fd = mkstemp(path);
        if (fd >= 0) {
            unlink(path);
            if (!(f = fdopen(fd, "w+b")))
                close(fd);
        }
    }
    if (!f)
        rb_cli_error(dir, NULL, "cannot make a temporary file for the summary here "
                     "(set TMPDIR to a writable directory)");
    return f;
}

rb_exit rb_cli_stream_open(rb_batch_cli *o)
{
    int want[RB_BATCH_N_FORMATS] = {0};
    want[RB_BATCH_JSON] = o->json_path != NULL;
    want[RB_BATCH_CSV] = o->csv_path != NULL;
    want[RB_BATCH_JUNIT] = o->junit_path != NULL;
    /* an output on standard output is all that goes there */
    want[RB_BATCH_TEXT] = !o->quiet && !rb_outplan_uses_stdout(&o->plan);
    for (int f = 0; f < RB_BATCH_N_FORMATS; f++)
        if (want[f] && !(o->spool[f] = spool_open()))
            return RB_EXIT_INTERNAL;
    if (!(o->error_spool = spool_open()))
        return RB_EXIT_INTERNAL;
    return RB_EXIT_PASS;
}

void rb_cli_stream_close(rb_batch_cli *o)
{
    for (int f = 0; f < RB_BATCH_N_FORMATS; f++) {
        if (o->spool[f])
            fclose(o->spool[f]);
        o->spool[f] = NULL;
    }
    if (o->error_spool)
        fclose(o->error_spool);
    o->error_spool = NULL;
}

static rb_status put(FILE *out, char *text)
{
    if (!text)
        return RB_ERR_NOMEM;
    size_t n = strlen(text);
    rb_status st = fwrite(text, 1, n, out) == n ? RB_OK : RB_ERR_IO;
    free(text);
    return st;
}

rb_status rb_cli_stream_sink(void *ctx, const rb_batch_summary *s,
                             const rb_batch_case *cases, size_t first, size_t n)
{
    rb_batch_cli *o = ctx;
    rb_status st = RB_OK;
    for (size_t i = 0; i < n && st == RB_OK; i++) {
        const rb_batch_case *c = &cases[i];
        if (c->verdict == RB_BATCH_UNREADABLE || c->verdict == RB_BATCH_ERROR)
            rb_cli_diag_fprint(o->error_spool, rb_batch_case_error(c));
        for (int f = 0; f < RB_BATCH_N_FORMATS && st == RB_OK; f++)
            if (o->spool[f])
                st = put(o->spool[f], rb_batch_render_case((rb_batch_format)f, s, c,
                                                          first + i));
    }
    if (st == RB_OK && ferror(o->error_spool))
        st = RB_ERR_IO;
    return st;
}

static rb_status copy(FILE *from, FILE *to)
{
    char buf[1 << 16];
    size_t n;
    if (fflush(from) != 0 || fseek(from, 0, SEEK_SET) != 0)
        return RB_ERR_IO;
    while ((n = fread(buf, 1, sizeof buf, from)) > 0)
        if (fwrite(buf, 1, n, to) != n)
            return RB_ERR_IO;
    return ferror(from) ? RB_ERR_IO : RB_OK;
}

rb_status rb_cli_stream_copy(rb_batch_cli *o, rb_batch_format f, const rb_batch_summary *s,
                             FILE *out)
{
    rb_batch_counts n;
    rb_batch_count(s, &n);
    rb_status st = put(out, rb_batch_render_head(f, s, &n));
    if (st == RB_OK)
        st = copy(o->spool[f], out);
    if (st == RB_OK)
        st = put(out, rb_batch_render_tail(f, s, &n));
    return st;
}
