/* "rockbolt merge SHARD.json...": the JSON summaries of the shards of one
 * batch into one summary, byte-identical to a single run's, with the same
 * outputs, table and exit code. */
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "cli_batch.h"

#define RB_MERGE_MAX_BYTES (1024u * 1024u * 1024u)

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

/* The whole summary, no more than RB_MERGE_MAX_BYTES: refused by its size
 * before it is read, or when it grows past the limit while read. NULL
 * with *why set, or NULL alone when out of memory. */
static char *slurp(const char *path, const char **why)
{
    static char over[160];
    struct stat sb;
    FILE *f = open_shard(path, why);
    if (!f)
        return NULL;
    snprintf(over, sizeof over, "it is larger than the limit of %u MiB for a shard's "
             "summary", RB_MERGE_MAX_BYTES >> 20);
    if (fstat(fileno(f), &sb) != 0)
        *why = strerror(errno);
    else if ((unsigned long long)sb.st_size > RB_MERGE_MAX_BYTES)
        *why = over;
    if (*why) {
        fclose(f);
        return NULL;
    }
    /* the size it says, and room to find out that it has grown */
    size_t cap = (size_t)sb.st_size + 2, len = 0;
    char *buf = malloc(cap);
    while (buf) {
        size_t n = fread(buf + len, 1, cap - len - 1, f);
        len += n;
        if (len + 1 < cap)
            break;
        if (len > RB_MERGE_MAX_BYTES) {
            *why = over;
            free(buf);
            buf = NULL;
            break;
        }
        size_t grown = cap < RB_MERGE_MAX_BYTES / 2 ? 2 * cap : (size_t)RB_MERGE_MAX_BYTES + 2;
        char *p = realloc(buf, grown);
        if (!p) {
            free(buf);
            buf = NULL;
        } else {
            buf = p;
            cap = grown;
        }
    }
    int err = ferror(f) ? (errno ? errno : EIO) : 0;
    fclose(f);
    if (buf && err) {
        *why = strerror(err);
        free(buf);
        return NULL;
    }
    if (buf)
        buf[len] = '\0';
    return buf;
}

static rb_exit read_shards(const rb_batch_cli *o, rb_batch_summary *sh)
{
    for (size_t i = 0; i < o->n_inputs; i++) {
        rb_diag d;
        rb_diag_clear(&d);
        const char *why = NULL;
        char *text = slurp(o->inputs[i], &why);
        if (!text) {
            if (!why) {
                rb_cli_error(o->inputs[i], NULL, "cannot read the summary: out of memory");
                return RB_EXIT_INTERNAL;
            }
            rb_cli_error(o->inputs[i], NULL, "cannot read the summary: %s", why);
            return RB_EXIT_USAGE;
        }
        rb_status st = rb_batch_summary_parse(text, &sh[i], &d);
        free(text);
        if (st != RB_OK) {
            snprintf(d.file, sizeof d.file, "%s", o->inputs[i]);
            rb_cli_diag_print(&d);
            return st == RB_ERR_NOMEM ? RB_EXIT_INTERNAL : RB_EXIT_USAGE;
        }
        /* shards of one list were run on the same list, cases and bases */
        if (i > 0 && strcmp(sh[i].inputs_digest, sh[0].inputs_digest) != 0) {
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
    rb_batch_summary *sh = NULL, merged;
    memset(&merged, 0, sizeof merged);
    int done;
    rb_exit e = rb_cli_batch_begin(argc, argv, 1, &o, &done);
    if (done)
        return RB_EXIT_PASS;
    if (e == RB_EXIT_PASS && !(sh = calloc(o.n_inputs, sizeof *sh))) {
        rb_cli_error(NULL, NULL, "out of memory");
        e = RB_EXIT_INTERNAL;
    }
    if (e == RB_EXIT_PASS)
        e = read_shards(&o, sh);
    if (e == RB_EXIT_PASS) {
        rb_diag d;
        rb_diag_clear(&d);
        rb_status st = rb_batch_merge(sh, o.n_inputs, &merged, &d);
        if (st != RB_OK) {
            rb_cli_diag_print(&d);
            e = st == RB_ERR_NOMEM ? RB_EXIT_INTERNAL : RB_EXIT_USAGE;
        }
    }
    if (e == RB_EXIT_PASS)
        e = rb_cli_batch_finish(&o, &merged);
    for (size_t i = 0; sh && i < o.n_inputs; i++)
        rb_batch_summary_free(&sh[i]);
    free(sh);
    rb_batch_summary_free(&merged);
    rb_cli_batch_cli_free(&o);
    return e;
}
