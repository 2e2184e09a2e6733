/* The files of `rockbolt motion`: every component as a PEER AT2 record
 * and a two-column CSV in g, which rockbolt's own readers (and a table
 * controller's) take back, and the summary as text and JSON. Nine
 * significant digits: a value read back differs from the solver's sample
 * by under 1e-8 of it (tests/motion/roundtrip.py). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "rockbolt/floor_files.h"
#include "rockbolt/names.h"
#include "rockbolt/textsafe.h"
#include "rockbolt/units.h"
#include "report_internal.h"

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

static void json_component(rb_strbuf *b, const rb_floor_component *fc, int a,
                           const char *const *files, size_t m)
{
    rb_strbuf_printf(b, "{\"axis\": \"%s\", \"between\": \"%s\", ",
                     rb_enum_str(rb_floor_axis_names, a),
                     rb_enum_str(rb_between_names, (int)fc->between));
    rb_report_json_num(b, "dt_s", fc->s.dt_s, 1);
    rb_strbuf_printf(b, "\"samples\": %zu, ", fc->s.n);
    const rb_motion_summary *sm = &fc->sum;
    rb_report_json_num(b, "pga_mps2", sm->pga_mps2, 1);
    rb_report_json_num(b, "pgv_mps", sm->pgv_mps, 1);
    rb_report_json_num(b, "pgd_m", sm->pgd_m, 1);
    rb_report_json_num(b, "end_velocity_mps", sm->end_velocity_mps, 1);
    rb_report_json_num(b, "end_displacement_m", sm->end_displacement_m, 1);
    rb_report_json_num(b, "arias_mps", sm->arias_mps, 1);
    rb_report_json_num(b, "arias_t5_s", sm->arias_t5_s, 1);
    rb_report_json_num(b, "arias_t95_s", sm->arias_t95_s, 1);
    if (sm->has_target) {
        rb_report_target_json(b, fc->target);
        rb_report_accept_json(b, &sm->accept);
        rb_strbuf_printf(b, "\"peak_ok\": %s, ", sm->peak_ok ? "true" : "false");
    }
    rb_strbuf_puts(b, "\"files\": {");
    static const char *const kinds[RB_FLOOR_FILE_KINDS] = {"at2", "csv"};
    int first = 1;
    for (int k = 0; k < RB_FLOOR_FILE_KINDS; k++) {
        const char *p = file_of(files, m, a, (rb_floor_file_kind)k);
        if (!p)
            continue;
        rb_strbuf_printf(b, "%s\"%s\": ", first ? "" : ", ", kinds[k]);
        rb_report_json_str(b, p);
        first = 0;
    }
    rb_strbuf_puts(b, "}}");
}

char *rb_floors_render_json(const rb_case *c, const rb_case_floors *f,
                            const char *const *files)
{
    rb_strbuf b = {0};
    rb_strbuf_puts(&b, "{\n  \"format\": \"rockbolt-motions\", \"format_version\": 1,\n"
                       "  \"case\": ");
    rb_report_json_str(&b, c->name ? c->name : "");
    rb_strbuf_puts(&b, ", ");
    rb_report_json_num(&b, "g_mps2", f->g_mps2, 0);
    rb_strbuf_puts(&b, ",\n  \"motions\": [\n");
    for (size_t m = 0; m < f->n_motions; m++) {
        const rb_floor_motion *fm = &f->motions[m];
        rb_strbuf_puts(&b, "    {\"name\": ");
        rb_report_json_str(&b, motion_name(c, m));
        rb_strbuf_printf(&b, ", \"kind\": \"%s\", ",
                         rb_enum_str(rb_case_motion_type_names, (int)c->motions[m].type));
        rb_report_json_num(&b, "run_s", fm->run_s, 1);
        rb_strbuf_puts(&b, "\"components\": [");
        int first = 1;
        for (int a = 0; a < RB_FLOOR_AXES; a++) {
            if (!fm->axis[a].present)
                continue;
            rb_strbuf_puts(&b, first ? "\n      " : ",\n      ");
            json_component(&b, &fm->axis[a], a, files, m);
            first = 0;
        }
        rb_strbuf_printf(&b, "]}%s\n", m + 1 < f->n_motions ? "," : "");
    }
    rb_strbuf_puts(&b, "  ]\n}\n");
    return rb_strbuf_take(&b);
}
