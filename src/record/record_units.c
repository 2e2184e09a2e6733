/* Acceleration units as record files spell them: "G", "(g)", "cm/sec/sec",
 * "CM/S^2", "gal", "in/s2". Headers are written by hand and by many
 * programs, so the spelling is normalised (case, blanks, "sec" for "s",
 * the ways of writing a square) before one short table is consulted. */
#include <string.h>
#include "rockbolt/model.h"
#include "record_internal.h"

/* Room for any unit we know after normalising; longer names are unknown. */
#define RB_REC_UNIT_MAX 24

typedef struct {
    const char *name;
    double to_mps2;
} rb_rec_unit;

static const rb_rec_unit rec_whole_units[] = {
    {"g", RB_G0}, {"gs", RB_G0}, {"mg", 1e-3 * RB_G0},
    {"gal", 1e-2}, {"gals", 1e-2},
};

static const rb_rec_unit rec_lengths[] = {
    {"m", 1.0}, {"cm", 1e-2}, {"mm", 1e-3},
    {"in", 0.0254}, {"inch", 0.0254}, {"ft", 0.3048},
};

static const char *const rec_squares[] = {"s^2", "s2", "s/s", "s**2", "s\xc2\xb2"};

#define RB_REC_COUNT(a) (sizeof(a) / sizeof((a)[0]))

/* Lower-case, without blanks or enclosing brackets, "sec" as "s". 0 if
 * the result does not fit. */
static int rec_units_normalise(const char *name, size_t len, char *out)
{
    size_t j = 0;
    while (len > 0 && strchr(" \t([", name[0])) {
        name++;
        len--;
    }
    while (len > 0 && strchr(" \t)].,;:", name[len - 1]))
        len--;
    for (size_t i = 0; i < len; i++) {
        char c = name[i];
        if (c == ' ' || c == '\t')
            continue;
        if (c >= 'A' && c <= 'Z')
            c = (char)(c - 'A' + 'a');
        if (j + 1 >= RB_REC_UNIT_MAX)
            return 0;
        out[j++] = c;
        if (j >= 3 && memcmp(out + j - 3, "sec", 3) == 0)
            j -= 2;
    }
    out[j] = '\0';
    return j > 0;
}

static double rec_units_per_square(const char *u)
{
    const char *slash = strchr(u, '/');
    if (!slash)
        return 0.0;
    size_t len_part = (size_t)(slash - u);
    for (size_t i = 0; i < RB_REC_COUNT(rec_squares); i++) {
        if (strcmp(slash + 1, rec_squares[i]) != 0)
            continue;
        for (size_t k = 0; k < RB_REC_COUNT(rec_lengths); k++)
            if (strlen(rec_lengths[k].name) == len_part
                && memcmp(u, rec_lengths[k].name, len_part) == 0)
                return rec_lengths[k].to_mps2;
    }
    return 0.0;
}

double rb_rec_units_lookup(const char *name, size_t len)
{
    char u[RB_REC_UNIT_MAX];
    if (!rec_units_normalise(name, len, u))
        return 0.0;
    for (size_t i = 0; i < RB_REC_COUNT(rec_whole_units); i++)
        if (strcmp(u, rec_whole_units[i].name) == 0)
            return rec_whole_units[i].to_mps2;
    return rec_units_per_square(u);
}

rb_status rb_record_units_parse(const char *name, double *to_mps2)
{
    if (!name || !to_mps2)
        return RB_ERR_INVALID;
    double f = rb_rec_units_lookup(name, strlen(name));
    if (f == 0.0)
        return RB_ERR_PARSE;
    *to_mps2 = f;
    return RB_OK;
}
