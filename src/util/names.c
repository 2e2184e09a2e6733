/* Names of enum values (rockbolt/names.h); each table is beside its enum. */
#include <stdio.h>
#include <string.h>
#include "rockbolt/names.h"

const char *rb_enum_str(const rb_enum_name *t, int value)
{
    for (; t->name; t++)
        if (t->value == value)
            return t->name;
    return "unknown";
}

int rb_enum_parse(const rb_enum_name *t, const char *s, int *value)
{
    for (; t->name; t++)
        if (strcmp(t->name, s) == 0) {
            *value = t->value;
            return 1;
        }
    return 0;
}

char *rb_enum_str_sep(const rb_enum_name *t, int value, char sep, char *buf, size_t n)
{
    if (!n)
        return buf;
    snprintf(buf, n, "%s", rb_enum_str(t, value));
    for (char *p = buf; *p; p++)
        if (*p == '-')
            *p = sep;
    return buf;
}
