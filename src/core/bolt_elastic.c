/* Elastic-plastic rows (sec. 5.7): a stiff spring of stiffness k_row from
 * the moment the chord takes up the gap, yielding at Fy. The plate keeps
 * rocking in stage 4 against the spring's tension. */
#include <math.h>
#include "bolt.h"

static double stretch(const rb_sys *S, const rb_disc *D, double th)
{
    return rb_dyn_chord(S, th) - D->gap[rb_row_of_side(D->side)];
}

static double tension(const rb_sys *S, const rb_disc *D, double th)
{
    double ext = stretch(S, D, th);
    return ext > 0 ? S->d.k_row_npm * ext : 0;
}

static double stored(const rb_sys *S, const rb_disc *D, double th)
{
    /* while the row yields its elastic stretch stays at Fy / k; the rest
     * of the chord's growth is plastic, booked as absorbed energy */
    double ext = D->stage == RB_STAGE_YIELD ? S->d.fy_row_n / S->d.k_row_npm
                                            : stretch(S, D, th);
    return ext > 0 ? 0.5 * S->d.k_row_npm * ext * ext : 0;
}

static double yield_stretch(const rb_sys *S)
{
    return S->d.fy_row_n / S->d.k_row_npm;
}

static double spring_npm(const rb_sys *S)
{
    return S->d.k_row_npm;
}

/* the rows on the body's rotational inertia about the pivot */
static double frequency_hz(const rb_sys *S)
{
    return sqrt(S->d.k_row_npm * S->l * S->l / S->d.Io) / (2 * M_PI);
}

const rb_bolt_ops rb_bolt_elastic_plastic = {
    .rows = 1, .yields = 1, .rigid_stop = 0,
    .tension = tension, .stored = stored,
    .yield_stretch = yield_stretch, .frequency_hz = frequency_hz,
    .spring_npm = spring_npm,
};
