/* The summary as a text table (for the terminal) and as CSV (one row per
 * case and motion, for spreadsheets). Numbers in the table are rounded for
 * reading; the CSV keeps 6 significant digits; the JSON keeps them all. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "batch_summary.h"
#include "rockbolt/names.h"
#include "rockbolt/report.h"
#include "rockbolt/textsafe.h"

static const char *upper_verdict(rb_batch_verdict v)
{
    switch (v) {
    case RB_BATCH_PASS: return "PASS";
    case RB_BATCH_FAIL: return "FAIL";
    case RB_BATCH_UNREADABLE: return "UNREADABLE";
    case RB_BATCH_ERROR: return "ERROR";
    }
    return "ERROR";
}

/* The columns' numbers of a row of the table: a run's, or a case's mean
 * or maximum (bounds 0). */
static void text_nums(rb_strbuf *b, const double *value, unsigned bounds, int design)
{
    for (size_t k = 0; k < rb_batch_n_columns; k++) {
        const rb_batch_column *col = &rb_batch_columns[k];
        if (!rb_batch_column_shown(k, design))
            continue;
        if (isnan(value[k]))
            rb_strbuf_printf(b, " %*s", col->width, col->none_text);
        else if (col->bound_of)
            rb_strbuf_printf(b, " %s%*.*f", (bounds >> k) & 1u ? ">" : " ", col->width - 1,
                             col->precision, value[k]);
        else
            rb_strbuf_printf(b, " %*.*f", col->width, col->precision, value[k]);
    }
    rb_strbuf_puts(b, "\n");
}

/* A line per limit state under the case's motions, in the motion column's
 * place its name. */
static void text_fragility(rb_strbuf *b, const rb_batch_case *c)
{
    const rb_batch_fragility *f = c->fragility;
    if (f->error) {
        char why[600];
        rb_strbuf_printf(b, "%-24s %-18s %-10s %s\n", "", "[fragility]", "",
                         rb_text_escape_buf(f->error, why, sizeof why));
        return;
    }
    for (int k = 0; k < RB_N_LIMITS; k++) {
        const rb_batch_limit *l = &f->limits[k];
        char name[32];
        if (!l->present)
            continue;
        snprintf(name, sizeof name, "[%s]", rb_enum_str(rb_limit_state_names, k));
        rb_strbuf_printf(b, "%-24s %-18s %-10s", "", name, "");
        /* in the spectral acceleration at the cabinet's f0, say so */
        if (l->fitted && f->im_freq_hz > 0)
            rb_strbuf_printf(b, " Sa(%.3g Hz)", f->im_freq_hz);
        if (l->fitted) {
            rb_strbuf_printf(b, " median %.4g g, beta %.3f, 90%% ", l->median_mps2 / f->g_mps2,
                             l->beta);
            /* too few motions to resample (two equal draws fit no spread):
             * no interval, as the fragility's own text says */
            if (isfinite(l->median_lo_mps2) && isfinite(l->median_hi_mps2))
                rb_strbuf_printf(b, "%.4g to %.4g g", l->median_lo_mps2 / f->g_mps2,
                                 l->median_hi_mps2 / f->g_mps2);
            else
                rb_strbuf_puts(b, "n/a (too few)");
            rb_strbuf_printf(b, "; P %.3f at %.4g g;", l->p_at_level, f->level_mps2 / f->g_mps2);
        } else
            rb_strbuf_puts(b, " not fitted;");
        rb_strbuf_printf(b, " reached by %zu of %zu", l->reached, c->n_runs);
        if (l->model_limited)
            rb_strbuf_printf(b, ", %zu at the model's limit (a lower bound)", l->model_limited);
        rb_strbuf_printf(b, "; %s%s\n", l->confirmed ? "confirmed" : "not confirmed",
                         k == f->governing ? "; governs" : "");
    }
    if (f->governing < 0)
        rb_strbuf_printf(b, "%-24s %-18s %-10s none of the limit states its criteria fail "
                         "on is reached by two motions\n", "", "[governs]", "");
}

/* The code-static line under a case with design.code: ratios only, so it
 * reads alike in every unit system. */
