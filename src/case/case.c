/* rb_case_load: the entry point of the case loader (its error context is
 * case_ctx.c).
 *
 * Runs the stages of case_internal.h in order and keeps going after
 * semantic errors so that one run reports every problem in a case; only a
 * syntax or limit error (after which the tree is incomplete) stops it. On
 * any error the half-built case is freed, so the caller either gets a
 * complete, validated case or a list of diagnostics, never both. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "case_internal.h"
#include "rockbolt/sandbox.h"
#include "util/grow.h"

void rb_cmotion_free(rb_cmotion *m)
{
    if (!m)
        return;
    free(m->name);
    if (m->vertical) {
        rb_cmotion_free(m->vertical);
        free(m->vertical);
    }
}

void rb_case_free(rb_case *c)
{
    if (!c)
        return;
    free(c->path);
    free(c->name);
    free(c->description);
    free(c->fragility.p58_id);
    rb_case_project_free(&c->project);
    for (size_t i = 0; c->motions && i < c->n_motions; i++) {
        free(c->motions[i].name);
        free(c->motions[i].source);
        rb_series_free(&c->motions[i].series);
        rb_series_free(&c->motions[i].h2);
        rb_case_motion *v = c->motions[i].vertical;
        if (v) {
            free(v->name);
            free(v->source);
            rb_series_free(&v->series);
            free(v);
        }
    }
    free(c->motions);
    for (size_t i = 0; c->targets && i < c->n_targets; i++) {
        rb_target_free(&c->targets[i].target);
        free(c->targets[i].file);
    }
    free(c->targets);
    for (size_t i = 0; c->input_files && i < c->n_input_files; i++)
        free(c->input_files[i]);
    free(c->input_files);
    memset(c, 0, sizeof *c);
}

/* Append a copy of path to cs->input_files unless it is there already. */
static int case_add_input(rb_case *cs, const char *path)
{
    for (size_t i = 0; i < cs->n_input_files; i++)
        if (strcmp(cs->input_files[i], path) == 0)
            return 1;
    size_t len = strlen(path) + 1;
    char *copy = malloc(len);
    if (!copy)
        return 0;
    memcpy(copy, path, len);
    cs->input_files[cs->n_input_files++] = copy;
    return 1;
}

/* The YAML files the loader read (c->files, in reading order) and the
 * record files of the motions. */
static int case_list_inputs(const rb_cctx *c, rb_case *cs, int first_in_memory)
{
    cs->input_files = calloc(c->n_files + cs->n_motions + cs->n_targets + 1,
                             sizeof *cs->input_files);
    if (!cs->input_files)
        return 0;
    for (size_t i = first_in_memory ? 1 : 0; i < c->n_files; i++)
        if (!case_add_input(cs, c->files[i]))
            return 0;
    for (size_t i = 0; i < cs->n_motions; i++)
        if (cs->motions[i].type == RB_CASE_MOTION_RECORD && cs->motions[i].source
            && !case_add_input(cs, cs->motions[i].source))
            return 0;
    for (size_t i = 0; i < cs->n_targets; i++)
        if (cs->targets[i].file && !case_add_input(cs, cs->targets[i].file))
            return 0;
    return 1;
}

static void cctx_free(rb_cctx *c)
{
    rb_record_cache_free(c->own_records);
    c->own_records = NULL;
    for (size_t i = 0; i < c->n_motions; i++)
        rb_cmotion_free(&c->motions[i]);
    free(c->motions);
    for (size_t i = 0; i < c->n_files; i++)
        free(c->files[i]);
}

