/* Scratch files for the fuzz harnesses (see fuzz_common.h). */
#define _XOPEN_SOURCE 700
#include "fuzz_common.h"
#include <errno.h>
#include <math.h>
#include <ftw.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static char rb_fuzz_scratch[256];

static int rb_fuzz_rm(const char *path, const struct stat *sb, int flag,
                      struct FTW *ftw)
{
    (void)sb;
    (void)flag;
    (void)ftw;
    return remove(path);
}

static void rb_fuzz_cleanup(void)
{
    if (rb_fuzz_scratch[0])
        nftw(rb_fuzz_scratch, rb_fuzz_rm, 16, FTW_DEPTH | FTW_PHYS);
}

void rb_fuzz_fail(const char *why, const char *detail)
{
    fprintf(stderr, "fuzz invariant violated: %s%s%s\n", why,
            detail ? ": " : "", detail ? detail : "");
    abort();
}

const char *rb_fuzz_dir(void)
{
    if (rb_fuzz_scratch[0])
        return rb_fuzz_scratch;
    const char *tmp = getenv("TMPDIR");
    struct stat sb;
    if (stat("/dev/shm", &sb) == 0 && S_ISDIR(sb.st_mode) && access("/dev/shm", W_OK) == 0)
        tmp = "/dev/shm";
    else if (!tmp || !tmp[0])
        tmp = "/tmp";
    snprintf(rb_fuzz_scratch, sizeof rb_fuzz_scratch, "%s/rb-fuzz-XXXXXX", tmp);
    if (!mkdtemp(rb_fuzz_scratch)) {
        perror("rb-fuzz: cannot make a scratch directory");
        abort();
    }
    atexit(rb_fuzz_cleanup);
    return rb_fuzz_scratch;
}

void rb_fuzz_path(char *buf, size_t size, const char *rel)
{
    int n = snprintf(buf, size, "%s/%s", rb_fuzz_dir(), rel);
    if (n < 0 || (size_t)n >= size)
        rb_fuzz_fail("scratch path too long", rel);
}

/* mkdir -p of the directories in front of the last '/' of path. */
static void rb_fuzz_mkdirs(char *path)
{
    for (char *p = path + strlen(rb_fuzz_dir()) + 1; (p = strchr(p, '/')); p++) {
        *p = '\0';
        if (mkdir(path, 0700) != 0 && errno != EEXIST)
            rb_fuzz_fail("cannot make a scratch directory", path);
        *p = '/';
    }
}

void rb_fuzz_write(const char *rel, const uint8_t *data, size_t len)
{
    char path[512];
    rb_fuzz_path(path, sizeof path, rel);
    rb_fuzz_mkdirs(path);
    FILE *f = fopen(path, "wb");
    if (!f)
        rb_fuzz_fail("cannot write a scratch file", path);
    int bad = len && fwrite(data, 1, len, f) != len;
    /* Close even after a short write, so no descriptor leaks. */
    if (fclose(f) != 0 || bad)
        rb_fuzz_fail("cannot write a scratch file", path);
}

static void rb_fuzz_check_failed_read(rb_status st, const rb_diag *d, const char *path,
                                      const rb_series *s)
{
    if (st != RB_ERR_IO && st != RB_ERR_PARSE && st != RB_ERR_INVALID
        && st != RB_ERR_LIMIT && st != RB_ERR_NOMEM)
        rb_fuzz_fail("record read returned an unexpected status", rb_status_str(st));
    if (d->msg[0] == '\0')
        rb_fuzz_fail("record error without a message", NULL);
    if (strcmp(d->file, path) != 0)
        rb_fuzz_fail("record error does not name the file", d->file);
    if (d->line < 0 || d->col < 0)
        rb_fuzz_fail("record error at a negative position", d->msg);
    if (s->accel_mps2 || s->n)
        rb_fuzz_fail("failed record read left samples behind", d->msg);
}

static void rb_fuzz_check_series(const rb_series *s, size_t max_points)
{
    if (s->n == 0 || !s->accel_mps2)
        rb_fuzz_fail("record read succeeded with no samples", NULL);
    if (s->n > max_points)
        rb_fuzz_fail("record read past the point limit", NULL);
    if (!(s->dt_s > 0.0) || !isfinite(s->dt_s) || !isfinite(s->t0_s))
        rb_fuzz_fail("record read succeeded with a bad dt or t0", NULL);
    for (size_t i = 0; i < s->n; i++)
        if (!isfinite(s->accel_mps2[i]))
            rb_fuzz_fail("record read succeeded with a non-finite sample", NULL);
}

rb_status rb_fuzz_record(const char *rel, const uint8_t *data, size_t len,
                         const rb_record_opts *opts)
{
    char path[512];
    rb_series s;
    rb_diag d;
    rb_fuzz_write(rel, data, len);
    rb_fuzz_path(path, sizeof path, rel);
    rb_status st = rb_record_read(path, opts, &s, &d);
    if (st != RB_OK) {
        rb_fuzz_check_failed_read(st, &d, path, &s);
        return st;
    }
    rb_fuzz_check_series(&s, opts->max_points ? opts->max_points : 10000000u);
    size_t n = s.n;
    rb_series_free(&s);
    if (n < 2)
        return st;
    rb_record_opts small = *opts;
    small.max_points = n - 1;
    rb_status st2 = rb_record_read(path, &small, &s, &d);
    if (st2 != RB_ERR_LIMIT)
        rb_fuzz_fail("a record one point over max_points was not refused with "
                     "RB_ERR_LIMIT", rb_status_str(st2));
    rb_fuzz_check_failed_read(st2, &d, path, &s);
    return st;
}
