/* Finding a shipped template (report.txt, calc.txt, starter.yaml, ac156.yaml) at run
 * time.
 *
 * A developer edits templates/ and wants the change seen without a
 * rebuild; a user runs an installed binary with no source tree. So the
 * search is: $RB_TEMPLATE_DIR, then the data directory's templates (the
 * installed share/rockbolt/templates, $RB_DATA_DIR, or the source tree the
 * binary was built from: rockbolt/datadir.h), then the compiled-in copy. */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/datadir.h"
#include "rockbolt/report.h"
#include "rockbolt/template.h"

#define TMPL_MAX_BYTES (1024L * 1024L) /* a template is a few kilobytes */

/* Read path whole. Returns RB_OK, RB_ERR_IO when it does not exist (errno
 * ENOENT, *missing set) or cannot be read, RB_ERR_LIMIT if huge. */
static rb_status read_whole(const char *path, char **text, int *missing,
                            rb_diag *diag)
{
    FILE *fp = fopen(path, "rb");
    char *buf = NULL;
    size_t n = 0, cap = 0;
    int err;
    *missing = 0;
    if (!fp) {
        *missing = errno == ENOENT || errno == ENOTDIR;
        goto fail;
    }
    for (;;) {
        size_t got;
        if (cap - n < 4096) {
            char *p = realloc(buf, cap + 65536);
            if (!p) {
                fclose(fp);
                free(buf);
                return RB_ERR_NOMEM;
            }
            buf = p;
            cap += 65536;
        }
        got = fread(buf + n, 1, cap - n - 1, fp);
        n += got;
        if (got == 0 || n > (size_t)TMPL_MAX_BYTES)
            break;
    }
    err = ferror(fp) || n > (size_t)TMPL_MAX_BYTES;
    fclose(fp);
    if (err)
        goto fail;
    buf[n] = '\0';
    *text = buf;
    return RB_OK;
fail:
    err = errno;
    free(buf);
    if (diag) {
        rb_diag_set_file(diag, "%.500s", path);
        rb_diag_set_msg(diag, "cannot read template: %s",
                        err ? strerror(err) : "too large");
    }
    return RB_ERR_IO;
}

/* Try dir/name; RB_OK and *text set if found, RB_ERR_IO with *missing set
 * if simply absent. */
static rb_status try_dir(const char *dir, const char *name, char **text,
                         int *missing, rb_diag *diag)
{
    char path[4096];
    int n = snprintf(path, sizeof path, "%s/%s", dir, name);
    if (n < 0 || (size_t)n >= sizeof path) {
        *missing = 1;
        return RB_ERR_IO;
    }
    errno = 0;
    return read_whole(path, text, missing, diag);
}

rb_status rb_template_load(const char *name, char **text, const char **origin,
                           rb_diag *diag)
{
    const char *env = getenv("RB_TEMPLATE_DIR");
    const char *builtin = rb_template_builtin(name);
    int missing = 0;
    rb_status st;
    *text = NULL;
    if (!builtin) {
        if (diag)
            rb_diag_set_msg(diag, "no template called '%s'", name);
        return RB_ERR_INVALID;
    }
    if (env && env[0]) {
        st = try_dir(env, name, text, &missing, diag);
        if (st == RB_OK && origin)
            *origin = "RB_TEMPLATE_DIR";
        if (st == RB_OK || !missing)
            return st;
    }
    st = try_dir(rb_data_templates_dir(), name, text, &missing, diag);
    if (st == RB_OK && origin)
        *origin = rb_data_origin();
    if (st == RB_OK || !missing)
        return st;
    rb_diag_clear(diag);
    if (!(*text = malloc(strlen(builtin) + 1)))
        return RB_ERR_NOMEM;
    memcpy(*text, builtin, strlen(builtin) + 1);
    if (origin)
        *origin = "built-in";
    return RB_OK;
}
