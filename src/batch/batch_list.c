/* The work list of a batch: what each command-line argument names.
 *
 * Directories and glob patterns are expanded and sorted by name with
 * strcmp, so that the list, and with it every shard, is the same on every
 * machine whatever its locale or file system order. */
#include <dirent.h>
#include <glob.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "batch_internal.h"

static int cmp_str(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static int ends_with(const char *s, const char *suffix)
{
    size_t n = strlen(s), k = strlen(suffix);
    return n >= k && strcmp(s + n - k, suffix) == 0;
}

/* A bad item for a name that is not a regular file: a FIFO would block
 * the batch for ever at its open, a device could be endless. */
static rb_status add_not_regular(rb_batch_list *l, const char *path, const char *what)
{
    rb_batch_item *it = rb_batch_list_push(l, path);
    if (!it)
        return RB_ERR_NOMEM;
    rb_batch_item_bad(it, 0, 0, "case", what);
    return RB_OK;
}

/* One file named or found: a list or a case. Names found by a directory
 * scan or a glob (found) must be regular files and are not opened
 * otherwise; so must an equipment list, which is named by its .csv. A case
 * named on the command line may be a pipe (`batch <(gen-case)`): the case
 * loader opens it without waiting for a writer. */
static rb_status add_file(rb_batch_list *l, const char *path, const char *default_base,
                          int found)
{
    struct stat sb;
    int csv = ends_with(path, ".csv");
    if ((found || csv) && stat(path, &sb) == 0 && !S_ISREG(sb.st_mode))
        return add_not_regular(l, path, S_ISDIR(sb.st_mode)
                               ? "not a regular file but a directory: skipped, not read"
                               : "not a regular file (a FIFO, socket or device): "
                                 "refused without opening it, since reading it could "
                                 "wait for ever");
    if (csv)
        return rb_batch_list_read_csv(l, path, default_base);
    return rb_batch_list_push(l, path) ? RB_OK : RB_ERR_NOMEM;
}

static rb_status add_dir(rb_batch_list *l, const char *dir, const char *default_base)
{
    DIR *d = opendir(dir);
    char **names = NULL;
    size_t n = 0, cap = 0;
    rb_status st = RB_OK;
    if (!d) {
        rb_batch_item *it = rb_batch_list_push(l, dir);
        if (!it)
            return RB_ERR_NOMEM;
        rb_batch_item_bad(it, 0, 0, "case", "cannot read the directory");
        return RB_OK;
    }
    struct dirent *e;
    while ((e = readdir(d)) != NULL && st == RB_OK) {
        if (e->d_name[0] == '.' || !ends_with(e->d_name, ".yaml"))
            continue;
        if (n == cap) {
            size_t c2 = cap ? 2 * cap : 32;
            char **p = realloc(names, c2 * sizeof *p);
            if (!p) {
                st = RB_ERR_NOMEM;
                break;
            }
            names = p;
            cap = c2;
        }
        size_t dl = strlen(dir);
        int slash = dl > 0 && dir[dl - 1] == '/';
        names[n] = malloc(dl + strlen(e->d_name) + 2);
        if (!names[n]) {
            st = RB_ERR_NOMEM;
            break;
        }
        sprintf(names[n], "%s%s%s", dir, slash ? "" : "/", e->d_name);
        n++;
    }
    closedir(d);
    if (st == RB_OK && n == 0) {
        rb_batch_item *it = rb_batch_list_push(l, dir);
        if (!it)
            st = RB_ERR_NOMEM;
        else
            rb_batch_item_bad(it, 0, 0, "case", "the directory holds no *.yaml file");
    }
    if (n > 1)
        qsort(names, n, sizeof *names, cmp_str);
    for (size_t i = 0; i < n; i++) {
        if (st == RB_OK)
            st = add_file(l, names[i], default_base, 1);
        free(names[i]);
    }
    free(names);
    return st;
}

static rb_status add_glob(rb_batch_list *l, const char *pattern, const char *default_base)
{
    glob_t g;
    rb_status st = RB_OK;
    memset(&g, 0, sizeof g);
    int rc = glob(pattern, 0, NULL, &g);
    if (rc == GLOB_NOSPACE) {
        globfree(&g);
        return RB_ERR_NOMEM;
    }
    if (rc != 0 || g.gl_pathc == 0) {
        globfree(&g);
        rb_batch_item *it = rb_batch_list_push(l, pattern);
        if (!it)
            return RB_ERR_NOMEM;
        rb_batch_item_bad(it, 0, 0, "case", "no file matches the pattern");
        return RB_OK;
    }
    qsort(g.gl_pathv, g.gl_pathc, sizeof *g.gl_pathv, cmp_str);
    for (size_t i = 0; i < g.gl_pathc && st == RB_OK; i++) {
        struct stat sb;
        if (stat(g.gl_pathv[i], &sb) == 0 && S_ISDIR(sb.st_mode))
            st = add_dir(l, g.gl_pathv[i], default_base);
        else
            st = add_file(l, g.gl_pathv[i], default_base, 1);
    }
    globfree(&g);
    return st;
}

rb_status rb_batch_list_add(rb_batch_list *l, const char *arg, const char *default_base)
{
    struct stat sb;
    if (stat(arg, &sb) == 0 && S_ISDIR(sb.st_mode))
        return add_dir(l, arg, default_base);
    if (strpbrk(arg, "*?[") && stat(arg, &sb) != 0)
        return add_glob(l, arg, default_base);
    return add_file(l, arg, default_base, 0);
}
