/* --sandbox DIR (include/rockbolt/sandbox.h): a path is inside when its
 * real path is DIR itself or starts with DIR and a '/'. */
#include <errno.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "rockbolt/datadir.h"
#include "rockbolt/sandbox.h"

#if defined(PATH_MAX) && PATH_MAX > RB_SANDBOX_PATH_MAX
#error "realpath may write more than rb_sandbox holds"
#endif

rb_status rb_sandbox_open(rb_sandbox *sb, const char *dir, rb_diag *diag)
{
    struct stat st;
    sb->on = 0;
    sb->root[0] = sb->shipped[0] = '\0';
    if (!dir)
        return RB_OK;
    /* errno names the cause only when a call failed: a path that exists
     * but is not a directory fails no call, and an earlier call's errno
     * would name a cause that is not this one. */
    errno = 0;
    if (!realpath(dir, sb->root) || stat(sb->root, &st) != 0
        || (!S_ISDIR(st.st_mode) && (errno = ENOTDIR))) {
        if (diag) {
            rb_diag_clear(diag);
            rb_diag_set_file(diag, "%s", dir);
            rb_diag_set_key(diag, "--sandbox");
            rb_diag_set_msg(diag, "expected an existing directory%s%s",
                            errno ? ": " : "", errno ? strerror(errno) : "");
        }
        return RB_ERR_IO;
    }
    if (!realpath(rb_data_records_dir(), sb->shipped))
        sb->shipped[0] = '\0';
    sb->on = 1;
    return RB_OK;
}

const char *rb_sandbox_dir(const rb_sandbox *sb)
{
    return sb && sb->on ? sb->root : NULL;
}

static int under(const char *real, const char *root)
{
    size_t n = strlen(root);
    if (!root[0])
        return 0;
    if (n == 1 && root[0] == '/')
        return 1;
    return strncmp(real, root, n) == 0 && (real[n] == '\0' || real[n] == '/');
}

int rb_sandbox_allows(const rb_sandbox *sb, const char *path, char *why, size_t why_size)
{
    char real[RB_SANDBOX_PATH_MAX];
    if (!sb || !sb->on)
        return 1;
    errno = 0;
    if (!realpath(path, real)) {
        /* missing: the open that follows says so; anything else (a loop
         * of links, a part that cannot be searched) cannot be shown to be
         * inside, so it is refused */
        if (errno == ENOENT || errno == ENOTDIR)
            return 1;
        if (why && why_size)
            snprintf(why, why_size, "its real path cannot be resolved: %s",
                     strerror(errno));
        return 0;
    }
    if (under(real, sb->root) || under(real, sb->shipped))
        return 1;
    if (why && why_size)
        snprintf(why, why_size, "it resolves to '%s'", real);
    return 0;
}
