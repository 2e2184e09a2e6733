/* The fragility: section of a case (docs/case-format.md): what the
 * anchorage fragility's FEMA P-58 row (`fragility --p58`) says beside the
 * numbers rockbolt computes, the row's ID and the weights of the damage
 * states an anchorage failure splits into. */
#include <math.h>
#include <string.h>
#include "case_internal.h"

/* A loss tool keys its components by ID; one longer than this is not a
 * component ID but text pasted into the wrong key. */
#define P58_ID_MAX 128

static const char *const fragility_keys[] = {"p58_id", "damage_state_weights", NULL};
const char *const *const rb_case_fragility_keys = fragility_keys;

static void read_weights(rb_cctx *c, const rb_ynode *v, rb_case_fragility_opts *f)
{
    const char *k = "fragility.damage_state_weights";
    if (v->kind != RB_YNODE_SEQ || v->n < 1 || v->n > RB_P58_MAX_WEIGHTS) {
        rb_cctx_error(c, v, k, "expected a list of 1 to %d weights summing to 1, e.g. "
                      "'[0.7, 0.3]' or '[70 %%, 30 %%]'", RB_P58_MAX_WEIGHTS);
        return;
    }
    double sum = 0;
    for (size_t i = 0; i < v->n; i++) {
        rb_quantity q;
        if (!rb_cv_quantity(c, v->items[i], k, RB_DIM_RATIO, &q))
            return;
        if (!(q.value > 0 && q.value <= 1)) {
            rb_cctx_error(c, v->items[i], k, "a weight must be > 0 and <= 1 (got '%s')",
                          v->items[i]->text);
            return;
        }
        f->weights[i] = q.value;
        sum += q.value;
    }
    /* the weights are probabilities of exclusive outcomes; 1e-6 lets
     * thirds written to six places (0.333333) through */
    if (fabs(sum - 1) > 1e-6) {
        rb_cctx_error(c, v, k, "the weights must sum to 1 (they sum to %.9g)", sum);
        return;
    }
    f->n_weights = v->n;
}

void rb_case_read_fragility(rb_cctx *c, rb_ynode *map, rb_case *cs)
{
    rb_case_fragility_opts *f = &cs->fragility;
    rb_ynode *v = rb_cv_get(c, map, "fragility", "p58_id", 0, "");
    if (v && rb_cv_string(c, v, "fragility.p58_id", &f->p58_id)) {
        size_t n = strlen(f->p58_id);
        if (n == 0 || n > P58_ID_MAX) {
            rb_cctx_error(c, v, "fragility.p58_id", "must be 1 to %d characters (got %zu)",
                          P58_ID_MAX, n);
        }
    }
    v = rb_cv_get(c, map, "fragility", "damage_state_weights", 0, "");
    if (v)
        read_weights(c, v, f);
    rb_cv_unknown_keys(c, map, "fragility", fragility_keys);
}
