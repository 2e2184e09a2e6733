/* The one name table of each enum that a case file, a report or a list
 * spells out: the case loader parses with it and every report prints with
 * it, so whatever a report writes can be pasted back into a case. Each
 * table lists its names in the order diagnostics offer them and ends with
 * {NULL, 0}. Each table is declared in its enum's header and defined in
 * the folder that owns the enum. No I/O. */
#ifndef ROCKBOLT_NAMES_H
#define ROCKBOLT_NAMES_H

#include <stddef.h> /* NULL, which ends each table */

typedef struct {
    const char *name;
    int value;
} rb_enum_name;

/* The name of value in table t; "unknown" when it has none. */
const char *rb_enum_str(const rb_enum_name *t, int value);
/* The value named s: 1 and *value set, or 0. */
int rb_enum_parse(const rb_enum_name *t, const char *s, int *value);
/* The name of value in table t with each '-' written as sep, into buf (of
 * size n, cut to fit): "no_yield" as a key or template name, "no yield" in
 * words. Returns buf. */
char *rb_enum_str_sep(const rb_enum_name *t, int value, char sep, char *buf, size_t n);

#endif
