/* The sections a case file may give at its top level. The schema reads
 * them (case_schema.c), and the YAML reader and extends: ask whether a
 * file gives any (a file that gives none is not taken for a case, and
 * none of its keys or values is quoted): one list, below them all. */
#include <string.h>
#include "case_internal.h"

static const char *const top_keys[] = {
    "name", "description", "extends", "equipment", "anchorage", "gap",
    "gap_ratio", "motion", "motions", "criteria", "analysis", "design",
    "output_units", "concrete", "fragility", "project", NULL};
int rb_case_top_key(const char *key)
{
    for (size_t k = 0; top_keys[k]; k++)
        if (strcmp(key, top_keys[k]) == 0)
            return 1;
    return 0;
}

const char *const *const rb_case_top_keys = top_keys;
