/* Every JSON output is printed here: cJSON's text with the format
 * characters escaped (rb_json_escape_format), so that no report, summary or
 * error carries a raw right-to-left override or zero-width space. */
#ifndef ROCKBOLT_JSONPRINT_H
#define ROCKBOLT_JSONPRINT_H

#include <stddef.h>
#include <cjson/cJSON.h>

/* The item as JSON text, with cJSON's layout (formatted: tabs and
 * newlines, else none), in a new string the caller frees with free();
 * NULL on NOMEM. */
char *rb_json_print(const cJSON *item, int formatted);

/* Where the lines of a JSON file laid out for people break (the fragility,
 * spectra and floor-motion files, whose layout is not cJSON's and whose
 * bytes are recorded). Everything not named here is on one line: members
 * and items apart by ", ", a key and its value by ": ". */
typedef struct {
    int depth;          /* of the object holding the member: 0 for the top one */
    const char *key;
    const char *before; /* written before the member in place of ", "; NULL: ", " */
    const char *items;  /* an array one item a line: written before each item,
                         * after the comma; NULL: the array on one line */
    const char *close;  /* with items: written before the array's ']' */
} rb_json_break;

typedef struct {
    const char *open;   /* after the top object's '{' */
    const char *close;  /* before its '}' (a newline always follows it) */
    const rb_json_break *breaks;
    size_t n_breaks;
} rb_json_layout;

/* The object root laid out by layout, as rb_json_print escapes it; a new
 * string (free()), NULL on NOMEM. */
char *rb_json_print_layout(const cJSON *root, const rb_json_layout *layout);

#endif
