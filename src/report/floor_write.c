/* The files of `rockbolt motion`: every component as a PEER AT2 record
 * and a two-column CSV in g, which rockbolt's own readers (and a table
 * controller's) take back, and the summary as text and JSON. Nine
 * significant digits: a value read back differs from the solver's sample
 * by under 1e-8 of it (tests/motion/roundtrip.py). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <cjson/cJSON.h>
#include "rockbolt/floor_files.h"
#include "rockbolt/jsonprint.h"
#include "rockbolt/names.h"
#include "rockbolt/textsafe.h"
#include "rockbolt/units.h"
#include "report_internal.h"
#include "util/strbuf.h"

static const char *motion_name(const rb_case *c, size_t m)
{
    return c->motions[m].name ? c->motions[m].name : "?";
}

/* What the solver's floor does between the samples written, for people. */
static const char *between_text(rb_between b)
{
    switch (b) {
    case RB_BETWEEN_BUILDING:
        return "exact samples of the floor through a building, which is not "
               "straight between them";
    case RB_BETWEEN_SAMPLED:
        return "a closed form sampled 200 times a period or pulse";
    case RB_BETWEEN_LINEAR:
        break;
    }
    return "the floor itself, straight between samples";
}

/* "case C, motion M, component h1 (...)": names escaped to one line */
static int describe(FILE *fp, const rb_case *c, const rb_floor_component *fc, size_t m,
                    rb_floor_axis axis)
{
    char cn[128], mn[128];
    return fprintf(fp, "case %s, motion %s, component %s (%s)\n",
                   rb_text_escape_buf(c->name ? c->name : "?", cn, sizeof cn),
                   rb_text_escape_buf(motion_name(c, m), mn, sizeof mn),
                   rb_enum_str(rb_floor_axis_names, (int)axis), between_text(fc->between));
}

rb_status rb_floors_write_at2(FILE *fp, const rb_case *c, const rb_case_floors *f, size_t m,
                              rb_floor_axis axis)
{
    const rb_floor_component *fc = &f->motions[m].axis[axis];
    const rb_series *s = &fc->s;
    int ok = fputs("PEER FORMAT ACCELERATION RECORD WRITTEN BY ROCKBOLT MOTION\n", fp) >= 0
             && describe(fp, c, fc, m, axis) > 0
             && fputs("ACCELERATION TIME HISTORY IN UNITS OF G\n", fp) >= 0
             && fprintf(fp, "NPTS= %zu, DT= %.10g SEC\n", s->n, s->dt_s) > 0;
    for (size_t i = 0; ok && i < s->n; i++)
        ok = fprintf(fp, " %15.8E%s", s->accel_mps2[i] / f->g_mps2,
                     i % 5 == 4 || i + 1 == s->n ? "\n" : "") > 0;
    return ok ? RB_OK : RB_ERR_IO;
}

rb_status rb_floors_write_csv(FILE *fp, const rb_case *c, const rb_case_floors *f, size_t m,
                              rb_floor_axis axis)
{
    const rb_floor_component *fc = &f->motions[m].axis[axis];
    const rb_series *s = &fc->s;
    int ok = fputs("# rockbolt motion: ", fp) >= 0 && describe(fp, c, fc, m, axis) > 0
             && fputs("# time (s), acceleration (g)\n", fp) >= 0;
    for (size_t i = 0; ok && i < s->n; i++)
        ok = fprintf(fp, "%.10g,%.8E\n", (double)i * s->dt_s,
                     s->accel_mps2[i] / f->g_mps2) > 0;
    return ok ? RB_OK : RB_ERR_IO;
}

static const char *file_of(const char *const *files, size_t m, int a, rb_floor_file_kind k)
{
    return files ? files[RB_FLOOR_FILE_INDEX(m, a, k)] : NULL;
}

/* ---- the summary --------------------------------------------------------- */

/* A velocity in the case's units: its small length per second. */
static void put_velocity(rb_strbuf *b, rb_unit_system u, double v)
{
    rb_strbuf_printf(b, "%.4g %s/s", rb_qty_value(u, RB_Q_SMALL_LENGTH, v),
                     rb_qty_unit(u, RB_Q_SMALL_LENGTH));
}

