/* --sandbox DIR: every input a run reads (the case, its extends bases, its
 * records, equipment lists and the bases their rows name) must lie inside
 * DIR once every symbolic link and '..' is resolved (realpath), or the run
 * refuses it with an error that names the key and the file (exit code 2).
 * The records shipped with rockbolt (the data directory's records, which
 * lists name as `elcentro`, `taft` and cases as `shipped:elcentro`:
 * rockbolt/datadir.h) are always allowed.
 *
 * The sandbox is process-wide: set it once, before loading anything (and
 * before any thread starts); the loaders then check every file they open.
 * Without a sandbox every path is allowed. docs/robustness.md ("Inputs
 * outside a tree") says what it defends against and what it does not. */
#ifndef ROCKBOLT_SANDBOX_H
#define ROCKBOLT_SANDBOX_H

#include <stddef.h>
#include "rockbolt/status.h"

/* Confine inputs to dir, which must be an existing directory: RB_ERR_IO
 * (with diag) if it is not. dir NULL lifts the sandbox. */
rb_status rb_sandbox_set(const char *dir, rb_diag *diag);

/* The sandbox's real path, or NULL when there is none. */
const char *rb_sandbox_dir(void);

/* 1 if path may be read: there is no sandbox, or its real path lies inside
 * the sandbox (or among the shipped records). A path that does not resolve
 * because it does not exist is allowed here: opening it then fails on its
 * own. Otherwise 0, with the real path (or why it could not be resolved)
 * in why. */
int rb_sandbox_allows(const char *path, char *why, size_t why_size);

#endif
