/* Atomic output files: a committed file has exactly the data; an aborted
 * or failed write leaves the old file as it was and no temporary file
 * behind; no_clobber refuses to replace; the path check catches missing
 * and non-directory parents before any work. Works as root too (it never
 * relies on permission bits). */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "harness.h"
#include "rockbolt/report.h"

static char dir[] = "/tmp/rb-outfile-XXXXXX";

static void path_in(char *buf, size_t n, const char *name)
{
    snprintf(buf, n, "%s/%s", dir, name);
}

static int file_equals(const char *path, const char *want)
{
    char buf[256] = {0};
    FILE *fp = fopen(path, "rb");
    size_t n;
    if (!fp)
        return 0;
    n = fread(buf, 1, sizeof buf - 1, fp);
    fclose(fp);
    return n == strlen(want) && memcmp(buf, want, n) == 0;
}

/* Entries in dir whose names contain ".tmp." */
static int temp_files(void)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    int n = 0;
    if (!d)
        return -1;
    while ((e = readdir(d)) != NULL)
        n += strstr(e->d_name, ".tmp.") != NULL;
    closedir(d);
    return n;
}

static void test_commit_and_abort(void)
{
    char p[512];
    rb_outfile f;
    rb_diag d;
    path_in(p, sizeof p, "a.json");
    CHECK(rb_outfile_check(p, &d) == RB_OK);
    CHECK(rb_outfile_write_all(p, "first\n", 6, 0, &d) == RB_OK);
    CHECK(file_equals(p, "first\n"));
    /* while being written the target still holds the old data */
    CHECK(rb_outfile_open(&f, p, 0, &d) == RB_OK);
    fputs("second, half", f.fp);
    fflush(f.fp);
    CHECK(file_equals(p, "first\n"));
    CHECK(temp_files() == 1);
    rb_outfile_abort(&f);
    CHECK(file_equals(p, "first\n"));
    CHECK(temp_files() == 0);
    rb_outfile_abort(&f); /* twice is harmless */
    /* finish then commit, as the CLI does for several outputs */
    CHECK(rb_outfile_open(&f, p, 0, &d) == RB_OK);
    fputs("second\n", f.fp);
    CHECK(rb_outfile_finish(&f, &d) == RB_OK);
    CHECK(file_equals(p, "first\n"));
    CHECK(rb_outfile_commit(&f, &d) == RB_OK);
    CHECK(file_equals(p, "second\n"));
    CHECK(temp_files() == 0);
    CHECK(f.path == NULL && f.tmp_path == NULL && f.fp == NULL);
}

static void test_no_clobber(void)
{
    char p[512];
    rb_outfile f;
    rb_diag d;
    path_in(p, sizeof p, "starter.yaml");
    CHECK(rb_outfile_write_all(p, "one\n", 4, 1, &d) == RB_OK);
    CHECK(file_equals(p, "one\n"));
    CHECK(rb_outfile_write_all(p, "two\n", 4, 1, &d) == RB_ERR_IO);
    CHECK(strstr(d.msg, "exists") != NULL);
    CHECK(file_equals(p, "one\n"));
    /* a file that appears between open and commit is not replaced */
    unlink(p);
    CHECK(rb_outfile_open(&f, p, 1, &d) == RB_OK);
    fputs("mine\n", f.fp);
    CHECK(rb_outfile_write_all(p, "theirs\n", 7, 0, &d) == RB_OK);
    CHECK(rb_outfile_commit(&f, &d) == RB_ERR_IO);
    CHECK(file_equals(p, "theirs\n"));
    CHECK(temp_files() == 0);
}

static void test_check(void)
{
    char p[512], q[512];
    rb_diag d;
    CHECK(rb_outfile_check("/nonexistent-rb-dir/x.json", &d) == RB_ERR_IO);
    CHECK(strcmp(d.file, "/nonexistent-rb-dir/x.json") == 0);
    CHECK(strstr(d.msg, "/nonexistent-rb-dir") != NULL);
    path_in(p, sizeof p, "plain");
    CHECK(rb_outfile_write_all(p, "x", 1, 0, &d) == RB_OK);
    path_in(q, sizeof q, "plain/x.json");
    CHECK(rb_outfile_check(q, &d) == RB_ERR_IO); /* parent is a file */
    CHECK(rb_outfile_check(dir, &d) == RB_ERR_IO); /* a directory */
    CHECK(rb_outfile_check("", &d) == RB_ERR_IO);
    CHECK(rb_outfile_check("relative-name.json", &d) == RB_OK);
    /* open fails the same way, leaving nothing to free */
    {
        rb_outfile f;
        CHECK(rb_outfile_open(&f, q, 0, &d) == RB_ERR_IO);
        CHECK(f.path == NULL && f.tmp_path == NULL && f.fp == NULL);
    }
    unlink(p);
}

int main(void)
{
    char p[512];
    if (!mkdtemp(dir)) {
        perror("mkdtemp");
        return 1;
    }
    test_commit_and_abort();
    test_no_clobber();
    test_check();
    path_in(p, sizeof p, "a.json");
    unlink(p);
    path_in(p, sizeof p, "starter.yaml");
    unlink(p);
    CHECK(rmdir(dir) == 0);
    TEST_MAIN_END();
}
