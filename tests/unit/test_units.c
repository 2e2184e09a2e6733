/* Unit tests for the quantity parser (units.h): every accepted unit against
 * its SI value, and every class of error with the start of its message. */
#include <math.h>
#include <string.h>
#include "harness.h"
#include "rockbolt/units.h"

static double parse_ok(const char *text, rb_dim dim)
{
    rb_quantity q;
    char msg[256] = "";
    rb_status st = rb_unit_parse(text, dim, &q, msg, sizeof msg);
    if (st != RB_OK)
        fprintf(stderr, "unexpected failure on '%s': %s\n", text, msg);
    CHECK(st == RB_OK);
    CHECK(!q.relative_a_star);
    return q.value;
}

/* The parse fails and the message contains want. */
static void parse_bad(const char *text, rb_dim dim, const char *want)
{
    rb_quantity q;
    char msg[256] = "";
    rb_status st = rb_unit_parse(text, dim, &q, msg, sizeof msg);
    CHECK(st == RB_ERR_PARSE);
    if (!strstr(msg, want))
        fprintf(stderr, "'%s': message '%s' lacks '%s'\n", text, msg, want);
    CHECK(strstr(msg, want) != NULL);
}

static void test_lengths_masses_forces(void)
{
    CHECK_REL(parse_ok("2 m", RB_DIM_LENGTH), 2.0, 1e-15);
    CHECK_REL(parse_ok("7.8 mm", RB_DIM_LENGTH), 7.8e-3, 1e-15);
    CHECK_REL(parse_ok("12 cm", RB_DIM_LENGTH), 0.12, 1e-15);
    CHECK_REL(parse_ok("0.5 in", RB_DIM_LENGTH), 0.0127, 1e-15);
    CHECK_REL(parse_ok("3 ft", RB_DIM_LENGTH), 0.9144, 1e-15);
    CHECK_REL(parse_ok("7.8mm", RB_DIM_LENGTH), 7.8e-3, 1e-15);
    CHECK_REL(parse_ok("  1e-3   m ", RB_DIM_LENGTH), 1e-3, 1e-15);
    CHECK_REL(parse_ok("-.5 m", RB_DIM_LENGTH), -0.5, 1e-15);
    CHECK_REL(parse_ok("454 kg", RB_DIM_MASS), 454.0, 1e-15);
    CHECK_REL(parse_ok("1000 lb", RB_DIM_MASS), 453.59237, 1e-15);
    CHECK_REL(parse_ok("1 lbm", RB_DIM_MASS), 0.45359237, 1e-15);
    CHECK_REL(parse_ok("5 N", RB_DIM_FORCE), 5.0, 1e-15);
    CHECK_REL(parse_ok("62.8 kN", RB_DIM_FORCE), 62800.0, 1e-15);
    CHECK_REL(parse_ok("1 MN", RB_DIM_FORCE), 1e6, 1e-15);
    CHECK_REL(parse_ok("1 kip", RB_DIM_FORCE), 4448.2216152605, 1e-12);
    CHECK_REL(parse_ok("1 lbf", RB_DIM_FORCE), 4.4482216152605, 1e-12);
}

