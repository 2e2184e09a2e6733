/* "rockbolt motion CASE.yaml": every motion's floor accelerations as the
 * cabinet feels them (rb_run_floors), each component as a PEER AT2 record
 * and a CSV under --dir, with a summary on stdout and as JSON, and each
 * TRS against its RRS as a figure (--svg, --html). Every file
 * is planned and checked against the case's inputs before anything is
 * written, and all are written or none. Exit 0 when they are written and
 * every component matched to a target is accepted, 1 when they are written
 * and one is not. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cli.h"
#include "cli_batch.h"
#include "rockbolt/batch.h"
#include "rockbolt/floor_files.h"
#include "rockbolt/names.h"
#include "rockbolt/outplan.h"
#include "rockbolt/plot.h"
#include "rockbolt/run.h"

typedef struct {
    const rb_case *c;
    const rb_case_floors *f;
    char **files;           /* RB_FLOOR_FILE_INDEX: the --dir files, or NULL */
    size_t *plan_of;        /* the plan's index of each, SIZE_MAX if none */
    size_t n_files;
} outputs;

static char *text_of(const void *ctx)
{
    const outputs *o = ctx;
    return rb_floors_render_text(o->c, o->f, (const char *const *)o->files);
}

static char *json_of(const void *ctx)
{
    const outputs *o = ctx;
    return rb_floors_render_json(o->c, o->f, (const char *const *)o->files);
}

static rb_status figure(const void *ctx, const char *title, char **out, rb_diag *d)
{
    const outputs *o = ctx;
    return rb_plot_floors_svg(o->c, o->f, title, out, d);
}

static rb_status dir_file(const void *ctx, size_t i, FILE *fp, rb_diag *d)
{
    const outputs *o = ctx;
    for (size_t k = 0; k < o->n_files; k++) {
        if (o->plan_of[k] != i)
            continue;
        size_t m = k / (RB_FLOOR_AXES * RB_FLOOR_FILE_KINDS);
        rb_floor_axis a = (rb_floor_axis)(k / RB_FLOOR_FILE_KINDS % RB_FLOOR_AXES);
        rb_status st = k % RB_FLOOR_FILE_KINDS == RB_FLOOR_FILE_AT2
                       ? rb_floors_write_at2(fp, o->c, o->f, m, a)
                       : rb_floors_write_csv(fp, o->c, o->f, m, a);
        if (st != RB_OK)
            rb_diag_set_msg(d, "cannot write %s", o->files[k]);
        return st;
    }
    rb_diag_set_msg(d, "no file planned at %zu (a bug)", i);
    return RB_ERR_INVALID;
}

/* DIR/<index>-<motion>-<axis>.at2 and .csv for every component: planned
 * with the other outputs (never an input of the case, nor a FIFO or
 * device that happens to have the name). */
static rb_exit plan_files(const rb_cli_opts *op, rb_outplan *p, outputs *o)
{
    const rb_case_floors *f = o->f;
    static const char *const ext[RB_FLOOR_FILE_KINDS] = {"at2", "csv"};
    o->n_files = f->n_motions * RB_FLOOR_AXES * RB_FLOOR_FILE_KINDS;
    o->files = calloc(o->n_files ? o->n_files : 1, sizeof *o->files);
    o->plan_of = malloc((o->n_files ? o->n_files : 1) * sizeof *o->plan_of);
    if (!o->files || !o->plan_of) {
        rb_cli_error(NULL, NULL, "out of memory");
        return RB_EXIT_INTERNAL;
    }
    for (size_t k = 0; k < o->n_files; k++) {
        size_t m = k / (RB_FLOOR_AXES * RB_FLOOR_FILE_KINDS);
        int a = (int)(k / RB_FLOOR_FILE_KINDS % RB_FLOOR_AXES);
        char stem[200];
        o->plan_of[k] = SIZE_MAX;
        if (!f->motions[m].axis[a].present)
            continue;
        rb_batch_report_stem(m, o->c->motions[m].name ? o->c->motions[m].name : "motion",
                             f->n_motions, stem, sizeof stem);
        size_t len = strlen(op->dir_path) + strlen(stem) + 16;
        if (!(o->files[k] = malloc(len))) {
            rb_cli_error(NULL, NULL, "out of memory");
            return RB_EXIT_INTERNAL;
        }
        snprintf(o->files[k], len, "%s/%s-%s.%s", op->dir_path, stem,
                 rb_enum_str(rb_floor_axis_names, a), ext[k % RB_FLOOR_FILE_KINDS]);
        rb_diag d;
        rb_diag_clear(&d);
        rb_status st = rb_outplan_add(p, "--dir", o->files[k], &d);
        if (st != RB_OK)
            return rb_cli_plan_error(st, &d);
        o->plan_of[k] = rb_outplan_count(p) - 1;
        if (!rb_outplan_is_file(p, o->plan_of[k])) {
            rb_cli_error(o->files[k], "--dir", "a FIFO, device or descriptor has the name "
                         "this motion's file takes: it is never written over; remove it or "
                         "give another directory");
            return RB_EXIT_USAGE;
        }
    }
    return RB_EXIT_PASS;
}

