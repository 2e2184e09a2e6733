/* A case's response spectra as text (the terminal), JSON (SI, every
 * ordinate) and CSV (one row per motion and frequency). Accelerations are
 * shown in g in the text and the CSV. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <cjson/cJSON.h>
#include "rockbolt/jsonbuild.h"
#include "rockbolt/jsonprint.h"
#include "rockbolt/names.h"
#include "rockbolt/report.h"
#include "rockbolt/textsafe.h"
#include "report_internal.h"
#include "util/strbuf.h"

static const char *motion_name(const rb_case *c, size_t m)
{
    return c->motions[m].name ? c->motions[m].name : "?";
}

/* s in a column of width w, padded on the left (right-aligned) or right:
 * never cut, so that a name is read whole however long it is. */
static void put_padded(rb_strbuf *b, const char *s, size_t w, int right)
{
    size_t n = rb_text_width(s), pad = n < w ? w - n : 0;
    if (!right)
        rb_strbuf_puts(b, s);
    for (size_t i = 0; i < pad; i++)
        rb_strbuf_puts(b, " ");
    if (right)
        rb_strbuf_puts(b, s);
}

/* The width of the motion column: its header's, or the longest name's. */
static size_t name_width(const rb_case *c, size_t n, size_t least)
{
    char name[128];
    size_t w = least;
    for (size_t m = 0; m < n; m++) {
        size_t k = rb_text_width(rb_text_escape_buf(motion_name(c, m), name, sizeof name));
        if (k > w)
            w = k;
    }
    return w;
}

static void text_motion(rb_strbuf *b, const rb_case *c, const rb_case_spectra *s, size_t m,
                        size_t width)
{
    const rb_motion_spectrum *ms = &s->motions[m];
    const rb_case_motion *cm = &c->motions[m];
    double g = s->g_mps2;
    char name[128];
    put_padded(b, rb_text_escape_buf(motion_name(c, m), name, sizeof name), width, 0);
    rb_strbuf_printf(b, " %9.4f", ms->peak_mps2 / g);
    if (ms->arias_t95_s > ms->arias_t5_s)
        rb_strbuf_printf(b, " %8.2f %6.2f-%6.2f", ms->arias_t95_s - ms->arias_t5_s,
                         ms->arias_t5_s, ms->arias_t95_s);
    else
        rb_strbuf_printf(b, " %8s %13s", "n/a", "");
    if (ms->has_target)
        rb_strbuf_printf(b, "  %.3f (%.2f Hz) to %.3f (%.2f Hz) %s", ms->fit.min_ratio,
                         ms->fit.min_at_hz, ms->fit.max_ratio, ms->fit.max_at_hz,
                         ms->fit.within ? "within" : "OUTSIDE");
    if (cm->type == RB_CASE_MOTION_SYNTHETIC && cm->target && cm->target->min_peak_mps2 > 0)
        rb_strbuf_printf(b, ", peak %s 0.9 A_RIG",
                         ms->peak_mps2 >= cm->target->min_peak_mps2 ? ">=" : "BELOW");
    rb_strbuf_puts(b, "\n");
}

char *rb_spectra_render_text(const rb_case *c, const rb_case_spectra *s)
{
    rb_strbuf b = {0};
    char name[128];
    double g = s->g_mps2;
    rb_strbuf_printf(&b, "response spectra of %s: %zu motions, damping %g %%, %g to %g Hz "
                     "at 1/%g octave\n", rb_text_escape_buf(c->name ? c->name : "case",
                     name, sizeof name), s->n_motions, 100 * s->opts.damping,
                     s->opts.f_min_hz, s->opts.f_max_hz, s->opts.per_octave);
    size_t width = name_width(c, s->n_motions, 24);
    put_padded(&b, "motion", width, 0);
    rb_strbuf_printf(&b, " %9s %8s %13s  %s\n", "peak g", "5-95% s",
                     "from-to s", "absolute acceleration / target at its check points");
    for (size_t m = 0; m < s->n_motions; m++)
        text_motion(&b, c, s, m, width);
    rb_strbuf_puts(&b, "\nabsolute acceleration spectra (g)\n");
    rb_strbuf_printf(&b, "%9s", "f (Hz)");
    /* each column as wide as its motion's name, 12 at least */
    for (size_t m = 0; m < s->n_motions; m++) {
        const char *nm = rb_text_escape_buf(motion_name(c, m), name, sizeof name);
        rb_strbuf_puts(&b, " ");
        put_padded(&b, nm, rb_text_width(nm) > 12 ? rb_text_width(nm) : 12, 1);
    }
    rb_strbuf_puts(&b, "\n");
    size_t n = s->n_motions ? s->motions[0].sp.n : 0;
    for (size_t i = 0; i < n; i++) {
        rb_strbuf_printf(&b, "%9.3f", s->motions[0].sp.freq_hz[i]);
        for (size_t m = 0; m < s->n_motions; m++) {
            size_t w = rb_text_width(rb_text_escape_buf(motion_name(c, m), name, sizeof name));
            rb_strbuf_printf(&b, " %*.4f", w > 12 ? (int)w : 12,
                             s->motions[m].sp.sa_mps2[i] / g);
        }
        rb_strbuf_puts(&b, "\n");
    }
    return rb_strbuf_take(&b);
}

