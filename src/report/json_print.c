/* The one printer of JSON (rockbolt/jsonprint.h). */
#include <stdlib.h>
#include "rockbolt/jsonprint.h"
#include "rockbolt/textsafe.h"

char *rb_json_print(const cJSON *item, int formatted)
{
    char *raw = formatted ? cJSON_Print(item) : cJSON_PrintUnformatted(item);
    char *safe = raw ? rb_json_escape_format(raw) : NULL;
    cJSON_free(raw);
    return safe;
}
