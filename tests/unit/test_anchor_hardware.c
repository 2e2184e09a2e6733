/* The anchor's hardware tables (rockbolt/anchor_hardware.h):
 *   - tensile stress areas against the published tables: UNC coarse from
 *     AISC Steel Construction Manual Table 7-17 / ASME B1.1 (as wermac.org
 *     and trfastenings.com transcribe them), ISO coarse from ISO 898-1's
 *     table of nominal stress areas, each to the rounding of the source;
 *     a fine pitch (UNF) through a given pitch;
 *   - nominal sizes recognised as UNC or ISO, also from an area, and a size
 *     that is neither;
 *   - bearing areas: heavy hex 1/2 in 0.467 in^2 as Hilti PROFIS tabulates
 *     it, regular hex head 1/2 in 0.291 in^2, and more heads worked by hand
 *     here from the widths across flats the standards publish;
 *   - the heavy hex nut's published widths follow B18.2.2's 1.5 d + 1/8 in
 *     for every size in whole eighths. */
#include <math.h>
#include <string.h>
#include "harness.h"
#include "rockbolt/aci17.h"
#include "rockbolt/anchor_hardware.h"

#define IN RB_ACI17_IN_M
#define IN2 (IN * IN)
#define MM 1e-3
#define MM2 (MM * MM)

/* |got - printed| within half a unit of the printed value's last place,
 * given as unit */
#define CHECK_PRINTED(got, printed, unit) \
    CHECK_NEAR((got), (printed), 0.5 * (unit) * (1 + 1e-9))

static double unc_ase_in2(double d_in)
{
    double pitch = 0;
    CHECK(rb_thread_standard(d_in * IN, &pitch) == RB_THREAD_UNC);
    return rb_thread_ase(RB_THREAD_UNC, d_in * IN, pitch) / IN2;
}

static double iso_ase_mm2(double d_mm)
{
    double pitch = 0;
    CHECK(rb_thread_standard(d_mm * MM, &pitch) == RB_THREAD_ISO);
    return rb_thread_ase(RB_THREAD_ISO, d_mm * MM, pitch) / MM2;
}

static void stress_areas_unc(void)
{
    /* AISC Manual Table 7-17 / ASME B1.1, in^2 */
    CHECK_PRINTED(unc_ase_in2(0.5), 0.1419, 1e-4);
    CHECK_PRINTED(unc_ase_in2(0.625), 0.226, 1e-3);
    CHECK_PRINTED(unc_ase_in2(0.75), 0.334, 1e-3);
    CHECK_PRINTED(unc_ase_in2(0.875), 0.462, 1e-3);
    CHECK_PRINTED(unc_ase_in2(1.0), 0.606, 1e-3);
    /* the same table's larger sizes: 1-3/4-5 1.90, 2-4.5 2.50, 4-4 11.08 */
    CHECK_PRINTED(unc_ase_in2(1.75), 1.90, 1e-2);
    CHECK_PRINTED(unc_ase_in2(2.0), 2.50, 1e-2);
    CHECK_PRINTED(unc_ase_in2(4.0), 11.08, 1e-2);
    /* 3/8-16 0.0775 and 7/16-14 0.1063 */
    CHECK_PRINTED(unc_ase_in2(0.375), 0.0775, 1e-4);
    CHECK_PRINTED(unc_ase_in2(0.4375), 0.1063, 1e-4);
}

static void stress_areas_iso(void)
{
    /* ISO 898-1, nominal stress area A_s,nom, mm^2 */
    CHECK_PRINTED(iso_ase_mm2(12), 84.3, 0.1);
    CHECK_PRINTED(iso_ase_mm2(16), 157, 1);
    CHECK_PRINTED(iso_ase_mm2(20), 245, 1);
    CHECK_PRINTED(iso_ase_mm2(24), 353, 1);
    CHECK_PRINTED(iso_ase_mm2(30), 561, 1);
    /* the same table: M8 36.6, M10 58.0, M36 817 */
    CHECK_PRINTED(iso_ase_mm2(8), 36.6, 0.1);
    CHECK_PRINTED(iso_ase_mm2(10), 58.0, 0.1);
    CHECK_PRINTED(iso_ase_mm2(36), 817, 1);
}

