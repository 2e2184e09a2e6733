/* Quantity strings of case files ("7.8 mm", "36 ksi", "0.4 A*") to SI.
 *
 * One table lists every unit the tool accepts with its dimension and its
 * factor to SI, so that a unit of the wrong kind ("MPa" where a length is
 * expected) can be told apart from an unknown one ("kgs"), and every message
 * can list the units that would have worked. Unit names are case-sensitive
 * because the SI prefixes are (mPa is not MPa); a case-insensitive match is
 * only offered as a hint. */
#include <ctype.h>
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/model.h"
#include "rockbolt/units.h"

#define RB_PSI RB_UNIT_PSI_PA
#define RB_LBF RB_UNIT_LBF_N
#define RB_TWO_PI 6.283185307179586

typedef struct {
    const char *name;
    rb_dim dim;
    double factor;   /* SI value of one unit; 0 marks A* */
} rb_unit;

/* The system of a unit: US customary names, then the neutral ones; any
 * other unit of the table is SI. */
static rb_unit_system unit_system_of(const char *name)
{
    static const char *const us[] = {"in", "ft", "lb", "lbm", "lbs", "kip", "kips", "lbf",
        "psi", "ksi", "in-lb/in^3", "in-lbf/in^3", "in/s^2", "ft/s^2",
        "in^2", "lb*in^2", "lb*ft^2", "lbf/in", "kip/in", "in/s", "ft/s", NULL};
    static const char *const neutral[] = {"%", "g", "A*", "Hz", "rad/s",
        "s", "ms", NULL};
    for (size_t i = 0; us[i]; i++)
        if (strcmp(name, us[i]) == 0)
            return RB_UNITS_US;
    for (size_t i = 0; neutral[i]; i++)
        if (strcmp(name, neutral[i]) == 0)
            return RB_UNITS_NEUTRAL;
    return RB_UNITS_SI;
}

static const rb_unit unit_table[] = {
    {"%", RB_DIM_RATIO, 0.01},
    {"m", RB_DIM_LENGTH, 1.0}, {"mm", RB_DIM_LENGTH, 1e-3},
    {"cm", RB_DIM_LENGTH, 1e-2}, {"in", RB_DIM_LENGTH, 0.0254},
    {"ft", RB_DIM_LENGTH, 0.3048},
    {"kg", RB_DIM_MASS, 1.0}, {"lb", RB_DIM_MASS, 0.45359237},
    {"lbm", RB_DIM_MASS, 0.45359237},
    /* the plurals engineers write on schedules: a weight of "1200 lbs" is
     * 1200 lb of mass, and "kips" are kips */
    {"lbs", RB_DIM_MASS, 0.45359237}, {"kips", RB_DIM_FORCE, 1e3 * RB_LBF},
    {"N", RB_DIM_FORCE, 1.0}, {"kN", RB_DIM_FORCE, 1e3},
    {"MN", RB_DIM_FORCE, 1e6}, {"kip", RB_DIM_FORCE, 1e3 * RB_LBF},
    {"lbf", RB_DIM_FORCE, RB_LBF},
    {"Pa", RB_DIM_STRESS, 1.0}, {"kPa", RB_DIM_STRESS, 1e3},
    {"MPa", RB_DIM_STRESS, 1e6}, {"GPa", RB_DIM_STRESS, 1e9},
    {"psi", RB_DIM_STRESS, RB_PSI}, {"ksi", RB_DIM_STRESS, 1e3 * RB_PSI},
    {"J/m^3", RB_DIM_ENERGY_DENSITY, 1.0},
    {"kJ/m^3", RB_DIM_ENERGY_DENSITY, 1e3},
    {"MJ/m^3", RB_DIM_ENERGY_DENSITY, 1e6},
    {"kN*m/m^3", RB_DIM_ENERGY_DENSITY, 1e3},
    {"kN.m/m^3", RB_DIM_ENERGY_DENSITY, 1e3},
    {"kN m/m^3", RB_DIM_ENERGY_DENSITY, 1e3},
    {"in-lb/in^3", RB_DIM_ENERGY_DENSITY, RB_PSI},
    {"in-lbf/in^3", RB_DIM_ENERGY_DENSITY, RB_PSI},
    {"m/s^2", RB_DIM_ACCEL, 1.0}, {"g", RB_DIM_ACCEL, RB_G0},
    {"cm/s^2", RB_DIM_ACCEL, 1e-2}, {"gal", RB_DIM_ACCEL, 1e-2},
    {"Gal", RB_DIM_ACCEL, 1e-2}, {"in/s^2", RB_DIM_ACCEL, 0.0254},
    {"ft/s^2", RB_DIM_ACCEL, 0.3048}, {"A*", RB_DIM_ACCEL, 0.0},
    {"Hz", RB_DIM_FREQUENCY, 1.0}, {"rad/s", RB_DIM_FREQUENCY, 1.0 / RB_TWO_PI},
    {"s", RB_DIM_TIME, 1.0}, {"ms", RB_DIM_TIME, 1e-3},
    {"m^2", RB_DIM_AREA, 1.0}, {"mm^2", RB_DIM_AREA, 1e-6},
    {"cm^2", RB_DIM_AREA, 1e-4}, {"in^2", RB_DIM_AREA, 0.0254 * 0.0254},
    {"kg*m^2", RB_DIM_INERTIA, 1.0}, {"kg.m^2", RB_DIM_INERTIA, 1.0},
    {"kg m^2", RB_DIM_INERTIA, 1.0},
    {"lb*in^2", RB_DIM_INERTIA, 0.45359237 * 0.0254 * 0.0254},
    {"lb*ft^2", RB_DIM_INERTIA, 0.45359237 * 0.3048 * 0.3048},
    {"N/m", RB_DIM_STIFFNESS, 1.0}, {"kN/m", RB_DIM_STIFFNESS, 1e3},
    {"MN/m", RB_DIM_STIFFNESS, 1e6}, {"N/mm", RB_DIM_STIFFNESS, 1e3},
    {"kN/mm", RB_DIM_STIFFNESS, 1e6},
    {"lbf/in", RB_DIM_STIFFNESS, RB_LBF / 0.0254},
    {"kip/in", RB_DIM_STIFFNESS, 1e3 * RB_LBF / 0.0254},
    {"m/s", RB_DIM_VELOCITY, 1.0}, {"mm/s", RB_DIM_VELOCITY, 1e-3},
    {"cm/s", RB_DIM_VELOCITY, 1e-2}, {"in/s", RB_DIM_VELOCITY, 0.0254},
    {"ft/s", RB_DIM_VELOCITY, 0.3048},
};
#define RB_N_UNITS (sizeof unit_table / sizeof unit_table[0])

