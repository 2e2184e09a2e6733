/* The shortest exact decimal form of a double, for JSON. */
#include <stdio.h>
#include <stdlib.h>
#include "rockbolt/jsonnum.h"

void rb_json_number(double v, char *buf)
{
    int prec;
    for (prec = 15; prec < 17; prec++) {
        snprintf(buf, RB_JSONNUM_MAX, "%.*g", prec, v);
        if (strtod(buf, NULL) == v)
            return;
    }
    snprintf(buf, RB_JSONNUM_MAX, "%.17g", v);
}
