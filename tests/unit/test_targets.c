/* Target spectra at hand-computed frequencies, against the published
 * formulas written out here (CODES.md; docs/motion.md "Target spectra"). */
#include <math.h>
#include <stdlib.h>
#include "harness.h"
#include "rockbolt/spectrum.h"

#define G 9.80665

/* IEEE 693-2005 High at 5 %, in g, as printed (Figure A.1), with beta
 * written out: beta = (3.21 - 0.68 ln(100 xi)) / 2.1156 */
static double ieee_high(double f, double xi)
{
    double b = (3.21 - 0.68 * log(100 * xi)) / 2.1156;
    if (f <= 1.1)
        return 2.288 * b * f;
    if (f <= 8)
        return 2.5 * b;
    if (f <= 33)
        return (26.4 * b - 10.56) / f - 0.8 * b + 1.32;
    return 1.0;
}

static void check_ieee693(void)
{
    rb_target h, m, v, h2;
    rb_target_ieee693(&h, RB_IEEE693_HIGH, 0.05, 0);
    rb_target_ieee693(&m, RB_IEEE693_MODERATE, 0.05, 0);
    rb_target_ieee693(&v, RB_IEEE693_HIGH, 0.05, 1);
    rb_target_ieee693(&h2, RB_IEEE693_HIGH, 0.02, 0);
    /* beta is 1 at 5 % (3.21 - 0.68 ln 5 = 2.1156) and 1.294507 at 2 % */
    CHECK_NEAR(rb_ieee693_beta(0.05), 1.0, 2e-5);
    CHECK_NEAR(rb_ieee693_beta(0.02), 1.294507, 1e-6);
    /* by hand, High at 5 %: 0.5 Hz 1.144 g; 1.1 Hz 2.5168 g; the plateau
     * 2.5 g; 16 Hz 15.84 / 16 + 0.52 = 1.51 g; 33 Hz 1.0 g; above 1.0 g */
    static const double f[] = {0.2, 0.5, 1.1, 1.2, 5.0, 8.0, 16.0, 25.0, 33.0, 40.0};
    static const double hand[] = {0.4576, 1.144, 2.5168, 2.5, 2.5, 2.5, 1.51,
                                  1.1536, 1.0, 1.0};
    for (size_t i = 0; i < sizeof f / sizeof *f; i++) {
        double want = ieee_high(f[i], 0.05) * G;
        CHECK_NEAR(rb_target_at(&h, f[i]), want, 1e-12 * want);
        CHECK_NEAR(rb_target_at(&h, f[i]) / G, hand[i], 2e-4 * hand[i]);
        CHECK_NEAR(rb_target_at(&m, f[i]), 0.5 * want, 1e-12 * want);
        CHECK_NEAR(rb_target_at(&v, f[i]), 0.8 * want, 1e-12 * want);
        double w2 = ieee_high(f[i], 0.02) * G;
        CHECK_NEAR(rb_target_at(&h2, f[i]), w2, 1e-12 * w2);
    }
    /* at 2 %, by hand: plateau 2.5 x 1.294507 = 3.23627 g, 16 Hz
     * (26.4 b - 10.56) / 16 - 0.8 b + 1.32 = 1.76033 g; the ZPA stays 1 g */
    CHECK_NEAR(rb_target_at(&h2, 4.0) / G, 3.23627, 1e-5);
    CHECK_NEAR(rb_target_at(&h2, 16.0) / G, 1.76033, 1e-5);
    CHECK_NEAR(rb_target_at(&h2, 33.0) / G, 1.0, 1e-12);
    /* continuous at 8 and 33 Hz for any damping */
    CHECK_NEAR(rb_target_at(&h2, 8.0 * (1 + 1e-12)), rb_target_at(&h2, 8.0), 1e-9);
    CHECK_NEAR(rb_target_at(&h2, 33.0 * (1 + 1e-12)), rb_target_at(&h2, 33.0), 1e-9);
    CHECK_NEAR(h.check_from_hz, 1.1, 0);
    CHECK_NEAR(h.check_to_hz, 33.0, 0);
    CHECK_NEAR(h.min_peak_mps2, 0.9 * G, 1e-12);
    CHECK_NEAR(m.min_peak_mps2, 0.45 * G, 1e-12);
    CHECK_NEAR(v.min_peak_mps2, 0.72 * G, 1e-12);
    CHECK(h2.damping == 0.02);
}