static void text_code(rb_strbuf *b, const rb_batch_case *c)
{
    rb_strbuf_printf(b, "%-24s %-18s %-10s Fp %.3f Wp; static tension of the far row "
                     "%.3f phi Nsa", "", "[code-static]", c->code_steel_ratio > 1 ? "FAIL"
                                                                                 : "pass",
                     c->code_fp_over_wp, c->code_steel_ratio);
    if (isfinite(c->code_anchor_utilization))
        rb_strbuf_printf(b, "; 17.8 utilization %.3f", c->code_anchor_utilization);
    rb_strbuf_puts(b, "\n");
}

static void text_case(rb_strbuf *b, const rb_batch_case *c, int design)
{
    if (c->verdict != RB_BATCH_PASS && c->verdict != RB_BATCH_FAIL) {
        const rb_diag *e = rb_batch_case_error(c);
        char tag[128], file[1024], key[256], msg[1024];
        rb_strbuf_printf(b, "%-24.24s %-18s %-10s ", rb_text_escape_buf(c->tag, tag, sizeof tag),
                       "-", upper_verdict(c->verdict));
        rb_strbuf_printf(b, "%s", rb_text_escape_buf(e->file, file, sizeof file));
        if (e->line > 0)
            rb_strbuf_printf(b, ":%d:%d", e->line, e->col);
        rb_strbuf_printf(b, ": %s%s%s\n", rb_text_escape_buf(e->key, key, sizeof key),
                       e->key[0] ? ": " : "", rb_text_escape_buf(e->msg, msg, sizeof msg));
        return;
    }
    size_t g = rb_batch_governing(c);
    for (size_t m = 0; m < c->n_runs; m++) {
        const rb_batch_result *r = &c->runs[m];
        char motion[24], name[24], tag[128];
        rb_text_escape_buf(r->motion, name, sizeof name);
        snprintf(motion, sizeof motion, "%s%.17s", c->n_runs > 1 && m == g ? "*" : "",
                 name);
        rb_strbuf_printf(b, "%-24.24s %-18s %-10s",
                       m == 0 ? rb_text_escape_buf(c->tag, tag, sizeof tag) : "", motion,
                       r->pass ? "pass" : "FAIL");
        text_nums(b, r->value, r->bounds, design);
        if (!r->pass) {
            /* why it fails, as the run's verdict line says it */
            char why[512];
            rb_strbuf_printf(b, "%-24s   %s\n", "",
                             rb_text_escape_buf(r->reason ? r->reason : "", why, sizeof why));
        }
    }
    if (c->n_runs > 1) {
        rb_batch_stat mean, max;
        rb_batch_stats(c, &mean, &max);
        rb_strbuf_printf(b, "%-24s %-18s %-10s", "", "(mean)", "");
        text_nums(b, mean.value, 0, design);
        rb_strbuf_printf(b, "%-24s %-18s %-10s", "", "(max)",
                       c->verdict == RB_BATCH_PASS ? "PASS" : "FAIL");
        text_nums(b, max.value, 0, design);
    }
    if (c->has_code)
        text_code(b, c);
    if (c->fragility)
        text_fragility(b, c);
}

void rb_batch_render_text_head(rb_strbuf *b, const rb_batch_summary *s,
                               const rb_batch_counts *n)
{
    (void)n;
    rb_strbuf_printf(b, "%-24s %-18s %-10s", "tag", "motion", "verdict");
    for (size_t k = 0; k < rb_batch_n_columns; k++)
        if (rb_batch_column_shown(k, s->design))
            rb_strbuf_printf(b, " %*s", rb_batch_columns[k].width, rb_batch_columns[k].label);
    rb_strbuf_puts(b, "\n");
}

void rb_batch_render_text_case(rb_strbuf *b, const rb_batch_summary *s, const rb_batch_case *c,
                               size_t pos)
{
    (void)pos;
    text_case(b, c, s->design);
}

void rb_batch_render_text_tail(rb_strbuf *b, const rb_batch_summary *s,
                               const rb_batch_counts *n)
{
    (void)s;
    rb_strbuf_printf(b, "%zu case%s: %zu passed, %zu failed, %zu unreadable, %zu "
                   "error%s; %zu runs\n", n->cases, n->cases == 1 ? "" : "s", n->passed,
                   n->failed, n->unreadable, n->errors, n->errors == 1 ? "" : "s", n->runs);
}

