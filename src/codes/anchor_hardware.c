/* Thread and head tables of the anchor's hardware (rockbolt/anchor_hardware.h).
 *
 * Where each table was read (public transcriptions of the standards; the
 * standards themselves were not at hand -- check a value against the
 * primary text before relying on it in a design):
 *   - UNC coarse pitches, ASME B1.1: wermac.org "Thread pitch chart"
 *     (bolts_thread_pitch_chart.html) and trfastenings.com "Unified coarse
 *     (UNC)", which agree on every size 1/4 to 4 in;
 *   - ISO coarse pitches, ISO 261/262: the pitch column of the ISO 4032
 *     transcriptions below;
 *   - ASME B18.2.1 hex bolts, width across flats F (basic = max):
 *     fastenrsc.com "ASME B18.2.1 - Dimensions Charts", 1/4 to 4 in
 *     (no 9/16 in row);
 *   - ASME B18.2.1 square bolts, F: fastener-technology.com "Square
 *     machine bolt", 1/4 to 1-1/2 in;
 *   - ASME B18.2.2 heavy hex nuts, F: smithfast.com "Heavy hex nuts" and
 *     westfieldfasteners.co.uk "UNC heavy hex nuts", 1/4 to 4 in (no
 *     1-7/8 in row). F is 1.5 d + 1/8 in rounded down to 1/16 in: the
 *     sizes in odd sixteenths (5/16, 7/16, 9/16) are 1/32 in narrower
 *     than the formula;
 *   - heavy square nuts, ASME B18.2.2 Table 1.1.1-9: UNCONFIRMED. No public
 *     transcription of the table was found; the widths of the heavy hex
 *     nut are assumed for 1/4 to 1-1/2 in;
 *   - ISO 4032 hex nuts, s: trojansf.co.uk "ISO 4032" and the skippy.org.uk
 *     ISO 4032 chart, M5 to M64 (agreeing with the preferred sizes of BS EN
 *     ISO 4032:2001 Table 1 as engineersedge.com prints it). ISO 4014/4017
 *     hex heads take the same s (mlc.org.uk's ISO 4014/4017 chart agrees
 *     M5 to M30 except M22, which it gives as 32 mm, DIN 931's width:
 *     unconfirmed, the nut's 34 mm is used);
 *   - metric heavy hex, EN 14399-4 (HV) bolt heads, s: bigboltnut.com
 *     "EN 14399-4", and the same widths for EN 14399-3 (HR) bolts on
 *     spdfasteners.com, M12 to M36. ISO 7414 (heavy hex nuts for
 *     structural bolting) was not found; that the HV nut's s equals the
 *     head's is likewise unconfirmed. */
#include <math.h>
#include <stddef.h>
#include "rockbolt/aci17.h"
#include "rockbolt/anchor_hardware.h"

#define IN RB_ACI17_IN_M
#define MM 1e-3
#define SIZE_REL_TOL 1e-6

const rb_enum_name rb_anchor_head_names[] = {
    {"heavy-hex", RB_HEAD_HEAVY_HEX}, {"hex", RB_HEAD_HEX}, {"square", RB_HEAD_SQUARE},
    {"heavy-square", RB_HEAD_HEAVY_SQUARE}, {"washer", RB_HEAD_WASHER}, {NULL, 0}};

/* Inch sizes. Diameters and widths in sixteenths of an inch (every
 * tabulated width is a whole number of them); 0: not tabulated. tpi 0:
 * no UNC coarse pitch for that size. */
