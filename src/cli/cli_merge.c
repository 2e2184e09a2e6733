/* "rockbolt merge SHARD.json...": the JSON summaries of the shards of one
 * batch into one summary, byte-identical to a single run's, with the same
 * outputs, table and exit code. The shards are read a case at a time
 * (rb_batch_reader) and the merged cases spooled as batch spools its own,
 * so that memory does not grow with the list. */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "cli_batch.h"

/* A shard must be a regular file, opened without waiting: a FIFO nobody
 * writes to would block the open for ever, and a device such as /dev/zero
 * never ends. NULL with *why set. */
static FILE *open_shard(const char *path, const char **why)
{
    struct stat sb;
    int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    *why = NULL;
    if (fd < 0) {
        *why = strerror(errno);
        return NULL;
    }
    int flags = fcntl(fd, F_GETFL);
    if (fstat(fd, &sb) != 0)
        *why = strerror(errno);
    else if (S_ISDIR(sb.st_mode))
        *why = "not a regular file but a directory";
    else if (!S_ISREG(sb.st_mode))
        *why = "not a regular file (a FIFO, socket or device)";
    if (*why) {
        close(fd);
        return NULL;
    }
    FILE *f = NULL;
    if (flags < 0 || fcntl(fd, F_SETFL, flags & ~O_NONBLOCK) != 0 || !(f = fdopen(fd, "rb"))) {
        *why = strerror(errno);
        close(fd);
    }
    return f;
}

typedef struct {
    const rb_batch_cli *o;
    rb_batch_reader **readers;
} shards_ctx;

static rb_status next_case(void *ctx, size_t k, rb_batch_case *c, int *got, rb_diag *d)
{
    shards_ctx *sx = ctx;
    return rb_batch_reader_next(sx->readers[k], c, got, d);
}

/* Each shard opened and its head read, in the order given. */
static rb_exit open_shards(const rb_batch_cli *o, FILE **files, rb_batch_reader **readers,
                           rb_batch_summary *heads)
{
    for (size_t i = 0; i < o->n_inputs; i++) {
        rb_diag d;
        rb_diag_clear(&d);
        const char *why = NULL;
        if (!(files[i] = open_shard(o->inputs[i], &why))) {
            rb_cli_error(o->inputs[i], NULL, "cannot read the summary: %s", why);
            return RB_EXIT_USAGE;
        }
        rb_status st = rb_batch_reader_open(files[i], o->inputs[i], &heads[i], &readers[i],
                                            &d);
        if (st != RB_OK) {
            if (st == RB_ERR_NOMEM) {
                rb_cli_error(o->inputs[i], NULL, "cannot read the summary: out of memory");
                return RB_EXIT_INTERNAL;
            }
            rb_cli_diag_print(&d);
            return RB_EXIT_USAGE;
        }
        /* shards of one list were run on the same list, cases and bases */
        if (i > 0 && strcmp(heads[i].inputs_digest, heads[0].inputs_digest) != 0) {
            rb_cli_error(o->inputs[i], "inputs_digest", "this shard was run on other "
                         "inputs than '%s' (a different list, case or base file)",
                         o->inputs[0]);
            return RB_EXIT_USAGE;
        }
    }
    return RB_EXIT_PASS;
}

rb_exit rb_cli_merge_main(int argc, char **argv)
{
    rb_batch_cli o;
    rb_batch_summary *heads = NULL, merged;
    rb_batch_reader **readers = NULL;
    FILE **files = NULL;
    memset(&merged, 0, sizeof merged);
    int done;
    rb_exit e = rb_cli_batch_begin(argc, argv, 1, &o, &done);
    if (done)
        return RB_EXIT_PASS;
    if (e == RB_EXIT_PASS && (!(heads = calloc(o.n_inputs, sizeof *heads))
                              || !(readers = calloc(o.n_inputs, sizeof *readers))
                              || !(files = calloc(o.n_inputs, sizeof *files)))) {
        rb_cli_error(NULL, NULL, "out of memory");
        e = RB_EXIT_INTERNAL;
    }
    if (e == RB_EXIT_PASS)
        e = open_shards(&o, files, readers, heads);
    if (e == RB_EXIT_PASS)
        e = rb_cli_stream_open(&o);
    if (e == RB_EXIT_PASS) {
        shards_ctx sx = {&o, readers};
        rb_diag d;
        rb_diag_clear(&d);
        rb_status st = rb_batch_merge_stream(heads, o.n_inputs, next_case, &sx,
                                             rb_cli_stream_sink, &o, &merged, &d);
        if (st != RB_OK && o.spool_failed)
            e = rb_cli_stream_error(&o);
        else if (st == RB_ERR_NOMEM) {
            rb_cli_error(NULL, NULL, "out of memory");
            e = RB_EXIT_INTERNAL;
        } else if (st != RB_OK) {
            rb_cli_diag_print(&d);
            e = RB_EXIT_USAGE;
        }
    }
    if (e == RB_EXIT_PASS)
        e = rb_cli_batch_finish(&o, &merged);
    for (size_t i = 0; i < o.n_inputs; i++) {
        if (readers && readers[i])
            rb_batch_reader_close(readers[i]);
        if (files && files[i])
            fclose(files[i]);
    }
    free(readers);
    free(files);
    free(heads);
    rb_batch_summary_free(&merged);
    rb_cli_batch_cli_free(&o);
    return e;
}