rb_exit rb_cli_motion_run(const rb_cli_opts *op)
{
    rb_outplan p;
    rb_case c;
    rb_case_floors f;
    outputs out;
    int made_dir = 0;
    memset(&c, 0, sizeof c);
    memset(&f, 0, sizeof f);
    memset(&out, 0, sizeof out);
    rb_outplan_init(&p);
    rb_exit e = rb_cli_plan_case_outputs(op, &p);
    if (e == RB_EXIT_PASS && op->dir_path)
        e = rb_cli_output_dir(op->dir_path, "--dir", &made_dir);
    if (e == RB_EXIT_PASS)
        e = rb_cli_load_case_planned(op, &c, &p);
    if (e == RB_EXIT_PASS) {
        rb_diag d;
        rb_diag_clear(&d);
        rb_status st = rb_run_floors(&c, &f, &d);
        if (st != RB_OK) {
            rb_cli_error(op->case_path, d.key[0] ? d.key : NULL, "%s", d.msg[0] ? d.msg
                         : rb_status_str(st));
            e = st == RB_ERR_INVALID || st == RB_ERR_LIMIT ? RB_EXIT_USAGE : RB_EXIT_INTERNAL;
        }
    }
    out.c = &c;
    out.f = &f;
    if (e == RB_EXIT_PASS && (op->svg_path || op->html_path) && !rb_plot_floors_has_figure(&f)) {
        rb_cli_error(op->case_path, op->svg_path ? "--svg" : "--html", "no motion of the "
                     "case has a target spectrum to draw its TRS against (the figure of "
                     "--svg and --html)");
        e = RB_EXIT_USAGE;
    }
    if (e == RB_EXIT_PASS && op->dir_path)
        e = plan_files(op, &p, &out);
    if (e == RB_EXIT_PASS) {
        char title[256];
        snprintf(title, sizeof title, "Floor motions of %.200s",
                 c.name ? c.name : "the case");
        rb_cli_renders r = {&out, title, "summary", text_of, json_of, NULL, figure,
                            NULL, NULL, "--dir", dir_file};
        e = rb_cli_emit_case_outputs(op, &p, &r);
        /* written and read: a motion that fails its acceptance is a failed
         * check of the motion (docs/exit-codes.md) */
        if (e == RB_EXIT_PASS && rb_case_floors_fail(&f))
            e = RB_EXIT_FAIL;
    }
    for (size_t k = 0; out.files && k < out.n_files; k++)
        free(out.files[k]);
    free(out.files);
    free(out.plan_of);
    rb_case_floors_free(&f);
    rb_case_free(&c);
    rb_outplan_free(&p);
    /* refused before anything was written: not even the directory is left */
    if (e != RB_EXIT_PASS && e != RB_EXIT_FAIL && made_dir)
        rmdir(op->dir_path);
    return e;
}
