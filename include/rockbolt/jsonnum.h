/* Numbers in JSON that read back exactly: every report and summary prints
 * through this one function, so the same double is the same text in all of
 * them (cJSON's own printer stops at 15 digits when they read back within
 * a relative DBL_EPSILON, an ulp off). */
#ifndef ROCKBOLT_JSONNUM_H
#define ROCKBOLT_JSONNUM_H

#include <stddef.h>

/* The shortest %g form of finite v (15 to 17 digits) that strtod reads back
 * as v, into buf (at least RB_JSONNUM_MAX bytes). */
#define RB_JSONNUM_MAX 32
void rb_json_number(double v, char *buf);

/* The same, or "null" when v is not finite: JSON has no infinity, and where
 * an output meets one (a ratio with nothing to divide by) it means none.
 * The one number format of every JSON output. */
void rb_json_number_or_null(double v, char *buf);

#endif
