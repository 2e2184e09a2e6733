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
#include "rockbolt/outplan.h"
#include "rockbolt/report.h"
#include "rockbolt/outfile.h"

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

/* Entries in dir that are temporary files (".rb-XXXXXX", or the old
 * "<name>.tmp.XXXXXX") */
static int temp_files(void)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    int n = 0;
    if (!d)
        return -1;
    while ((e = readdir(d)) != NULL)
        n += strstr(e->d_name, ".tmp.") != NULL || strncmp(e->d_name, ".rb-", 4) == 0;
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

/* A 255-byte name: the temporary name must not grow from it. */
static void test_long_name(void)
{
    char name[256], p[600];
    rb_diag d;
    memset(name, 'x', 255);
    name[255] = '\0';
    memcpy(name + 250, ".json", 5);
    snprintf(p, sizeof p, "%s/%s", dir, name);
    CHECK(rb_outfile_write_all(p, "long\n", 5, 0, &d) == RB_OK);
    CHECK(file_equals(p, "long\n"));
    CHECK(temp_files() == 0);
    unlink(p);
}

/* An overwritten file keeps its mode (and owner where allowed). */
static void test_keep_mode(void)
{
    char p[512];
    struct stat sb;
    rb_diag d;
    path_in(p, sizeof p, "mode.json");
    CHECK(rb_outfile_write_all(p, "a\n", 2, 0, &d) == RB_OK);
    CHECK(chmod(p, 0604) == 0);
    CHECK(rb_outfile_write_all(p, "b\n", 2, 0, &d) == RB_OK);
    CHECK(stat(p, &sb) == 0 && (sb.st_mode & 07777) == 0604);
    CHECK(file_equals(p, "b\n"));
    unlink(p);
}

static rb_status fill_name(void *ctx, size_t i, FILE *fp, rb_diag *d)
{
    const rb_outplan *p = ctx;
    (void)d;
    fprintf(fp, "%s\n", rb_outplan_opt(p, i));
    return RB_OK;
}

static rb_status fill_fails(void *ctx, size_t i, FILE *fp, rb_diag *d)
{
    (void)ctx;
    fputs("partial", fp);
    if (i == 1) {
        snprintf(d->msg, sizeof d->msg, "refused");
        return RB_ERR_INVALID;
    }
    return RB_OK;
}

/* Clashes between outputs and with inputs, however spelt. */
static void test_plan_clashes(void)
{
    char a[512], a2[512], in[512], ln[512];
    rb_outplan p;
    rb_diag d;
    path_in(a, sizeof a, "a.json");
    snprintf(a2, sizeof a2, "%s/./a.json", dir);
    path_in(in, sizeof in, "case.yaml");
    path_in(ln, sizeof ln, "case-link.yaml");
    CHECK(rb_outfile_write_all(in, "case\n", 5, 0, &d) == RB_OK);
    CHECK(symlink("case.yaml", ln) == 0);
    rb_outplan_init(&p);
    CHECK(rb_outplan_add_input(&p, in, &d) == RB_OK);
    CHECK(rb_outplan_add_input(&p, ln, &d) == RB_OK); /* one input, twice */
    CHECK(rb_outplan_inputs(&p) == 1);
    CHECK(rb_outplan_add(&p, "--json", a, &d) == RB_OK);
    /* a file still to be made, spelt differently */
    CHECK(rb_outplan_add(&p, "--html", a2, &d) == RB_ERR_INVALID);
    CHECK(strcmp(d.key, "--html") == 0 && strstr(d.msg, "--json") != NULL);
    /* the input through a link */
    CHECK(rb_outplan_add(&p, "--text", ln, &d) == RB_ERR_INVALID);
    CHECK(strstr(d.msg, "input") != NULL);
    CHECK(rb_outplan_reserve(&p, "--reports", in, &d) == RB_ERR_INVALID);
    /* one descriptor twice */
    CHECK(rb_outplan_add(&p, "--csv", "-", &d) == RB_OK);
    CHECK(rb_outplan_uses_stdout(&p));
    CHECK(rb_outplan_add(&p, "--junit", "/dev/fd/1", &d) == RB_ERR_INVALID);
    /* names */
    CHECK(rb_outplan_add(&p, "--svg", "", &d) == RB_ERR_IO);
    CHECK(rb_outplan_add(&p, "--svg", dir, &d) == RB_ERR_IO);
    {
        char longp[700], name[300];
        memset(name, 'y', 256);
        name[256] = '\0';
        snprintf(longp, sizeof longp, "%s/%s", dir, name);
        CHECK(rb_outplan_add(&p, "--svg", longp, &d) == RB_ERR_IO);
        CHECK(strstr(d.msg, "too long") != NULL);
    }
    CHECK(rb_outplan_count(&p) == 2);
    rb_outplan_free(&p);
    /* an output added first, the input after */
    rb_outplan_init(&p);
    CHECK(rb_outplan_add(&p, "--json", in, &d) == RB_OK);
    CHECK(rb_outplan_add_input(&p, in, &d) == RB_ERR_INVALID);
    rb_outplan_free(&p);
    CHECK(file_equals(in, "case\n"));
    unlink(ln);
    unlink(in);
}

