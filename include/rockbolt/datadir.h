/* Where rockbolt finds the data it ships: the ground-motion records that
 * lists name as `elcentro` and `taft` and cases as `shipped:elcentro`, and
 * the report and starter templates.
 *
 * The data directory holds records/ and templates/. It is, first found:
 *   1. $RB_DATA_DIR, when set and not empty (used whether or not it exists,
 *      so a wrong value shows as a missing file, not as other data);
 *   2. ../share/rockbolt next to the running executable (/proc/self/exe),
 *      so an installed tree works wherever it is moved;
 *   3. the source tree the binary was built from (cases/records and
 *      templates), for a build that is not installed;
 *   4. the data directory of the install prefix the build was configured
 *      with.
 * The answer is computed once per process. */
#ifndef ROCKBOLT_DATADIR_H
#define ROCKBOLT_DATADIR_H

#include <stddef.h>

/* The directory of the shipped records, without a trailing slash. */
const char *rb_data_records_dir(void);

/* The directory of the shipped templates, without a trailing slash. */
const char *rb_data_templates_dir(void);

/* Where the data directory was found: "RB_DATA_DIR", "installed",
 * "source tree" or "install prefix". */
const char *rb_data_origin(void);

/* A record shipped with rockbolt, by the short name lists and cases use. */
typedef struct {
    const char *name;    /* "elcentro" */
    const char *file;    /* file name in the records directory */
    const char *format;  /* the case's `format:` value for it */
    const char *dt;      /* `dt:` for formats without one, or NULL */
    const char *units;   /* `units:` for formats without them, or NULL */
} rb_shipped_record;

/* The shipped record called name, or NULL. */
const rb_shipped_record *rb_shipped_find(const char *name);

/* The names of the shipped records, ", "-separated ("elcentro, taft"). */
const char *rb_shipped_names(void);

/* The full path of the shipped record called name into buf: buf, or NULL
 * when there is no such record or the path does not fit. */
const char *rb_shipped_path(const char *name, char *buf, size_t size);

/* The prefix a case's `file:` uses to name a shipped record. */
#define RB_SHIPPED_PREFIX "shipped:"

#endif
