/* The sandbox is a value: two opened side by side each keep their own
 * tree (nothing of one leaks into the other, as a process-wide one would),
 * a link out of the tree and a sibling whose name starts with the tree's
 * are refused, a missing file is left to the open, and NULL or a sandbox
 * opened without a directory allows everything. */
#include <limits.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "harness.h"
#include "rockbolt/sandbox.h"

static void touch(const char *path)
{
    FILE *f = fopen(path, "w");
    CHECK(f != NULL);
    if (f)
        fclose(f);
}

int main(void)
{
    char top[] = "/tmp/rb_sandbox_XXXXXX";
    CHECK(mkdtemp(top) != NULL);
    char a[512], ax[512], b[512], fa[600], fax[600], fb[600], link[600], missing[600];
    snprintf(a, sizeof a, "%s/a", top);
    snprintf(ax, sizeof ax, "%s/ax", top); /* "a" is a prefix of its name */
    snprintf(b, sizeof b, "%s/b", top);
    CHECK(mkdir(a, 0700) == 0 && mkdir(ax, 0700) == 0 && mkdir(b, 0700) == 0);
    snprintf(fa, sizeof fa, "%s/in.yaml", a);
    snprintf(fax, sizeof fax, "%s/in.yaml", ax);
    snprintf(fb, sizeof fb, "%s/in.yaml", b);
    snprintf(link, sizeof link, "%s/out.yaml", a);
    snprintf(missing, sizeof missing, "%s/none.yaml", a);
    touch(fa);
    touch(fax);
    touch(fb);
    CHECK(symlink(fb, link) == 0);

    static rb_sandbox sa, sb, off;
    rb_diag d;
    CHECK(rb_sandbox_open(&sa, a, &d) == RB_OK);
    CHECK(rb_sandbox_open(&sb, b, &d) == RB_OK);
    CHECK(rb_sandbox_open(&off, NULL, &d) == RB_OK);

    char real_a[PATH_MAX], real_fb[PATH_MAX], why[PATH_MAX + 64];
    CHECK(realpath(a, real_a) != NULL);
    CHECK(realpath(fb, real_fb) != NULL);
    CHECK(rb_sandbox_dir(&sa) && strcmp(rb_sandbox_dir(&sa), real_a) == 0);
    CHECK(rb_sandbox_dir(&off) == NULL);
    CHECK(rb_sandbox_dir(NULL) == NULL);

    /* each sandbox its own tree, whichever was opened last */
    CHECK(rb_sandbox_allows(&sa, fa, why, sizeof why) == 1);
    CHECK(rb_sandbox_allows(&sa, fb, why, sizeof why) == 0);
    CHECK(rb_sandbox_allows(&sb, fb, why, sizeof why) == 1);
    CHECK(rb_sandbox_allows(&sb, fa, why, sizeof why) == 0);

    /* a link out, named by where it resolves; a sibling sharing a prefix */
    why[0] = '\0';
    CHECK(rb_sandbox_allows(&sa, link, why, sizeof why) == 0);
    CHECK(strstr(why, real_fb) != NULL);
    CHECK(rb_sandbox_allows(&sa, fax, why, sizeof why) == 0);
    CHECK(rb_sandbox_allows(&sa, missing, why, sizeof why) == 1);

    /* no sandbox: everything */
    CHECK(rb_sandbox_allows(NULL, fb, why, sizeof why) == 1);
    CHECK(rb_sandbox_allows(&off, fb, why, sizeof why) == 1);

    /* not a directory: an error naming the option, and the value stays off */
    rb_sandbox bad;
    errno = ENOENT; /* a cause left by an earlier call must not be named */
    CHECK(rb_sandbox_open(&bad, fa, &d) == RB_ERR_IO);
    CHECK(strcmp(d.key, "--sandbox") == 0);
    CHECK(strstr(d.msg, strerror(ENOTDIR)) != NULL);
    CHECK(strstr(d.msg, strerror(ENOENT)) == NULL);
    errno = 0;
    CHECK(rb_sandbox_open(&bad, missing, &d) == RB_ERR_IO);
    CHECK(strstr(d.msg, strerror(ENOENT)) != NULL);
    CHECK(rb_sandbox_dir(&bad) == NULL);
    CHECK(rb_sandbox_allows(&bad, fb, why, sizeof why) == 1);

    unlink(link);
    unlink(fa);
    unlink(fax);
    unlink(fb);
    rmdir(a);
    rmdir(ax);
    rmdir(b);
    rmdir(top);
    TEST_MAIN_END();
}
