/* Names of enum values (rockbolt/names.h); each table is beside its enum. */
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