/* Defaults of everything a case may leave out. */
static int case_defaults(rb_case *cs, const char *path)
{
    memset(cs, 0, sizeof *cs);
    rb_model_init(&cs->model);
    rb_solve_opts_init(&cs->solve);
    rb_criteria_init(&cs->criteria);
    cs->design.scan_start = 0.05;
    cs->design.scan_step = 0.05;
    cs->design.scan_end = 1.5;
    cs->design.resolution = 0.001;
    cs->design.gap_ratio_min = 0.0;
    /* a practical range: gaps beyond these are not built under the bolt
     * heads of equipment (docs/design.md, Recommended gap) */
    cs->design.gap_ratio_max = 0.03;
    cs->design.gap_ratio_step = 0.0025;
    cs->design.max_gap_m = RB_DESIGN_MAX_GAP_M;
    size_t len = strlen(path) + 1;
    cs->path = malloc(len);
    if (!cs->path)
        return 0;
    memcpy(cs->path, path, len);
    return 1;
}

rb_status rb_case_load(const char *path, rb_case *out, rb_diag_list *diags)
{
    return rb_case_load_cached(path, NULL, NULL, out, diags);
}

static rb_status case_load_any(const char *path, unsigned char *text, size_t len,
                                  rb_record_cache *cache, const rb_sandbox *sandbox,
                                  rb_case *out, rb_diag_list *diags);

rb_status rb_case_load_cached(const char *path, rb_record_cache *cache,
                              const rb_sandbox *sandbox, rb_case *out, rb_diag_list *diags)
{
    return case_load_any(path, NULL, 0, cache, sandbox, out, diags);
}

rb_status rb_case_load_text(const char *name, const char *text, size_t len,
                            rb_record_cache *cache, const rb_sandbox *sandbox,
                            rb_case *out, rb_diag_list *diags)
{
    unsigned char *copy = malloc(len + 1);
    if (!copy) {
        memset(out, 0, sizeof *out);
        return RB_ERR_NOMEM;
    }
    memcpy(copy, text, len);
    copy[len] = '\0';
    return case_load_any(name, copy, len, cache, sandbox, out, diags);
}

/* A case file at path, or (text != NULL, taken and freed) a document in
 * memory named path: a list row's overrides, whose `motion:` applies to
 * each motion of a base's list and which is not a file to list as read. */
static rb_status case_load_any(const char *path, unsigned char *text, size_t len,
                                  rb_record_cache *cache, const rb_sandbox *sandbox,
                                  rb_case *out, rb_diag_list *diags)
{
    rb_cctx c;
    char why[600];
    rb_ynode *root = NULL;
    memset(&c, 0, sizeof c);
    c.judge_concrete = -1;
    c.diags = diags;
    c.cache = cache;
    c.sandbox = sandbox;
    c.overrides = text != NULL;
    size_t first = diags->n;
    c.first_diag = first;
    if (!case_defaults(out, path)) {
        free(text);
        rb_case_free(out);
        return RB_ERR_NOMEM;
    }
    rb_status read;
    if (text) {
        read = rb_case_read_merged_text(&c, path, text, len, &root);
    } else if (path && !rb_sandbox_allows(sandbox, path, why, sizeof why)) {
        rb_cctx_error_at(&c, RB_ERR_IO, path, 0, 0, "case", "'%s' lies outside the "
                         "sandbox '%s' (%s)", path, rb_sandbox_dir(sandbox), why);
        c.fatal = 1;
        read = RB_ERR_IO;
    } else {
        read = rb_case_read_merged(&c, path, &root);
    }
    if (read == RB_OK && !c.fatal) {
        rb_case_read_schema(&c, root, out);
        if (!c.nomem)
            rb_case_resolve(&c, out, root);
    }
    rb_ynode_free(root);
    rb_cctx_finish(&c, first);
    rb_status st = c.nomem ? RB_ERR_NOMEM : c.status;
    if (st == RB_OK && c.n_errors > 0)
        st = RB_ERR_INVALID;
    if (st == RB_OK && !case_list_inputs(&c, out, text != NULL))
        st = RB_ERR_NOMEM;
    cctx_free(&c);
    if (st != RB_OK)
        rb_case_free(out);
    return st;
}