static void fine_pitch(void)
{
    /* UNF 1/2-20: 0.1599 in^2 (ASME B1.1 UNF table). The formula gives
     * 0.15995, on the rounding boundary of the printed fourth figure, so
     * one unit of it is allowed. */
    double ase = rb_thread_ase(RB_THREAD_UNC, 0.5 * IN, IN / 20) / IN2;
    CHECK_NEAR(ase, 0.1599, 1e-4);
    /* M20 x 1.5 fine, by hand: (pi/4)(20 - 0.9382 x 1.5)^2
     * = 0.785398 x 18.5927^2 = 271.503 mm^2 */
    CHECK_REL(rb_thread_ase(RB_THREAD_ISO, 20 * MM, 1.5 * MM) / MM2, 271.503, 1e-5);
    /* the coarse 1/2-13 is more than the fine pitch takes away */
    CHECK(ase > unc_ase_in2(0.5));
}

static void sizes(void)
{
    double p = -1;
    /* 1/2 in recovered from its gross area, as the model holds it */
    double a = M_PI / 4 * (0.5 * IN) * (0.5 * IN);
    CHECK(rb_thread_standard(sqrt(4 * a / M_PI), &p) == RB_THREAD_UNC);
    CHECK_REL(p, IN / 13, 1e-12);
    CHECK(rb_thread_standard(12 * MM, &p) == RB_THREAD_ISO);
    CHECK_REL(p, 1.75 * MM, 1e-12);
    CHECK(rb_thread_standard(64 * MM, &p) == RB_THREAD_ISO);
    CHECK_REL(p, 6 * MM, 1e-12);
    /* 13 mm is neither an inch size (1/2 in is 12.7 mm) nor an ISO one */
    CHECK(rb_thread_standard(13 * MM, &p) == RB_THREAD_UNKNOWN);
    CHECK(p == 0);
    CHECK(rb_thread_ase(RB_THREAD_UNKNOWN, 13 * MM, 1.75 * MM) == 0);
    /* the match is to a relative 1e-6 */
    CHECK(rb_thread_standard(0.5 * IN * (1 + 5e-7), NULL) == RB_THREAD_UNC);
    CHECK(rb_thread_standard(0.5 * IN * (1 + 2e-6), NULL) == RB_THREAD_UNKNOWN);
    /* 1-5/8 in has a heavy hex nut but no UNC coarse pitch */
    CHECK(rb_thread_standard(1.625 * IN, &p) == RB_THREAD_UNKNOWN);
    CHECK(rb_thread_standard(0, &p) == RB_THREAD_UNKNOWN);
    CHECK(rb_thread_standard(NAN, &p) == RB_THREAD_UNKNOWN);
    CHECK(rb_thread_standard(-12 * MM, &p) == RB_THREAD_UNKNOWN);
    /* a pitch too coarse for the diameter has no area */
    CHECK(rb_thread_ase(RB_THREAD_ISO, 2 * MM, 3 * MM) == 0);
    CHECK(rb_thread_ase(RB_THREAD_UNC, 0.5 * IN, 0) == 0);
}

