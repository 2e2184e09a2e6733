/* --sandbox DIR: every input a run reads (the case, its extends bases, its
 * records, equipment lists and the bases their rows name) must lie inside
 * DIR once every symbolic link and '..' is resolved (realpath), or the run
 * refuses it with an error that names the key and the file (exit code 2).
 * The records shipped with rockbolt (the data directory's records, which
 * lists name as `elcentro`, `taft` and cases as `shipped:elcentro`:
 * rockbolt/datadir.h) are always allowed.
 *
 * The sandbox is a value, not process state: the command opens it once,
 * before loading anything, and hands it to each loader (the case loader,
 * rb_record_opts.sandbox, the equipment-list reader), which checks every
 * file it opens; threads only read it. A NULL sandbox, or one opened with
 * no directory, allows every path. docs/robustness.md ("Inputs
 * outside a tree") says what it defends against and what it does not. */
#ifndef ROCKBOLT_SANDBOX_H
#define ROCKBOLT_SANDBOX_H

#include <stddef.h>
#include "rockbolt/status.h"

/* Longest real path the sandbox holds (PATH_MAX on Linux). */
#define RB_SANDBOX_PATH_MAX 4096

typedef struct rb_sandbox {
    char root[RB_SANDBOX_PATH_MAX];    /* real path of DIR */
    char shipped[RB_SANDBOX_PATH_MAX]; /* real path of the shipped records,
                                          or "" when they do not resolve */
    int on;                            /* 0: every path allowed */
} rb_sandbox;

/* Open sb confining inputs to dir, which must be an existing directory:
 * RB_ERR_IO (with diag, sb left off) if it is not. dir NULL: sb allows
 * every path. */
rb_status rb_sandbox_open(rb_sandbox *sb, const char *dir, rb_diag *diag);

/* The sandbox's real path, or NULL when sb is NULL or allows every path. */
const char *rb_sandbox_dir(const rb_sandbox *sb);

/* 1 if path may be read: sb is NULL or off, or path's real path lies
 * inside the sandbox (or among the shipped records). A path that does not resolve
 * because it does not exist is allowed here: opening it then fails on its
 * own. Otherwise 0, with the real path (or why it could not be resolved)
 * in why. */
int rb_sandbox_allows(const rb_sandbox *sb, const char *path, char *why, size_t why_size);

#endif
