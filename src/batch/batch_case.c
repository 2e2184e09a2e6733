/* One case of a batch: load it, judge its runs, write its reports.
 *
 * Loading and finishing are separate because the runs of a case go to the
 * thread pool one by one: the case is loaded first, its motions solved in
 * any order on any thread, and the last run to finish concludes the case.
 * Everything a case keeps in the summary is copied out of the rb_case, so
 * the case can be freed at once. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "batch_engine.h"
#include "batch_summary.h"
#include "rockbolt/outplan.h"
#include "rockbolt/report.h"
#include "rockbolt/run.h"
#include "rockbolt/outfile.h"

/* The case name from a path: file name without directory and extension. */
static char *stem_of(const char *path)
{
    const char *b = strrchr(path, '/');
    b = b ? b + 1 : path;
    char *s = rb_batch_strdup(b);
    char *dot = s ? strrchr(s, '.') : NULL;
    if (dot && dot != s)
        *dot = '\0';
    return s;
}

static void set_error(rb_batch_case *bc, const rb_diag *d, const char *source)
{
    if (rb_batch_case_set_error(bc, d) && !bc->error->file[0])
        rb_diag_set_file(bc->error, "%s", source);
}

/* The code-static numbers beside the dynamic result, worked out as
 * `design` works them out (rb_code_static; the 17.8 utilization the case
 * loader found for the same demand). */
static void code_static(const rb_case *c, rb_batch_case *bc)
{
    rb_code_result k;
    rb_diag d;
    rb_diag_clear(&d);
    if (!c->has_code || rb_code_static(&c->model, &c->code, &k, &d) != RB_OK)
        return;
    bc->has_code = 1;
    bc->code_fp_n = k.fp_n;
    bc->code_fp_over_wp = k.fp_over_wp;
    bc->code_tension_n = k.tension_n;
    bc->code_steel_ratio = k.ratio;
    bc->code_anchor_utilization = c->has_anchor_static ? c->anchor_static_utilization
                                                       : (double)NAN;
}

void rb_batch_case_load(rb_batch_slot *s, const rb_batch_item *it, rb_batch_case *bc)
{
    rb_diag_list diags = {0};
    rb_status st;
    if (it->bad) {
        bc->verdict = RB_BATCH_UNREADABLE;
        set_error(bc, it->error ? it->error : rb_batch_case_error(NULL), it->source);
        bc->n_errors = 1;
        return;
    }
    if (it->tag)
        st = rb_case_load_overrides_at(it->base, it->base_line ? it->base_line : it->line,
                                       it->base_col, it->source,
                                       it->tag, it->ov, it->n_ov, s->cache, s->sandbox, &s->c,
                                       &diags);
    else
        st = rb_case_load_cached(it->source, s->cache, s->sandbox, &s->c, &diags);
    if (st != RB_OK) {
        rb_diag d;
        rb_diag_clear(&d);
        if (diags.n)
            d = diags.items[0];
        else
            rb_diag_set_msg(&d, "cannot load the case: %s", rb_status_str(st));
        if (!d.key[0])
            rb_diag_set_key(&d, "case");
        bc->verdict = st == RB_ERR_NOMEM ? RB_BATCH_ERROR : RB_BATCH_UNREADABLE;
        set_error(bc, &d, it->source);
        bc->n_errors = diags.n ? diags.n : 1;
        rb_diag_list_free(&diags);
        return;
    }
    rb_diag_list_free(&diags);
    code_static(&s->c, bc);
    if (!it->tag) {
        free(bc->tag);
        bc->tag = rb_batch_strdup(s->c.name ? s->c.name : it->source);
    }
    size_t n = s->c.n_motions;
    s->results = calloc(n, sizeof *s->results);
    s->rms = calloc(n, sizeof *s->rms);
    s->run_status = calloc(n, sizeof *s->run_status);
    s->run_diag = calloc(n, sizeof *s->run_diag);
    bc->runs = calloc(n, sizeof *bc->runs);
    if (!bc->tag || !s->results || !s->rms || !s->run_status || !s->run_diag || !bc->runs) {
        rb_diag d;
        rb_diag_clear(&d);
        rb_diag_set_key(&d, "case");
        rb_diag_set_msg(&d, "out of memory");
        set_error(bc, &d, it->source);
        bc->verdict = RB_BATCH_ERROR;
        return;
    }
    bc->n_runs = n;
    s->loaded = 1;
    s->remaining = n;
}

