/* Time-history figures of the cases that reproduce the thesis's figures,
 * drawn by the plot module into docs/validation/, next to the report. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "rockbolt/rockbolt.h"
#include "rockbolt/plot.h"
#include "vd.h"
#include "rockbolt/outfile.h"

/* History interval: the plot reduces to its pixel columns anyway, and
 * 0.01 s is twenty points per period of the 5 Hz frame. */
#define VD_FIGURE_DT_S 0.01

const vd_figure_spec vd_figures[] = {
    {"fig-5.13-harmonic.yaml", "Figs. 5.13 and 5.14"},
    {"fig-5.15-small-gap-resonance.yaml", "Fig. 5.15"},
    {"fig-5.16-fixed-base-resonance.yaml", "Fig. 5.16"},
    {"fig-5.17-small-gap-elcentro.yaml", "Fig. 5.17"},
    {"table-6.2-nonyielding-gr0.01.yaml", "Fig. 5.25"},
    {"table-6.2-nonyielding-gr0.03.yaml", "Fig. 5.26"},
    {"table-6.2-yielding-gr0.001.yaml", "Fig. 6.8"},
    {"table-6.2-yielding-gr0.01.yaml", "Fig. 6.9"},
    {"table-6.2-yielding-gr0.03.yaml", "Fig. 6.10"},
    {"table-6.3-elcentro-0.2.yaml", "Fig. 6.11"},
    {"table-6.3-elcentro-0.3.yaml", "Fig. 6.12"},
    {"table-6.4-taft-0.2.yaml", "Fig. 6.14"},
    {"table-6.4-taft-0.3.yaml", "Fig. 6.15"},
    {"table-6.4-taft-0.4.yaml", "Fig. 6.16"},
    {"table-6.5-taft-building-4hz.yaml", "Fig. 6.18"},
    {NULL, NULL}};

int vd_figure_dir(const char *dir)
{
    if (mkdir(dir, 0777) == 0 || errno == EEXIST)
        return 1;
    fprintf(stderr, "%s: %s\n", dir, strerror(errno));
    return 0;
}

int vd_figure_write(const char *root, const char *kase, const char *svg_path)
{
    char path[1024];
    snprintf(path, sizeof path, "%s/cases/thesis/%s", root, kase);
    rb_case c;
    rb_diag_list dl = {0};
    rb_status st = rb_case_load(path, &c, &dl);
    rb_diag_list_free(&dl);
    if (st != RB_OK) {
        fprintf(stderr, "%s: figure not drawn: %s\n", kase, rb_status_str(st));
        return 0;
    }
    rb_solve_opts o = c.solve;
    o.history_dt_s = VD_FIGURE_DT_S;
    rb_result r;
    rb_diag d;
    rb_diag_clear(&d);
    st = rb_solve_run(&c.model, &c.motions[0].motion, &o, &r, &d);
    char *svg = NULL;
    if (st == RB_OK) {
        rb_report_motion m;
        memset(&m, 0, sizeof m);
        m.motion = &c.motions[0];
        m.result = &r;
        rb_judge(&c.criteria, &r, &m.verdict);
        rb_report rep;
        memset(&rep, 0, sizeof rep);
        rep.kase = &c;
        rep.motions = &m;
        rep.n_motions = 1;
        st = rb_model_derive(&c.model, &rep.derived, &d);
        if (st == RB_OK) {
            rb_report_conclude(&rep);
            st = rb_plot_history_svg(&rep, 0, &svg, &d);
        }
        if (st == RB_OK)
            st = rb_outfile_write_all(svg_path, svg, strlen(svg), 0, &d);
    }
    if (st != RB_OK)
        fprintf(stderr, "%s: figure not drawn: %s: %s\n", kase, rb_status_str(st), d.msg);
    free(svg);
    rb_result_free(&r);
    rb_case_free(&c);
    return st == RB_OK;
}
