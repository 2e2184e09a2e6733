/* The case pipeline (include/rockbolt/run.h). */
#include <string.h>
#include "rockbolt/run.h"

rb_status rb_run_motion(const rb_case *c, size_t i, int want_history, rb_result *r,
                        rb_report_motion *rm, rb_diag *diag)
{
    rb_solve_opts so = c->solve;
    if (!(c->write_history || want_history))
        so.history_dt_s = 0;
    else if (!(so.history_dt_s > 0))
        so.history_dt_s = RB_HISTORY_DT_DEFAULT_S;
    rb_status st = rb_solve_run(&c->model, &c->motions[i].motion, &so, r, diag);
    if (st != RB_OK)
        return st;
    rm->motion = &c->motions[i];
    rm->result = r;
    rb_judge_run(&c->criteria, &c->model, &c->motions[i].motion, &so, r, NULL, NULL,
                 &rm->verdict, rm->confirm, &rm->n_confirm);
    return RB_OK;
}

void rb_run_conclude(const rb_case *c, const rb_report_motion *rms, rb_report *rep)
{
    memset(rep, 0, sizeof *rep);
    rep->kase = c;
    rep->motions = rms;
    rep->n_motions = c->n_motions;
    rep->with_history = c->write_history;
    /* the case loaded, so its model derives */
    rb_model_derive(&c->model, &rep->derived, NULL);
    rb_report_conclude(rep);
}