static void text_component(rb_strbuf *b, const rb_case *c, const rb_floor_motion *fm,
                           int a, const char *name)
{
    const rb_floor_component *fc = &fm->axis[a];
    const rb_motion_summary *sm = &fc->sum;
    rb_unit_system u = c->output_units;
    rb_strbuf_printf(b, "%s %s: %zu samples at %g s, run %g s (%s)\n", name,
                     rb_enum_str(rb_floor_axis_names, a), fc->s.n, fc->s.dt_s, fm->run_s,
                     rb_enum_str(rb_between_names, (int)fc->between));
    rb_strbuf_printf(b, "    PGA %s, PGV ", rb_qty_str(u, RB_Q_ACCEL, sm->pga_mps2, 4).s);
    put_velocity(b, u, sm->pgv_mps);
    rb_strbuf_printf(b, ", PGD %s, Arias 5-95 %% %.2f s (%.2f to %.2f s)\n",
                     rb_qty_str(u, RB_Q_SMALL_LENGTH, sm->pgd_m, 4).s,
                     sm->arias_t95_s - sm->arias_t5_s, sm->arias_t5_s, sm->arias_t95_s);
    if (!sm->has_target)
        return;
    const rb_accept_result *ac = &sm->accept;
    const rb_accept_rules *r = &fc->rules;
    rb_strbuf_printf(b, "    against %s at %g %% damping from %g to %g Hz: no point below "
                     "%g x RRS", rb_enum_str(rb_target_type_names, (int)fc->target->kind),
                     100.0 * r->damping, r->low_cutoff_hz, r->high_cutoff_hz, r->lower);
    if (r->lower < 1.0)
        rb_strbuf_printf(b, ", no two adjacent below 1, at most two below 1 up to and "
                         "above %g Hz", r->split_hz);
    if (r->max_ratio > 0)
        rb_strbuf_printf(b, ", none above max_ratio %g\n", r->max_ratio);
    else
        rb_strbuf_printf(b, "; %g x RRS the guide line (%s)\n", r->guide, ac->above_guide
                         ? "crossed, reported" : "not crossed");
    rb_strbuf_printf(b, "    TRS / RRS %.3f (%.2f Hz) to %.3f (%.2f Hz) on the 1/%d-octave "
                     "grid; least margin %.3f at offset %u: %s\n", ac->min_ratio,
                     ac->min_at_hz, ac->max_ratio, ac->max_at_hz, RB_ACCEPT_PER_OCTAVE,
                     ac->margin, ac->worst, ac->pass ? "accepted at every offset"
                     : "NOT accepted at every offset");
    if (fc->target->min_peak_mps2 > 0)
        rb_strbuf_printf(b, "    peak %s the target's least, %s\n",
                         sm->peak_ok ? "reaches" : "is BELOW",
                         rb_qty_str(u, RB_Q_ACCEL, fc->target->min_peak_mps2, 4).s);
}

char *rb_floors_render_text(const rb_case *c, const rb_case_floors *f,
                            const char *const *files)
{
    rb_strbuf b = {0};
    char name[128], path[512];
    rb_strbuf_printf(&b, "floor motions of %s as the cabinet feels them: %zu motion%s\n",
                     rb_text_escape_buf(c->name ? c->name : "case", name, sizeof name),
                     f->n_motions, f->n_motions == 1 ? "" : "s");
    for (size_t m = 0; m < f->n_motions; m++) {
        rb_text_escape_buf(motion_name(c, m), name, sizeof name);
        for (int a = 0; a < RB_FLOOR_AXES; a++) {
            if (!f->motions[m].axis[a].present)
                continue;
            text_component(&b, c, &f->motions[m], a, name);
            for (int k = 0; k < RB_FLOOR_FILE_KINDS; k++) {
                const char *p = file_of(files, m, a, (rb_floor_file_kind)k);
                if (p)
                    rb_strbuf_printf(&b, "    %s\n", rb_text_escape_buf(p, path, sizeof path));
            }
        }
    }
    return rb_strbuf_take(&b);
}

/* "rules": how the acceptance was judged (accept.h's rb_accept_rules);
 * max_ratio null: not enforced, the guide line reported */