/* The acceptance as JSON: the rules' outcome at every offset (the floor
 * files' summary and the spectra's alike). */
void rb_report_accept_json(rb_jctx *cx, cJSON *o, const rb_accept_result *ac)
{
    cJSON *a = rb_j_obj(cx, o, "acceptance");
    rb_j_bool(cx, a, "pass", ac->pass);
    rb_j_uint(cx, a, "worst_offset", ac->worst);
    rb_j_num_or_null(cx, a, "margin", ac->margin);
    rb_j_num_or_null(cx, a, "min_ratio", ac->min_ratio);
    rb_j_num_or_null(cx, a, "min_at_hz", ac->min_at_hz);
    rb_j_num_or_null(cx, a, "max_ratio", ac->max_ratio);
    rb_j_num_or_null(cx, a, "max_at_hz", ac->max_at_hz);
    rb_j_bool(cx, a, "above_guide", ac->above_guide);
    rb_j_num_or_null(cx, a, "tail_min_ratio", ac->tail_min_ratio);
    rb_j_num_or_null(cx, a, "tail_max_ratio", ac->tail_max_ratio);
    cJSON *offsets = rb_j_arr(cx, a, "offsets");
    for (int k = 0; k < RB_ACCEPT_OFFSETS; k++) {
        const rb_accept_offset *off = &ac->offset[k];
        cJSON *e = rb_j_item(cx, offsets);
        rb_j_bool(cx, e, "pass", off->pass);
        rb_j_num_or_null(cx, e, "margin", off->margin);
        rb_j_num_or_null(cx, e, "min_ratio", off->min_ratio);
        rb_j_num_or_null(cx, e, "max_ratio", off->max_ratio);
    }
}

/* A generated motion's summary: its peaks and the laboratory's
 * acceptance at the least favourable of the 12 offsets (accept.h). */
static void json_summary(rb_jctx *cx, cJSON *o, const char *key, const rb_motion_summary *m)
{
    cJSON *s = rb_j_obj(cx, o, key);
    rb_j_num_or_null(cx, s, "pga_mps2", m->pga_mps2);
    rb_j_num_or_null(cx, s, "pgv_mps", m->pgv_mps);
    rb_j_num_or_null(cx, s, "pgd_m", m->pgd_m);
    rb_j_num_or_null(cx, s, "arias_t5_s", m->arias_t5_s);
    rb_j_num_or_null(cx, s, "arias_t95_s", m->arias_t95_s);
    rb_j_bool(cx, s, "peak_ok", m->peak_ok);
    if (m->has_target)
        rb_report_accept_json(cx, s, &m->accept);
    rb_j_num_or_null(cx, s, "end_velocity_mps", m->end_velocity_mps);
}

/* A triaxial set's other components and their independence. */
static void json_set(rb_jctx *cx, cJSON *o, const rb_case_motion *cm)
{
    static const char *const pairs[3] = {"h1_h2", "h1_v", "h2_v"};
    json_summary(cx, o, "h2", &cm->h2_synth.summary);
    json_summary(cx, o, "vertical", &cm->vertical->synth.summary);
    cJSON *ind = rb_j_obj(cx, o, "independence");
    for (int p = 0; p < 3; p++) {
        cJSON *e = rb_j_obj(cx, ind, pairs[p]);
        rb_j_num_or_null(cx, e, "correlation", cm->independence[p].correlation);
        rb_j_num_or_null(cx, e, "coherence", cm->independence[p].coherence);
    }
}