/* Write: all or none, links written through, staged extras renamed last. */
static void test_plan_write(void)
{
    char a[512], b[512], real[512], ln[512], x[512];
    rb_outplan p;
    rb_diag d;
    path_in(a, sizeof a, "a.out");
    path_in(b, sizeof b, "b.out");
    path_in(real, sizeof real, "real.out");
    path_in(ln, sizeof ln, "link.out");
    path_in(x, sizeof x, "extra.out");
    CHECK(rb_outfile_write_all(real, "old\n", 4, 0, &d) == RB_OK);
    CHECK(symlink("real.out", ln) == 0);
    /* a failing output: nothing is written, no temporary file is left */
    rb_outplan_init(&p);
    CHECK(rb_outplan_add(&p, "--json", a, &d) == RB_OK);
    CHECK(rb_outplan_add(&p, "--csv", ln, &d) == RB_OK);
    CHECK(rb_outplan_stage_data(&p, x, "x\n", 2, &d) == RB_OK);
    CHECK(temp_files() == 1);
    CHECK(rb_outplan_write(&p, fill_fails, &p, &d) == RB_ERR_INVALID);
    CHECK(strcmp(d.msg, "refused") == 0);
    CHECK(access(a, F_OK) != 0 && access(x, F_OK) != 0);
    CHECK(file_equals(real, "old\n"));
    CHECK(temp_files() == 0);
    rb_outplan_free(&p);
    /* and one that works */
    rb_outplan_init(&p);
    CHECK(rb_outplan_add(&p, "--json", a, &d) == RB_OK);
    CHECK(rb_outplan_add(&p, "--csv", ln, &d) == RB_OK);
    CHECK(rb_outplan_add(&p, "--null", "/dev/null", &d) == RB_OK);
    CHECK(rb_outplan_stage_data(&p, b, "b\n", 2, &d) == RB_OK);
    CHECK(access(b, F_OK) != 0);
    CHECK(rb_outplan_write(&p, fill_name, &p, &d) == RB_OK);
    CHECK(file_equals(a, "--json\n"));
    CHECK(file_equals(real, "--csv\n"));
    CHECK(file_equals(b, "b\n"));
    {
        struct stat sb;
        CHECK(lstat(ln, &sb) == 0 && S_ISLNK(sb.st_mode));
        CHECK(stat("/dev/null", &sb) == 0 && S_ISCHR(sb.st_mode));
    }
    CHECK(temp_files() == 0);
    rb_outplan_free(&p);
    /* a full device says why */
    if (access("/dev/full", W_OK) == 0) {
        rb_outplan_init(&p);
        CHECK(rb_outplan_add(&p, "--json", "/dev/full", &d) == RB_OK);
        CHECK(rb_outplan_write(&p, fill_name, &p, &d) == RB_ERR_IO);
        CHECK(strstr(d.msg, "No space left on device") != NULL);
        CHECK(strcmp(d.key, "--json") == 0);
        rb_outplan_free(&p);
    }
    unlink(a);
    unlink(b);
    unlink(ln);
    unlink(real);
}

/* The outputs go to the directory they were planned in, and only over the
 * file planned there or where there is none: a directory renamed and
 * replaced by a link to somewhere else between planning and writing (say
 * to the directory of the case), or a file made or swapped in under the
 * output's name, is not written through. */
