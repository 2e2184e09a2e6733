/* The shortest exact decimal form of a double, for JSON. */
#include <math.h>
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

void rb_json_number_or_null(double v, char *buf)
{
    if (isfinite(v))
        rb_json_number(v, buf);
    else
        snprintf(buf, RB_JSONNUM_MAX, "null");
}
