/* Sweep writers: CSV (one row per point, a header line) and JSON (cJSON),
 * to an open stream or atomically to a path through the report layer's
 * atomic output file, so a reader never sees half a sweep. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cjson/cJSON.h>
#include "rockbolt/jsonprint.h"
#include "rockbolt/jsonnum.h"
#include "rockbolt/report.h"
#include "rockbolt/textsafe.h"
#include "rockbolt/design.h"
#include "rockbolt/outfile.h"

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

/* JSON has no infinity: such numbers are written as null. */
static int add_num(cJSON *o, const char *key, double v)
{
    char buf[RB_JSONNUM_MAX];
    if (!isfinite(v))
        return cJSON_AddNullToObject(o, key) != NULL;
    rb_json_number(v, buf);
    return cJSON_AddRawToObject(o, key, buf) != NULL;
}

/* Per-row values as {"left": .., "right": ..}, as in the check report. */
static int add_pair(cJSON *o, const char *key, double left, double right)
{
    cJSON *p = cJSON_AddObjectToObject(o, key);
    return p && add_num(p, "left", left) && add_num(p, "right", right);
}

static int add_pair_bool(cJSON *o, const char *key, int left, int right)
{
    cJSON *p = cJSON_AddObjectToObject(o, key);
    return p && cJSON_AddBoolToObject(p, "left", left != 0)
           && cJSON_AddBoolToObject(p, "right", right != 0);
}

static cJSON *point_json(const rb_sweep *s, const rb_sweep_point *p)
{
    cJSON *o = cJSON_CreateObject();
    int ok = o && add_num(o, x_name(s), p->x) && add_num(o, "freq_hz", p->freq_hz)
             && add_num(o, "peak_mps2", p->peak_mps2)
             && add_num(o, "level_astar", p->level_astar)
             && add_num(o, "max_u_over_ustatic", p->max_u_over_ustatic)
             && add_pair(o, "max_force_over_fy", p->max_force_over_fy[0],
                         p->max_force_over_fy[1])
             && add_num(o, "max_theta_over_alpha", p->max_theta_over_alpha)
             && add_pair(o, "usage", p->usage[0], p->usage[1])
             && add_pair_bool(o, "yielded", p->yielded[0], p->yielded[1])
             && add_pair_bool(o, "broken", p->broken[0], p->broken[1])
             && cJSON_AddBoolToObject(o, "overturned", p->overturned)
             && (p->meets < 0 ? cJSON_AddNullToObject(o, "meets")
                              : cJSON_AddBoolToObject(o, "meets", p->meets))
             && cJSON_AddStringToObject(o, "status", rb_status_str(p->status));
    if (!ok) {
        cJSON_Delete(o);
        return NULL;
    }
    return o;
}

struct cJSON *rb_sweep_to_json(const rb_sweep *s)
{
    cJSON *o = cJSON_CreateObject();
    cJSON *pts = NULL;
    int ok = o && cJSON_AddStringToObject(o, "kind", s->kind == RB_SWEEP_FREQUENCY
                                          ? "frequency" : "amplitude")
             && add_num(o, "a_star_mps2", s->a_star_mps2)
             && add_num(o, "fixed_base_hz", s->fixed_base_hz)
             && (s->kind != RB_SWEEP_FREQUENCY
                 || add_num(o, "amplitude_astar", s->amplitude_astar))
             && (pts = cJSON_AddArrayToObject(o, "points")) != NULL;
    for (size_t i = 0; ok && i < s->n_points; i++) {
        cJSON *p = point_json(s, &s->points[i]);
        ok = p != NULL;
        if (ok)
            cJSON_AddItemToArray(pts, p);
    }
    if (!ok) {
        cJSON_Delete(o);
        return NULL;
    }
    return o;
}

rb_status rb_sweep_write_json(const rb_sweep *s, FILE *fp)
{
    cJSON *o = rb_sweep_to_json(s);
    char *text = o ? rb_json_print(o, 1) : NULL;
    cJSON_Delete(o);
    if (!text)
        return RB_ERR_NOMEM;
    fputs(text, fp);
    fputc('\n', fp);
    free(text);
    return ferror(fp) ? RB_ERR_IO : RB_OK;
}

/* Write through the atomic output file: the path only appears at commit. */
static rb_status save(const rb_sweep *s, const char *path, int json, rb_diag *diag)
{
    rb_outfile f;
    rb_status st = rb_outfile_open(&f, path, 0, diag);
    if (st != RB_OK)
        return st;
    st = json ? rb_sweep_write_json(s, f.fp) : rb_sweep_write_csv(s, f.fp);
    if (st != RB_OK) {
        rb_outfile_abort(&f);
        return rb_diag_set(diag, st, path, 0, 0, "", "%s", st == RB_ERR_NOMEM
                           ? "out of memory" : "cannot write the sweep");
    }
    return rb_outfile_commit(&f, diag);
}

rb_status rb_sweep_save_csv(const rb_sweep *s, const char *path, rb_diag *diag)
{
    return save(s, path, 0, diag);
}

rb_status rb_sweep_save_json(const rb_sweep *s, const char *path, rb_diag *diag)
{
    return save(s, path, 1, diag);
}