static void rules_json(rb_jctx *cx, cJSON *parent, const rb_accept_rules *r)
{
    cJSON *o = rb_j_obj(cx, parent, "rules");
    rb_j_num_or_null(cx, o, "damping", r->damping);
    rb_j_num_or_null(cx, o, "low_cutoff_hz", r->low_cutoff_hz);
    rb_j_num_or_null(cx, o, "high_cutoff_hz", r->high_cutoff_hz);
    rb_j_num_or_null(cx, o, "split_hz", r->split_hz);
    rb_j_num_or_null(cx, o, "lower", r->lower);
    rb_j_num_or_null(cx, o, "guide", r->guide);
    rb_j_num_or_null(cx, o, "max_ratio", r->max_ratio > 0 ? r->max_ratio : (double)NAN);
    rb_j_num_or_null(cx, o, "tail_to_hz", r->tail_to_hz > 0 ? r->tail_to_hz : (double)NAN);
}

static void json_component(rb_jctx *cx, cJSON *arr, const rb_floor_component *fc, int a,
                           const char *const *files, size_t m)
{
    static const char *const kinds[RB_FLOOR_FILE_KINDS] = {"at2", "csv"};
    const rb_motion_summary *sm = &fc->sum;
    cJSON *o = rb_j_item(cx, arr);
    rb_j_str(cx, o, "axis", rb_enum_str(rb_floor_axis_names, a));
    rb_j_str(cx, o, "between", rb_enum_str(rb_between_names, (int)fc->between));
    rb_j_num_or_null(cx, o, "dt_s", fc->s.dt_s);
    rb_j_uint(cx, o, "samples", fc->s.n);
    rb_j_num_or_null(cx, o, "pga_mps2", sm->pga_mps2);
    rb_j_num_or_null(cx, o, "pgv_mps", sm->pgv_mps);
    rb_j_num_or_null(cx, o, "pgd_m", sm->pgd_m);
    rb_j_num_or_null(cx, o, "end_velocity_mps", sm->end_velocity_mps);
    rb_j_num_or_null(cx, o, "end_displacement_m", sm->end_displacement_m);
    rb_j_num_or_null(cx, o, "arias_mps", sm->arias_mps);
    rb_j_num_or_null(cx, o, "arias_t5_s", sm->arias_t5_s);
    rb_j_num_or_null(cx, o, "arias_t95_s", sm->arias_t95_s);
    if (sm->has_target) {
        rb_report_target_json(cx, o, fc->target);
        rules_json(cx, o, &fc->rules);
        rb_report_accept_json(cx, o, &sm->accept);
        rb_j_bool(cx, o, "peak_ok", sm->peak_ok);
    }
    cJSON *fo = rb_j_obj(cx, o, "files");
    for (int k = 0; k < RB_FLOOR_FILE_KINDS; k++) {
        const char *p = file_of(files, m, a, (rb_floor_file_kind)k);
        if (p)
            rb_j_text(cx, fo, kinds[k], p);
    }
}

/* Where the summary's lines break: the head in two lines, each motion on a
 * line of its own and each of its components on one below it. */
static const rb_json_break floors_breaks[] = {
    {0, "case", ",\n  ", NULL, NULL},
    {0, "motions", ",\n  ", "\n    ", "\n  "},
    {1, "components", NULL, "\n      ", ""},
};
static const rb_json_layout floors_layout = {
    "\n  ", "\n", floors_breaks, sizeof floors_breaks / sizeof floors_breaks[0]};

char *rb_floors_render_json(const rb_case *c, const rb_case_floors *f,
                            const char *const *files)
{
    rb_jctx cx = {.st = RB_OK, .where = "motions"};
    cJSON *root = rb_report_file_json(&cx, "rockbolt-motions", c);
    rb_j_num_or_null(&cx, root, "g_mps2", f->g_mps2);
    cJSON *motions = rb_j_arr(&cx, root, "motions");
    for (size_t m = 0; m < f->n_motions; m++) {
        const rb_floor_motion *fm = &f->motions[m];
        cJSON *o = rb_j_item(&cx, motions);
        rb_j_text(&cx, o, "name", motion_name(c, m));
        rb_j_str(&cx, o, "kind", rb_enum_str(rb_case_motion_type_names, (int)c->motions[m].type));
        rb_j_num_or_null(&cx, o, "run_s", fm->run_s);
        cJSON *comps = rb_j_arr(&cx, o, "components");
        for (int a = 0; a < RB_FLOOR_AXES; a++)
            if (fm->axis[a].present)
                json_component(&cx, comps, &fm->axis[a], a, files, m);
    }
    return rb_report_file_print(&cx, root, &floors_layout);
}