static void bearing_areas(void)
{
    const rb_thread_std U = RB_THREAD_UNC, S = RB_THREAD_ISO;
    /* 1/2 in heavy hex, F = 7/8 in: 0.467 in^2 (Hilti PROFIS) */
    CHECK_PRINTED(rb_head_abrg(RB_HEAD_HEAVY_HEX, U, 0.5 * IN, 0) / IN2, 0.467, 1e-3);
    /* 1/2 in hex head, F = 3/4 in: 0.291 in^2 */
    CHECK_PRINTED(rb_head_abrg(RB_HEAD_HEX, U, 0.5 * IN, 0) / IN2, 0.291, 1e-3);
    /* by hand: 3/4 in heavy hex nut, F = 1-1/4 in:
     * 0.866025 x 1.5625 - 0.441786 = 0.911379 in^2 */
    CHECK_REL(rb_head_abrg(RB_HEAD_HEAVY_HEX, U, 0.75 * IN, 0) / IN2, 0.911379, 1e-6);
    /* 1 in hex bolt head, F = 1-1/2 in: 0.866025 x 2.25 - 0.785398 = 1.163159 */
    CHECK_REL(rb_head_abrg(RB_HEAD_HEX, U, 1.0 * IN, 0) / IN2, 1.163159, 1e-6);
    /* 7/16 in heavy hex nut, F = 3/4 in (not 1.5 d + 1/8 = 25/32 in):
     * 0.866025 x 0.5625 - 0.150330 = 0.336809 */
    CHECK_REL(rb_head_abrg(RB_HEAD_HEAVY_HEX, U, 0.4375 * IN, 0) / IN2, 0.336809, 1e-5);
    /* 1/2 in square bolt head, F = 3/4 in: 0.5625 - 0.196350 = 0.366150 */
    CHECK_REL(rb_head_abrg(RB_HEAD_SQUARE, U, 0.5 * IN, 0) / IN2, 0.366150, 1e-5);
    /* 1/2 in heavy square nut, F = 7/8 in assumed: 0.765625 - 0.196350 */
    CHECK_REL(rb_head_abrg(RB_HEAD_HEAVY_SQUARE, U, 0.5 * IN, 0) / IN2, 0.569275, 1e-5);
    /* M20 ISO 4032 nut, s = 30 mm: 0.866025 x 900 - 314.159 = 465.264 mm^2 */
    CHECK_REL(rb_head_abrg(RB_HEAD_HEX, S, 20 * MM, 0) / MM2, 465.264, 1e-5);
    /* M20 EN 14399-4 head, s = 32 mm: 0.866025 x 1024 - 314.159 = 572.651 */
    CHECK_REL(rb_head_abrg(RB_HEAD_HEAVY_HEX, S, 20 * MM, 0) / MM2, 572.651, 1e-5);
    /* a 2 in washer on a 3/4 in rod: (pi/4)(4 - 0.5625) = 2.699806 in^2,
     * whatever the thread */
    CHECK_REL(rb_head_abrg(RB_HEAD_WASHER, U, 0.75 * IN, 2 * IN) / IN2, 2.699806, 1e-6);
    CHECK_REL(rb_head_abrg(RB_HEAD_WASHER, RB_THREAD_UNKNOWN, 0.75 * IN, 2 * IN) / IN2,
              2.699806, 1e-6);
    /* not defined */
    CHECK(rb_head_abrg(RB_HEAD_WASHER, U, 0.75 * IN, 0.75 * IN) == 0);
    CHECK(rb_head_abrg(RB_HEAD_WASHER, U, 0.75 * IN, NAN) == 0);
    CHECK(rb_head_abrg(RB_HEAD_SQUARE, S, 20 * MM, 0) == 0);
    CHECK(rb_head_abrg(RB_HEAD_HEAVY_HEX, RB_THREAD_UNKNOWN, 13 * MM, 0) == 0);
    CHECK(rb_head_abrg(RB_HEAD_HEAVY_HEX, S, 14 * MM, 0) == 0);  /* no HV M14 */
    CHECK(rb_head_abrg(RB_HEAD_HEX, U, 0.5625 * IN, 0) == 0);    /* no 9/16 hex bolt */
}