typedef struct {
    const char *phrase;   /* "a length" */
    const char *units;    /* accepted units, for messages */
    const char *example;  /* a valid value */
    const char *noun;     /* "length", for "a unit of length" */
} rb_dim_info;

static const rb_dim_info dims[RB_DIM_COUNT] = {
    [RB_DIM_RATIO] = {"a dimensionless number", "no unit, or %", "0.01", "a dimensionless number"},
    [RB_DIM_LENGTH] = {"a length", "m, mm, cm, in, ft", "7.8 mm", "length"},
    [RB_DIM_MASS] = {"a mass", "kg, lb", "454 kg", "mass"},
    [RB_DIM_FORCE] = {"a force", "N, kN, MN, lbf, kip", "62.8 kN", "force"},
    [RB_DIM_STRESS] = {"a stress", "Pa, kPa, MPa, GPa, psi, ksi", "248 MPa", "stress"},
    [RB_DIM_ENERGY_DENSITY] = {"an energy per volume",
        "J/m^3, kJ/m^3, MJ/m^3, kN*m/m^3, kN.m/m^3, in-lb/in^3", "82700 kJ/m^3", "energy per volume"},
    [RB_DIM_ACCEL] = {"an acceleration",
        "m/s^2, g, cm/s^2, gal, in/s^2, ft/s^2, A*", "0.4 A*", "acceleration"},
    [RB_DIM_FREQUENCY] = {"a frequency", "Hz, rad/s", "5 Hz", "frequency"},
    [RB_DIM_TIME] = {"a time", "s, ms", "2.5 s", "time"},
    [RB_DIM_AREA] = {"an area", "mm^2, cm^2, in^2, m^2", "126.7 mm^2", "area"},
    [RB_DIM_INERTIA] = {"a moment of inertia",
        "kg*m^2, kg.m^2, lb*in^2, lb*ft^2", "150 kg*m^2", "moment of inertia"},
    [RB_DIM_STIFFNESS] = {"a stiffness",
        "N/m, kN/m, MN/m, N/mm, kN/mm, lbf/in, kip/in", "520 MN/m", "stiffness"},
    [RB_DIM_VELOCITY] = {"a velocity", "m/s, mm/s, cm/s, in/s, ft/s", "1.0 m/s", "velocity"},
};

const char *rb_dim_str(rb_dim dim)
{
    return dim < RB_DIM_COUNT ? dims[dim].phrase : "a quantity";
}

const char *rb_dim_units(rb_dim dim)
{
    return dim < RB_DIM_COUNT ? dims[dim].units : "";
}

/* A message in msg (if any), always RB_ERR_PARSE. */
static rb_status unit_fail(char *msg, size_t size, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));

static rb_status unit_fail(char *msg, size_t size, const char *fmt, ...)
{
    if (msg && size) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(msg, size, fmt, ap);
        va_end(ap);
    }
    return RB_ERR_PARSE;
}

