/* The summary outputs of batch written as the cases are done: each case is
 * rendered into an anonymous temporary file per format as soon as its
 * chunk is finished, and freed. The head, which holds the counts, is
 * known only at the end; then head, spool and tail go out together (into
 * the staged outputs, which are renamed into place all or none). So the
 * memory of a batch does not grow with the summary, only its disk. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cli_batch.h"

/* An anonymous file in TMPDIR (else /tmp), gone when closed or when the
 * process ends: glibc's tmpfile() does not look at TMPDIR, which is where
 * CI systems put their scratch space. Its name is kept for messages. */
static FILE *spool_open(char **name)
{
    const char *dir = getenv("TMPDIR");
    char path[4096];
    int err = ENAMETOOLONG;
    if (!dir || !*dir)
        dir = "/tmp";
    FILE *f = NULL;
    if (snprintf(path, sizeof path, "%s/rockbolt-summary-XXXXXX", dir) < (int)sizeof path) {
        int fd = mkstemp(path);
        err = errno;
        if (fd >= 0) {
            unlink(path);
            if (!(f = fdopen(fd, "w+b"))) {
                err = errno;
                close(fd);
            } else if (!(*name = strdup(path))) {
                err = ENOMEM;
                fclose(f);
                f = NULL;
            }
        }
    }
    if (!f)
        rb_cli_error(dir, NULL, "cannot make a temporary file for the summary here: %s "
                     "(set TMPDIR to a writable directory)", strerror(err));
    return f;
}

rb_exit rb_cli_stream_open(rb_batch_cli *o)
{
    int want[RB_BATCH_N_FORMATS] = {0};
    want[RB_BATCH_JSON] = o->json_path != NULL;
    want[RB_BATCH_CSV] = o->csv_path != NULL;
    want[RB_BATCH_JUNIT] = o->junit_path != NULL;
    want[RB_BATCH_P58] = o->p58_path != NULL;
    /* an output on standard output is all that goes there */
    want[RB_BATCH_TEXT] = (!o->quiet && !rb_outplan_uses_stdout(&o->plan)) || o->pdf_path;
    for (int f = 0; f < RB_BATCH_N_FORMATS; f++)
        if (want[f] && !(o->spool[f] = spool_open(&o->spool_path[f])))
            return RB_EXIT_USAGE;
    if (!(o->error_spool = spool_open(&o->spool_path[RB_BATCH_N_FORMATS])))
        return RB_EXIT_USAGE;
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
    for (int f = 0; f <= RB_BATCH_N_FORMATS; f++) {
        free(o->spool_path[f]);
        o->spool_path[f] = NULL;
    }
    o->spool_failed = NULL;
}

/* Remember the first spool that failed and why (errno as the failing call
 * left it); RB_ERR_IO. */
static rb_status spool_fail(rb_batch_cli *o, int which)
{
    int err = errno ? errno : EIO;
    if (!o->spool_failed) {
        o->spool_failed = o->spool_path[which] ? o->spool_path[which] : "TMPDIR";
        o->spool_errno = err;
    }
    return RB_ERR_IO;
}

rb_exit rb_cli_stream_error(const rb_batch_cli *o)
{
    rb_cli_error(o->spool_failed, NULL, "cannot write the summary's temporary file: %s "
                 "(TMPDIR, else /tmp, must have room for the summaries)",
                 strerror(o->spool_errno));
    return RB_EXIT_USAGE;
}

static rb_status put(rb_batch_cli *o, int which, char *text)
{
    FILE *out = o->spool[which];
    if (!text)
        return RB_ERR_NOMEM;
    size_t n = strlen(text);
    errno = 0;
    rb_status st = fwrite(text, 1, n, out) == n ? RB_OK : spool_fail(o, which);
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
        errno = 0;
        if (c->verdict == RB_BATCH_UNREADABLE || c->verdict == RB_BATCH_ERROR) {
            rb_cli_diag_fprint(o->error_spool, rb_batch_case_error(c));
            if (ferror(o->error_spool))
                st = spool_fail(o, RB_BATCH_N_FORMATS);
        }
        for (int f = 0; f < RB_BATCH_N_FORMATS && st == RB_OK; f++)
            if (o->spool[f])
                st = put(o, f, rb_batch_render_case((rb_batch_format)f, s, c, first + i));
    }
    return st;
}

/* Spool f into to: a failure on the spool's side (its last buffer written
 * out, or read back) is the spool's, remembered; one on to's side is
 * to's, left to its caller. */
static rb_status copy(rb_batch_cli *o, int f, FILE *to)
{
    FILE *from = o->spool[f];
    char buf[1 << 16];
    size_t n;
    errno = 0;
    if (fflush(from) != 0 || fseek(from, 0, SEEK_SET) != 0)
        return spool_fail(o, f);
    while ((n = fread(buf, 1, sizeof buf, from)) > 0)
        if (fwrite(buf, 1, n, to) != n)
            return RB_ERR_IO;
    return ferror(from) ? spool_fail(o, f) : RB_OK;
}

rb_status rb_cli_stream_copy(rb_batch_cli *o, rb_batch_format f, const rb_batch_summary *s,
                             FILE *out)
{
    rb_batch_counts n;
    rb_batch_count(s, &n);
    char *head = rb_batch_render_head(f, s, &n), *tail;
    if (!head)
        return RB_ERR_NOMEM;
    size_t len = strlen(head);
    rb_status st = fwrite(head, 1, len, out) == len ? RB_OK : RB_ERR_IO;
    free(head);
    if (st == RB_OK)
        st = copy(o, f, out);
    if (st == RB_OK) {
        if (!(tail = rb_batch_render_tail(f, s, &n)))
            return RB_ERR_NOMEM;
        len = strlen(tail);
        st = fwrite(tail, 1, len, out) == len ? RB_OK : RB_ERR_IO;
        free(tail);
    }
    return st;
}
