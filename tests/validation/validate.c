/* rb_validate: reproduce the thesis's published results and say how close
 * rockbolt comes.
 *
 *   rb_validate [--root DIR] [--write FILE] [--threads N] [--verbose]
 *
 * Reads cases/thesis/expected.csv under DIR (default: the current
 * directory, which must be the source root), runs every row's case through
 * the library and judges it against the row's tolerance. --write puts the
 * Markdown report in FILE (docs/validation.md is the published one; the
 * ctest writes into the build tree). Exit status: 0 when every row agrees
 * or is a known, explained difference; 1 when a row that must agree leaves
 * its tolerance or cannot be computed; 2 for bad usage or unreadable input. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "rockbolt/rockbolt.h"
#include "vd.h"
#include "rockbolt/outfile.h"

#define VD_COMMAND "cmake --build build && ./build/rb_validate --write docs/validation.md"

static int usage(void)
{
    fputs("usage: rb_validate [--root DIR] [--write FILE] [--threads N] [--verbose]\n",
          stderr);
    return 2;
}

static double now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static const char *verdict_word(vd_verdict v)
{
    static const char *const w[] = {"agrees", "OUT OF TOLERANCE", "differs (known)",
                                    "agrees, though expected to differ", "ERROR"};
    return w[v];
}

/* Draw the figures into the directory "validation" next to the report and
 * fill svgs[i] with the path of figure i relative to the report (NULL when
 * not drawn). Returns 0 if the directory cannot be made. */
static int draw_figures(const char *report, const char *root, char **svgs)
{
    char dir[1024];
    const char *slash = strrchr(report, '/');
    int len = slash ? (int)(slash - report) : 0;
    snprintf(dir, sizeof dir, "%.*s%svalidation", len, report, slash ? "/" : "");
    if (!vd_figure_dir(dir))
        return 0;
    for (size_t i = 0; vd_figures[i].kase; i++) {
        char path[1200], rel[300];
        /* the figure is named after its case, without ".yaml" */
        size_t n = strlen(vd_figures[i].kase) - strlen(".yaml");
        snprintf(rel, sizeof rel, "validation/%.*s.svg", (int)n, vd_figures[i].kase);
        snprintf(path, sizeof path, "%s/%.*s.svg", dir, (int)n, vd_figures[i].kase);
        svgs[i] = NULL;
        if (vd_figure_write(root, vd_figures[i].kase, path)) {
            size_t m = strlen(rel) + 1;
            if ((svgs[i] = malloc(m)))
                memcpy(svgs[i], rel, m);
        }
    }
    return 1;
}

static int write_report(const char *path, const vd_table *t, const vd_outcome *o,
                        const char *root)
{
    char notes[1024];
    snprintf(notes, sizeof notes, "%s/tests/validation/notes.md", root);
    size_t n_fig = 0;
    while (vd_figures[n_fig].kase)
        n_fig++;
    char **svgs = calloc(n_fig + 1, sizeof *svgs);
    if (!svgs || !draw_figures(path, root, svgs)) {
        free(svgs);
        return 0;
    }
    vd_report_opts opts = {VD_COMMAND, notes, (const char *const *)svgs, root};
    rb_outfile f;
    rb_diag d;
    rb_diag_clear(&d);
    int ok = 0;
    if (rb_outfile_open(&f, path, 0, &d) != RB_OK) {
        fprintf(stderr, "%s: %s\n", path, d.msg);
    } else if (!vd_report_write(f.fp, t, o, &opts)) {
        rb_outfile_abort(&f);
        fprintf(stderr, "%s: could not write the report\n", path);
    } else if (rb_outfile_commit(&f, &d) != RB_OK) {
        fprintf(stderr, "%s: %s\n", path, d.msg);
    } else {
        ok = 1;
    }
    for (size_t i = 0; i < n_fig; i++)
        free(svgs[i]);
    free(svgs);
    return ok;
}

int main(int argc, char **argv)
{
    const char *root = ".", *write = NULL;
    int threads = 1, verbose = 0;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--root") == 0 && i + 1 < argc)
            root = argv[++i];
        else if (strcmp(argv[i], "--write") == 0 && i + 1 < argc)
            write = argv[++i];
        else if (strcmp(argv[i], "--threads") == 0 && i + 1 < argc)
            threads = atoi(argv[++i]);
        else if (strcmp(argv[i], "--verbose") == 0)
            verbose = 1;
        else
            return usage();
    }
    char table_path[1024];
    snprintf(table_path, sizeof table_path, "%s/cases/thesis/expected.csv", root);
    vd_table t;
    if (!vd_table_read(table_path, &t))
        return 2;
    vd_outcome *o = calloc(t.n ? t.n : 1, sizeof *o);
    vd_ctx *c = vd_ctx_new(root, threads);
    if (!o || !c) {
        fputs("rb_validate: out of memory\n", stderr);
        free(o);
        vd_ctx_free(c);
        vd_table_free(&t);
        return 2;
    }
    double t0 = now_s();
    int failed = 0, counts[5] = {0};
    for (size_t i = 0; i < t.n; i++) {
        const vd_row *r = &t.rows[i];
        double ti = now_s();
        vd_evaluate(c, r, &o[i]);
        counts[o[i].verdict]++;
        int bad = o[i].verdict == VD_OUT || o[i].verdict == VD_ERROR;
        failed |= bad;
        if (bad || verbose || o[i].verdict == VD_AGREES_UNEXPECTED)
            printf("%s:%d: %s %s #%d: thesis %s, rockbolt %s (tolerance %s): %s%s%s"
                   " [%.2f s]\n", table_path, r->line, r->kase, r->quantity, r->motion,
                   r->thesis, o[i].verdict == VD_ERROR ? "-" : o[i].word, r->tol_text,
                   verdict_word(o[i].verdict), o[i].verdict == VD_ERROR ? ": " : "",
                   o[i].error, now_s() - ti);
    }
    printf("%zu rows: %d agree, %d differ as explained, %d out of tolerance, %d errors"
           "; %ld solver runs in %.1f s\n", t.n, counts[VD_AGREES] + counts[VD_AGREES_UNEXPECTED],
           counts[VD_DIFFERS], counts[VD_OUT], counts[VD_ERROR], vd_ctx_runs(c),
           now_s() - t0);
    int status = failed ? 1 : 0;
    if (write && !write_report(write, &t, o, root))
        status = 2;
    vd_ctx_free(c);
    free(o);
    vd_table_free(&t);
    return status;
}
