/* Writes sample figures for the parser and browser checks, and for looking
 * at: the time-history figure of every motion of a case, an amplitude
 * sweep of its first motion, a frequency sweep of its model, and the HTML
 * page with all of them.
 *
 * Usage: plot_sample OUT_DIR [CASE.yaml]   (from the repository root;
 * the case defaults to cases/reference-elcentro.yaml). Writes
 * OUT_DIR/history-N.svg, sweep-frequency.svg, sweep-amplitude.svg and
 * report.html. Exit 0 on success, 1 on any error (reason on stderr). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/rockbolt.h"
#include "rockbolt/plot.h"

#define N_SWEEP_POINTS 9

static int save(const char *dir, const char *name, const char *text)
{
    char path[1024];
    FILE *fp;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    fp = fopen(path, "w");
    if (fp) {
        int bad = fputs(text, fp) < 0;
        if (fclose(fp) == 0 && !bad)
            return 0;
    }
    fprintf(stderr, "plot_sample: cannot write %s\n", path);
    return 1;
}

static int fail(const char *what, rb_status st, const rb_diag *d)
{
    fprintf(stderr, "plot_sample: %s: %s: %s\n", what, rb_status_str(st), d->msg);
    return 1;
}

/* Both sweeps, short runs: the figures, not the numbers, are under test. */
static int sweeps(const rb_case *c, const char *dir, char **svg_f, char **svg_a)
{
    rb_sweep_opts o;
    rb_sweep s;
    rb_diag d;
    rb_status st;
    rb_diag_clear(&d);
    rb_sweep_opts_init(&o, RB_SWEEP_FREQUENCY);
    o.from = 0.4;
    o.to = 1.6;
    o.n_points = N_SWEEP_POINTS;
    o.amplitude_astar = 0.3;
    o.duration_s = 3;
    memset(&s, 0, sizeof s);
    st = rb_sweep_frequency(&c->model, &c->solve, &c->criteria, &o, 1, &s, &d);
    if (st == RB_OK)
        st = rb_plot_sweep_svg(&s, "Frequency response of the reference cabinet", svg_f, &d);
    rb_sweep_free(&s);
    if (st != RB_OK)
        return fail("frequency sweep", st, &d);
    rb_sweep_opts_init(&o, RB_SWEEP_AMPLITUDE);
    o.from = 0.05;
    o.to = 0.6;
    o.n_points = N_SWEEP_POINTS;
    memset(&s, 0, sizeof s);
    st = rb_sweep_amplitude(&c->model, &c->motions[0].motion, &c->solve, &c->criteria,
                            &o, 1, NULL, &s, &d);
    if (st == RB_OK)
        st = rb_plot_sweep_svg(&s, NULL, svg_a, &d);
    rb_sweep_free(&s);
    if (st != RB_OK)
        return fail("amplitude sweep", st, &d);
    return save(dir, "sweep-frequency.svg", *svg_f) || save(dir, "sweep-amplitude.svg", *svg_a);
}

int main(int argc, char **argv)
{
    const char *dir = argc > 1 ? argv[1] : NULL;
    const char *path = argc > 2 ? argv[2] : "cases/reference-elcentro.yaml";
    rb_case c;
    rb_diag_list dl = {0};
    rb_result *res = NULL;
    rb_report_motion *rm = NULL;
    rb_report rep;
    rb_solve_opts so;
    rb_diag d;
    rb_status st;
    char *text = NULL, *html = NULL, *svg_f = NULL, *svg_a = NULL, **svgs = NULL;
    size_t i, n_svgs = 0;
    int rc = 1;
    if (!dir) {
        fprintf(stderr, "usage: plot_sample OUT_DIR [CASE.yaml]\n");
        return 2;
    }
    memset(&c, 0, sizeof c);
    memset(&rep, 0, sizeof rep);
    rb_diag_clear(&d);
    if (rb_case_load(path, &c, &dl) != RB_OK) {
        fprintf(stderr, "plot_sample: cannot load %s: %s\n", path,
                dl.n ? dl.items[0].msg : "?");
        rb_diag_list_free(&dl);
        return 1;
    }
    rb_diag_list_free(&dl);
    res = calloc(c.n_motions, sizeof *res);
    rm = calloc(c.n_motions, sizeof *rm);
    svgs = calloc(2 * c.n_motions + 2, sizeof *svgs);
    if (!res || !rm || !svgs)
        goto out;
    so = c.solve;
    so.history_dt_s = 0.005;
    for (i = 0; i < c.n_motions; i++) {
        st = rb_solve_run(&c.model, &c.motions[i].motion, &so, &res[i], &d);
        if (st != RB_OK) {
            fail("solve", st, &d);
            goto out;
        }
        rm[i].motion = &c.motions[i];
        rm[i].result = &res[i];
        rb_judge(&c.criteria, &res[i], &rm[i].verdict);
    }
    rep.kase = &c;
    rep.motions = rm;
    rep.n_motions = c.n_motions;
    if (rb_model_derive(&c.model, &rep.derived, &d) != RB_OK)
        goto out;
    rb_report_conclude(&rep);
    st = rb_report_render_text(&rep, rb_template_builtin("report.txt"), &text, &d);
    if (st != RB_OK) {
        fail("text report", st, &d);
        goto out;
    }
    for (i = 0; i < c.n_motions; i++) {
        char name[64];
        st = rb_plot_history_svg(&rep, i, &svgs[n_svgs], &d);
        if (st != RB_OK) {
            fail("history figure", st, &d);
            goto out;
        }
        snprintf(name, sizeof name, "history-%zu.svg", i + 1);
        if (save(dir, name, svgs[n_svgs++]))
            goto out;
        st = rb_plot_hysteresis_svg(&rep, i, &svgs[n_svgs], &d);
        if (st != RB_OK) {
            fail("hysteresis figure", st, &d);
            goto out;
        }
        snprintf(name, sizeof name, "hysteresis-%zu.svg", i + 1);
        if (save(dir, name, svgs[n_svgs++]))
            goto out;
    }
    if (sweeps(&c, dir, &svg_f, &svg_a))
        goto out;
    svgs[n_svgs++] = svg_f;
    svgs[n_svgs++] = svg_a;
    svg_f = svg_a = NULL;
    {
        char title[256];
        snprintf(title, sizeof title, "%s: %.200s", rep.pass ? "PASS" : "FAIL", c.name);
        st = rb_plot_html_page(&rep, title, text, (const char *const *)svgs, n_svgs, &html,
                               &d);
    }
    if (st != RB_OK) {
        fail("html page", st, &d);
        goto out;
    }
    rc = save(dir, "report.html", html);
out:
    for (i = 0; svgs && i < n_svgs; i++)
        free(svgs[i]);
    free(svgs);
    free(svg_f);
    free(svg_a);
    free(html);
    free(text);
    for (i = 0; res && i < c.n_motions; i++)
        rb_result_free(&res[i]);
    free(res);
    free(rm);
    rb_case_free(&c);
    return rc;
}