static void test_stresses_energies(void)
{
    CHECK_REL(parse_ok("3 Pa", RB_DIM_STRESS), 3.0, 1e-15);
    CHECK_REL(parse_ok("3 kPa", RB_DIM_STRESS), 3e3, 1e-15);
    CHECK_REL(parse_ok("248 MPa", RB_DIM_STRESS), 248e6, 1e-15);
    CHECK_REL(parse_ok("200 GPa", RB_DIM_STRESS), 200e9, 1e-15);
    CHECK_REL(parse_ok("1 psi", RB_DIM_STRESS), 6894.757293168361, 1e-12);
    CHECK_REL(parse_ok("36 ksi", RB_DIM_STRESS), 248.211262554e6, 1e-9);
    CHECK_REL(parse_ok("5 J/m^3", RB_DIM_ENERGY_DENSITY), 5.0, 1e-15);
    CHECK_REL(parse_ok("82700 kJ/m^3", RB_DIM_ENERGY_DENSITY), 82.7e6, 1e-15);
    CHECK_REL(parse_ok("82.7 MJ/m^3", RB_DIM_ENERGY_DENSITY), 82.7e6, 1e-15);
    CHECK_REL(parse_ok("82700 kN*m/m^3", RB_DIM_ENERGY_DENSITY), 82.7e6, 1e-15);
    CHECK_REL(parse_ok("82700 kN.m/m^3", RB_DIM_ENERGY_DENSITY), 82.7e6, 1e-15);
    CHECK_REL(parse_ok("82700 kN m/m^3", RB_DIM_ENERGY_DENSITY), 82.7e6, 1e-15);
    CHECK_REL(parse_ok("3 in-lb/in^3", RB_DIM_ENERGY_DENSITY), 3 * 6894.757293168361, 1e-12);
    CHECK_REL(parse_ok("3 in-lbf/in^3", RB_DIM_ENERGY_DENSITY), 3 * 6894.757293168361, 1e-12);
}

static void test_accelerations(void)
{
    rb_quantity q;
    CHECK_REL(parse_ok("2 m/s^2", RB_DIM_ACCEL), 2.0, 1e-15);
    CHECK_REL(parse_ok("0.5 g", RB_DIM_ACCEL), 0.5 * 9.80665, 1e-15);
    CHECK_REL(parse_ok("981 cm/s^2", RB_DIM_ACCEL), 9.81, 1e-15);
    CHECK_REL(parse_ok("981 gal", RB_DIM_ACCEL), 9.81, 1e-15);
    CHECK_REL(parse_ok("981 Gal", RB_DIM_ACCEL), 9.81, 1e-15);
    CHECK_REL(parse_ok("386.1 in/s^2", RB_DIM_ACCEL), 386.1 * 0.0254, 1e-15);
    CHECK_REL(parse_ok("32.17 ft/s^2", RB_DIM_ACCEL), 32.17 * 0.3048, 1e-15);
    CHECK(rb_unit_parse("0.4 A*", RB_DIM_ACCEL, &q, NULL, 0) == RB_OK);
    CHECK(q.relative_a_star == 1);
    CHECK_NEAR(q.value, 0.4, 0);
    CHECK(rb_unit_parse("1.2A*", RB_DIM_ACCEL, &q, NULL, 0) == RB_OK);
    CHECK(q.relative_a_star == 1);
    CHECK_NEAR(q.value, 1.2, 0);
}

static void test_other_dimensions(void)
{
    CHECK_REL(parse_ok("5 Hz", RB_DIM_FREQUENCY), 5.0, 1e-15);
    CHECK_REL(parse_ok("31.4159265358979 rad/s", RB_DIM_FREQUENCY), 5.0, 1e-13);
    CHECK_REL(parse_ok("2.5 s", RB_DIM_TIME), 2.5, 1e-15);
    CHECK_REL(parse_ok("10 ms", RB_DIM_TIME), 0.01, 1e-15);
    CHECK_REL(parse_ok("0.01", RB_DIM_RATIO), 0.01, 1e-15);
    CHECK_REL(parse_ok("1 %", RB_DIM_RATIO), 0.01, 1e-15);
    CHECK_REL(parse_ok("5%", RB_DIM_RATIO), 0.05, 1e-15);
    CHECK_REL(parse_ok("126.7 mm^2", RB_DIM_AREA), 126.7e-6, 1e-15);
    CHECK_REL(parse_ok("2 cm^2", RB_DIM_AREA), 2e-4, 1e-15);
    CHECK_REL(parse_ok("0.196 in^2", RB_DIM_AREA), 0.196 * 0.00064516, 1e-15);
    CHECK_REL(parse_ok("1 m^2", RB_DIM_AREA), 1.0, 1e-15);
    CHECK_REL(parse_ok("150 kg*m^2", RB_DIM_INERTIA), 150.0, 1e-15);
    CHECK_REL(parse_ok("150 kg.m^2", RB_DIM_INERTIA), 150.0, 1e-15);
    CHECK_REL(parse_ok("150 kg m^2", RB_DIM_INERTIA), 150.0, 1e-15);
    CHECK_REL(parse_ok("1 lb*in^2", RB_DIM_INERTIA), 0.45359237 * 0.00064516, 1e-12);
    CHECK_REL(parse_ok("1 lb*ft^2", RB_DIM_INERTIA), 0.45359237 * 0.09290304, 1e-12);
    CHECK_REL(parse_ok("520 MN/m", RB_DIM_STIFFNESS), 520e6, 1e-15);
    CHECK_REL(parse_ok("3 N/m", RB_DIM_STIFFNESS), 3.0, 1e-15);
    CHECK_REL(parse_ok("3 kN/m", RB_DIM_STIFFNESS), 3e3, 1e-15);
    CHECK_REL(parse_ok("3 N/mm", RB_DIM_STIFFNESS), 3e3, 1e-15);
    CHECK_REL(parse_ok("3 kN/mm", RB_DIM_STIFFNESS), 3e6, 1e-15);
    CHECK_REL(parse_ok("1 lbf/in", RB_DIM_STIFFNESS), 175.126835, 1e-8);
    CHECK_REL(parse_ok("1 kip/in", RB_DIM_STIFFNESS), 175126.835, 1e-8);
}

