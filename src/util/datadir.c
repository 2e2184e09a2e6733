/* The data directory (include/rockbolt/datadir.h): records and templates
 * found relative to the installed binary, with RB_DATA_DIR to override and
 * the source tree for a build that is not installed. */
#include <limits.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "rockbolt/datadir.h"

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif

/* The data directory relative to the installed binary's directory, as the
 * build's install layout has it. */
#ifndef RB_DATA_FROM_BIN
#define RB_DATA_FROM_BIN "../share/rockbolt"
#endif

static const rb_shipped_record shipped[] = {
    {"elcentro", "elcentro_1940_ns.at2", "at2", NULL, NULL},
    {"taft", "taft_1952_s69e.txt", "one-column", "0.01 s", "g"},
};

static char records_dir[PATH_MAX];
static char templates_dir[PATH_MAX];
static const char *data_origin;
static pthread_mutex_t data_lock = PTHREAD_MUTEX_INITIALIZER;

static int is_dir(const char *p)
{
    struct stat sb;
    return stat(p, &sb) == 0 && S_ISDIR(sb.st_mode);
}

static int set_pair(const char *rec, const char *tmpl, const char *origin)
{
    int a = snprintf(records_dir, sizeof records_dir, "%s", rec);
    int b = snprintf(templates_dir, sizeof templates_dir, "%s", tmpl);
    if (a < 0 || (size_t)a >= sizeof records_dir || b < 0
        || (size_t)b >= sizeof templates_dir)
        return 0;
    data_origin = origin;
    return 1;
}

/* DIR/records and DIR/templates. */
static int set_share(const char *dir, const char *origin)
{
    char rec[PATH_MAX], tmpl[PATH_MAX];
    int a = snprintf(rec, sizeof rec, "%s/records", dir);
    int b = snprintf(tmpl, sizeof tmpl, "%s/templates", dir);
    if (a < 0 || (size_t)a >= sizeof rec || b < 0 || (size_t)b >= sizeof tmpl)
        return 0;
    return set_pair(rec, tmpl, origin);
}

/* ../share/rockbolt (RB_DATA_FROM_BIN) from the directory of the running
 * executable. */
static int from_exe(void)
{
    char exe[PATH_MAX], share[PATH_MAX], rec[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0)
        return 0;
    exe[n] = '\0';
    char *slash = strrchr(exe, '/');
    if (!slash)
        return 0;
    *slash = '\0';
    int a = snprintf(share, sizeof share, "%s/%s", exe, RB_DATA_FROM_BIN);
    if (a < 0 || (size_t)a >= sizeof share)
        return 0;
    int b = snprintf(rec, sizeof rec, "%s/records", share);
    if (b < 0 || (size_t)b >= sizeof rec || !is_dir(rec))
        return 0;
    /* a clean path in messages and reports */
    char real[PATH_MAX];
    return set_share(realpath(share, real) ? real : share, "installed");
}

static void find(void)
{
    const char *env = getenv("RB_DATA_DIR");
    if (env && env[0] && set_share(env, "RB_DATA_DIR"))
        return;
    if (from_exe())
        return;
#ifdef RB_SOURCE_DIR
    if (is_dir(RB_SOURCE_DIR "/cases/records")
        && set_pair(RB_SOURCE_DIR "/cases/records", RB_SOURCE_DIR "/templates",
                    "source tree"))
        return;
#endif
#ifdef RB_INSTALL_DATADIR
    if (set_share(RB_INSTALL_DATADIR, "install prefix"))
        return;
#endif
    set_share("/usr/share/rockbolt", "install prefix");
}

static void ensure(void)
{
    pthread_mutex_lock(&data_lock);
    if (!data_origin)
        find();
    pthread_mutex_unlock(&data_lock);
}

const char *rb_data_records_dir(void)
{
    ensure();
    return records_dir;
}

const char *rb_data_templates_dir(void)
{
    ensure();
    return templates_dir;
}

const char *rb_data_origin(void)
{
    ensure();
    return data_origin;
}

const rb_shipped_record *rb_shipped_find(const char *name)
{
    for (size_t k = 0; k < sizeof shipped / sizeof shipped[0]; k++)
        if (strcmp(shipped[k].name, name) == 0)
            return &shipped[k];
    return NULL;
}

const char *rb_shipped_names(void)
{
    return "elcentro, taft";
}

const char *rb_shipped_path(const char *name, char *buf, size_t size)
{
    const rb_shipped_record *r = rb_shipped_find(name);
    if (!r)
        return NULL;
    int n = snprintf(buf, size, "%s/%s", rb_data_records_dir(), r->file);
    return n > 0 && (size_t)n < size ? buf : NULL;
}
