/* The numbers of a run that the batch's summaries show, as one table:
 * every output (batch_table.c, batch_json.c, batch_junit.c) and the mean
 * and maximum of a case (batch_summary.c) loop over it, so that a new
 * number is a line here and its accessor. */
#include <math.h>
#include "batch_summary.h"
#include "rockbolt/criteria.h"

static double usage_of(const rb_batch_source *s)
{
    return fmax(s->result->usage[0], s->result->usage[1]);
}

static double shear_over_w_of(const rb_batch_source *s)
{
    const rb_result *r = s->result;
    return r->weight_n > 0 ? r->max_shear_elastic_n / r->weight_n : 0.0;
}

/* NaN without bolts (rb_result_governing) */
static double force_over_fy_of(const rb_batch_source *s)
{
    return rb_result_governing(s->result).force_over_fy;
}

static double theta_over_alpha_of(const rb_batch_source *s)
{
    return s->result->max_theta_over_alpha;
}

/* the factor against the case's own criteria; none when no level passes */
static double design_factor_of(const rb_batch_source *s)
{
    const rb_design_factor_result *f = s->factor;
    return f->level_mps2 > 0 && isfinite(f->factor) ? f->factor : (double)NAN;
}

static int design_factor_bound(const rb_batch_source *s)
{
    return s->factor->no_failure;
}

static double gap_ratio_of(const rb_batch_source *s)
{
    const rb_motion_design *md = s->design;
    return md->has_gap && md->gap.found ? md->gap.gap_ratio : (double)NAN;
}

const rb_batch_column rb_batch_columns[] = {
    {"usage", "usage", "usage", 0, 7, 3, "n/a", "n/a", RB_BATCH_AGG_MAX, "usage",
     usage_of, NULL},
    {"shear_over_w", "V/W", "V/W", 0, 7, 3, "n/a", "n/a", RB_BATCH_AGG_MAX, "shear_over_w",
     shear_over_w_of, NULL},
    {"force_over_fy", "F/Fy", "F/Fy", 0, 7, 3, "n/a", "n/a", RB_BATCH_AGG_MAX,
     "force_over_fy", force_over_fy_of, NULL},
    {"theta_over_alpha", "th/alp", "theta/alpha", 0, 7, 3, "n/a", "n/a", RB_BATCH_AGG_MAX,
     "theta_over_alpha", theta_over_alpha_of, NULL},
    {"design_factor", "factor", NULL, 1, 8, 3, "n/a", "", RB_BATCH_AGG_MIN,
     "min_design_factor", design_factor_of, design_factor_bound},
    {"gap_ratio", "gap", NULL, 1, 8, 4, "none", "", RB_BATCH_AGG_MAX, "gap_ratio",
     gap_ratio_of, NULL},
};

const size_t rb_batch_n_columns = sizeof rb_batch_columns / sizeof rb_batch_columns[0];

_Static_assert(sizeof rb_batch_columns / sizeof rb_batch_columns[0] <= RB_BATCH_MAX_COLUMNS,
               "rb_batch_result.value holds RB_BATCH_MAX_COLUMNS columns");

int rb_batch_column_shown(size_t k, int design)
{
    return !rb_batch_columns[k].design || design;
}

void rb_batch_columns_fill(rb_batch_result *run, const rb_batch_source *src, int design)
{
    for (size_t k = 0; k < rb_batch_n_columns; k++) {
        const rb_batch_column *col = &rb_batch_columns[k];
        if (col->design != design)
            continue;
        run->value[k] = src ? col->of(src) : (double)NAN;
        if (src && col->bound_of && isfinite(run->value[k]) && col->bound_of(src))
            run->bounds |= 1u << k;
    }
}