void rb_batch_case_solve(rb_batch_slot *s, rb_batch_case *bc, size_t m, int design)
{
    const rb_case_motion *cm = &s->c.motions[m];
    rb_result *r = &s->results[m];
    rb_batch_result *run = &bc->runs[m];
    rb_diag *d = &s->run_diag[m];
    rb_report_motion *rm = &s->rms[m];
    rb_diag_clear(d);
    s->run_status[m] = rb_run_motion(&s->c, m, 0, r, rm, d);
    run->motion = rb_batch_strdup(cm->name ? cm->name : "?");
    if (!run->motion && s->run_status[m] == RB_OK)
        s->run_status[m] = RB_ERR_NOMEM;
    if (s->run_status[m] != RB_OK)
        return;
    run->pass = rm->verdict.pass;
    run->warnings = rm->verdict.warnings;
    rb_governs_limit lim;
    run->margin = rb_verdict_governing(&s->c.criteria, r, &rm->verdict, &lim);
    run->limit = (int)lim;
    run->reason = rb_batch_strdup(rm->verdict.reason);
    if (!run->reason)
        s->run_status[m] = RB_ERR_NOMEM;
    rb_batch_source src = {r, NULL, NULL};
    rb_batch_columns_fill(run, &src, 0);
    rb_batch_columns_fill(run, NULL, 1);
    if (s->c.has_concrete && r->anchor_checked) {
        const rb_anchor_strength *a = &s->c.anchor;
        run->has_anchor = 1;
        run->anchor_utilization = r->anchor_max_ratio;
        run->anchor_mode = (int)rb_anchor_governing_mode(a, r->anchor_tension_n,
                                                         r->anchor_shear_n);
    }
    if (!design)
        return;
    rb_case_design cd;
    memset(&cd, 0, sizeof cd);
    rb_run_design_criteria(&s->c, &cd);
    rb_motion_design md;
    /* the row's own run is the recommended gap's at the case's own gap */
    rb_status st = rb_run_motion_design(&s->c, m, r, RB_RUN_DESIGN_BRIEF, 1, &cd, &md, d);
    if (st == RB_OK) {
        src.factor = rb_run_own_factor(&s->c, &md);
        src.design = &md;
        rb_batch_columns_fill(run, &src, 1);
    }
    rb_motion_design_free(&md);
    if (st != RB_OK)
        s->run_status[m] = st;
}

/* Report file names: the work index keeps them unique and in work order
 * whatever the tags, and the same in every shard. */
void rb_batch_report_stem(size_t index, const char *tag, size_t total, char *buf,
                          size_t n)
{
    int width = 1;
    for (size_t t = total > 0 ? total - 1 : 0; t >= 10; t /= 10)
        width++;
    int k = snprintf(buf, n, "%0*zu-", width, index);
    for (const char *p = tag; *p && k + 1 < (int)n && k < 120; p++, k++) {
        int ok = (*p >= 'A' && *p <= 'Z') || (*p >= 'a' && *p <= 'z')
              || (*p >= '0' && *p <= '9') || *p == '-' || *p == '_' || *p == '.';
        buf[k] = ok ? *p : '_';
    }
    buf[k] = '\0';
}

/* DIR/STEM.SUFFIX, staged with the summaries when they are */
static rb_status write_one(const rb_batch_opts *o, const char *stem, const char *suffix,
                           const char *data, rb_diag *d)
{
    char path[4600];
    snprintf(path, sizeof path, "%s/%s.%s", o->reports_dir, stem, suffix);
    return o->report_stage
        ? rb_outplan_stage_data(o->report_stage, path, data, strlen(data), d)
        : rb_outfile_write_all(path, data, strlen(data), 0, d);
}

