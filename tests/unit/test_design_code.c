/* Code-static comparison against hand-computed examples: ASCE 7-16 and
 * 7-22 component forces with the bounds inactive, at the maximum and at the
 * minimum; the row tension; the ACI 318-19 futa limits. The reference
 * cabinet: W = 454 kg x 9.80665 = 4452.2191 N, h = 0.979 m, b = 0.45 m,
 * l = 0.78 m, two bolts of 126.7 mm^2 per row, fya = 248 MPa. */
#include <math.h>
#include <string.h>
#include "harness.h"
#include "rockbolt/design.h"

#define W_REF 4452.2191

static void asce7_16_inactive(void)
{
    rb_model m;
    rb_code_inputs in;
    rb_code_result r;
    rb_model_reference(&m);
    rb_code_inputs_init(&in);
    in.edition = RB_ASCE7_16;
    in.sds = 1.0, in.ap = 2.5, in.rp = 6.0, in.z_over_h = 0.5, in.futa_pa = 400e6;
    CHECK(rb_code_static(&m, &in, &r, NULL) == RB_OK);
    /* Fp = 0.4 x 2.5 x 1.0 x W (1 + 2 x 0.5) / (6 / 1) = W / 3 */
    CHECK_REL(r.fp_n, W_REF / 3, 1e-9);
    CHECK(r.bound == 0 && r.fp_formula_n == r.fp_n);
    CHECK_REL(r.fp_max_n, 1.6 * W_REF, 1e-9);
    CHECK_REL(r.fp_min_n, 0.3 * W_REF, 1e-9);
    CHECK_REL(r.fp_anchor_n, 2 * W_REF / 3, 1e-9);
    /* T = (2 W/3 x 0.979 - 0.7 W x 0.45) / 0.78 = 1927.392 N */
    CHECK_REL(r.tension_n, 1927.3923, 1e-7);
    /* futa = 400 MPa < 1.9 x 248 = 471.2 MPa; phi Nsa = 0.75 x 2 x 126.7e-6 x 400e6 */
    CHECK_REL(r.futa_used_pa, 400e6, 1e-12);
    CHECK_REL(r.phi_nsa_n, 76020.0, 1e-12);
    CHECK_REL(r.ratio, 1927.3923 / 76020.0, 1e-7);
    CHECK_REL(r.fp_over_wp, 1.0 / 3, 1e-12);
    CHECK_REL(r.accel_mps2, 9.80665 / 3, 1e-12);
    /* A* = (2 x 126.7e-6 x 248e6 x 0.78 + W x 0.45) / (454 x 0.979) = 114.7921 */
    CHECK_REL(r.accel_astar, 0.0284765481, 1e-8);
}

static void asce7_16_bounds(void)
{
    rb_model m;
    rb_code_inputs in;
    rb_code_result r;
    rb_model_reference(&m);
    rb_code_inputs_init(&in);
    in.edition = RB_ASCE7_16;
    /* formula 0.4 x 2.5 x 1.2 x 3 / (1.5 / 1.5) = 3.6 W > 1.6 x 1.2 x 1.5 = 2.88 W */
    in.sds = 1.2, in.ip = 1.5, in.ap = 2.5, in.rp = 1.5, in.z_over_h = 1.0;
    in.omega0p = 2.5, in.futa_pa = 900e6;
    CHECK(rb_code_static(&m, &in, &r, NULL) == RB_OK);
    CHECK_REL(r.fp_formula_n, 3.6 * W_REF, 1e-9);
    CHECK(r.bound == 1);
    CHECK_REL(r.fp_n, 2.88 * W_REF, 1e-9);
    /* T = (2.5 x 2.88 W x 0.979 - (0.9 - 0.24) W x 0.45) / 0.78 = 38539.09 N */
    CHECK_REL(r.tension_n, 38539.0935, 1e-7);
    /* futa limited to 1.9 fya = 471.2 MPa: phi Nsa = 89551.56 N */
    CHECK_REL(r.futa_used_pa, 471.2e6, 1e-12);
    CHECK_REL(r.phi_nsa_n, 89551.56, 1e-9);
    /* formula 0.4 x 1 x 0.5 x 1 / 12 = 0.01667 W < 0.3 x 0.5 = 0.15 W; no uplift:
     * T = (0.15 W x 0.979 - 0.8 W x 0.45) / 0.78 < 0 */
    in.sds = 0.5, in.ip = 1.0, in.ap = 1.0, in.rp = 12.0, in.z_over_h = 0.0;
    in.anchorage_in_concrete = 0;
    CHECK(rb_code_static(&m, &in, &r, NULL) == RB_OK);
    CHECK(r.bound == -1);
    CHECK_REL(r.fp_formula_n, W_REF / 60, 1e-9);
    CHECK_REL(r.fp_n, 0.15 * W_REF, 1e-9);
    CHECK_REL(r.fp_anchor_n, r.fp_n, 1e-15);
    CHECK_REL(r.tension_raw_n, -1216.65449, 1e-7);
    CHECK(r.tension_n == 0 && r.ratio == 0);
    /* 125 ksi governs for a high-strength anchor: min(1.9 x 640, 861.8) MPa */
    m.yield_stress_pa = 640e6;
    in.futa_pa = 1000e6;
    CHECK(rb_code_static(&m, &in, &r, NULL) == RB_OK);
    CHECK_REL(r.futa_used_pa, 861.8e6, 1e-12);
}