static void test_errors(void)
{
    parse_bad("", RB_DIM_LENGTH, "empty value (expected a length such as '7.8 mm')");
    parse_bad("   ", RB_DIM_MASS, "empty value");
    parse_bad("abc", RB_DIM_LENGTH, "'abc' is not a number");
    parse_bad("mm", RB_DIM_LENGTH, "'mm' is not a number");
    parse_bad("0x10 m", RB_DIM_LENGTH, "unknown unit 'x10 m'");
    parse_bad("nan", RB_DIM_RATIO, "'nan' is not a finite number");
    parse_bad("-inf kg", RB_DIM_MASS, "'-inf kg' is not a finite number");
    parse_bad("Infinity", RB_DIM_RATIO, "not a finite number");
    parse_bad(".nan", RB_DIM_RATIO, "'.nan' is not a finite number");
    parse_bad("-.inf kg", RB_DIM_MASS, "'-.inf kg' is not a finite number");
    parse_bad("1e999 m", RB_DIM_LENGTH, "number '1e999' is out of range");
    parse_bad("1e308 MN", RB_DIM_FORCE, "is out of range");
    parse_bad("7.8", RB_DIM_LENGTH, "missing unit on '7.8' (expected a length: m, mm, cm, in, ft)");
    parse_bad("454", RB_DIM_MASS, "missing unit on '454' (expected a mass: kg, lb)");
    parse_bad("454 kgs", RB_DIM_MASS, "unknown unit 'kgs' (expected a mass: kg, lb)");
    parse_bad("7.8 MM", RB_DIM_LENGTH, "unknown unit 'MM' (did you mean 'mm'?");
    parse_bad("248 MPa", RB_DIM_LENGTH, "'MPa' is a unit of stress, not of length");
    parse_bad("5 mm", RB_DIM_RATIO, "'mm' is a unit of length");
    parse_bad("0.4 A*", RB_DIM_LENGTH, "'A*' is only for floor accelerations");
    parse_bad("1 lb", RB_DIM_FORCE, "'lb' is a unit of mass, not of force");
    parse_bad("7.8 mm thick", RB_DIM_LENGTH, "unexpected text 'thick' after the unit 'mm'");
    parse_bad("1.5.3 m", RB_DIM_LENGTH, "unexpected text '.3 m' after the number");
    parse_bad("82,700 kJ/m^3", RB_DIM_ENERGY_DENSITY, "unexpected text ',700 kJ/m^3'");
    parse_bad("0.01 0.02", RB_DIM_RATIO, "unexpected text '0.02' after the number");
    parse_bad("1/0 in", RB_DIM_LENGTH, "'1/0 in' divides by zero");
    parse_bad("1 1/0 in", RB_DIM_LENGTH, "divides by zero");
    parse_bad("1.5/2 in", RB_DIM_LENGTH, "unexpected text '/2 in' after the number");
    parse_bad("1/ in", RB_DIM_LENGTH, "unexpected text '/ in' after the number");
    parse_bad("1 lbs", RB_DIM_FORCE, "'lbs' is a unit of mass, not of force (a pound of "
              "force is 'lbf'");
    parse_bad("5 kips", RB_DIM_STRESS, "'kips' is a unit of force, not of stress");
    /* a stress stands for an energy per volume, not the other way round */
    parse_bad("5 kJ/m^3", RB_DIM_STRESS, "is a unit of energy per volume, not of stress");
    CHECK(strcmp(rb_dim_str(RB_DIM_STRESS), "a stress") == 0);
    CHECK(strstr(rb_dim_units(RB_DIM_ACCEL), "A*") != NULL);
}

