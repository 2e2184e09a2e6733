/* Growing arrays (grow.h). */
#include <stdint.h>
#include <stdlib.h>
#include "util/grow.h"

void *rb_grow(void *items, size_t *cap, size_t size, size_t first)
{
    size_t want = *cap ? 2 * *cap : first;
    if (want <= *cap || size == 0 || want > SIZE_MAX / size)
        return NULL;
    void *p = realloc(items, want * size);
    if (p)
        *cap = want;
    return p;
}