static const struct {
    int d;          /* nominal size */
    double tpi;     /* UNC threads per inch */
    int hex;        /* B18.2.1 hex bolt */
    int heavy_hex;  /* B18.2.2 heavy hex nut */
    int square;     /* B18.2.1 square bolt */
    int heavy_sq;   /* heavy square nut (unconfirmed, see above) */
} inch[] = {
    {4, 20, 7, 8, 6, 8},          /* 1/4 */
    {5, 18, 8, 9, 8, 9},          /* 5/16 */
    {6, 16, 9, 11, 9, 11},        /* 3/8 */
    {7, 14, 10, 12, 10, 12},      /* 7/16 */
    {8, 13, 12, 14, 12, 14},      /* 1/2 */
    {9, 12, 0, 15, 0, 15},        /* 9/16 */
    {10, 11, 15, 17, 15, 17},     /* 5/8 */
    {12, 10, 18, 20, 18, 20},     /* 3/4 */
    {14, 9, 21, 23, 21, 23},      /* 7/8 */
    {16, 8, 24, 26, 24, 26},      /* 1 */
    {18, 7, 27, 29, 27, 29},      /* 1-1/8 */
    {20, 7, 30, 32, 30, 32},      /* 1-1/4 */
    {22, 6, 33, 35, 33, 35},      /* 1-3/8 */
    {24, 6, 36, 38, 36, 38},      /* 1-1/2 */
    {26, 0, 39, 41, 0, 0},        /* 1-5/8 */
    {28, 5, 42, 44, 0, 0},        /* 1-3/4 */
    {30, 0, 45, 0, 0, 0},         /* 1-7/8 */
    {32, 4.5, 48, 50, 0, 0},      /* 2 */
    {36, 4.5, 54, 56, 0, 0},      /* 2-1/4 */
    {40, 4, 60, 62, 0, 0},        /* 2-1/2 */
    {44, 4, 66, 68, 0, 0},        /* 2-3/4 */
    {48, 4, 72, 74, 0, 0},        /* 3 */
    {52, 4, 78, 80, 0, 0},        /* 3-1/4 */
    {56, 4, 84, 86, 0, 0},        /* 3-1/2 */
    {60, 4, 90, 92, 0, 0},        /* 3-3/4 */
    {64, 4, 96, 98, 0, 0},        /* 4 */
};

/* Metric sizes, mm; 0: not tabulated. */
static const struct {
    double d, pitch;   /* nominal size, ISO 261/262 coarse pitch */
    double hex;        /* ISO 4032 nut (ISO 4014/4017 head) */
    double heavy_hex;  /* EN 14399-4 (HV) */
} metric[] = {
    {5, 0.8, 8, 0},      {6, 1, 10, 0},       {8, 1.25, 13, 0},    {10, 1.5, 16, 0},
    {12, 1.75, 18, 22},  {14, 2, 21, 0},      {16, 2, 24, 27},     {18, 2.5, 27, 0},
    {20, 2.5, 30, 32},   {22, 2.5, 34, 36},   {24, 3, 36, 41},     {27, 3, 41, 46},
    {30, 3.5, 46, 50},   {33, 3.5, 50, 0},    {36, 4, 55, 60},     {39, 4, 60, 0},
    {42, 4.5, 65, 0},    {45, 4.5, 70, 0},    {48, 5, 75, 0},      {52, 5, 80, 0},
    {56, 5.5, 85, 0},    {60, 5.5, 90, 0},    {64, 6, 95, 0},
};

#define N_INCH (sizeof inch / sizeof inch[0])
#define N_METRIC (sizeof metric / sizeof metric[0])

static int same_size(double d_m, double table_m)
{
    return fabs(d_m - table_m) <= SIZE_REL_TOL * table_m;
}

static int inch_row(double d_m)
{
    for (size_t i = 0; i < N_INCH; i++)
        if (same_size(d_m, inch[i].d / 16.0 * IN))
            return (int)i;
    return -1;
}

static int metric_row(double d_m)
{
    for (size_t i = 0; i < N_METRIC; i++)
        if (same_size(d_m, metric[i].d * MM))
            return (int)i;
    return -1;
}

rb_thread_std rb_thread_standard(double d_m, double *coarse_pitch_m)
{
    double pitch = 0;
    rb_thread_std std = RB_THREAD_UNKNOWN;
    int i = isfinite(d_m) && d_m > 0 ? inch_row(d_m) : -1;
    if (i >= 0 && inch[i].tpi > 0) {
        std = RB_THREAD_UNC;
        pitch = IN / inch[i].tpi;
    } else if (i < 0 && isfinite(d_m) && d_m > 0 && (i = metric_row(d_m)) >= 0) {
        std = RB_THREAD_ISO;
        pitch = metric[i].pitch * MM;
    }
    if (coarse_pitch_m)
        *coarse_pitch_m = pitch;
    return std;
}

