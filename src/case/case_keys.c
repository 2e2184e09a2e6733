/* rb_case_key_settable: which dotted keys of a case one value can set (a
 * column of an equipment list, docs/batch.md).
 *
 * Walked over the very key lists the schema's readers check a case file
 * against, so that a column is known exactly when a case file could give
 * that key; a misspelt column is refused at the header, once, rather than
 * at every row. What a value must look like is left to the loader, which
 * reads each row's cell as it reads a case file's. */
#include <stdio.h>
#include <string.h>
#include "case_internal.h"
#include "rockbolt/case_overrides.h"
#include "util/nearest.h"

#define KEYS_MAX_LISTS 4
#define KEYS_MAX_DEPTH 4

typedef enum { K_LEAF, K_MAP, K_SEQ } key_shape;

/* The keys of a section; a motion's depend on its type, hence several. */
static const struct {
    const char *path;
    const char *const *const *lists[KEYS_MAX_LISTS];
} sections[] = {
    {"", {&rb_case_top_keys}},
    {"equipment", {&rb_case_equipment_keys}},
    {"anchorage", {&rb_case_anchorage_keys}},
    {"anchorage.product", {&rb_case_product_keys}},
    {"concrete", {&rb_case_concrete_keys}},
    {"criteria", {&rb_case_criteria_keys}},
    {"analysis", {&rb_case_analysis_keys}},
    {"design", {&rb_case_design_keys}},
    {"design.code", {&rb_case_code_keys}},
    {"fragility", {&rb_case_fragility_keys}},
    {"motion", {&rb_case_harmonic_keys, &rb_case_pulse_keys, &rb_case_record_keys,
                &rb_case_synthetic_keys}},
    {"motion.building", {&rb_case_building_keys}},
    {"motion.spectrum", {&rb_case_ac156_keys, &rb_case_table_keys, &rb_case_ieee693_keys,
                         &rb_case_gr63_keys}},
    {"motion.table", {&rb_case_synth_table_keys}},
    {"motion.spectrum.envelope", {&rb_case_envelope_keys}},
    {"motion.spectrum.tolerance", {&rb_case_tolerance_keys}},
    {"motion.vertical", {&rb_case_vertical_harmonic_keys, &rb_case_vertical_pulse_keys,
                         &rb_case_vertical_record_keys}},
    {"project", {&rb_case_project_keys}},
};

/* The keys whose value is not one scalar. */
static const struct {
    const char *path;
    key_shape shape;
} shapes[] = {
    {"equipment", K_MAP}, {"anchorage", K_MAP}, {"motion", K_MAP}, {"motions", K_SEQ},
    {"criteria", K_MAP}, {"analysis", K_MAP}, {"design", K_MAP}, {"concrete", K_MAP},
    {"fragility", K_MAP}, {"anchorage.product", K_MAP}, {"design.code", K_MAP},
    {"design.sweeps", K_SEQ}, {"motion.building", K_MAP}, {"motion.spectrum", K_MAP},
    {"motion.spectrum.envelope", K_MAP}, {"motion.spectrum.tolerance", K_MAP},
    {"motion.window", K_SEQ}, {"fragility.damage_state_weights", K_SEQ},
    {"motion.vertical", K_MAP}, {"motion.vertical.window", K_SEQ}, {"project", K_MAP},
    {"motion.table", K_MAP},
};

static int section_of(const char *path)
{
    for (size_t i = 0; i < sizeof sections / sizeof sections[0]; i++)
        if (strcmp(sections[i].path, path) == 0)
            return (int)i;
    return -1;
}

static key_shape shape_of(const char *path)
{
    for (size_t i = 0; i < sizeof shapes / sizeof shapes[0]; i++)
        if (strcmp(shapes[i].path, path) == 0)
            return shapes[i].shape;
    return K_LEAF;
}

/* 1 if section s has key; else the nearest of its keys in *near (or NULL). */
static int section_has(int s, const char *key, const char **near)
{
    int best = 9;
    *near = NULL;
    for (size_t l = 0; l < KEYS_MAX_LISTS && sections[s].lists[l]; l++) {
        const char *const *keys = *sections[s].lists[l];
        for (size_t k = 0; keys[k]; k++) {
            if (strcmp(keys[k], key) == 0)
                return 1;
            int d = rb_edit_distance(key, keys[k]);
            if (d < best) {
                best = d;
                *near = keys[k];
            }
        }
    }
    if (best > rb_typo_limit(strlen(key)))
        *near = NULL;
    return 0;
}

/* The first key of section s, for an example. */
static const char *first_key(int s)
{
    return (*sections[s].lists[0])[0];
}

int rb_case_key_settable(const char *key, char *msg, size_t msg_size)
{
    char path[RB_CASE_KEY_MAX], next[RB_CASE_KEY_MAX], comp[RB_CASE_KEY_MAX];
    size_t len = strlen(key), at = 0;
    int depth = 0;
    if (len == 0 || len >= sizeof path
        || strspn(key, "abcdefghijklmnopqrstuvwxyz0123456789_.") != len
        || key[0] == '.' || key[len - 1] == '.' || strstr(key, "..")) {
        snprintf(msg, msg_size, "'%.100s' is no case key (expected lower-case words "
                 "joined by dots, such as 'anchorage.embedment')", key);
        return 0;
    }
    path[0] = '\0';
    while (at < len) {
        size_t n = strcspn(key + at, ".");
        memcpy(comp, key + at, n);
        comp[n] = '\0';
        if (++depth > KEYS_MAX_DEPTH) {
            snprintf(msg, msg_size, "'%s' is deeper than any case key", key);
            return 0;
        }
        int s = section_of(path);
        if (s < 0)
            return 1;   /* a block the loader reads whole: it checks each row's keys */
        const char *near;
        if (!section_has(s, comp, &near)) {
            if (near)
                snprintf(msg, msg_size, "unknown key '%s'%s%s%s (did you mean '%s'?)", comp,
                         path[0] ? " in '" : "", path, path[0] ? "'" : "", near);
            else
                snprintf(msg, msg_size, "unknown key '%s'%s%s%s", comp,
                         path[0] ? " in '" : "", path, path[0] ? "'" : "");
            return 0;
        }
        rb_case_keypath(next, path, comp);
        memcpy(path, next, sizeof path);
        at += n + (key[at + n] == '.');
        key_shape sh = shape_of(path);
        if (at < len && sh != K_MAP) {
            snprintf(msg, msg_size, "'%s' is %s, not a section with keys", path,
                     sh == K_SEQ ? "a list" : "a value");
            return 0;
        }
        if (at >= len && sh == K_MAP) {
            int sub = section_of(path);
            snprintf(msg, msg_size, "'%s' is a section: name one of its keys, such as "
                     "'%s.%s'", path, path, sub >= 0 ? first_key(sub) : "...");
            return 0;
        }
        if (at >= len && sh == K_SEQ) {
            snprintf(msg, msg_size, "'%s' is a list, which one cell cannot give", path);
            return 0;
        }
    }
    if (strcmp(key, "extends") == 0 || strcmp(key, "name") == 0) {
        snprintf(msg, msg_size, "'%s' cannot be a column: a row's %s", key,
                 key[0] == 'e' ? "base case is its 'base' cell"
                               : "case is named by its 'tag' cell");
        return 0;
    }
    return 1;
}