/* ASCII case-insensitive comparison of n bytes (strncasecmp is POSIX,
 * not C11). */
static int unit_casecmp(const char *a, const char *b, size_t n)
{
    for (size_t i = 0; i < n; i++) {
        int ca = tolower((unsigned char)a[i]), cb = tolower((unsigned char)b[i]);
        if (ca != cb)
            return ca - cb;
    }
    return 0;
}

/* The unit named by the len bytes at name, or NULL. fold: ignore case. */
static const rb_unit *unit_find(const char *name, size_t len, int fold)
{
    for (size_t i = 0; i < RB_N_UNITS; i++) {
        const char *u = unit_table[i].name;
        if (strlen(u) != len)
            continue;
        if (fold ? unit_casecmp(u, name, len) == 0 : strncmp(u, name, len) == 0)
            return &unit_table[i];
    }
    return NULL;
}

/* Length of the decimal number at s (sign, digits, point, exponent), or 0
 * when there is none. Scanning ourselves keeps strtod from accepting hex,
 * "inf" or "nan". */
static size_t unit_scan_number(const char *s)
{
    size_t i = 0, digits = 0;
    if (s[i] == '+' || s[i] == '-')
        i++;
    while (isdigit((unsigned char)s[i])) {
        i++;
        digits++;
    }
    if (s[i] == '.') {
        i++;
        while (isdigit((unsigned char)s[i])) {
            i++;
            digits++;
        }
    }
    if (digits == 0)
        return 0;
    if (s[i] == 'e' || s[i] == 'E') {
        size_t j = i + 1;
        if (s[j] == '+' || s[j] == '-')
            j++;
        if (isdigit((unsigned char)s[j])) {
            while (isdigit((unsigned char)s[j]))
                j++;
            i = j;
        }
    }
    return i;
}

/* A fraction after the whole number of nlen bytes at s (its value *v):
 * "1/2" or a mixed number "1 1/2", "1-1/2", as US drawings size bolts. The
 * new length of the number, nlen when none follows, or 0 for a zero
 * denominator. Only whole numbers take part: "1.5/2" is no fraction. */
static size_t unit_scan_fraction(const char *s, size_t nlen, double *v)
{
    size_t i = 0, j, k;
    if (s[i] == '+' || s[i] == '-')
        i++;
    for (j = i; j < nlen; j++)
        if (!isdigit((unsigned char)s[j]))
            return nlen;
    double sign = s[0] == '-' ? -1.0 : 1.0, whole = fabs(*v), num;
    j = nlen;
    if (s[j] == ' ' || s[j] == '-') {
        /* a mixed number: whole, blank or hyphen, then num/den */
        for (k = j + 1; isdigit((unsigned char)s[k]); k++)
            ;
        if (k == j + 1 || s[k] != '/')
            return nlen;
        num = strtod(s + j + 1, NULL);
        j = k;
    } else if (s[j] == '/') {
        num = whole;
        whole = 0;
    } else {
        return nlen;
    }
    for (k = j + 1; isdigit((unsigned char)s[k]); k++)
        ;
    if (k == j + 1)
        return nlen;
    double den = strtod(s + j + 1, NULL);
    if (den == 0)
        return 0;
    *v = sign * (whole + num / den);
    return k;
}

/* 1 if s (after an optional sign) spells NaN or infinity in any case, in
 * C's spelling or YAML's (".nan", ".inf"). */
static int unit_is_nonfinite_word(const char *s)
{
    if (*s == '+' || *s == '-')
        s++;
    if (*s == '.')
        s++;
    return unit_casecmp(s, "nan", 3) == 0 || unit_casecmp(s, "inf", 3) == 0;
}

/* Report why the unit text u (len bytes, trimmed) is not a unit of dim. */
static rb_status unit_explain(const char *u, size_t len, rb_dim dim,
                                 char *msg, size_t size)
{
    const rb_dim_info *di = &dims[dim];
    const rb_unit *other = unit_find(u, len, 0);
    if (other && other->factor == 0.0)
        return unit_fail(msg, size, "'A*' is only for floor accelerations "
                            "(expected %s: %s)", di->phrase, di->units);
    if (other && other->dim == RB_DIM_MASS && dim == RB_DIM_FORCE)
        return unit_fail(msg, size, "'%.*s' is a unit of mass, not of force (a "
                            "pound of force is 'lbf'; expected %s)", (int)len, u,
                            di->units);
    if (other)
        return unit_fail(msg, size, "'%.*s' is a unit of %s, not of %s "
                            "(expected %s)", (int)len, u,
                            dims[other->dim].noun, di->noun, di->units);
    /* A known unit followed by more words: the unit is fine, the rest is not. */
    size_t word = 0;
    while (word < len && !isspace((unsigned char)u[word]))
        word++;
    if (word < len && unit_find(u, word, 0)) {
        size_t rest = word;
        while (isspace((unsigned char)u[rest]))
            rest++;
        return unit_fail(msg, size, "unexpected text '%.*s' after the unit '%.*s'",
                            (int)(len - rest), u + rest, (int)word, u);
    }
    if (!isalpha((unsigned char)u[0]) && u[0] != '%')
        return unit_fail(msg, size, "unexpected text '%.*s' after the number",
                            (int)len, u);
    const rb_unit *near = unit_find(u, len, 1);
    if (near && near->dim == dim)
        return unit_fail(msg, size, "unknown unit '%.*s' (did you mean '%s'? "
                            "units are case-sensitive)", (int)len, u, near->name);
    return unit_fail(msg, size, "unknown unit '%.*s' (expected %s: %s)",
                        (int)len, u, di->phrase, di->units);
}

