/* A case made of a base case file and a few overriding values (library rb_case).
 *
 * Equipment lists give one row per cabinet: a base case plus the values
 * that differ (mass, height, bolt size, gap, motion, ...). Each value is
 * written as in a case file ("454 kg", "12.7 mm", "0.4 A*") under its
 * dotted case key ("equipment.mass"), and the case is loaded exactly as a
 * case file that `extends:` the base and gives those keys would be: the
 * same merge rules, checks and units. Diagnostics about an override point
 * at the place the value came from (origin:line:col, e.g. the CSV file and
 * row), with the dotted key; diagnostics about the base point into it. */
#ifndef ROCKBOLT_CASE_OVERRIDES_H
#define ROCKBOLT_CASE_OVERRIDES_H

#include <stddef.h>
#include "rockbolt/case.h"

typedef struct {
    const char *key;   /* dotted case key: "equipment.mass", "gap_ratio",
                          "motion.file"; at most 4 levels */
    const char *value; /* value text as in a case file; a path value (keys
                          ending in "file") is relative to the directory of
                          origin, like a record named in a case file */
    int line, col;     /* where the value was given (1-based), for diags */
} rb_case_override;

/* Load base_path with the overrides applied. origin names the file the
 * overrides came from (diagnostics, relative paths); name (may be NULL)
 * becomes the case's name; out->path is set to origin. Returns as
 * rb_case_load, plus RB_ERR_INVALID with a diag at the override when a key
 * is malformed. On error *out is left empty. Records come from cache (may
 * be NULL) and files are held to sandbox (may be NULL), as with
 * rb_case_load_cached. */
struct rb_record_cache;
struct rb_sandbox;
rb_status rb_case_load_overrides(const char *base_path, const char *origin,
                                 const char *name, const rb_case_override *ov,
                                 size_t n, struct rb_record_cache *cache,
                                 const struct rb_sandbox *sandbox,
                                 rb_case *out, rb_diag_list *diags);

/* rb_case_load_overrides with the place the base was named (1-based
 * base_line and base_col in origin): what cannot be read of the base
 * itself (missing, outside the sandbox) is reported there, where
 * rb_case_load_overrides uses the first override's line (none: line 0)
 * and column 1. */
rb_status rb_case_load_overrides_at(const char *base_path, int base_line, int base_col,
                                    const char *origin, const char *name,
                                    const rb_case_override *ov, size_t n,
                                    struct rb_record_cache *cache,
                                    const struct rb_sandbox *sandbox, rb_case *out,
                                    rb_diag_list *diags);

/* 1 if the dotted key names a value a case file can give (one scalar), as
 * the case schema knows its keys; else 0 with msg saying why: an unknown
 * key (with the nearest known one), a section or a list, or a key a row
 * gives otherwise (extends, name). */
int rb_case_key_settable(const char *key, char *msg, size_t msg_size);

#endif