static void json_synthetic(rb_jctx *cx, cJSON *o, const rb_case_motion *cm)
{
    rb_j_uint(cx, o, "seed", cm->synth_seed);
    rb_j_uint(cx, o, "index", cm->synth_index + 1);
    rb_j_uint(cx, o, "passes", cm->synth.iterations);
    rb_j_uint(cx, o, "starts", cm->synth.attempts);
    rb_j_num_or_null(cx, o, "end_velocity_mps", cm->synth.end_velocity_mps);
    rb_j_num_or_null(cx, o, "end_displacement_m", cm->synth.end_displacement_m);
    rb_j_num_or_null(cx, o, "peak_velocity_mps", cm->synth.peak_velocity_mps);
    rb_j_num_or_null(cx, o, "peak_displacement_m", cm->synth.peak_displacement_m);
    json_summary(cx, o, "summary", &cm->synth.summary);
    if (cm->has_set)
        json_set(cx, o, cm);
}

static void json_fit(rb_jctx *cx, cJSON *o, const rb_target_fit *fit)
{
    cJSON *f = rb_j_obj(cx, o, "fit");
    rb_j_num_or_null(cx, f, "min_ratio", fit->min_ratio);
    rb_j_num_or_null(cx, f, "min_at_hz", fit->min_at_hz);
    rb_j_num_or_null(cx, f, "max_ratio", fit->max_ratio);
    rb_j_num_or_null(cx, f, "max_at_hz", fit->max_at_hz);
    rb_j_uint(cx, f, "points", fit->n_checked);
    rb_j_bool(cx, f, "within", fit->within);
}

/* Where the spectra's lines break: the head in two lines, each motion on
 * lines of its own, its two spectra each on one. */
static const rb_json_break spectra_breaks[] = {
    {0, "case", ",\n  ", NULL, NULL},
    {0, "motions", ",\n  ", "\n    ", "\n  "},
    {1, "psa_mps2", ", \n     ", NULL, NULL},
    {1, "sa_mps2", ",\n     ", NULL, NULL},
};
static const rb_json_layout spectra_layout = {
    "\n  ", "\n", spectra_breaks, sizeof spectra_breaks / sizeof spectra_breaks[0]};

char *rb_spectra_render_json(const rb_case *c, const rb_case_spectra *s)
{
    rb_jctx cx = {.st = RB_OK, .where = "spectra"};
    cJSON *root = rb_report_file_json(&cx, "rockbolt-spectra", c);
    rb_j_num_or_null(&cx, root, "damping", s->opts.damping);
    rb_j_num_or_null(&cx, root, "g_mps2", s->g_mps2);
    size_t n = s->n_motions ? s->motions[0].sp.n : 0;
    rb_j_nums(&cx, root, "frequency_hz", n ? s->motions[0].sp.freq_hz : NULL, n);
    cJSON *motions = rb_j_arr(&cx, root, "motions");
    for (size_t m = 0; m < s->n_motions; m++) {
        const rb_motion_spectrum *ms = &s->motions[m];
        const rb_case_motion *cm = &c->motions[m];
        cJSON *o = rb_j_item(&cx, motions);
        rb_j_text(&cx, o, "name", motion_name(c, m));
        rb_j_str(&cx, o, "kind", rb_enum_str(rb_case_motion_type_names, (int)cm->type));
        rb_j_num_or_null(&cx, o, "peak_mps2", ms->peak_mps2);
        rb_j_num_or_null(&cx, o, "arias_mps", ms->arias_mps);
        rb_j_num_or_null(&cx, o, "arias_t5_s", ms->arias_t5_s);
        rb_j_num_or_null(&cx, o, "arias_t95_s", ms->arias_t95_s);
        if (cm->type == RB_CASE_MOTION_SYNTHETIC)
            json_synthetic(&cx, o, cm);
        if (ms->has_target) {
            rb_report_target_json(&cx, o, cm->target);
            json_fit(&cx, o, &ms->fit);
        }
        rb_j_nums(&cx, o, "psa_mps2", ms->sp.psa_mps2, ms->sp.n);
        rb_j_nums(&cx, o, "sa_mps2", ms->sp.sa_mps2, ms->sp.n);
    }
    return rb_report_file_print(&cx, root, &spectra_layout);
}