/* ASCE 7-22 13.3.1: H_f and R_mu written out (CODES.md) */
static double hf(double zh, double ta)
{
    if (ta <= 0)
        return 1 + 2.5 * zh;
    double a1 = 1 / ta < 2.5 ? 1 / ta : 2.5;
    double a2 = 1 - (0.4 / ta) * (0.4 / ta);
    return 1 + a1 * zh + (a2 > 0 ? a2 : 0) * pow(zh, 10);
}

static void check_ac156_2024(void)
{
    rb_target t;
    double flx, rig;
    /* the laboratory's published AC156-24 test (CODES.md): S_DS 2.0 g at
     * z/h 1 gave A_FLX-H 3.20 g and A_RIG-H 2.15 g (to 0.01 g) */
    rb_ac156_levels(RB_AC156_2024, 2.0 * G, 1.0, &flx, &rig);
    CHECK_NEAR(flx / G, 3.20, 0.005);
    CHECK_NEAR(rig / G, 2.15, 0.005);
    /* by hand: T_a 0.5 s, z/h 0.5: a1 = 2, a2 = 0.36, H_f = 2 + 0.36 / 1024
     * = 2.000352; R 8, I_e 1, Omega_0 3: R_mu = sqrt(8.8 / 3) = 1.712698;
     * A_FLX = 1.167954 S_DS, A_RIG = 0.467181 S_DS */
    rb_ac156_building b = {0.5, 8, 1, 3};
    CHECK_NEAR(rb_asce722_hf(0.5, 0.5, 0), 2.000352, 1e-6);
    CHECK_NEAR(rb_asce722_rmu(8, 1, 3, 0), 1.712698, 1e-6);
    rb_target_ac156(&t, RB_AC156_2024, G, 0.5);
    rb_target_ac156_more(&t, &b, 0, 0);
    rb_target_ac156_levels(&t, &flx, &rig);
    CHECK_NEAR(flx / G, 1.167954, 1e-6);
    CHECK_NEAR(rig / G, 0.467181, 1e-6);
    CHECK_NEAR(t.min_peak_mps2, 0.9 * rig, 1e-12);
    CHECK_NEAR(rb_target_at(&t, 5.0), flx, 1e-12);
    CHECK_NEAR(rb_target_at(&t, 40.0), rig, 1e-12);
    /* T_a 1 s on the roof: a1 = 1, a2 = 0.84, H_f = 2.84; R 6, I_e 1.5,
     * Omega_0 2.5: R_mu = sqrt(6.6 / 3.75) = 1.326650; A_FLX capped at
     * 1.6 S_DS, A_RIG = 0.4 x 2.84 / 1.326650 = 0.856292 S_DS */
    rb_ac156_building b2 = {1.0, 6, 1.5, 2.5};
    rb_target_ac156(&t, RB_AC156_2024, G, 1.0);
    rb_target_ac156_more(&t, &b2, 0, 0);
    rb_target_ac156_levels(&t, &flx, &rig);
    CHECK_NEAR(flx / G, 1.6, 1e-12);
    CHECK_NEAR(rig / G, 0.856292, 1e-6);
    /* R_mu's floor 1.3, and at grade H_f = R_mu = 1 */
    CHECK_NEAR(rb_asce722_rmu(1, 1, 3, 0), 1.3, 0);
    CHECK_NEAR(rb_asce722_rmu(0, 0, 0, 0), 1.3, 0);
    CHECK_NEAR(rb_asce722_rmu(8, 1, 3, 1), 1.0, 0);
    CHECK_NEAR(rb_asce722_hf(0.7, 0.5, 1), 1.0, 0);
    rb_target_ac156(&t, RB_AC156_2024, G, 0.0);
    rb_target_ac156_more(&t, &b, 0, 0);
    rb_target_ac156_levels(&t, &flx, &rig);
    CHECK_NEAR(flx / G, 1.0, 1e-12);
    CHECK_NEAR(rig / G, 0.4, 1e-12);
    /* H_f over random cases against the formula written here */
    for (int i = 0; i < 1000; i++) {
        double zh = (i % 101) / 100.0, ta = 0.05 + (i * 37 % 400) / 100.0;
        CHECK_NEAR(rb_asce722_hf(zh, ta, 0), hf(zh, ta), 1e-12);
        CHECK_NEAR(rb_asce722_hf(zh, 0, 0), hf(zh, 0), 1e-12);
    }
    /* the two-level envelope: roof S_DS 1.0 g (2024: A_FLX 1.6, A_RIG
     * 0.4 x 3.5 / 1.3 = 1.076923 g) with grade S_DS 2.0 g (A_FLX 2.0,
     * A_RIG 0.8 g): A_FLX 2.0 g and A_RIG 1.076923 g, the least peak
     * 0.9 of that; the 2010 form: roof 1.6 / 1.2, grade 2.0 / 0.8 */
    rb_target_ac156(&t, RB_AC156_2024, G, 1.0);
    rb_target_ac156_more(&t, NULL, 2.0 * G, 0.0);
    rb_target_ac156_levels(&t, &flx, &rig);
    CHECK_NEAR(flx / G, 2.0, 1e-12);
    CHECK_NEAR(rig / G, 1.076923, 1e-6);
    CHECK_NEAR(t.min_peak_mps2 / G, 0.9 * 1.076923, 1e-6);
    rb_target_ac156(&t, RB_AC156_2010, G, 1.0);
    rb_target_ac156_more(&t, NULL, 2.0 * G, 0.0);
    rb_target_ac156_levels(&t, &flx, &rig);
    CHECK_NEAR(flx / G, 2.0, 1e-12);
    CHECK_NEAR(rig / G, 1.2, 1e-12);
}