static void asce7_22(void)
{
    rb_model m;
    rb_code_inputs in;
    rb_code_result r;
    rb_model_reference(&m);
    rb_code_inputs_init(&in);
    in.sds = 1.0, in.ip = 1.5, in.z_over_h = 0.5, in.ta_s = 0.5;
    in.r = 8, in.ie = 1, in.omega0 = 3, in.car = 1.0, in.rpo = 1.5, in.omega0p = 1.5;
    in.futa_pa = 400e6;
    CHECK(rb_code_static(&m, &in, &r, NULL) == RB_OK);
    /* Hf = 1 + min(2, 2.5) 0.5 + (1 - 0.8^2) 0.5^10 = 2.0003515625;
     * Rmu = max(1.3, sqrt(8.8 / 3)) = 1.712697677 */
    CHECK_REL(r.hf, 2.0003515625, 1e-12);
    CHECK_REL(r.rmu, 1.7126976772, 1e-9);
    /* Fp = 0.4 x 1 x 1.5 W (Hf / Rmu)(1 / 1.5) = 0.46718147 W > 0.45 W */
    CHECK(r.bound == 0);
    CHECK_REL(r.fp_over_wp, 0.4671814738, 1e-9);
    CHECK_REL(r.tension_n, 2117.97767, 1e-7);
    /* Ta unknown: Hf = 1 + 2.5 z/h; formula 0.4 x 1.5 x (3.5 / 1.3)(2.8 / 1.5)
     * = 3.0154 W > 1.6 x 1.5 = 2.4 W; Rmu = max(1.3, sqrt(1.1)) */
    in.sds = 1.5, in.ip = 1.0, in.z_over_h = 1.0, in.ta_s = 0;
    in.r = 3, in.omega0 = 3, in.car = 2.8;
    CHECK(rb_code_static(&m, &in, &r, NULL) == RB_OK);
    CHECK_REL(r.hf, 3.5, 1e-12);
    CHECK_REL(r.rmu, 1.3, 1e-12);
    CHECK_REL(r.fp_formula_n, 3.0153846154 * W_REF, 1e-9);
    CHECK(r.bound == 1);
    CHECK_REL(r.fp_n, 2.4 * W_REF, 1e-9);
    /* at grade: Hf = Rmu = 1 whatever R, Ta; 0.4 / 2.5 = 0.16 W < 0.3 W */
    in.sds = 1.0, in.at_or_below_grade = 1, in.z_over_h = 0.0, in.ta_s = 0.5;
    in.car = 1.0, in.rpo = 2.5, in.r = 0, in.anchorage_in_concrete = 0;
    CHECK(rb_code_static(&m, &in, &r, NULL) == RB_OK);
    CHECK(r.hf == 1.0 && r.rmu == 1.0 && r.bound == -1);
    CHECK_REL(r.fp_formula_n, 0.16 * W_REF, 1e-9);
    CHECK_REL(r.tension_raw_n, -121.579829, 1e-6);
}

static void invalid_inputs(void)
{
    rb_model m;
    rb_code_inputs in;
    rb_code_result r;
    rb_diag diag;
    rb_model_reference(&m);
    rb_code_inputs_init(&in);
    in.sds = 1.0, in.car = 1.0, in.rpo = 1.5, in.futa_pa = 400e6;
    CHECK(rb_code_static(&m, &in, &r, &diag) == RB_ERR_INVALID); /* no R, Ie, Omega0 */
    CHECK(strcmp(diag.key, "r, ie, omega0") == 0);
    in.r = 8, in.ie = 1, in.omega0 = 3;
    CHECK(rb_code_static(&m, &in, &r, &diag) == RB_OK);
    in.z_over_h = 1.5;
    CHECK(rb_code_static(&m, &in, &r, &diag) == RB_ERR_INVALID);
    CHECK(strcmp(diag.key, "z_over_h") == 0);
    in.z_over_h = 0.5, in.futa_pa = 0;
    CHECK(rb_code_static(&m, &in, &r, &diag) == RB_ERR_INVALID);
    CHECK(strcmp(diag.key, "futa") == 0);
    in.futa_pa = 400e6, in.edition = (rb_code_edition)10;
    CHECK(rb_code_static(&m, &in, &r, &diag) == RB_ERR_INVALID);
}

int main(void)
{
    asce7_16_inactive();
    asce7_16_bounds();
    asce7_22();
    invalid_inputs();
    TEST_MAIN_END();
}