/* A CSV text field through the shared writer (escaped, formula-guarded). */
static void csv_field(rb_strbuf *b, const char *s)
{
    char *f = rb_csv_field(s, 0);
    if (!f) {
        b->oom = 1;
        return;
    }
    rb_strbuf_puts(b, f);
    free(f);
}

static void csv_head(rb_strbuf *b, const rb_batch_case *c, const char *motion,
                     int governing, const char *verdict)
{
    rb_strbuf_printf(b, "%zu,", c->index);
    csv_field(b, c->source);
    rb_strbuf_printf(b, ",%d,", c->line);
    csv_field(b, c->tag);
    rb_strbuf_puts(b, ",");
    csv_field(b, motion);
    rb_strbuf_printf(b, ",%d,%s,%s", governing, verdict, rb_batch_verdict_str(c->verdict));
}

/* A number of 6 significant digits, or an empty field when there is none. */
static void csv_num(rb_strbuf *b, double v)
{
    if (isfinite(v))
        rb_strbuf_printf(b, ",%.6g", v);
    else
        rb_strbuf_puts(b, ",");
}

/* The run's numbers, one field per column (and its bound's). */
static void csv_columns(rb_strbuf *b, const rb_batch_result *r, int design)
{
    for (size_t k = 0; k < rb_batch_n_columns; k++) {
        const rb_batch_column *col = &rb_batch_columns[k];
        double v = r->value[k];
        if (!rb_batch_column_shown(k, design))
            continue;
        if (isnan(v))
            rb_strbuf_printf(b, ",%s", col->none_csv);
        else
            rb_strbuf_printf(b, ",%.6g", v);
        if (col->bound_of && isnan(v))
            rb_strbuf_puts(b, ",");
        else if (col->bound_of)
            rb_strbuf_printf(b, ",%u", (r->bounds >> k) & 1u);
    }
}

/* The case's fragility, the same on each of its rows: its intensity
 * (with the frequency of a spectral acceleration), level, eight columns per
 * limit state, or why it has none. */
static void csv_fragility(rb_strbuf *b, const rb_batch_fragility *f,
                         rb_fragility_intensity im)
{
    rb_strbuf_printf(b, ",%s", rb_enum_str(rb_intensity_names, (int)im));
    if (f->im_freq_hz > 0)
        csv_num(b, f->im_freq_hz);
    else
        rb_strbuf_puts(b, ",");
    if (f->error) {
        rb_strbuf_puts(b, ",");
        for (int k = 0; k < RB_N_LIMITS; k++)
            rb_strbuf_puts(b, ",,,,,,,,");
        rb_strbuf_puts(b, ",,");
        csv_field(b, f->error);
        return;
    }
    double g = f->g_mps2;
    csv_num(b, f->level_mps2 / g);
    for (int k = 0; k < RB_N_LIMITS; k++) {
        const rb_batch_limit *l = &f->limits[k];
        if (!l->present) {
            /* a state the case does not have: no reached count or flags */
            rb_strbuf_puts(b, ",,,,,,,,");
            continue;
        }
        if (l->fitted) {
            csv_num(b, l->median_mps2 / g);
            csv_num(b, l->beta);
            csv_num(b, l->median_lo_mps2 / g);
            csv_num(b, l->median_hi_mps2 / g);
            csv_num(b, l->p_at_level);
        } else {
            rb_strbuf_puts(b, ",,,,,");
        }
        rb_strbuf_printf(b, ",%zu,%d,%zu", l->reached, l->confirmed != 0, l->model_limited);
    }
    char gov[32] = "";
    if (f->governing >= 0)
        rb_enum_str_sep(rb_limit_state_names, f->governing, '_', gov, sizeof gov);
    rb_strbuf_printf(b, ",%s,", f->governing >= 0 ? gov : "none");
}

/* The columns of --fragility after the design's: intensity and its
 * frequency, level, eight per limit state, the governing one and the reason
 * when there is none. */
#define FRAGILITY_COLUMNS (2 + 1 + 8 * RB_N_LIMITS + 1 + 1)

