/* Output plans: every file a command writes, known and checked before any
 * work, then written all together or not at all (library rb_output).
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

#include <stdio.h>
#include "rockbolt/status.h"

/* The plan: its outputs, inputs, the directories it holds open and its
 * temporary files, behind one pointer (outplan.c), so that callers keep it
 * where they like and see none of it. */
typedef struct rb_outplan {
    struct rb_outplan_state *st;   /* owned; NULL when init ran out of memory */
} rb_outplan;

/* An empty plan; every later call fails with RB_ERR_NOMEM when it could not
 * be made. Free it with rb_outplan_free. */
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

/* The outputs added (rb_outplan_add and rb_outplan_reserve, in that order),
 * output i's option, and whether it is a regular file (staged in a
 * temporary file and renamed into place) rather than a stream or device. */
size_t rb_outplan_count(const rb_outplan *p);
const char *rb_outplan_opt(const rb_outplan *p, size_t i);
int rb_outplan_is_file(const rb_outplan *p, size_t i);
/* The inputs added (rb_outplan_add_input), each file once. */
size_t rb_outplan_inputs(const rb_outplan *p);

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