static void test_plan_dir_swapped(void)
{
    char sub[512], real[512], victim[512], victim2[512], out[512], rep[512];
    char moved[512], moved2[512], e[512], eo[512], late[512];
    rb_outplan p;
    rb_diag d;
    path_in(sub, sizeof sub, "d");
    path_in(real, sizeof real, "d.real");
    path_in(victim, sizeof victim, "victim.yaml");
    path_in(victim2, sizeof victim2, "victim2.yaml");
    path_in(out, sizeof out, "d/victim.yaml");
    path_in(rep, sizeof rep, "d/victim2.yaml");
    path_in(moved, sizeof moved, "d.real/victim.yaml");
    path_in(moved2, sizeof moved2, "d.real/victim2.yaml");
    CHECK(mkdir(sub, 0755) == 0);
    CHECK(rb_outfile_write_all(victim, "case\n", 5, 0, &d) == RB_OK);
    CHECK(rb_outfile_write_all(victim2, "case2\n", 6, 0, &d) == RB_OK);
    rb_outplan_init(&p);
    CHECK(rb_outplan_add(&p, "--json", out, &d) == RB_OK);
    CHECK(rb_outplan_reserve(&p, "--reports", rep, &d) == RB_OK);
    /* the swap, while the command would be solving */
    CHECK(rename(sub, real) == 0);
    CHECK(symlink(".", sub) == 0);
    CHECK(rb_outplan_stage_data(&p, rep, "report\n", 7, &d) == RB_OK);
    CHECK(rb_outplan_write(&p, fill_name, &p, &d) == RB_OK);
    rb_outplan_free(&p);
    CHECK(file_equals(victim, "case\n"));
    CHECK(file_equals(victim2, "case2\n"));
    CHECK(file_equals(moved, "--json\n"));
    CHECK(file_equals(moved2, "report\n"));
    CHECK(temp_files() == 0);
    unlink(moved);
    unlink(moved2);
    unlink(sub);
    rmdir(real);

    /* a file made under the name after planning is not replaced, and no
     * other output is written either */
    path_in(e, sizeof e, "e.json");
    path_in(late, sizeof late, "late.json");
    rb_outplan_init(&p);
    CHECK(rb_outplan_add(&p, "--json", e, &d) == RB_OK);
    CHECK(rb_outplan_add(&p, "--csv", late, &d) == RB_OK);
    CHECK(rb_outfile_write_all(late, "theirs\n", 7, 0, &d) == RB_OK);
    rb_diag_clear(&d);
    CHECK(rb_outplan_write(&p, fill_name, &p, &d) == RB_ERR_IO);
    CHECK(strstr(d.msg, "appeared since the outputs were planned") != NULL);
    CHECK(strcmp(d.key, "--csv") == 0 && strcmp(d.file, late) == 0);
    CHECK(file_equals(late, "theirs\n"));
    CHECK(access(e, F_OK) != 0);
    CHECK(temp_files() == 0);
    rb_outplan_free(&p);
    unlink(late);

    /* a planned file swapped for a link to another is not replaced */
    path_in(eo, sizeof eo, "eo.json");
    CHECK(rb_outfile_write_all(eo, "old\n", 4, 0, &d) == RB_OK);
    rb_outplan_init(&p);
    CHECK(rb_outplan_add(&p, "--json", eo, &d) == RB_OK);
    CHECK(unlink(eo) == 0 && symlink("victim.yaml", eo) == 0);
    rb_diag_clear(&d);
    CHECK(rb_outplan_write(&p, fill_name, &p, &d) == RB_ERR_IO);
    CHECK(strstr(d.msg, "another file has taken its place") != NULL);
    CHECK(file_equals(victim, "case\n"));
    {
        struct stat sb;
        CHECK(lstat(eo, &sb) == 0 && S_ISLNK(sb.st_mode));
    }
    CHECK(temp_files() == 0);
    rb_outplan_free(&p);
    /* planned and then removed: written */
    CHECK(unlink(eo) == 0);
    CHECK(rb_outfile_write_all(eo, "old\n", 4, 0, &d) == RB_OK);
    rb_outplan_init(&p);
    CHECK(rb_outplan_add(&p, "--json", eo, &d) == RB_OK);
    CHECK(unlink(eo) == 0);
    CHECK(rb_outplan_write(&p, fill_name, &p, &d) == RB_OK);
    CHECK(file_equals(eo, "--json\n"));
    rb_outplan_free(&p);
    unlink(eo);
    unlink(victim);
    unlink(victim2);
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
    test_long_name();
    test_keep_mode();
    test_plan_clashes();
    test_plan_write();
    test_plan_dir_swapped();
    path_in(p, sizeof p, "a.json");
    unlink(p);
    path_in(p, sizeof p, "starter.yaml");
    unlink(p);
    CHECK(rmdir(dir) == 0);
    TEST_MAIN_END();
}
