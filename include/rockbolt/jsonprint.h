/* Every JSON output is printed here: cJSON's text with the format
 * characters escaped (rb_json_escape_format), so that no report, summary or
 * error carries a raw right-to-left override or zero-width space. */
#ifndef ROCKBOLT_JSONPRINT_H
#define ROCKBOLT_JSONPRINT_H

#include <cjson/cJSON.h>

/* The item as JSON text, with cJSON's layout (formatted: tabs and
 * newlines, else none), in a new string the caller frees with free();
 * NULL on NOMEM. */
char *rb_json_print(const cJSON *item, int formatted);

#endif
