/* A case's response spectra as text (the terminal), JSON (SI, every
 * ordinate) and CSV (one row per motion and frequency). Accelerations are
 * shown in g in the text and the CSV. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "rockbolt/jsonnum.h"
#include "rockbolt/names.h"
#include "rockbolt/report.h"
#include "rockbolt/textsafe.h"
#include "report_internal.h"

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

static void array(rb_strbuf *b, const char *key, const double *v, size_t n)
{
    char buf[RB_JSONNUM_MAX];
    rb_strbuf_printf(b, "\"%s\": [", key);
    for (size_t i = 0; i < n; i++) {
        rb_json_number_or_null(v[i], buf);
        rb_strbuf_printf(b, "%s%s", i ? ", " : "", buf);
    }
    rb_strbuf_puts(b, "]");
}

/* The acceptance as JSON: the rules' outcome at every offset (the floor
 * files' summary and the spectra's alike). */
void rb_report_accept_json(rb_strbuf *b, const rb_accept_result *ac)
{
    rb_strbuf_puts(b, "\"acceptance\": {");
    rb_strbuf_printf(b, "\"pass\": %s, \"worst_offset\": %u, ", ac->pass ? "true" : "false",
                     ac->worst);
    rb_report_json_num(b, "margin", ac->margin, 1);
    rb_report_json_num(b, "min_ratio", ac->min_ratio, 1);
    rb_report_json_num(b, "min_at_hz", ac->min_at_hz, 1);
    rb_report_json_num(b, "max_ratio", ac->max_ratio, 1);
    rb_report_json_num(b, "max_at_hz", ac->max_at_hz, 1);
    rb_strbuf_printf(b, "\"above_guide\": %s, ", ac->above_guide ? "true" : "false");
    rb_report_json_num(b, "tail_min_ratio", ac->tail_min_ratio, 1);
    rb_report_json_num(b, "tail_max_ratio", ac->tail_max_ratio, 1);
    rb_strbuf_puts(b, "\"offsets\": [");
    for (int k = 0; k < RB_ACCEPT_OFFSETS; k++) {
        const rb_accept_offset *o = &ac->offset[k];
        rb_strbuf_printf(b, "%s{\"pass\": %s, ", k ? ", " : "", o->pass ? "true" : "false");
        rb_report_json_num(b, "margin", o->margin, 1);
        rb_report_json_num(b, "min_ratio", o->min_ratio, 1);
        rb_report_json_num(b, "max_ratio", o->max_ratio, 0);
        rb_strbuf_puts(b, "}");
    }
    rb_strbuf_puts(b, "]}, ");
}

/* A generated motion's summary: its peaks and the laboratory's
 * acceptance at the least favourable of the 12 offsets (accept.h). */
static void json_summary(rb_strbuf *b, const char *key, const rb_motion_summary *m)
{
    rb_strbuf_printf(b, "\"%s\": {", key);
    rb_report_json_num(b, "pga_mps2", m->pga_mps2, 1);
    rb_report_json_num(b, "pgv_mps", m->pgv_mps, 1);
    rb_report_json_num(b, "pgd_m", m->pgd_m, 1);
    rb_report_json_num(b, "arias_t5_s", m->arias_t5_s, 1);
    rb_report_json_num(b, "arias_t95_s", m->arias_t95_s, 1);
    rb_strbuf_printf(b, "\"peak_ok\": %s, ", m->peak_ok ? "true" : "false");
    if (m->has_target)
        rb_report_accept_json(b, &m->accept);
    rb_report_json_num(b, "end_velocity_mps", m->end_velocity_mps, 0);
    rb_strbuf_puts(b, "}, ");
}

/* A triaxial set's other components and their independence. */
static void json_set(rb_strbuf *b, const rb_case_motion *cm)
{
    static const char *const pairs[3] = {"h1_h2", "h1_v", "h2_v"};
    json_summary(b, "h2", &cm->h2_synth.summary);
    json_summary(b, "vertical", &cm->vertical->synth.summary);
    rb_strbuf_puts(b, "\"independence\": {");
    for (int p = 0; p < 3; p++) {
        rb_strbuf_printf(b, "\"%s\": {", pairs[p]);
        rb_report_json_num(b, "correlation", cm->independence[p].correlation, 1);
        rb_report_json_num(b, "coherence", cm->independence[p].coherence, 0);
        rb_strbuf_printf(b, "}%s", p < 2 ? ", " : "");
    }
    rb_strbuf_puts(b, "}, ");
}

