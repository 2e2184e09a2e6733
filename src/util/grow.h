/* Growing arrays: the doubling every list of the libraries does, written
 * once, with the size overflow checked. Internal to the libraries
 * (src/util). */
#ifndef RB_UTIL_GROW_H
#define RB_UTIL_GROW_H

#include <stddef.h>

/* items (room for *cap elements of size bytes, NULL when *cap is 0) moved
 * to twice the room, or first elements when empty; *cap follows. NULL when
 * out of memory or the size would overflow: items and *cap are then as
 * they were, and still the caller's. */
void *rb_grow(void *items, size_t *cap, size_t size, size_t first);

#endif
