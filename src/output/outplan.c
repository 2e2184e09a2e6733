/* Output plans: see rockbolt/outplan.h. POSIX (Linux for /proc/self/fd). */
#define _GNU_SOURCE  /* renameat2 */
#include "rockbolt/outplan.h"
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdarg.h>
#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>
#include "util/grow.h"
#include <pthread.h>
#include <sys/types.h>

#ifndef PATH_MAX
#define PATH_MAX 4096
#endif
#define RB_TEMP_NAME ".rb-XXXXXX"
#define RB_TEMP_TRIES 100
#define RB_LINK_HOPS 40
#define RB_FIFO_WAIT_MS 10000  /* for a FIFO's reader to open it */

/* ---- The plan's parts --------------------------------------------------- */

typedef enum {
    RB_OUT_FILE = 0,  /* regular file, new or replaced: staged and renamed */
    RB_OUT_FD,        /* an open descriptor: "-", /dev/stdout, /dev/fd/N */
    RB_OUT_DEVICE     /* a character device or a FIFO, opened by name */
} rb_out_how;

typedef struct {
    char *opt;        /* owned: the option that asked for it ("--json") */
    char *path;       /* owned: as given */
    rb_out_how how;
    int fd_no;        /* RB_OUT_FD: the descriptor */
    char *target;     /* owned: FILE: the path renamed over, links
                         followed; DEVICE: the path opened */
    int exists;       /* dev, ino valid */
    dev_t dev;
    ino_t ino;
    char *canon;      /* owned: FILE not existing yet: canonical dir/name */
    struct rb_out_temp *tmp; /* FILE while staged */
    int reserved;     /* rb_outplan_reserve: checked, never filled */
    int dir_fd;       /* FILE: its directory, held open from planning to
                         the rename (the plan's, not owned) */
} rb_out;

/* A directory that outputs go to, opened when the first of them is
 * planned: temporary files are made and renamed in it through the
 * descriptor, so a directory renamed or replaced by a link while the
 * command runs does not send the outputs elsewhere. */
typedef struct {
    char *path;       /* owned: as planned */
    dev_t dev;
    ino_t ino;
    int fd;
    int probed;       /* took a new file when tried */
} rb_out_dir;

typedef struct {
    char *path;       /* owned */
    dev_t dev;
    ino_t ino;
} rb_out_input;

typedef struct rb_outplan_state {
    rb_out *outs;
    size_t n, cap;
    rb_out_input *ins;
    size_t n_in, cap_in;
    struct rb_out_temp **extra;  /* rb_outplan_stage_data's files */
    size_t n_extra, cap_extra;
    pthread_mutex_t lock;
    struct rb_out_slot { char *key; long val; } *idx; /* identities */
    size_t idx_n, idx_cap;
    rb_out_dir *dirs;            /* under lock */
    size_t n_dirs, cap_dirs;
} plan;

/* ---- Temporary files and signals ---------------------------------------- */

/* Every temporary file is on one list that the signal handler walks. A
 * node is published complete (its path set) before it is linked in; the
 * handler only reads it. Nodes are unlinked from the list with the
 * signals blocked, by the thread that owns the plan, once no other thread
 * runs. */
struct rb_out_temp {
    int dir_fd;                   /* the plan's: where both names are */
    char name[sizeof RB_TEMP_NAME];
    char *target;                 /* owned: the name renamed over */
    char *shown;                  /* owned: the output's path, for messages */
    int had;                      /* target existed when planned: dev, ino */
    dev_t dev;
    ino_t ino;
    volatile sig_atomic_t live;   /* the file may exist */
    struct rb_out_temp *next;
};

/* The umask, read once by rb_outplan_init: reading it means setting it, so
 * worker threads staging reports must not do that. */
static mode_t file_mask = 022;

static _Atomic(struct rb_out_temp *) temp_head;
static pthread_mutex_t temp_lock = PTHREAD_MUTEX_INITIALIZER;
static const int clean_signals[] = { SIGTERM, SIGINT, SIGHUP, SIGPIPE };
#define N_CLEAN_SIGNALS (sizeof clean_signals / sizeof clean_signals[0])

static void on_signal(int sig)
{
    int saved = errno;
    struct rb_out_temp *t;
    for (t = atomic_load(&temp_head); t; t = t->next)
        if (t->live)
            unlinkat(t->dir_fd, t->name, 0);
    /* SA_RESETHAND put the default action back: end as the signal would */
    raise(sig);
    errno = saved;
}

void rb_outplan_signals_install(void)
{
    size_t i;
    for (i = 0; i < N_CLEAN_SIGNALS; i++) {
        struct sigaction old, sa;
        if (sigaction(clean_signals[i], NULL, &old) != 0 || old.sa_handler == SIG_IGN)
            continue;
        memset(&sa, 0, sizeof sa);
        sa.sa_handler = on_signal;
        sigemptyset(&sa.sa_mask);
        sa.sa_flags = SA_RESETHAND;
        sigaction(clean_signals[i], &sa, NULL);
    }
}