char *rb_spectra_render_csv(const rb_case *c, const rb_case_spectra *s)
{
    rb_strbuf b = {0};
    double g = s->g_mps2;
    rb_strbuf_puts(&b, "motion,frequency_hz,psa_g,sa_g,target_g\n");
    for (size_t m = 0; m < s->n_motions && !b.oom; m++) {
        const rb_motion_spectrum *ms = &s->motions[m];
        const rb_target *t = ms->has_target ? c->motions[m].target : NULL;
        char *name = rb_csv_field(motion_name(c, m), 0);
        if (!name) {
            b.oom = 1;
            break;
        }
        for (size_t i = 0; i < ms->sp.n; i++) {
            rb_strbuf_printf(&b, "%s,%.6g,%.6g,%.6g,", name, ms->sp.freq_hz[i],
                             ms->sp.psa_mps2[i] / g, ms->sp.sa_mps2[i] / g);
            if (t)
                rb_strbuf_printf(&b, "%.6g", rb_target_at(t, ms->sp.freq_hz[i]) / g);
            rb_strbuf_puts(&b, "\n");
        }
        free(name);
    }
    return rb_strbuf_take(&b);
}

/* "target": {...}: what a target is, for every JSON output that compares
 * a motion with one. */
void rb_report_target_json(rb_jctx *cx, cJSON *o, const rb_target *t)
{
    cJSON *j = rb_j_obj(cx, o, "target");
    rb_j_str(cx, j, "type", rb_enum_str(rb_target_type_names, (int)t->kind));
    if (t->kind == RB_TARGET_AC156) {
        double flx, rig;
        rb_target_ac156_levels(t, &flx, &rig);
        rb_j_str(cx, j, "edition", rb_enum_str(rb_ac156_edition_names, (int)t->edition));
        rb_j_num_or_null(cx, j, "sds_mps2", t->sds_mps2);
        rb_j_num_or_null(cx, j, "z_over_h", t->z_over_h);
        if (t->building.ta_s > 0)
            rb_j_num_or_null(cx, j, "ta_s", t->building.ta_s);
        if (t->building.r > 0) {
            rb_j_num_or_null(cx, j, "r", t->building.r);
            rb_j_num_or_null(cx, j, "ie", t->building.ie);
            rb_j_num_or_null(cx, j, "omega0", t->building.omega0);
        }
        if (t->sds2_mps2 > 0) {
            cJSON *e = rb_j_obj(cx, j, "envelope");
            rb_j_num_or_null(cx, e, "sds_mps2", t->sds2_mps2);
            rb_j_num_or_null(cx, e, "z_over_h", t->z_over_h2);
        }
        rb_j_num_or_null(cx, j, "a_flx_mps2", flx);
        rb_j_num_or_null(cx, j, "a_rig_mps2", rig);
        rb_j_num_or_null(cx, j, "min_peak_mps2", t->min_peak_mps2);
    } else if (t->kind == RB_TARGET_IEEE693) {
        rb_j_str(cx, j, "level", rb_enum_str(rb_ieee693_level_names, (int)t->level));
        rb_j_bool(cx, j, "vertical", t->vertical);
        rb_j_num_or_null(cx, j, "beta", rb_ieee693_beta(t->damping));
        rb_j_num_or_null(cx, j, "zpa_mps2", rb_target_at(t, t->check_to_hz * 2.0));
        rb_j_num_or_null(cx, j, "min_peak_mps2", t->min_peak_mps2);
    }
    rb_j_num_or_null(cx, j, "damping", t->damping);
    rb_j_num_or_null(cx, j, "check_from_hz", t->check_from_hz);
    rb_j_num_or_null(cx, j, "check_to_hz", t->check_to_hz);
    rb_j_num_or_null(cx, j, "check_per_octave", t->check_per_octave);
    rb_j_num_or_null(cx, j, "band_lower", t->band_lower);
    rb_j_num_or_null(cx, j, "band_upper", t->band_upper);
}
