/* The anchor's hardware: the thread standard a nominal diameter belongs
 * to, the tensile stress area A_se of its thread (ACI 318-19 17.6.1.2,
 * 17.7.1.2 take A_se,N and A_se,V from it), and the width across flats and
 * bearing area A_brg of the head or nut that bears on the concrete
 * (17.6.3.2.2 pullout, 17.6.4.1 side-face blowout). Tables transcribed
 * from the dimensional standards; docs/anchor-hardware.md lists them and
 * their sources. No I/O, no allocation, no state.
 *
 * Units: SI in and out -- diameters, pitches and widths in m, areas in m^2
 * (as rockbolt/aci17.h). A nominal size is matched to a table to a
 * relative 1e-6, so that a diameter recovered from an area,
 * sqrt(4 A / pi), still finds its row. */
#ifndef ROCKBOLT_ANCHOR_HARDWARE_H
#define ROCKBOLT_ANCHOR_HARDWARE_H

#include "rockbolt/names.h"

typedef enum {
    RB_THREAD_UNKNOWN = 0, /* no standard size */
    RB_THREAD_UNC,         /* Unified inch (ASME B1.1); coarse pitch UNC */
    RB_THREAD_ISO          /* ISO metric (ISO 261/262); coarse pitch */
} rb_thread_std;

/* The thread standard whose nominal size d_m is: UNC coarse inch sizes
 * 1/4 to 4 in (1-5/8 and 1-7/8 in have no UNC pitch and are not
 * included), ISO coarse metric M5 to M64 (first and second choice sizes).
 * *coarse_pitch_m (may be NULL) is set to the coarse pitch (UNC: 1/n in,
 * n threads per inch), or 0 with RB_THREAD_UNKNOWN when d_m is no
 * standard size. */
rb_thread_std rb_thread_standard(double d_m, double *coarse_pitch_m);

/* Tensile stress area of a thread of nominal diameter d_m and pitch
 * pitch_m (any pitch: coarse, fine or a constant-pitch series):
 *   RB_THREAD_UNC  ASME B1.1: 0.7854 (d - 0.9743 / n)^2, n = 1 / pitch
 *                  (the formula is the same in any length unit);
 *   RB_THREAD_ISO  ISO 898-1: (pi / 4) (d - 0.9382 P)^2.
 * 0 for RB_THREAD_UNKNOWN, a non-positive or non-finite d_m or pitch_m,
 * or a pitch too coarse for the diameter. */
double rb_thread_ase(rb_thread_std std, double d_m, double pitch_m);

/* The head or nut that bears on the concrete at the anchor's embedded
 * end. A headed bolt bears with its head, a rod with a nut on it. */
typedef enum {
    RB_HEAD_HEAVY_HEX = 0,  /* inch: ASME B18.2.2 heavy hex nut (the nut an
                               ASTM F1554 rod takes, ASTM A563); metric:
                               EN 14399-4 (HV) head and nut */
    RB_HEAD_HEX,            /* inch: ASME B18.2.1 hex bolt head; metric:
                               ISO 4032 hex nut (ISO 4014/4017 head) */
    RB_HEAD_SQUARE,         /* inch: ASME B18.2.1 square bolt head */
    RB_HEAD_HEAVY_SQUARE,   /* inch: heavy square nut, ASME B18.2.2 */
    RB_HEAD_WASHER          /* a round washer or plate of a given outside
                               diameter bearing on the concrete */
} rb_anchor_head;

/* "heavy-hex", "hex", "square", "heavy-square", "washer" */
extern const rb_enum_name rb_anchor_head_names[];

/* Width across flats of a head or nut of kind head for the standard size
 * d_m of std (RB_THREAD_UNC: any inch size the table holds, coarse
 * pitch or not). 0 when the table has no such size, for
 * RB_THREAD_UNKNOWN, and for RB_HEAD_WASHER. */
double rb_head_across_flats(rb_anchor_head head, rb_thread_std std, double d_m);

/* Bearing area A_brg of the head, net of the anchor's gross section
 * pi d^2 / 4:
 *   hex kinds     (sqrt(3) / 2) F^2 - pi d^2 / 4, F across flats;
 *   square kinds  F^2 - pi d^2 / 4;
 *   washer        (pi / 4) (D^2 - d^2), D = washer_d_m its outside
 *                 diameter (std is not used).
 * washer_d_m is read only for RB_HEAD_WASHER. 0 when not defined: a size
 * the table lacks, a washer not wider than the anchor, a non-positive or
 * non-finite d_m. */
double rb_head_abrg(rb_anchor_head head, rb_thread_std std, double d_m,
                    double washer_d_m);

/* The source of the dimensions rb_head_across_flats uses for head and std
 * ("ASME B18.2.2 heavy hex nut", ...), for reports; "not tabulated" where
 * there is no table. Never NULL; static storage. */
const char *rb_head_source(rb_anchor_head head, rb_thread_std std);

#endif