static void block_signals(sigset_t *old)
{
    sigset_t set;
    size_t i;
    sigemptyset(&set);
    for (i = 0; i < N_CLEAN_SIGNALS; i++)
        sigaddset(&set, clean_signals[i]);
    pthread_sigmask(SIG_BLOCK, &set, old);
}

/* A fresh ".rb-XXXXXX": mkstemp takes a path, which would resolve the
 * directory again; the name is made here and created with O_EXCL. */
static void temp_name(char name[sizeof RB_TEMP_NAME])
{
    static const char set[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";
    static _Atomic unsigned long long counter;
    struct timespec ts;
    unsigned long long x;
    clock_gettime(CLOCK_REALTIME, &ts);
    x = ((unsigned long long)getpid() << 32) ^ (unsigned long long)ts.tv_nsec
        ^ ((unsigned long long)ts.tv_sec << 20)
        ^ (atomic_fetch_add(&counter, 1) + 1) * 0x9E3779B97F4A7C15ULL;
    /* splitmix64's finaliser: neighbouring counts give unrelated names */
    x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
    x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
    x ^= x >> 31;
    memcpy(name, RB_TEMP_NAME, sizeof RB_TEMP_NAME);
    for (size_t i = 4; i < sizeof RB_TEMP_NAME - 1; i++, x /= 62)
        name[i] = set[x % 62];
}

/* A new temporary file in the directory dir_fd for target: registered
 * before it is created, so no moment exists where it is on disk but not
 * listed. had, dev, ino: the file planned under target, if any. */
static struct rb_out_temp *temp_create(int dir_fd, const char *target,
                                       const char *shown, int had, dev_t dev, ino_t ino,
                                       int *fd, int *err)
{
    struct rb_out_temp *t = calloc(1, sizeof *t);
    int tries;
    *fd = -1;
    *err = ENOMEM;
    if (!t)
        return NULL;
    t->target = strdup(target);
    t->shown = strdup(shown);
    if (!t->target || !t->shown) {
        free(t->target);
        free(t->shown);
        free(t);
        return NULL;
    }
    t->dir_fd = dir_fd;
    t->had = had, t->dev = dev, t->ino = ino;
    temp_name(t->name);
    pthread_mutex_lock(&temp_lock);
    t->next = atomic_load(&temp_head);
    atomic_store(&temp_head, t);
    pthread_mutex_unlock(&temp_lock);
    for (tries = 0; tries < RB_TEMP_TRIES; tries++) {
        t->live = 1;
        *fd = openat(dir_fd, t->name,
                     O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
        if (*fd >= 0)
            return t;
        *err = errno;
        t->live = 0;
        if (*err != EEXIST)
            break;
        temp_name(t->name);
    }
    return t;
}

/* Remove the file if it is still there and take the node off the list.
 * Called only where no other thread runs: the signal handler may walk the
 * list from any thread that does not block the signals. */
static void temp_drop(struct rb_out_temp *t)
{
    sigset_t old;
    struct rb_out_temp *q;
    if (!t)
        return;
    if (t->live)
        unlinkat(t->dir_fd, t->name, 0);
    t->live = 0;
    block_signals(&old);
    pthread_mutex_lock(&temp_lock);
    if (atomic_load(&temp_head) == t) {
        atomic_store(&temp_head, t->next);
    } else {
        for (q = atomic_load(&temp_head); q && q->next != t; q = q->next)
            ;
        if (q)
            q->next = t->next;
    }
    pthread_mutex_unlock(&temp_lock);
    pthread_sigmask(SIG_SETMASK, &old, NULL);
    free(t->target);
    free(t->shown);
    free(t);
}

/* ---- Diagnostics -------------------------------------------------------- */

#if defined(__GNUC__)
__attribute__((format(printf, 6, 7)))
#endif
static rb_status fail(rb_diag *d, rb_status st, const char *file, const char *opt,
                      int err, const char *fmt, ...)
{
    char what[400];
    va_list ap;
    if (!d)
        return st;
    va_start(ap, fmt);
    vsnprintf(what, sizeof what, fmt, ap);
    va_end(ap);
    if (err)
        return rb_diag_set(d, st, file, 0, 0, opt, "%.400s: %.100s", what, strerror(err));
    return rb_diag_set(d, st, file, 0, 0, opt, "%.500s", what);
}

/* ---- Resolving a name ---------------------------------------------------- */

static char *dir_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    size_t n = slash ? (size_t)(slash - path) : 1;
    char *d;
    if (slash && n == 0)
        n = 1;
    if (!(d = malloc(n + 1)))
        return NULL;
    memcpy(d, slash ? path : ".", n);
    d[n] = '\0';
    return d;
}

static const char *base_of(const char *path)
{
    const char *slash = strrchr(path, '/');
    return slash ? slash + 1 : path;
}

/* "/dev/fd/N", "/proc/self/fd/N", "/proc/<our pid>/fd/N": N, else -1. */
static int fd_path(const char *p)
{
    char own[64];
    const char *rest = NULL;
    char *end;
    long n;
    snprintf(own, sizeof own, "/proc/%ld/fd/", (long)getpid());
    if (strncmp(p, "/dev/fd/", 8) == 0)
        rest = p + 8;
    else if (strncmp(p, "/proc/self/fd/", 14) == 0)
        rest = p + 14;
    else if (strncmp(p, own, strlen(own)) == 0)
        rest = p + strlen(own);
    if (!rest || !*rest || *rest < '0' || *rest > '9')
        return -1;
    errno = 0;
    n = strtol(rest, &end, 10);
    return *end || errno || n > INT_MAX ? -1 : (int)n;
}

/* Follow symbolic links from path to the name that is finally written:
 * *fd_no >= 0 when the chain ends at a descriptor path. NULL with *err. */
static char *follow_links(const char *path, int *fd_no, int *err)
{
    char *cur = strdup(path);
    int hops;
    *fd_no = -1;
    *err = ENOMEM;
    for (hops = 0; cur && hops <= RB_LINK_HOPS; hops++) {
        struct stat sb;
        char buf[PATH_MAX], *next, *dir;
        ssize_t n;
        if ((*fd_no = fd_path(cur)) >= 0)
            return cur;
        if (strcmp(cur, "/dev/stdout") == 0) {
            *fd_no = 1;
            return cur;
        }
        if (strcmp(cur, "/dev/stderr") == 0) {
            *fd_no = 2;
            return cur;
        }
        if (lstat(cur, &sb) != 0) {
            if (errno == ENOENT)
                return cur;
            *err = errno;
            free(cur);
            return NULL;
        }
        if (!S_ISLNK(sb.st_mode))
            return cur;
        n = readlink(cur, buf, sizeof buf - 1);
        if (n < 0) {
            *err = errno;
            free(cur);
            return NULL;
        }
        buf[n] = '\0';
        if (buf[0] == '/' || !strchr(cur, '/')) {
            next = strdup(buf);
        } else {
            dir = dir_of(cur);
            next = dir ? malloc(strlen(dir) + (size_t)n + 2) : NULL;
            if (next)
                sprintf(next, "%s/%s", dir, buf);
            free(dir);
        }
        free(cur);
        cur = next;
    }
    if (cur)
        *err = ELOOP;
    free(cur);
    return NULL;
}

static void out_free(rb_out *o)
{
    if (o->tmp)
        temp_drop(o->tmp);
    free(o->opt);
    free(o->path);
    free(o->target);
    free(o->canon);
    memset(o, 0, sizeof *o);
}

/* Can a file be made in the directory? Tried, not guessed: a directory
 * that grants write access may still refuse new files (/proc, /sys), and
 * finding that out only when the outputs are written would be an internal
 * error after the solve rather than a usage error before it. The probe is
 * removed at once. 0 with *err set when not. */
static int can_create(int dir_fd, int *err)
{
    char name[sizeof RB_TEMP_NAME];
    int fd = -1, tries;
    for (tries = 0; tries < RB_TEMP_TRIES; tries++) {
        temp_name(name);
        fd = openat(dir_fd, name, O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC,
                    0600);
        if (fd >= 0 || errno != EEXIST)
            break;
    }
    *err = fd < 0 ? errno : 0;
    if (fd >= 0) {
        unlinkat(dir_fd, name, 0);
        close(fd);
    }
    return fd >= 0;
}

/* Open dir and add it to the plan's directories; NULL with *err. Under
 * the plan's lock. */
static rb_out_dir *dir_open(plan *p, const char *dir, int *err)
{
    struct stat sb;
    rb_out_dir *e;
    int fd = open(dir, O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0 || fstat(fd, &sb) != 0) {
        *err = errno;
        if (fd >= 0)
            close(fd);
        return NULL;
    }
    if (p->n_dirs == p->cap_dirs) {
        rb_out_dir *n = rb_grow(p->dirs, &p->cap_dirs, sizeof *n, 4);
        if (!n) {
            close(fd);
            *err = ENOMEM;
            return NULL;
        }
        p->dirs = n;
    }
    e = &p->dirs[p->n_dirs];
    if (!(e->path = strdup(dir))) {
        close(fd);
        *err = ENOMEM;
        return NULL;
    }
    e->dev = sb.st_dev;
    e->ino = sb.st_ino;
    e->fd = fd;
    e->probed = 0;
    p->n_dirs++;
    return e;
}

/* The plan's descriptor of directory dir: opened when the first output is
 * planned there, and found again by the name it was planned by, so that
 * what is written later goes to that directory even if the name has been
 * given to another since. A file is tried there once (can_create).
 * Returns the descriptor, or -1 with *err, and *probe set when the
 * directory opened but took no file. Thread-safe. */
static int plan_dir(plan *p, const char *dir, int *err, int *probe)
{
    rb_out_dir *e = NULL;
    size_t i;
    int fd;
    *err = 0;
    *probe = 0;
    pthread_mutex_lock(&p->lock);
    for (i = 0; i < p->n_dirs && !e; i++)
        if (strcmp(p->dirs[i].path, dir) == 0)
            e = &p->dirs[i];
    if (!e)
        e = dir_open(p, dir, err);
    if (e && !e->probed) {
        if (can_create(e->fd, err))
            e->probed = 1;
        else
            *probe = 1;
    }
    fd = e && e->probed ? e->fd : -1;
    pthread_mutex_unlock(&p->lock);
    return fd;
}

/* The directory of a regular output: exists, is a directory, writable and
 * takes new files; the name and the temporary file's fit the limits. It
 * is held open (o->dir_fd) until the plan is freed. */
static rb_status check_dir(plan *p, rb_out *o, rb_diag *d)
{
    char *dir = dir_of(o->target), *real;
    const char *name = base_of(o->target);
    struct stat sb;
    long name_max;
    int err = 0, probe = 0;
    rb_status st = RB_OK;
    if (!dir)
        return RB_ERR_NOMEM;
    errno = 0;
    name_max = pathconf(dir, _PC_NAME_MAX);
    if (name_max <= 0)
        name_max = NAME_MAX;
    if (stat(dir, &sb) != 0)
        st = fail(d, RB_ERR_IO, o->path, o->opt, errno, "cannot use directory '%.300s'",
                  dir);
    else if (!S_ISDIR(sb.st_mode))
        st = fail(d, RB_ERR_IO, o->path, o->opt, 0, "'%.300s' is not a directory", dir);
    else if (access(dir, W_OK | X_OK) != 0)
        st = fail(d, RB_ERR_IO, o->path, o->opt, errno,
                  "directory '%.300s' is not writable", dir);
    else if ((o->dir_fd = plan_dir(p, dir, &err, &probe)) < 0)
        st = err == ENOMEM ? RB_ERR_NOMEM
           : fail(d, RB_ERR_IO, o->path, o->opt, err, probe
                  ? "cannot create files in directory '%.300s'"
                  : "cannot use directory '%.300s'", dir);
    else if (strlen(name) > (size_t)name_max) {
        char lim[96];
        snprintf(lim, sizeof lim, "%zu bytes, over the limit of %ld", strlen(name),
                 name_max);
        st = fail(d, RB_ERR_IO, o->path, o->opt, 0, "the file name is too long (%s)",
                  lim);
    } else if (strlen(o->target) >= PATH_MAX
               || strlen(dir) + sizeof "/" RB_TEMP_NAME > PATH_MAX)
        st = fail(d, RB_ERR_IO, o->path, o->opt, ENAMETOOLONG, "cannot use this path");
    if (st == RB_OK && !o->exists) {
        real = realpath(dir, NULL);
        if (!real)
            st = fail(d, RB_ERR_IO, o->path, o->opt, errno,
                      "cannot use directory '%.300s'", dir);
        else if ((o->canon = malloc(strlen(real) + strlen(name) + 2)))
            sprintf(o->canon, "%s/%s", real, name);
        else
            st = RB_ERR_NOMEM;
        free(real);
    }
    free(dir);
    return st;
}

/* Resolve o->path into how it is written and what file it is. */
static rb_status resolve(plan *pl, rb_out *o, rb_diag *d)
{
    struct stat sb;
    int err;
    const char *p = o->path;
    if (!p[0])
        return fail(d, RB_ERR_IO, p, o->opt, 0, "empty output path");
    if (strcmp(p, "-") == 0)
        o->fd_no = 1;
    else {
        if (p[strlen(p) - 1] == '/')
            return fail(d, RB_ERR_IO, p, o->opt, 0, "output path names a directory");
        if (strlen(base_of(p)) > NAME_MAX) {
            char lim[64];
            snprintf(lim, sizeof lim, "%zu bytes, over the limit of %d",
                     strlen(base_of(p)), NAME_MAX);
            return fail(d, RB_ERR_IO, p, o->opt, 0, "the file name is too long (%s)",
                        lim);
        }
        if (!(o->target = follow_links(p, &o->fd_no, &err)))
            return err == ENOMEM ? RB_ERR_NOMEM
                 : fail(d, RB_ERR_IO, p, o->opt, err, "cannot use this path");
    }
    if (o->fd_no >= 0) {
        int fl = fcntl(o->fd_no, F_GETFL);
        o->how = RB_OUT_FD;
        if (fl < 0 || (fl & O_ACCMODE) == O_RDONLY || fstat(o->fd_no, &sb) != 0)
            return fail(d, RB_ERR_IO, p, o->opt, fl < 0 ? errno : EBADF,
                        "cannot write to this descriptor");
        o->exists = 1, o->dev = sb.st_dev, o->ino = sb.st_ino;
        return RB_OK;
    }
    if (stat(o->target, &sb) == 0) {
        o->exists = 1, o->dev = sb.st_dev, o->ino = sb.st_ino;
        if (S_ISDIR(sb.st_mode))
            return fail(d, RB_ERR_IO, p, o->opt, 0, "output path is a directory");
        if (S_ISCHR(sb.st_mode) || S_ISFIFO(sb.st_mode)) {
            o->how = RB_OUT_DEVICE;
            if (access(o->target, W_OK) != 0)
                return fail(d, RB_ERR_IO, p, o->opt, errno, "cannot write to it");
            return RB_OK;
        }
        if (!S_ISREG(sb.st_mode))
            return fail(d, RB_ERR_IO, p, o->opt, 0, "not a regular file, character "
                        "device or FIFO (a socket or block device)");
    } else if (errno != ENOENT) {
        return fail(d, RB_ERR_IO, p, o->opt, errno, "cannot use this path");
    }
    o->how = RB_OUT_FILE;
    return check_dir(pl, o, d);
}


/* ---- Identity index ------------------------------------------------------ */

/* Keys: "i:DEV:INO" for a file that exists, "n:CANONICAL" for one still to
 * be made, "d:N" for a descriptor. Value: output index, or -1 - input
 * index. Open addressing, at most half full: a batch plans two report
 * files per case, so a list of pairs would be quadratic. */
typedef struct rb_out_slot idx_slot;

static unsigned long hash_str(const char *s)
{
    unsigned long h = 1469598103934665603UL;
    for (; *s; s++)
        h = (h ^ (unsigned char)*s) * 1099511628211UL;
    return h;
}

static long *idx_find(plan *p, const char *key)
{
    size_t i;
    if (!p->idx_cap)
        return NULL;
    for (i = hash_str(key) & (p->idx_cap - 1); p->idx[i].key; i = (i + 1) & (p->idx_cap - 1))
        if (strcmp(p->idx[i].key, key) == 0)
            return &p->idx[i].val;
    return NULL;
}

static rb_status idx_put(plan *p, const char *key, long val)
{
    size_t i;
    char *k;
    if (2 * (p->idx_n + 1) > p->idx_cap) {
        size_t cap = p->idx_cap ? 2 * p->idx_cap : 64, j;
        idx_slot *n = calloc(cap, sizeof *n);
        if (!n)
            return RB_ERR_NOMEM;
        for (j = 0; j < p->idx_cap; j++)
            if (p->idx[j].key) {
                for (i = hash_str(p->idx[j].key) & (cap - 1); n[i].key; i = (i + 1) & (cap - 1))
                    ;
                n[i] = p->idx[j];
            }
        free(p->idx);
        p->idx = n;
        p->idx_cap = cap;
    }
    if (!(k = strdup(key)))
        return RB_ERR_NOMEM;
    for (i = hash_str(key) & (p->idx_cap - 1); p->idx[i].key; i = (i + 1) & (p->idx_cap - 1))
        ;
    p->idx[i].key = k;
    p->idx[i].val = val;
    p->idx_n++;
    return RB_OK;
}

/* The keys of an output (a descriptor has two); n set. */
static void out_keys(const rb_out *o, char keys[2][PATH_MAX + 32], int *n)
{
    *n = 0;
    if (o->how == RB_OUT_FD)
        snprintf(keys[(*n)++], PATH_MAX + 32, "d:%d", o->fd_no);
    if (o->exists)
        snprintf(keys[(*n)++], PATH_MAX + 32, "i:%ju:%ju", (uintmax_t)o->dev,
                 (uintmax_t)o->ino);
    else if (o->canon)
        snprintf(keys[(*n)++], PATH_MAX + 32, "n:%.*s", PATH_MAX, o->canon);
}

/* ---- The plan ---------------------------------------------------------- */

void rb_outplan_init(rb_outplan *op)
{
    plan *p = op->st = malloc(sizeof *op->st);
    mode_t mask = umask(0);
    umask(mask);
    file_mask = mask;
    if (!p)
        return;
    memset(p, 0, sizeof *p);
    pthread_mutex_init(&p->lock, NULL);
}

void rb_outplan_free(rb_outplan *op)
{
    plan *p = op->st;
    size_t i;
    if (!p)
        return;
    for (i = 0; i < p->n; i++)
        out_free(&p->outs[i]);
    for (i = 0; i < p->n_in; i++)
        free(p->ins[i].path);
    for (i = 0; i < p->n_extra; i++)
        temp_drop(p->extra[i]);
    /* after every temporary file is gone: the signal handler uses these */
    for (i = 0; i < p->n_dirs; i++) {
        close(p->dirs[i].fd);
        free(p->dirs[i].path);
    }
    free(p->dirs);
    for (i = 0; i < p->idx_cap; i++)
        free(p->idx[i].key);
    free(p->idx);
    free(p->outs);
    free(p->ins);
    free(p->extra);
    pthread_mutex_destroy(&p->lock);
    free(p);
    op->st = NULL;
}

static rb_status clash_input(const rb_out *o, const rb_out_input *in, rb_diag *d)
{
    return fail(d, RB_ERR_INVALID, o->path, o->opt, 0,
                "is an input (%.300s); refusing to overwrite it", in->path);
}

static rb_status add_out(plan *p, const char *opt, const char *path, int reserved,
                         rb_diag *d)
{
    char keys[2][PATH_MAX + 32];
    rb_out o;
    rb_status st;
    int nk = 0, k;
    memset(&o, 0, sizeof o);
    o.fd_no = -1;
    o.dir_fd = -1;
    o.reserved = reserved;
    o.opt = strdup(opt);
    o.path = strdup(path);
    if (!o.opt || !o.path) {
        out_free(&o);
        return RB_ERR_NOMEM;
    }
    st = resolve(p, &o, d);
    if (st == RB_OK)
        out_keys(&o, keys, &nk);
    for (k = 0; st == RB_OK && k < nk; k++) {
        long *v = idx_find(p, keys[k]);
        if (v && *v >= 0) {
            char other[300];
            snprintf(other, sizeof other, "%.40s '%.250s'", p->outs[*v].opt,
                     p->outs[*v].path);
            st = fail(d, RB_ERR_INVALID, o.path, o.opt, 0,
                      "is the same file as %.300s; each output needs its own file",
                      other);
        } else if (v) {
            st = clash_input(&o, &p->ins[-1 - *v], d);
        }
    }
    if (st == RB_OK && p->n == p->cap) {
        rb_out *n = rb_grow(p->outs, &p->cap, sizeof *n, 8);
        if (!n)
            st = RB_ERR_NOMEM;
        else
            p->outs = n;
    }
    for (k = 0; st == RB_OK && k < nk; k++)
        st = idx_put(p, keys[k], (long)p->n);
    if (st == RB_OK && reserved && o.how == RB_OUT_FILE) {
        /* rb_outplan_stage_data finds it by the name it was reserved by */
        char *key = malloc(strlen(path) + 3);
        if (key) {
            sprintf(key, "p:%s", path);
            st = idx_find(p, key) ? RB_OK : idx_put(p, key, (long)p->n);
        } else {
            st = RB_ERR_NOMEM;
        }
        free(key);
    }
    if (st != RB_OK) {
        out_free(&o);
        return st;
    }
    p->outs[p->n++] = o;
    return RB_OK;
}

rb_status rb_outplan_add(rb_outplan *p, const char *opt, const char *path, rb_diag *d)
{
    return !p->st ? RB_ERR_NOMEM : add_out(p->st, opt, path, 0, d);
}

rb_status rb_outplan_reserve(rb_outplan *p, const char *opt, const char *path,
                             rb_diag *d)
{
    return !p->st ? RB_ERR_NOMEM : add_out(p->st, opt, path, 1, d);
}

rb_status rb_outplan_add_input(rb_outplan *op, const char *path, rb_diag *d)
{
    plan *p = op->st;
    if (!p)
        return RB_ERR_NOMEM;
    struct stat sb;
    rb_out_input in;
    char key[64];
    long *v;
    if (stat(path, &sb) != 0)
        return RB_OK;
    snprintf(key, sizeof key, "i:%ju:%ju", (uintmax_t)sb.st_dev, (uintmax_t)sb.st_ino);
    if ((v = idx_find(p, key)) != NULL) {
        if (*v < 0)
            return RB_OK;   /* read twice: one input */
        in.path = (char *)path;
        return clash_input(&p->outs[*v], &in, d);
    }
    if (p->n_in == p->cap_in) {
        rb_out_input *n = rb_grow(p->ins, &p->cap_in, sizeof *n, 16);
        if (!n)
            return RB_ERR_NOMEM;
        p->ins = n;
    }
    in.dev = sb.st_dev;
    in.ino = sb.st_ino;
    if (!(in.path = strdup(path)))
        return RB_ERR_NOMEM;
    if (idx_put(p, key, -1 - (long)p->n_in) != RB_OK) {
        free(in.path);
        return RB_ERR_NOMEM;
    }
    p->ins[p->n_in++] = in;
    return RB_OK;
}

int rb_outplan_uses_stdout(const rb_outplan *op)
{
    const plan *p = op->st;
    size_t i;
    if (!p)
        return 0;
    for (i = 0; i < p->n; i++)
        if (p->outs[i].how == RB_OUT_FD && p->outs[i].fd_no == 1)
            return 1;
    return 0;
}

/* ---- Writing ------------------------------------------------------------ */

/* Give the temporary file the mode and owner of the file it replaces, or
 * the usual mode of a new file (it is made 0600). The owner can only be
 * kept where the process may set it; otherwise it becomes ours. Only the
 * file planned is copied from: another in its place is not replaced. */
static void copy_meta(const struct rb_out_temp *t, int fd)
{
    struct stat sb;
    if (t->had && fstatat(t->dir_fd, t->target, &sb, AT_SYMLINK_NOFOLLOW) == 0
        && S_ISREG(sb.st_mode) && sb.st_dev == t->dev && sb.st_ino == t->ino) {
        if (fchown(fd, sb.st_uid, sb.st_gid) != 0)
            (void)fchown(fd, (uid_t)-1, sb.st_gid);
        (void)fchmod(fd, sb.st_mode & 07777);
    } else {
        (void)fchmod(fd, 0666 & ~file_mask);
    }
}

/* A temporary file for o (a regular file, planned): in o's directory. */
static rb_status open_temp(const rb_out *o, const char *opt, struct rb_out_temp **tp,
                           FILE **fp, rb_diag *d)
{
    int fd = -1, err = 0;
    *fp = NULL;
    *tp = temp_create(o->dir_fd, base_of(o->target), o->path, o->exists, o->dev, o->ino,
                      &fd, &err);
    if (!*tp)
        return RB_ERR_NOMEM;
    if (fd < 0)
        return fail(d, RB_ERR_IO, o->path, opt, err, "cannot create a temporary file");
    copy_meta(*tp, fd);
    if (!(*fp = fdopen(fd, "wb"))) {
        err = errno;
        close(fd);
        return fail(d, RB_ERR_IO, o->path, opt, err, "cannot write");
    }
    return RB_OK;
}

static rb_status open_stream(const rb_out *o, FILE **fp, rb_diag *d)
{
    int fd, err;
    *fp = NULL;
    if (o->how == RB_OUT_FD) {
        fflush(stdout);
        fd = dup(o->fd_no);
    } else {
        /* a FIFO's reader may come a little later; none within the
         * bound is an error, not a wait without end */
        int waited_ms = 0;
        while ((fd = open(o->target, O_WRONLY | O_NONBLOCK | O_NOCTTY)) < 0
               && errno == ENXIO && waited_ms < RB_FIFO_WAIT_MS) {
            struct timespec ts = { 0, 10 * 1000000L };
            nanosleep(&ts, NULL);
            waited_ms += 10;
        }
        if (fd < 0 && errno == ENXIO)
            return fail(d, RB_ERR_IO, o->path, o->opt, 0,
                        "the FIFO has no reader (waited %d s): nothing to write to",
                        RB_FIFO_WAIT_MS / 1000);
        if (fd >= 0) {
            int fl = fcntl(fd, F_GETFL);
            if (fl >= 0)
                (void)fcntl(fd, F_SETFL, fl & ~O_NONBLOCK);
        }
    }
    if (fd < 0 || !(*fp = fdopen(fd, "wb"))) {
        err = errno;
        if (fd >= 0)
            close(fd);
        return fail(d, RB_ERR_IO, o->path, o->opt, err, "cannot open for writing");
    }
    return RB_OK;
}

/* Flush, sync (regular files), close; the system's reason on error. */
static rb_status close_out(FILE *fp, int sync, const char *path, const char *opt,
                           int write_err, rb_diag *d)
{
    const char *what = NULL;
    int err = 0;
    if (write_err)
        what = "cannot write", err = write_err;
    if (!what && (fflush(fp) != 0 || ferror(fp)))
        what = "cannot write", err = errno ? errno : EIO;
    if (!what && sync && fsync(fileno(fp)) != 0)
        what = "cannot sync to disk", err = errno;
    if (fclose(fp) != 0 && !what)
        what = "cannot close", err = errno;
    if (what)
        return fail(d, RB_ERR_IO, path, opt, err, "%s", what);
    return RB_OK;
}

static rb_status fill_one(plan *p, size_t i, FILE *fp, rb_outplan_fill_fn fill,
                          void *ctx, rb_diag *d)
{
    rb_out *o = &p->outs[i];
    rb_status st;
    int err;
    errno = 0;
    st = fill(ctx, i, fp, d);
    err = ferror(fp) ? (errno ? errno : EIO) : 0;
    if (st != RB_OK && !err) {
        fclose(fp);
        if (!d->file[0])
            rb_diag_set_file(d, "%s", o->path);
        return st;
    }
    return close_out(fp, o->how == RB_OUT_FILE, o->path, o->opt, err, d);
}

/* Is the name still the file planned there, or none? Whatever else has
 * taken it since (a file made meanwhile, a link swapped in) is left
 * alone: renaming over it would replace a file nobody asked to write.
 * *absent: no file has the name. */
static rb_status check_target(const struct rb_out_temp *t, const char *opt, int *absent,
                              rb_diag *d)
{
    struct stat sb;
    *absent = 0;
    if (fstatat(t->dir_fd, t->target, &sb, AT_SYMLINK_NOFOLLOW) != 0) {
        if (errno == ENOENT) {
            *absent = 1;
            return RB_OK;
        }
        return fail(d, RB_ERR_IO, t->shown, opt, errno, "cannot look at the file to replace");
    }
    /* a regular file was planned: a link made since may even have its
     * inode number, freed and given again */
    if (t->had && S_ISREG(sb.st_mode) && sb.st_dev == t->dev && sb.st_ino == t->ino)
        return RB_OK;
    return fail(d, RB_ERR_IO, t->shown, opt, 0, t->had
                ? "another file has taken its place since the outputs were planned; "
                  "it is left as it is"
                : "a file of this name has appeared since the outputs were planned; "
                  "it is left as it is");
}

static rb_status rename_temp(struct rb_out_temp *t, const char *opt, rb_diag *d)
{
    int absent, r;
    rb_status st = check_target(t, opt, &absent, d);
    if (st != RB_OK)
        return st;
#ifdef RENAME_NOREPLACE
    /* where there was nothing, nothing made since is replaced either */
    if (absent) {
        r = renameat2(t->dir_fd, t->name, t->dir_fd, t->target, RENAME_NOREPLACE);
        if (r != 0 && errno == EEXIST)
            return check_target(t, opt, &absent, d);
        if (r == 0 || (errno != EINVAL && errno != ENOSYS))
            goto done;
    }
#endif
    r = renameat(t->dir_fd, t->name, t->dir_fd, t->target);
#ifdef RENAME_NOREPLACE
done:
#endif
    if (r != 0)
        return fail(d, RB_ERR_IO, t->shown, opt, errno,
                    "cannot rename the temporary file into place");
    t->live = 0;
    return RB_OK;
}

rb_status rb_outplan_write(rb_outplan *op, rb_outplan_fill_fn fill, void *ctx,
                           rb_diag *d)
{
    plan *p = op->st;
    if (!p)
        return RB_ERR_NOMEM;
    rb_status st = RB_OK;
    size_t i;
    int pass, absent;
    /* regular files first, so that a failure there leaves the streams
     * without data; then the streams; then the renames */
    for (pass = 0; pass < 2 && st == RB_OK; pass++)
        for (i = 0; i < p->n && st == RB_OK; i++) {
            rb_out *o = &p->outs[i];
            FILE *fp;
            if (o->reserved || (o->how == RB_OUT_FILE) != (pass == 0))
                continue;
            if (o->how == RB_OUT_FILE)
                st = open_temp(o, o->opt, &o->tmp, &fp, d);
            else
                st = open_stream(o, &fp, d);
            if (st == RB_OK)
                st = fill_one(p, i, fp, fill, ctx, d);
        }
    /* every name checked before any is renamed: all or none */
    for (i = 0; i < p->n && st == RB_OK; i++)
        if (p->outs[i].tmp)
            st = check_target(p->outs[i].tmp, p->outs[i].opt, &absent, d);
    for (i = 0; i < p->n_extra && st == RB_OK; i++)
        if (p->extra[i]->live)
            st = check_target(p->extra[i], NULL, &absent, d);
    for (i = 0; i < p->n && st == RB_OK; i++)
        if (p->outs[i].tmp)
            st = rename_temp(p->outs[i].tmp, p->outs[i].opt, d);
    for (i = 0; i < p->n_extra && st == RB_OK; i++)
        if (p->extra[i]->live)
            st = rename_temp(p->extra[i], NULL, d);
    for (i = 0; i < p->n; i++)
        if (p->outs[i].tmp) {
            temp_drop(p->outs[i].tmp);
            p->outs[i].tmp = NULL;
        }
    for (i = 0; i < p->n_extra; i++)
        temp_drop(p->extra[i]);
    p->n_extra = 0;
    return st;
}

/* A reserved output by the path it was reserved by, else NULL. The
 * outputs are all added before any file is staged, so reading the index
 * from the threads that stage is safe. */
static const rb_out *reserved_out(const plan *p, const char *path)
{
    char *key = malloc(strlen(path) + 3);
    long *v;
    if (!key)
        return NULL;
    sprintf(key, "p:%s", path);
    v = idx_find((plan *)p, key);
    free(key);
    return v && *v >= 0 && (size_t)*v < p->n ? &p->outs[*v] : NULL;
}

rb_status rb_outplan_stage_data(rb_outplan *op, const char *path, const char *data,
                                size_t len, rb_diag *d)
{
    plan *p = op->st;
    if (!p)
        return RB_ERR_NOMEM;
    rb_out o;
    struct rb_out_temp *t = NULL;
    FILE *fp = NULL;
    rb_status st;
    int err = 0;
    const rb_out *planned = reserved_out(p, path);
    memset(&o, 0, sizeof o);
    o.fd_no = -1;
    o.dir_fd = -1;
    if (!(o.path = strdup(path)))
        return RB_ERR_NOMEM;
    /* a reserved file goes where it was planned, whatever its directory's
     * name leads to now */
    st = planned ? RB_OK : resolve(p, &o, d);
    if (st == RB_OK && !planned && o.how != RB_OUT_FILE)
        st = fail(d, RB_ERR_IO, path, NULL, 0, "not a regular file");
    if (st == RB_OK)
        st = open_temp(planned ? planned : &o, NULL, &t, &fp, d);
    if (st == RB_OK) {
        if (len && fwrite(data, 1, len, fp) != len)
            err = errno ? errno : EIO;
        st = close_out(fp, 1, path, NULL, err, d);
    }
    /* a failed one stays listed, removed, until the plan is freed: other
     * threads may be running and the signal handler walking the list */
    if (t && st != RB_OK) {
        if (t->live)
            unlinkat(t->dir_fd, t->name, 0);
        t->live = 0;
    }
    if (t) {
        pthread_mutex_lock(&p->lock);
        if (p->n_extra == p->cap_extra) {
            struct rb_out_temp **n = rb_grow(p->extra, &p->cap_extra, sizeof *n, 16);
            if (n)
                p->extra = n;
        }
        if (p->n_extra < p->cap_extra)
            p->extra[p->n_extra++] = t, t = NULL;
        else if (st == RB_OK)
            st = RB_ERR_NOMEM;
        pthread_mutex_unlock(&p->lock);
    }
    if (t && t->live) {
        unlinkat(t->dir_fd, t->name, 0);
        t->live = 0;   /* the node stays on the list: see above */
    }
    out_free(&o);
    return st;
}

size_t rb_outplan_count(const rb_outplan *p)
{
    return p->st ? p->st->n : 0;
}

const char *rb_outplan_opt(const rb_outplan *p, size_t i)
{
    return p->st->outs[i].opt;
}

int rb_outplan_is_file(const rb_outplan *p, size_t i)
{
    return p->st->outs[i].how == RB_OUT_FILE;
}

size_t rb_outplan_inputs(const rb_outplan *p)
{
    return p->st ? p->st->n_in : 0;
}