/* What a US schedule writes: plurals, fractions of an inch, a toughness
 * as a stress; each against its value worked by hand. */
static void test_schedule_spellings(void)
{
    CHECK_REL(parse_ok("1200 lbs", RB_DIM_MASS), 1200 * 0.45359237, 1e-15);
    CHECK_REL(parse_ok("12 kips", RB_DIM_FORCE), 12 * 4448.2216152605, 1e-12);
    CHECK_REL(parse_ok("1/2 in", RB_DIM_LENGTH), 0.0127, 1e-15);
    CHECK_REL(parse_ok("3/4in", RB_DIM_LENGTH), 0.01905, 1e-15);
    CHECK_REL(parse_ok("1 1/2 in", RB_DIM_LENGTH), 0.0381, 1e-15);
    CHECK_REL(parse_ok("3-15/16 in", RB_DIM_LENGTH), 3.9375 * 0.0254, 1e-15);
    CHECK_REL(parse_ok("-1/4 in", RB_DIM_LENGTH), -0.00635, 1e-15);
    CHECK_REL(parse_ok("1/2", RB_DIM_RATIO), 0.5, 1e-15);
    CHECK_REL(parse_ok("12000 psi", RB_DIM_ENERGY_DENSITY), 12000 * 6894.757293168361,
              1e-12);
    CHECK_REL(parse_ok("82.7 MPa", RB_DIM_ENERGY_DENSITY), 82.7e6, 1e-15);
    /* "1-1/2" is a mixed number, not 1 minus a half */
    CHECK_REL(parse_ok("1-1/2 in", RB_DIM_LENGTH), 0.0381, 1e-15);
}

/* The formatter of outputs for people: each quantity against its value in
 * the other system worked out here from the definitions (1 lbf = 0.45359237
 * kg x 9.80665 m/s^2, 1 in = 25.4 mm, 1 psi = 1 lbf/in^2). */