rb_status rb_unit_parse(const char *text, rb_dim dim, rb_quantity *out,
                        char *msg, size_t msg_size)
{
    if (dim >= RB_DIM_COUNT)
        dim = RB_DIM_RATIO;
    const rb_dim_info *di = &dims[dim];
    out->value = 0.0;
    out->relative_a_star = 0;
    out->system = RB_UNITS_NEUTRAL;
    while (isspace((unsigned char)*text))
        text++;
    size_t len = strlen(text);
    while (len > 0 && isspace((unsigned char)text[len - 1]))
        len--;
    if (len == 0)
        return unit_fail(msg, msg_size, "empty value (expected %s such as '%s')",
                            di->phrase, di->example);
    if (unit_is_nonfinite_word(text))
        return unit_fail(msg, msg_size, "'%.*s' is not a finite number",
                            (int)len, text);
    size_t nlen = unit_scan_number(text);
    if (nlen == 0)
        return unit_fail(msg, msg_size, "'%.*s' is not a number (expected %s "
                            "such as '%s')", (int)len, text, di->phrase, di->example);
    char num[64];
    if (nlen >= sizeof num)
        return unit_fail(msg, msg_size, "number '%.*s...' is too long", 20, text);
    memcpy(num, text, nlen);
    num[nlen] = '\0';
    errno = 0;
    double v = strtod(num, NULL);
    if (errno == ERANGE && fabs(v) > 1.0)
        return unit_fail(msg, msg_size, "number '%s' is out of range", num);
    size_t flen = unit_scan_fraction(text, nlen, &v);
    if (flen == 0)
        return unit_fail(msg, msg_size, "'%.*s' divides by zero", (int)len, text);
    nlen = flen;
    const char *u = text + nlen;
    while (u < text + len && isspace((unsigned char)*u))
        u++;
    size_t ulen = (size_t)(text + len - u);
    if (ulen == 0) {
        if (dim == RB_DIM_RATIO) {
            out->value = v;
            return RB_OK;
        }
        return unit_fail(msg, msg_size, "missing unit on '%s' (expected %s: %s)",
                            num, di->phrase, di->units);
    }
    const rb_unit *unit = unit_find(u, ulen, 0);
    /* an energy per volume is a stress in SI (J/m^3 = Pa), and a toughness
     * is often given as one: 1 psi is 1 in-lbf/in^3, 1 MPa 1 MJ/m^3 */
    int stress_for_energy = unit && dim == RB_DIM_ENERGY_DENSITY
                            && unit->dim == RB_DIM_STRESS;
    if (!unit || (unit->dim != dim && !stress_for_energy))
        return unit_explain(u, ulen, dim, msg, msg_size);
    out->system = unit_system_of(unit->name);
    if (unit->factor == 0.0) {
        out->value = v;
        out->relative_a_star = 1;
        return RB_OK;
    }
    out->value = v * unit->factor;
    if (!isfinite(out->value))
        return unit_fail(msg, msg_size, "'%.*s' is out of range", (int)len, text);
    return RB_OK;
}

rb_unit_system rb_unit_system_of_text(const char *text)
{
    while (isspace((unsigned char)*text))
        text++;
    if (unit_is_nonfinite_word(text))
        return RB_UNITS_NEUTRAL;
    size_t nlen = unit_scan_number(text);
    if (nlen == 0)
        return RB_UNITS_NEUTRAL;
    double v = 0;
    nlen = unit_scan_fraction(text, nlen, &v);
    if (nlen == 0)
        return RB_UNITS_NEUTRAL;
    const char *u = text + nlen;
    while (isspace((unsigned char)*u))
        u++;
    size_t len = strlen(u);
    while (len > 0 && isspace((unsigned char)u[len - 1]))
        len--;
    const rb_unit *unit = len ? unit_find(u, len, 0) : NULL;
    return unit ? unit_system_of(unit->name) : RB_UNITS_NEUTRAL;
}