char *rb_spectra_render_json(const rb_case *c, const rb_case_spectra *s)
{
    rb_strbuf b = {0};
    rb_strbuf_puts(&b, "{\n  \"format\": \"rockbolt-spectra\", \"format_version\": 1,\n"
                       "  \"case\": ");
    rb_report_json_str(&b, c->name ? c->name : "");
    rb_strbuf_puts(&b, ", ");
    rb_report_json_num(&b, "damping", s->opts.damping, 1);
    rb_report_json_num(&b, "g_mps2", s->g_mps2, 1);
    size_t n = s->n_motions ? s->motions[0].sp.n : 0;
    array(&b, "frequency_hz", n ? s->motions[0].sp.freq_hz : NULL, n);
    rb_strbuf_puts(&b, ",\n  \"motions\": [\n");
    for (size_t m = 0; m < s->n_motions; m++) {
        const rb_motion_spectrum *ms = &s->motions[m];
        const rb_case_motion *cm = &c->motions[m];
        rb_strbuf_puts(&b, "    {\"name\": ");
        rb_report_json_str(&b, motion_name(c, m));
        rb_strbuf_printf(&b, ", \"kind\": \"%s\", ",
                         rb_enum_str(rb_case_motion_type_names, (int)cm->type));
        rb_report_json_num(&b, "peak_mps2", ms->peak_mps2, 1);
        rb_report_json_num(&b, "arias_mps", ms->arias_mps, 1);
        rb_report_json_num(&b, "arias_t5_s", ms->arias_t5_s, 1);
        rb_report_json_num(&b, "arias_t95_s", ms->arias_t95_s, 1);
        if (cm->type == RB_CASE_MOTION_SYNTHETIC) {
            rb_strbuf_printf(&b, "\"seed\": %llu, \"index\": %u, \"passes\": %u, "
                             "\"starts\": %u, ", cm->synth_seed, cm->synth_index + 1,
                             cm->synth.iterations, cm->synth.attempts);
            rb_report_json_num(&b, "end_velocity_mps", cm->synth.end_velocity_mps, 1);
            rb_report_json_num(&b, "end_displacement_m", cm->synth.end_displacement_m, 1);
            rb_report_json_num(&b, "peak_velocity_mps", cm->synth.peak_velocity_mps, 1);
            rb_report_json_num(&b, "peak_displacement_m", cm->synth.peak_displacement_m, 1);
            json_summary(&b, "summary", &cm->synth.summary);
            if (cm->has_set)
                json_set(&b, cm);
        }
        if (ms->has_target) {
            rb_report_target_json(&b, cm->target);
            rb_strbuf_puts(&b, "\"fit\": {");
            rb_report_json_num(&b, "min_ratio", ms->fit.min_ratio, 1);
            rb_report_json_num(&b, "min_at_hz", ms->fit.min_at_hz, 1);
            rb_report_json_num(&b, "max_ratio", ms->fit.max_ratio, 1);
            rb_report_json_num(&b, "max_at_hz", ms->fit.max_at_hz, 1);
            rb_strbuf_printf(&b, "\"points\": %zu, \"within\": %s}, ", ms->fit.n_checked,
                             ms->fit.within ? "true" : "false");
        }
        rb_strbuf_puts(&b, "\n     ");
        array(&b, "psa_mps2", ms->sp.psa_mps2, ms->sp.n);
        rb_strbuf_puts(&b, ",\n     ");
        array(&b, "sa_mps2", ms->sp.sa_mps2, ms->sp.n);
        rb_strbuf_printf(&b, "}%s\n", m + 1 < s->n_motions ? "," : "");
    }
    rb_strbuf_puts(&b, "  ]\n}\n");
    return rb_strbuf_take(&b);
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

/* "target": {...}, with ", " after it: what a target is, for every JSON
 * output that compares a motion with one. */
void rb_report_target_json(rb_strbuf *b, const rb_target *t)
{
    rb_strbuf_printf(b, "\"target\": {\"type\": \"%s\", ",
                     rb_enum_str(rb_target_type_names, (int)t->kind));
    if (t->kind == RB_TARGET_AC156) {
        double flx, rig;
        rb_target_ac156_levels(t, &flx, &rig);
        rb_strbuf_printf(b, "\"edition\": \"%s\", ",
                         rb_enum_str(rb_ac156_edition_names, (int)t->edition));
        rb_report_json_num(b, "sds_mps2", t->sds_mps2, 1);
        rb_report_json_num(b, "z_over_h", t->z_over_h, 1);
        if (t->building.ta_s > 0)
            rb_report_json_num(b, "ta_s", t->building.ta_s, 1);
        if (t->building.r > 0) {
            rb_report_json_num(b, "r", t->building.r, 1);
            rb_report_json_num(b, "ie", t->building.ie, 1);
            rb_report_json_num(b, "omega0", t->building.omega0, 1);
        }
        if (t->sds2_mps2 > 0) {
            rb_strbuf_puts(b, "\"envelope\": {");
            rb_report_json_num(b, "sds_mps2", t->sds2_mps2, 1);
            rb_report_json_num(b, "z_over_h", t->z_over_h2, 0);
            rb_strbuf_puts(b, "}, ");
        }
        rb_report_json_num(b, "a_flx_mps2", flx, 1);
        rb_report_json_num(b, "a_rig_mps2", rig, 1);
        rb_report_json_num(b, "min_peak_mps2", t->min_peak_mps2, 1);
    } else if (t->kind == RB_TARGET_IEEE693) {
        rb_strbuf_printf(b, "\"level\": \"%s\", \"vertical\": %s, ",
                         rb_enum_str(rb_ieee693_level_names, (int)t->level),
                         t->vertical ? "true" : "false");
        rb_report_json_num(b, "beta", rb_ieee693_beta(t->damping), 1);
        rb_report_json_num(b, "zpa_mps2", rb_target_at(t, t->check_to_hz * 2.0), 1);
        rb_report_json_num(b, "min_peak_mps2", t->min_peak_mps2, 1);
    }
    rb_report_json_num(b, "damping", t->damping, 1);
    rb_report_json_num(b, "check_from_hz", t->check_from_hz, 1);
    rb_report_json_num(b, "check_to_hz", t->check_to_hz, 1);
    rb_report_json_num(b, "check_per_octave", t->check_per_octave, 1);
    rb_report_json_num(b, "band_lower", t->band_lower, 1);
    rb_report_json_num(b, "band_upper", t->band_upper, 0);
    rb_strbuf_puts(b, "}, ");
}
