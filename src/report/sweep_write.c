/* A sweep as CSV (one row per point, a header line; `design --sweep-csv`
 * through the output plan) and as its part of the JSON report. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/design.h"
#include "rockbolt/report.h"
#include "rockbolt/textsafe.h"
#include "report_json_build.h"

static const char *x_name(const rb_sweep *s)
{
    return s->kind == RB_SWEEP_FREQUENCY ? "frequency_ratio" : "level_astar_asked";
}

rb_status rb_sweep_write_csv(const rb_sweep *s, FILE *fp)
{
    fprintf(fp, "%s,freq_hz,peak_mps2,level_astar,max_u_over_ustatic,"
            "max_force_over_fy_left,max_force_over_fy_right,max_theta_over_alpha,"
            "usage_left,usage_right,yielded_left,yielded_right,broken_left,"
            "broken_right,overturned,meets,status\n", x_name(s));
    for (size_t i = 0; i < s->n_points; i++) {
        const rb_sweep_point *p = &s->points[i];
        /* %.10g keeps ten digits: more than any of these numbers carries */
        fprintf(fp, "%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,"
                "%d,%d,%d,%d,%d,%s,", p->x, p->freq_hz, p->peak_mps2,
                p->level_astar, p->max_u_over_ustatic, p->max_force_over_fy[0],
                p->max_force_over_fy[1], p->max_theta_over_alpha, p->usage[0],
                p->usage[1], p->yielded[0], p->yielded[1], p->broken[0], p->broken[1],
                p->overturned, p->meets < 0 ? "" : p->meets ? "1" : "0");
        if (rb_csv_field_write(fp, rb_status_str(p->status), 1) != 0)
            return RB_ERR_IO;
        fputc('\n', fp);
    }
    return ferror(fp) ? RB_ERR_IO : RB_OK;
}

/* A point's numbers, and its verdict: null when the sweep had no criteria. */
static void point_json(rb_jctx *cx, cJSON *o, const rb_sweep *s, const rb_sweep_point *p)
{
    rb_j_num_or_null(cx, o, x_name(s), p->x);
    rb_j_num_or_null(cx, o, "freq_hz", p->freq_hz);
    rb_j_num_or_null(cx, o, "peak_mps2", p->peak_mps2);
    rb_j_num_or_null(cx, o, "level_astar", p->level_astar);
    rb_j_num_or_null(cx, o, "max_u_over_ustatic", p->max_u_over_ustatic);
    rb_j_pair_or_null(cx, o, "max_force_over_fy", p->max_force_over_fy);
    rb_j_num_or_null(cx, o, "max_theta_over_alpha", p->max_theta_over_alpha);
    rb_j_pair_or_null(cx, o, "usage", p->usage);
    rb_j_pair_bool(cx, o, "yielded", p->yielded);
    rb_j_pair_bool(cx, o, "broken", p->broken);
    rb_j_bool(cx, o, "overturned", p->overturned);
    if (p->meets < 0)
        rb_j_null(cx, o, "meets");
    else
        rb_j_bool(cx, o, "meets", p->meets);
    rb_j_str(cx, o, "status", rb_status_str(p->status));
}

void rb_report_json_sweep(rb_jctx *cx, cJSON *arr, const rb_sweep *s)
{
    cJSON *o = rb_j_item(cx, arr);
    rb_j_str(cx, o, "kind", s->kind == RB_SWEEP_FREQUENCY ? "frequency" : "amplitude");
    rb_j_num_or_null(cx, o, "a_star_mps2", s->a_star_mps2);
    rb_j_num_or_null(cx, o, "fixed_base_hz", s->fixed_base_hz);
    if (s->kind == RB_SWEEP_FREQUENCY)
        rb_j_num_or_null(cx, o, "amplitude_astar", s->amplitude_astar);
    cJSON *pts = rb_j_arr(cx, o, "points");
    for (size_t i = 0; i < s->n_points && cx->st == RB_OK; i++)
        point_json(cx, rb_j_item(cx, pts), s, &s->points[i]);
}