double rb_thread_ase(rb_thread_std std, double d_m, double pitch_m)
{
    if (!(isfinite(d_m) && d_m > 0 && isfinite(pitch_m) && pitch_m > 0))
        return 0;
    double mean;   /* the mean of the pitch and minor diameters */
    switch (std) {
    case RB_THREAD_UNC:
        /* ASME B1.1 prints 0.7854, not pi / 4; the published areas are
         * computed with it */
        mean = d_m - 0.9743 * pitch_m;
        return mean > 0 ? 0.7854 * mean * mean : 0;
    case RB_THREAD_ISO:
        mean = d_m - 0.9382 * pitch_m;
        return mean > 0 ? M_PI / 4 * mean * mean : 0;
    case RB_THREAD_UNKNOWN:
        return 0;
    }
    return 0;
}

double rb_head_across_flats(rb_anchor_head head, rb_thread_std std, double d_m)
{
    if (!(isfinite(d_m) && d_m > 0))
        return 0;
    if (std == RB_THREAD_UNC) {
        int i = inch_row(d_m);
        if (i < 0)
            return 0;
        int f = 0;
        switch (head) {
        case RB_HEAD_HEAVY_HEX: f = inch[i].heavy_hex; break;
        case RB_HEAD_HEX: f = inch[i].hex; break;
        case RB_HEAD_SQUARE: f = inch[i].square; break;
        case RB_HEAD_HEAVY_SQUARE: f = inch[i].heavy_sq; break;
        case RB_HEAD_WASHER: f = 0; break;
        }
        return f / 16.0 * IN;
    }
    if (std == RB_THREAD_ISO) {
        int i = metric_row(d_m);
        if (i < 0)
            return 0;
        switch (head) {
        case RB_HEAD_HEAVY_HEX: return metric[i].heavy_hex * MM;
        case RB_HEAD_HEX: return metric[i].hex * MM;
        case RB_HEAD_SQUARE:
        case RB_HEAD_HEAVY_SQUARE:
        case RB_HEAD_WASHER: return 0;
        }
    }
    return 0;
}

double rb_head_abrg(rb_anchor_head head, rb_thread_std std, double d_m,
                    double washer_d_m)
{
    if (!(isfinite(d_m) && d_m > 0))
        return 0;
    double rod = M_PI / 4 * d_m * d_m;
    if (head == RB_HEAD_WASHER) {
        if (!(isfinite(washer_d_m) && washer_d_m > d_m))
            return 0;
        return M_PI / 4 * washer_d_m * washer_d_m - rod;
    }
    double f = rb_head_across_flats(head, std, d_m);
    if (!(f > 0))
        return 0;
    switch (head) {
    case RB_HEAD_HEAVY_HEX:
    case RB_HEAD_HEX:
        return sqrt(3.0) / 2 * f * f - rod;
    case RB_HEAD_SQUARE:
    case RB_HEAD_HEAVY_SQUARE:
        return f * f - rod;
    case RB_HEAD_WASHER:
        break;
    }
    return 0;
}

const char *rb_head_source(rb_anchor_head head, rb_thread_std std)
{
    if (head == RB_HEAD_WASHER)
        return "washer outside diameter";
    if (std == RB_THREAD_UNC) {
        switch (head) {
        case RB_HEAD_HEAVY_HEX: return "ASME B18.2.2 heavy hex nut";
        case RB_HEAD_HEX: return "ASME B18.2.1 hex bolt head";
        case RB_HEAD_SQUARE: return "ASME B18.2.1 square bolt head";
        case RB_HEAD_HEAVY_SQUARE: return "ASME B18.2.2 heavy square nut (unconfirmed)";
        case RB_HEAD_WASHER: break;
        }
    } else if (std == RB_THREAD_ISO) {
        switch (head) {
        case RB_HEAD_HEAVY_HEX: return "EN 14399-4 (HV) hex head";
        case RB_HEAD_HEX: return "ISO 4032 hex nut";
        case RB_HEAD_SQUARE:
        case RB_HEAD_HEAVY_SQUARE:
        case RB_HEAD_WASHER: break;
        }
    }
    return "not tabulated";
}