void rb_batch_render_csv_head(rb_strbuf *b, const rb_batch_summary *s, const rb_batch_counts *n)
{
    (void)n;
    rb_strbuf_puts(b, "index,source,line,tag,motion,governing,verdict,case_verdict");
    for (size_t k = 0; k < rb_batch_n_columns; k++) {
        const rb_batch_column *col = &rb_batch_columns[k];
        if (!rb_batch_column_shown(k, s->design))
            continue;
        rb_strbuf_printf(b, ",%s", col->name);
        if (col->bound_of)
            rb_strbuf_printf(b, ",%s_bound", col->name);
    }
    if (s->fragility) {
        rb_strbuf_puts(b, ",fragility_intensity,fragility_intensity_freq_hz,"
                        "fragility_level_g");
        for (int k = 0; k < RB_N_LIMITS; k++) {
            char st[32];
            rb_enum_str_sep(rb_limit_state_names, k, '_', st, sizeof st);
            rb_strbuf_printf(b, ",fragility_%s_median_g,fragility_%s_beta,"
                             "fragility_%s_median_lo_g,fragility_%s_median_hi_g,"
                             "fragility_%s_p_at_level,fragility_%s_reached,"
                             "fragility_%s_confirmed,fragility_%s_model_limited", st, st, st,
                             st, st, st, st, st);
        }
        rb_strbuf_puts(b, ",fragility_governing,fragility_error");
    }
    rb_strbuf_puts(b, ",validity_warnings,anchor_mode,anchor_utilization,code_fp_n,"
                    "code_fp_over_wp,code_tension_n,code_steel_ratio,"
                    "code_anchor_utilization,governs,reason,error\n");
}

void rb_batch_render_csv_tail(rb_strbuf *b, const rb_batch_summary *s, const rb_batch_counts *n)
{
    (void)b, (void)s, (void)n;
}

void rb_batch_render_csv_case(rb_strbuf *b, const rb_batch_summary *s, const rb_batch_case *c,
                              size_t pos)
{
    (void)pos;
    if (c->verdict != RB_BATCH_PASS && c->verdict != RB_BATCH_FAIL) {
        char err[1400];
        const rb_diag *e = rb_batch_case_error(c);
        csv_head(b, c, "", 0, rb_batch_verdict_str(c->verdict));
        for (size_t k = 0; k < rb_batch_n_columns; k++)
            if (rb_batch_column_shown(k, s->design))
                rb_strbuf_puts(b, rb_batch_columns[k].bound_of ? ",," : ",");
        /* validity_warnings to reason; the error follows */
        rb_strbuf_puts(b, ",,,,,,,,,,,");
        for (int k = 0; s->fragility && k < FRAGILITY_COLUMNS; k++)
            rb_strbuf_puts(b, ",");
        if (e->line > 0)
            snprintf(err, sizeof err, "%s:%d:%d: %s: %s", e->file, e->line, e->col,
                     e->key, e->msg);
        else
            snprintf(err, sizeof err, "%s: %s: %s", e->file, e->key, e->msg);
        csv_field(b, err);
        rb_strbuf_puts(b, "\n");
        return;
    }
    size_t g = rb_batch_governing(c);
    for (size_t m = 0; m < c->n_runs; m++) {
        const rb_batch_result *r = &c->runs[m];
        csv_head(b, c, r->motion, m == g, r->pass ? "pass" : "fail");
        csv_columns(b, r, s->design);
        if (s->fragility && c->fragility)
            csv_fragility(b, c->fragility, s->intensity);
        else
            for (int k = 0; s->fragility && k < FRAGILITY_COLUMNS; k++)
                rb_strbuf_puts(b, ",");
        char w[80];
        rb_warnings_names(r->warnings, w, sizeof w);
        rb_strbuf_puts(b, ",");
        csv_field(b, w);
        if (r->has_anchor)
            rb_strbuf_printf(b, ",%s,%.6g", rb_enum_str(rb_anchor_mode_names, r->anchor_mode),
                             r->anchor_utilization);
        else
            rb_strbuf_puts(b, ",,");
        if (c->has_code) {
            csv_num(b, c->code_fp_n);
            csv_num(b, c->code_fp_over_wp);
            csv_num(b, c->code_tension_n);
            csv_num(b, c->code_steel_ratio);
            csv_num(b, c->code_anchor_utilization);
        } else {
            rb_strbuf_puts(b, ",,,,,");
        }
        /* the limit nearest to failing; a failing run's reason */
        rb_strbuf_printf(b, ",%s,", rb_governs_name((rb_governs_limit)r->limit));
        csv_field(b, r->pass || !r->reason ? "" : r->reason);
        rb_strbuf_puts(b, ",\n");
    }
}
