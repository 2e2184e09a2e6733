/* How a case judges its motions against their targets (the laboratory's
 * acceptance, rockbolt/accept.h): a motion's `low_cutoff` and `max_ratio`,
 * and the `spectrum:` a record, harmonic or pulse is judged against
 * (docs/case-format.md, "Acceptance"). The rules themselves are
 * rb_accept_rules_init's; these keys only move the low cutoff and set the
 * upper limit the laboratories otherwise draw as a guide. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "case_internal.h"
#include "rockbolt/accept.h"

/* A low cutoff from the 1/72-octave grid's origin to the spectra's top of
 * practice; the target's high cutoff bounds it further once known. */
#define LOW_CUTOFF_MIN_HZ 0.1
#define LOW_CUTOFF_MAX_HZ 100.0
/* A max_ratio under 1 would fail a TRS equal to its RRS. */
#define MAX_RATIO_MIN 1.0
#define MAX_RATIO_MAX 10.0

static int read_low_cutoff(rb_cctx *c, rb_ynode *map, rb_cmotion *cm)
{
    char k[RB_CASE_KEY_MAX], msg[300];
    rb_ynode *v = rb_cv_get(c, map, cm->key, "low_cutoff", 0, "");
    if (!v)
        return 1;
    rb_case_keypath(k, cm->key, "low_cutoff");
    cm->low_cutoff_node = v;
    if (v->kind == RB_YNODE_SCALAR && strcmp(v->text, "auto") == 0) {
        cm->low_cutoff_auto = 1;
        return 1;
    }
    rb_quantity q;
    if (v->kind != RB_YNODE_SCALAR || rb_ynode_is_null(v)) {
        rb_cctx_error(c, v, k, "expected a frequency such as '2 Hz', or auto (the "
                      "laboratory's rule from equipment.frequency), found %s",
                      rb_ynode_kind_str(v));
        return 0;
    }
    if (rb_unit_parse(v->text, RB_DIM_FREQUENCY, &q, msg, sizeof msg) != RB_OK) {
        rb_cctx_error(c, v, k, "expected a frequency such as '2 Hz', or auto: %s", msg);
        return 0;
    }
    if (!(q.value >= LOW_CUTOFF_MIN_HZ && q.value <= LOW_CUTOFF_MAX_HZ)) {
        rb_cctx_error(c, v, k, "must be >= %g Hz and <= %g Hz, or auto (got '%s')",
                      LOW_CUTOFF_MIN_HZ, LOW_CUTOFF_MAX_HZ, v->text);
        return 0;
    }
    cm->low_cutoff_hz = q.value;
    return 1;
}

int rb_case_read_accept(rb_cctx *c, rb_ynode *map, rb_cmotion *cm)
{
    int ok = read_low_cutoff(c, map, cm);
    if (rb_ymap_find(map, "max_ratio")) {
        cm->max_ratio_node = rb_cv_number(c, map, cm->key, "max_ratio", 0, RB_DIM_RATIO,
                                          MAX_RATIO_MIN, 1, MAX_RATIO_MAX, 1,
                                          &cm->max_ratio);
        ok &= cm->max_ratio_node != NULL;
    }
    if (!cm->synthetic && (cm->low_cutoff_node || cm->max_ratio_node)
        && !rb_ymap_find(map, "spectrum")) {
        const rb_ynode *v = cm->low_cutoff_node ? cm->low_cutoff_node : cm->max_ratio_node;
        char k[RB_CASE_KEY_MAX];
        rb_case_keypath(k, cm->key, cm->low_cutoff_node ? "low_cutoff" : "max_ratio");
        rb_cctx_error(c, v, k, "the acceptance needs a target: give the motion a "
                      "'spectrum' (ac156, ieee693, table or gr63) to judge it against");
        ok = 0;
    }
    return ok;
}

/* The rules of one target with the motion's keys; 0 after an error. */
static int rules_of(rb_cctx *c, const rb_cmotion *cm, double low_hz, const rb_target *t,
                    rb_accept_rules *r)
{
    rb_accept_rules_init(r, t);
    if (low_hz > 0)
        r->low_cutoff_hz = low_hz;
    r->max_ratio = cm->max_ratio;
    if (r->low_cutoff_hz < r->high_cutoff_hz)
        return 1;
    char k[RB_CASE_KEY_MAX];
    const rb_ynode *v = cm->low_cutoff_node;
    rb_case_keypath(k, cm->key, "low_cutoff");
    rb_cctx_error(c, v, k, "the low cutoff, %g Hz%s, must be below the target's high "
                  "cutoff, %g Hz", r->low_cutoff_hz, cm->low_cutoff_auto
                  ? " (auto, from equipment.frequency)" : "", r->high_cutoff_hz);
    return 0;
}

int rb_case_accept_rules(rb_cctx *c, const rb_cmotion *cm, const rb_model *m,
                         rb_case_target *ct)
{
    /* auto: the laboratory's rule with the cabinet's own (fixed-base)
     * frequency; a rigid cabinet has no resonance in the range, 1.3 Hz.
     * The vertical takes the same cutoff: the model has no vertical mode,
     * and the horizontal's lower frequency keeps more of the range judged */
    double low = cm->low_cutoff_hz;
    if (cm->low_cutoff_auto)
        low = rb_accept_low_cutoff(m && !m->rigid ? m->freq_hz : 0.0);
    int ok = rules_of(c, cm, low, &ct->target, &ct->rules);
    if (ok && ct->vertical.check_to_hz > 0)
        ok = rules_of(c, cm, low, &ct->vertical, &ct->vertical_rules);
    return ok;
}
