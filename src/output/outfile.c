/* Atomic output files: a report is either there whole or not at all.
 *
 * Data go to ".rb-XXXXXX" created by mkstemp in the directory of path (so
 * the final rename stays within one file system and is atomic, and the
 * temporary name fits NAME_MAX whatever the name of path), are flushed
 * and fsync'ed, and only then renamed over path; a file being replaced
 * keeps its mode and, where the process may set it, its owner. For files that
 * must not replace an existing one (rockbolt init) the temporary file is
 * hard-linked to path instead, which fails atomically if path exists.
 * Every error path removes the temporary file. POSIX. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "rockbolt/outfile.h"

static rb_status io_fail(rb_diag *diag, const char *path, const char *what, int err)
{
    if (err)
        return rb_diag_set(diag, RB_ERR_IO, path, 0, 0, "", "%.300s: %.200s", what,
                           strerror(err));
    return rb_diag_set(diag, RB_ERR_IO, path, 0, 0, "", "%.500s", what);
}

/* The directory part of path ("." when there is none); caller frees. */
static char *dir_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    size_t n = slash ? (size_t)(slash - path) : 1;
    char *d;
    if (slash && n == 0)
        n = 1; /* "/file": the root */
    d = malloc(n + 1);
    if (!d)
        return NULL;
    memcpy(d, slash ? path : ".", n);
    d[n] = '\0';
    return d;
}

rb_status rb_outfile_check(const char *path, rb_diag *diag)
{
    struct stat sb;
    char *dir;
    rb_status st = RB_OK;
    if (!path[0])
        return io_fail(diag, path, "empty output path", 0);
    if (path[strlen(path) - 1] == '/')
        return io_fail(diag, path, "output path names a directory", 0);
    if (stat(path, &sb) == 0 && S_ISDIR(sb.st_mode))
        return io_fail(diag, path, "output path is a directory", 0);
    if (!(dir = dir_of(path)))
        return RB_ERR_NOMEM;
    if (stat(dir, &sb) != 0) {
        char what[600];
        snprintf(what, sizeof what, "cannot use directory '%.500s'", dir);
        st = io_fail(diag, path, what, errno);
    } else if (!S_ISDIR(sb.st_mode)) {
        char what[600];
        snprintf(what, sizeof what, "'%.500s' is not a directory", dir);
        st = io_fail(diag, path, what, 0);
    } else if (access(dir, W_OK | X_OK) != 0) {
        char what[600];
        snprintf(what, sizeof what, "directory '%.500s' is not writable", dir);
        st = io_fail(diag, path, what, errno);
    }
    free(dir);
    return st;
}

static void outfile_release(rb_outfile *f)
{
    free(f->path);
    free(f->tmp_path);
    memset(f, 0, sizeof *f);
}

rb_status rb_outfile_open(rb_outfile *f, const char *path, int no_clobber,
                          rb_diag *diag)
{
    size_t n = strlen(path);
    int fd;
    char *dir;
    size_t nd;
    struct stat sb;
    memset(f, 0, sizeof *f);
    if (no_clobber && access(path, F_OK) == 0)
        return io_fail(diag, path, "file exists; not overwriting it", 0);
    if (!(dir = dir_of(path)))
        return RB_ERR_NOMEM;
    nd = strlen(dir);
    f->path = malloc(n + 1);
    f->tmp_path = malloc(nd + sizeof "/.rb-XXXXXX");
    if (!f->path || !f->tmp_path) {
        free(dir);
        outfile_release(f);
        return RB_ERR_NOMEM;
    }
    memcpy(f->path, path, n + 1);
    memcpy(f->tmp_path, dir, nd);
    memcpy(f->tmp_path + nd, "/.rb-XXXXXX", sizeof "/.rb-XXXXXX");
    free(dir);
    f->no_clobber = no_clobber;
    fd = mkstemp(f->tmp_path);
    if (fd < 0) {
        rb_status st = io_fail(diag, path, "cannot create a temporary file", errno);
        outfile_release(f);
        return st;
    }
    /* mkstemp makes the file 0600: a replaced file's mode and owner, or
     * the usual mode of a new file */
    if (stat(path, &sb) == 0 && S_ISREG(sb.st_mode)) {
        if (fchown(fd, sb.st_uid, sb.st_gid) != 0)
            (void)fchown(fd, (uid_t)-1, sb.st_gid);
        (void)fchmod(fd, sb.st_mode & 07777);
    } else {
        mode_t mask = umask(0);
        umask(mask);
        (void)fchmod(fd, 0666 & ~mask);
    }
    if (!(f->fp = fdopen(fd, "wb"))) {
        rb_status st = io_fail(diag, path, "cannot open the temporary file", errno);
        close(fd);
        unlink(f->tmp_path);
        outfile_release(f);
        return st;
    }
    return RB_OK;
}

void rb_outfile_abort(rb_outfile *f)
{
    if (!f)
        return;
    if (f->fp)
        fclose(f->fp);
    if (f->tmp_path)
        unlink(f->tmp_path);
    outfile_release(f);
}

rb_status rb_outfile_finish(rb_outfile *f, rb_diag *diag)
{
    int err = 0;
    const char *what = NULL;
    if (f->finished)
        return RB_OK;
    if (fflush(f->fp) != 0 || ferror(f->fp))
        what = "cannot write", err = errno;
    else if (fsync(fileno(f->fp)) != 0)
        what = "cannot sync to disk", err = errno;
    if (fclose(f->fp) != 0 && !what)
        what = "cannot close", err = errno;
    f->fp = NULL;
    if (what) {
        rb_status st = io_fail(diag, f->path, what, err);
        rb_outfile_abort(f);
        return st;
    }
    f->finished = 1;
    return RB_OK;
}

rb_status rb_outfile_commit(rb_outfile *f, rb_diag *diag)
{
    rb_status st = rb_outfile_finish(f, diag);
    if (st != RB_OK)
        return st;
    if (f->no_clobber) {
        if (link(f->tmp_path, f->path) != 0) {
            st = errno == EEXIST
                ? io_fail(diag, f->path, "file exists; not overwriting it", 0)
                : io_fail(diag, f->path, "cannot create", errno);
        }
    } else if (rename(f->tmp_path, f->path) != 0) {
        st = io_fail(diag, f->path, "cannot rename the temporary file into place",
                     errno);
    }
    if (st != RB_OK || f->no_clobber)
        unlink(f->tmp_path);
    outfile_release(f);
    return st;
}

rb_status rb_outfile_write_all(const char *path, const char *data, size_t len,
                               int no_clobber, rb_diag *diag)
{
    rb_outfile f;
    rb_status st = rb_outfile_open(&f, path, no_clobber, diag);
    if (st != RB_OK)
        return st;
    if (len > 0 && fwrite(data, 1, len, f.fp) != len) {
        st = io_fail(diag, path, "cannot write", errno);
        rb_outfile_abort(&f);
        return st;
    }
    return rb_outfile_commit(&f, diag);
}
