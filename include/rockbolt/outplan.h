/* Output plans: every file a command writes, known and checked before any
 * work, then written all together or not at all (library rb_report).
 *
 * A command adds each output it will write (with the option that asked for
 * it) and each file it reads. Every output is resolved to the file it
 * really is: "-" and /dev/stdout, /dev/fd/N are open descriptors; character
 * devices and FIFOs are written straight through; anything else is a
 * regular file, reached through symbolic links, that is written to a
 * temporary file ".rb-XXXXXX" in its directory and renamed over it at the
 * end, keeping the mode and (where allowed) the owner of the file it
 * replaces; the directory is the one opened at planning, held open until
 * then. Two outputs that are one file, or an output that is an input,
 * are refused when added: compared by device and inode after following
 * links, or for a file that does not exist yet by its canonical directory
 * and name. Names longer than the file system allows are refused too.
 *
 * rb_outplan_write then fills every output through a callback: regular
 * files first (to their temporary files, flushed and synced), then the
 * streams, then every temporary file is renamed into place. Files staged
 * from other threads while the command runs (batch reports) are renamed
 * in the same last step. A temporary file is never left behind: errors
 * remove them, and after rb_outplan_signals_install so do SIGTERM, SIGINT,
 * SIGHUP and SIGPIPE before the signal ends the process as usual. */
#ifndef ROCKBOLT_OUTPLAN_H
#define ROCKBOLT_OUTPLAN_H

#include <pthread.h>
#include <stdio.h>
#include <sys/types.h>
#include "rockbolt/status.h"

typedef enum {
    RB_OUT_FILE = 0,  /* regular file, new or replaced: staged and renamed */
    RB_OUT_FD,        /* an open descriptor: "-", /dev/stdout, /dev/fd/N */
    RB_OUT_DEVICE     /* a character device or a FIFO, opened by name */
} rb_out_how;

struct rb_out_temp;   /* a registered temporary file (outplan.c) */

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

typedef struct rb_outplan {
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
} rb_outplan;

void rb_outplan_init(rb_outplan *p);

/* Remove every temporary file not yet renamed and free the plan. */
void rb_outplan_free(rb_outplan *p);

/* Add an output. Checks: the name is not empty, does not end in '/', is
 * no directory, its directory exists and is writable, every name in it
 * and the temporary file's fit NAME_MAX and PATH_MAX, a device or FIFO is
 * writable, a descriptor is open for writing; and it is neither an output
 * already added nor an input. RB_ERR_IO (cannot be written) or
 * RB_ERR_INVALID (a clash) with diag->file = path, diag->key = opt and
 * the reason, naming the other file; RB_ERR_NOMEM. */
rb_status rb_outplan_add(rb_outplan *p, const char *opt, const char *path,
                         rb_diag *diag);

/* The same checks for a file written by other means (rb_outplan_stage_data,
 * batch reports): it takes part in the clash checks, and rb_outplan_write
 * does not fill it. */
rb_status rb_outplan_reserve(rb_outplan *p, const char *opt, const char *path,
                             rb_diag *diag);

/* Add a file the command reads. One that does not exist is ignored.
 * RB_ERR_INVALID when an output already added is that file (diag names
 * the output's option and path, and the input). */
rb_status rb_outplan_add_input(rb_outplan *p, const char *path, rb_diag *diag);

/* Is an output standard output (then nothing else may be printed there)? */
int rb_outplan_uses_stdout(const rb_outplan *p);

/* Write output i to fp; RB_OK or an error with diag set. */
typedef rb_status (*rb_outplan_fill_fn)(void *ctx, size_t i, FILE *fp, rb_diag *diag);

/* Fill every output, then rename every staged file into place (see the
 * top). On error nothing regular is replaced (streams may have had their
 * data), no temporary file is left, and diag names the file and says why,
 * with the system's reason ("No space left on device"). Each file is
 * renamed in the directory it was planned in, and only over the file
 * planned there or where there is none: a file made or swapped in under
 * that name since planning is RB_ERR_IO, before anything is renamed. */
rb_status rb_outplan_write(rb_outplan *p, rb_outplan_fill_fn fill, void *ctx,
                           rb_diag *diag);

/* Stage len bytes for path, a regular file (links followed) not in the
 * plan's outputs list, to be renamed into place by rb_outplan_write: in
 * the directory and over the file reserved for path, when it was
 * (rb_outplan_reserve), else as resolved now. Thread-safe. RB_ERR_IO with
 * the reason. */
rb_status rb_outplan_stage_data(rb_outplan *p, const char *path, const char *data,
                                size_t len, rb_diag *diag);

/* Install the handlers that remove temporary files on SIGTERM, SIGINT,
 * SIGHUP and SIGPIPE (signals ignored at start stay ignored). */
void rb_outplan_signals_install(void);

#endif