static void widths(void)
{
    const rb_thread_std U = RB_THREAD_UNC, S = RB_THREAD_ISO;
    /* published rows: ISO 4032 M12 s = 18, M24 36, M64 95 mm; B18.2.1 hex
     * bolt 4 in F = 6 in; B18.2.2 heavy hex nut 1-5/8 in F = 2-9/16 in,
     * 4 in 6-1/8 in */
    CHECK_REL(rb_head_across_flats(RB_HEAD_HEX, S, 12 * MM), 18 * MM, 1e-12);
    CHECK_REL(rb_head_across_flats(RB_HEAD_HEX, S, 24 * MM), 36 * MM, 1e-12);
    CHECK_REL(rb_head_across_flats(RB_HEAD_HEX, S, 64 * MM), 95 * MM, 1e-12);
    CHECK_REL(rb_head_across_flats(RB_HEAD_HEX, U, 4 * IN), 6 * IN, 1e-12);
    CHECK_REL(rb_head_across_flats(RB_HEAD_HEAVY_HEX, U, 1.625 * IN), 2.5625 * IN, 1e-12);
    CHECK_REL(rb_head_across_flats(RB_HEAD_HEAVY_HEX, U, 4 * IN), 6.125 * IN, 1e-12);
    /* EN 14399-3 (HR) bolts as spdfasteners.com prints them, the same s as
     * the EN 14399-4 (HV) rows transcribed: M12 22, M24 41, M36 60 mm */
    CHECK_REL(rb_head_across_flats(RB_HEAD_HEAVY_HEX, S, 12 * MM), 22 * MM, 1e-12);
    CHECK_REL(rb_head_across_flats(RB_HEAD_HEAVY_HEX, S, 24 * MM), 41 * MM, 1e-12);
    CHECK_REL(rb_head_across_flats(RB_HEAD_HEAVY_HEX, S, 36 * MM), 60 * MM, 1e-12);
    CHECK(rb_head_across_flats(RB_HEAD_WASHER, U, 0.5 * IN) == 0);
    /* B18.2.2: heavy hex nut F = 1.5 d + 1/8 in; exact for sizes in whole
     * eighths, every UNC one of which has a nut */
    for (int e = 2; e <= 32; e++) {
        double d = e / 8.0 * IN;
        if (rb_thread_standard(d, NULL) != RB_THREAD_UNC)
            continue;
        CHECK_REL(rb_head_across_flats(RB_HEAD_HEAVY_HEX, U, d), 1.5 * d + IN / 8, 1e-12);
    }
    /* and every regular hex bolt head from 5/8 in up is 1.5 d (B18.2.1) */
    for (int e = 5; e <= 32; e++) {
        double d = e / 8.0 * IN;
        double f = rb_head_across_flats(RB_HEAD_HEX, U, d);
        if (f > 0)
            CHECK_REL(f, 1.5 * d, 1e-12);
    }
}

static void names_and_sources(void)
{
    int v = -1;
    CHECK(rb_enum_parse(rb_anchor_head_names, "heavy-hex", &v) && v == RB_HEAD_HEAVY_HEX);
    CHECK(rb_enum_parse(rb_anchor_head_names, "heavy-square", &v) && v == RB_HEAD_HEAVY_SQUARE);
    CHECK(strcmp(rb_enum_str(rb_anchor_head_names, RB_HEAD_WASHER), "washer") == 0);
    CHECK(strcmp(rb_enum_str(rb_anchor_head_names, RB_HEAD_HEX), "hex") == 0);
    CHECK(!rb_enum_parse(rb_anchor_head_names, "hexagon", &v));
    CHECK(strcmp(rb_head_source(RB_HEAD_HEAVY_HEX, RB_THREAD_UNC),
                 "ASME B18.2.2 heavy hex nut") == 0);
    CHECK(strstr(rb_head_source(RB_HEAD_HEX, RB_THREAD_ISO), "ISO 4032") != NULL);
    CHECK(strcmp(rb_head_source(RB_HEAD_SQUARE, RB_THREAD_ISO), "not tabulated") == 0);
    CHECK(strcmp(rb_head_source(RB_HEAD_HEX, RB_THREAD_UNKNOWN), "not tabulated") == 0);
}

int main(void)
{
    stress_areas_unc();
    stress_areas_iso();
    fine_pitch();
    sizes();
    bearing_areas();
    widths();
    names_and_sources();
    TEST_MAIN_END();
}
