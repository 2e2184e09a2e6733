/* Growing arrays (src/util/grow.h): the room doubles from its first size,
 * the contents move along, and a size that would overflow leaves the
 * array as it was. */
#include <stdint.h>
#include <stdlib.h>
#include "harness.h"
#include "util/grow.h"

int main(void)
{
    size_t cap = 0, n = 0;
    int *v = NULL;
    for (int i = 0; i < 1000; i++) {
        if (n == cap) {
            size_t before = cap;
            int *p = rb_grow(v, &cap, sizeof *p, 4);
            CHECK(p != NULL);
            CHECK(cap == (before ? 2 * before : 4));
            if (!p)
                break;
            v = p;
        }
        v[n++] = i;
    }
    CHECK(cap == 1024);
    int ok = 1;
    for (size_t i = 0; i < n; i++)
        ok &= v[i] == (int)i;
    CHECK(ok);
    /* twice the room would not fit in a size_t: refused, nothing moved */
    size_t huge = SIZE_MAX / sizeof *v / 2 + 1;
    size_t keep = huge;
    CHECK(rb_grow(v, &keep, sizeof *v, 4) == NULL && keep == huge);
    keep = cap;
    CHECK(rb_grow(v, &keep, 0, 4) == NULL && keep == cap);
    CHECK(v[999] == 999);
    free(v);
    TEST_MAIN_END();
}