static rb_status write_reports(const rb_batch_slot *s, const rb_batch_case *bc,
                               const rb_batch_opts *o, size_t total,
                               const rb_report *rep, rb_diag *d)
{
    char stem[200];
    char *json = NULL, *text = NULL;
    rb_status st = rb_report_render_json(rep, &json, d);
    if (st == RB_OK)
        st = rb_report_render_text(rep, o->report_template, &text, d);
    rb_batch_report_stem(bc->index, bc->tag, total, stem, sizeof stem);
    if (st == RB_OK)
        st = write_one(o, stem, "json", json, d);
    if (st == RB_OK)
        st = write_one(o, stem, "txt", text, d);
    /* the fragility's, as `rockbolt fragility --json` and its text */
    if (st == RB_OK && s->frag_json)
        st = write_one(o, stem, "fragility.json", s->frag_json, d);
    if (st == RB_OK && s->frag_text)
        st = write_one(o, stem, "fragility.txt", s->frag_text, d);
    free(json);
    free(text);
    return st;
}

void rb_batch_case_finish(rb_batch_slot *s, rb_batch_case *bc, const rb_batch_opts *o,
                          size_t total)
{
    if (!s->loaded)
        goto done;
    for (size_t m = 0; m < bc->n_runs; m++) {
        if (s->run_status[m] == RB_OK)
            continue;
        rb_diag d;
        rb_diag_clear(&d);
        rb_diag_set_file(&d, "%s", bc->source);
        d.line = bc->line;   /* the row of a list; 0 for a case file */
        rb_diag_set_key(&d, "motion '%.100s'",
                        s->c.motions[m].name ? s->c.motions[m].name : "?");
        rb_diag_set_msg(&d, "%s%s%.400s", rb_status_str(s->run_status[m]),
                        s->run_diag[m].msg[0] ? ": " : "", s->run_diag[m].msg);
        bc->verdict = RB_BATCH_ERROR;
        rb_batch_case_set_error(bc, &d);
        bc->n_errors = 1;
        goto done;
    }
    if (s->frag_status != RB_OK) {
        rb_diag d;
        rb_diag_clear(&d);
        rb_diag_set_file(&d, "%s", bc->source);
        d.line = bc->line;
        rb_diag_set_key(&d, "fragility%s%.100s", s->frag_diag.key[0] ? ": " : "",
                        s->frag_diag.key);
        rb_diag_set_msg(&d, "%s%s%.400s", rb_status_str(s->frag_status),
                        s->frag_diag.msg[0] ? ": " : "", s->frag_diag.msg);
        bc->verdict = RB_BATCH_ERROR;
        rb_batch_case_set_error(bc, &d);
        bc->n_errors = 1;
        goto done;
    }
    rb_report rep;
    rb_diag d;
    rb_diag_clear(&d);
    rb_run_conclude(&s->c, s->rms, &rep);
    bc->verdict = rep.pass ? RB_BATCH_PASS : RB_BATCH_FAIL;
    bc->reason = rb_batch_strdup(rep.reason);
    if (o->reports_dir) {
        if (write_reports(s, bc, o, total, &rep, &d) != RB_OK) {
            if (!d.key[0])
                rb_diag_set_key(&d, "--reports");
            bc->verdict = RB_BATCH_ERROR;
            rb_batch_case_set_error(bc, &d);
            bc->n_errors = 1;
        }
    }
done:
    if (bc->fragility && bc->verdict != RB_BATCH_PASS && bc->verdict != RB_BATCH_FAIL) {
        /* a case that was not solved shows its error alone */
        free(bc->fragility->error);
        free(bc->fragility);
        bc->fragility = NULL;
    }
    if (!bc->reason) {
        char buf[700];
        snprintf(buf, sizeof buf, "%s: %s", bc->verdict == RB_BATCH_UNREADABLE
                 ? "cannot read the case" : "error", rb_batch_case_error(bc)->msg);
        bc->reason = rb_batch_strdup(buf);
    }
    rb_batch_slot_free(s);
}

void rb_batch_slot_free(rb_batch_slot *s)
{
    if (s->results)
        for (size_t m = 0; m < s->c.n_motions; m++)
            rb_result_free(&s->results[m]);
    free(s->results);
    free(s->rms);
    free(s->run_status);
    free(s->run_diag);
    free(s->frag_json);
    free(s->frag_text);
    rb_case_free(&s->c);
    memset(s, 0, sizeof *s);
}

char *rb_batch_default_tag(const rb_batch_item *it)
{
    return it->tag ? rb_batch_strdup(it->tag) : stem_of(it->source);
}
