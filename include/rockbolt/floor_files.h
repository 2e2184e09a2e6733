/* The files of `rockbolt motion` (rb_run_floors): each component of each
 * motion as a PEER AT2 record and as a two-column CSV, both in g, and the
 * summary of every component as text and JSON (docs/motion.md, "Motions
 * for a table"). */
#ifndef ROCKBOLT_FLOOR_FILES_H
#define ROCKBOLT_FLOOR_FILES_H

#include <stdio.h>
#include "rockbolt/case.h"
#include "rockbolt/floors.h"

/* The file kinds of one component, in the order of a names array. */
typedef enum {
    RB_FLOOR_FILE_AT2 = 0,
    RB_FLOOR_FILE_CSV,
    RB_FLOOR_FILE_KINDS
} rb_floor_file_kind;

/* Index of a component's file in a names array of n_motions x
 * RB_FLOOR_AXES x RB_FLOOR_FILE_KINDS entries (NULL where not written). */
#define RB_FLOOR_FILE_INDEX(m, axis, kind) \
    (((m) * RB_FLOOR_AXES + (size_t)(axis)) * RB_FLOOR_FILE_KINDS + (size_t)(kind))

/* Component axis of motion m as a PEER AT2 record (the legacy header: line
 * 3 "UNITS OF G", line 4 "NPTS=, DT= SEC"; 5 values a line, each in 16
 * columns with 9 significant digits) or as CSV ('#' comment lines, then
 * time in s and acceleration in g, comma-separated: a two-column record).
 * RB_ERR_IO when fp fails. */
rb_status rb_floors_write_at2(FILE *fp, const rb_case *c, const rb_case_floors *f, size_t m,
                              rb_floor_axis axis);
rb_status rb_floors_write_csv(FILE *fp, const rb_case *c, const rb_case_floors *f, size_t m,
                              rb_floor_axis axis);

/* The summary for the terminal and as JSON (SI), naming the files written
 * (files: NULL, or as above). New strings, NULL when memory runs out. */
char *rb_floors_render_text(const rb_case *c, const rb_case_floors *f,
                            const char *const *files);
char *rb_floors_render_json(const rb_case *c, const rb_case_floors *f,
                            const char *const *files);

#endif