static void test_format(void)
{
    double lbf = 0.45359237 * 9.80665, in = 0.0254, psi = lbf / (in * in);
    CHECK(strcmp(rb_qty_str(RB_UNITS_SI, RB_Q_FORCE, 62890, 4).s, "62.89 kN") == 0);
    /* 62.89 kN / 4448.22 N = 14.138 kip */
    CHECK(strcmp(rb_qty_str(RB_UNITS_US, RB_Q_FORCE, 62890, 4).s, "14.14 kip") == 0);
    CHECK_REL(rb_qty_value(RB_UNITS_US, RB_Q_FORCE, 1e3 * lbf), 1.0, 1e-14);
    CHECK(strcmp(rb_qty_str(RB_UNITS_SI, RB_Q_LENGTH, 0.4064, 6).s, "0.4064 m") == 0);
    CHECK(strcmp(rb_qty_str(RB_UNITS_US, RB_Q_LENGTH, 0.4064, 6).s, "16 in") == 0);
    CHECK(strcmp(rb_qty_str(RB_UNITS_SI, RB_Q_SMALL_LENGTH, 7.8e-3, 4).s, "7.8 mm") == 0);
    CHECK(strcmp(rb_qty_str(RB_UNITS_US, RB_Q_SMALL_LENGTH, 1.5 * in, 4).s, "1.5 in") == 0);
    CHECK(strcmp(rb_qty_str(RB_UNITS_US, RB_Q_AREA, 0.142 * in * in, 4).s, "0.142 in^2") == 0);
    CHECK(strcmp(rb_qty_str(RB_UNITS_SI, RB_Q_AREA, 126.7e-6, 4).s, "126.7 mm^2") == 0);
    CHECK(strcmp(rb_qty_str(RB_UNITS_US, RB_Q_STRESS, 36e3 * psi, 4).s, "36 ksi") == 0);
    CHECK(strcmp(rb_qty_str(RB_UNITS_SI, RB_Q_STRESS, 248e6, 4).s, "248 MPa") == 0);
    CHECK(strcmp(rb_qty_str(RB_UNITS_US, RB_Q_MASS, 1200 * 0.45359237, 6).s, "1200 lb") == 0);
    /* accelerations: m/s^2 in SI, g in US customary */
    CHECK(strcmp(rb_qty_str(RB_UNITS_SI, RB_Q_ACCEL, 14.71, 4).s, "14.71 m/s^2") == 0);
    CHECK(strcmp(rb_qty_str(RB_UNITS_US, RB_Q_ACCEL, 1.5 * 9.80665, 4).s, "1.5 g") == 0);
    /* 1 ft-lbf = 0.3048 m x 4.44822 N = 1.35582 J; 1 kip-in = 112.985 N m */
    CHECK_REL(rb_qty_value(RB_UNITS_US, RB_Q_ENERGY, 0.3048 * lbf), 1.0, 1e-14);
    CHECK_REL(rb_qty_value(RB_UNITS_US, RB_Q_MOMENT, 1e3 * lbf * in), 1.0, 1e-14);
    CHECK_REL(rb_qty_value(RB_UNITS_US, RB_Q_ENERGY_DENSITY, 12000 * psi), 12000, 1e-14);
    CHECK_REL(rb_qty_value(RB_UNITS_US, RB_Q_STIFFNESS, 1e3 * lbf / in), 1.0, 1e-14);
    CHECK(strcmp(rb_qty_unit(RB_UNITS_SI, RB_Q_MOMENT), "kN*m") == 0);
    CHECK(strcmp(rb_qty_unit(RB_UNITS_US, RB_Q_MOMENT), "kip-in") == 0);
    /* a neutral system prints SI, as the outputs of a case with no unit */
    CHECK(strcmp(rb_qty_str(RB_UNITS_NEUTRAL, RB_Q_FORCE, 1e3, 4).s, "1 kN") == 0);
    CHECK(strcmp(rb_qty_str(RB_UNITS_US, RB_Q_FORCE, (double)NAN, 4).s, "n/a") == 0);
    rb_qty q;
    CHECK(rb_dim_qty(RB_DIM_STRESS, &q) && q == RB_Q_STRESS);
    CHECK(!rb_dim_qty(RB_DIM_TIME, &q));
    /* the system of a quantity's text */
    CHECK(rb_unit_system_of_text("1/2 in") == RB_UNITS_US);
    CHECK(rb_unit_system_of_text(" 7.8 mm ") == RB_UNITS_SI);
    CHECK(rb_unit_system_of_text("12000 in-lb/in^3") == RB_UNITS_US);
    CHECK(rb_unit_system_of_text("5 Hz") == RB_UNITS_NEUTRAL);
    CHECK(rb_unit_system_of_text("0.4 A*") == RB_UNITS_NEUTRAL);
    CHECK(rb_unit_system_of_text("1200 lb panel") == RB_UNITS_NEUTRAL);
    CHECK(rb_unit_system_of_text("mm") == RB_UNITS_NEUTRAL);
}

int main(void)
{
    test_schedule_spellings();
    test_lengths_masses_forces();
    test_stresses_energies();
    test_accelerations();
    test_other_dimensions();
    test_errors();
    test_format();
    TEST_MAIN_END();
}