/* a table: log-log between its points, constant above its last, and
 * below its first in proportion to f (the taper); its own tolerance */
static void check_table(void)
{
    double *f = malloc(3 * sizeof *f), *a = malloc(3 * sizeof *a);
    f[0] = 2.0, f[1] = 8.0, f[2] = 32.0;
    a[0] = 1.0 * G, a[1] = 2.0 * G, a[2] = 0.5 * G;
    rb_target t;
    rb_target_table(&t, f, a, 3, 0.05);
    CHECK_NEAR(t.band_lower, 0.9, 0);
    CHECK_NEAR(t.band_upper, 1.3, 0);
    /* by hand: 4 Hz is half way (in log f) from 2 to 8 Hz: sqrt(1 x 2) g */
    CHECK_NEAR(rb_target_at(&t, 4.0) / G, sqrt(2.0), 1e-12);
    CHECK_NEAR(rb_target_at(&t, 16.0) / G, 1.0, 1e-12);
    CHECK_NEAR(rb_target_at(&t, 50.0) / G, 0.5, 1e-12);
    /* the taper: 1 Hz is half the first frequency, 0.5 g; 0.2 Hz 0.1 g */
    CHECK_NEAR(rb_target_at(&t, 1.0) / G, 0.5, 1e-12);
    CHECK_NEAR(rb_target_at(&t, 0.2) / G, 0.1, 1e-12);
    CHECK_NEAR(rb_target_at(&t, 2.0) / G, 1.0, 1e-12);
    rb_target_tolerance(&t, 0.95, 1.4);
    CHECK_NEAR(t.band_lower, 0.95, 0);
    CHECK_NEAR(t.band_upper, 1.4, 0);
    rb_target_free(&t);
}

int main(void)
{
    check_table();
    check_ieee693();
    check_ac156_2024();
    TEST_MAIN_END();
}
