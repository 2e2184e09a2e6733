/* The design searches' run against the case pipeline, on case files:
 *
 *   judge_probe CASE.yaml...
 *
 * For every motion of every case, the pipeline's run (rb_run_motion, as
 * check and batch make it) and the searches' run at the motion's own level
 * (rb_design_run_at) must give the same verdict and the same numbers: the
 * "verdict", "validity" and "result" parts of the motion's JSON report are
 * compared as text. Prints one line per mismatch and a count; exit 1 when
 * anything differs or a case does not run.
 *
 *   judge_probe --design CASE.yaml...
 *
 * For every motion, the design factors against no yield and no break
 * (rb_run_design_criteria) and then the one judge at the ends of each
 * final bracket, the same scaled motion as the search's: the passing end
 * must pass confirmed (rb_design_run_at), the failing end fail. Prints
 * each factor with its confirm_fails. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cjson/cJSON.h>
#include "rockbolt/design.h"
#include "rockbolt/run.h"

/* The parts of motion 0 of a one-motion report that a run decides. */
static char *run_parts(const rb_case *c, const rb_report_motion *rm)
{
    rb_report rep;
    char *json = NULL, *out = NULL;
    memset(&rep, 0, sizeof rep);
    rep.kase = c;
    rep.motions = rm;
    rep.n_motions = 1;
    rb_model_derive(&c->model, &rep.derived, NULL);
    rb_report_conclude(&rep);
    if (rb_report_render_json(&rep, &json, NULL) != RB_OK)
        return NULL;
    cJSON *root = cJSON_Parse(json), *m = cJSON_GetArrayItem(
        cJSON_GetObjectItem(root, "motions"), 0), *parts = cJSON_CreateObject();
    static const char *const keys[] = {"verdict", "validity", "result"};
    for (int k = 0; m && parts && k < 3; k++)
        cJSON_AddItemToObject(parts, keys[k],
                              cJSON_Duplicate(cJSON_GetObjectItem(m, keys[k]), 1));
    if (m && parts)
        out = cJSON_PrintUnformatted(parts);
    cJSON_Delete(parts);
    cJSON_Delete(root);
    free(json);
    return out;
}

static int probe(const char *path, long *runs)
{
    rb_case c;
    rb_diag_list diags = {0};
    int bad = 0;
    if (rb_case_load(path, &c, &diags) != RB_OK) {
        printf("%s: does not load: %s\n", path, diags.n ? diags.items[0].msg : "?");
        rb_diag_list_free(&diags);
        return 1;
    }
    rb_diag_list_free(&diags);
    for (size_t i = 0; i < c.n_motions; i++) {
        rb_result r1, r2;
        rb_report_motion rm1, rm2;
        rb_diag d;
        memset(&rm2, 0, sizeof rm2);
        rb_diag_clear(&d);
        if (rb_run_motion(&c, i, 0, &r1, &rm1, &d) != RB_OK) {
            printf("%s: motion %zu: the pipeline's run fails: %s\n", path, i + 1, d.msg);
            bad = 1;
            rb_result_free(&r1);
            continue;
        }
        const rb_motion *mo = &c.motions[i].motion;
        if (rb_design_run_at(&c.model, mo, &c.solve, &c.criteria, rb_motion_peak(mo), &r2,
                             &rm2.verdict, rm2.confirm, &rm2.n_confirm, &d) != RB_OK) {
            printf("%s: motion %zu: the search's run fails: %s\n", path, i + 1, d.msg);
            bad = 1;
        } else {
            rm2.motion = &c.motions[i];
            rm2.result = &r2;
            char *a = run_parts(&c, &rm1), *b = run_parts(&c, &rm2);
            if (!a || !b || strcmp(a, b) != 0) {
                printf("%s: motion %zu differs:\n  pipeline %s\n  search   %s\n", path, i + 1,
                       a ? a : "(no report)", b ? b : "(no report)");
                bad = 1;
            }
            free(a);
            free(b);
            (*runs)++;
        }
        rb_result_free(&r1);
        rb_result_free(&r2);
    }
    rb_case_free(&c);
    return bad;
}

/* The verdict rb_design_run_at gives at level: 1 pass, 0 fail, -1 error. */
static int verdict_at(const rb_case *c, size_t i, const rb_criteria *cr, double level,
                      size_t *n_confirm)
{
    rb_result r;
    rb_verdict v;
    rb_confirm_run runs[RB_CONFIRM_RUNS];
    const rb_motion *mo = &c->motions[i].motion;
    if (rb_design_run_at(&c->model, mo, &c->solve, cr, level, &r, &v, runs, n_confirm,
                         NULL) != RB_OK)
        return -1;
    rb_result_free(&r);
    return v.pass;
}

static int probe_design(const char *path)
{
    rb_case c;
    rb_diag_list diags = {0};
    rb_case_design cd;
    int bad = 0;
    if (rb_case_load(path, &c, &diags) != RB_OK) {
        printf("%s: does not load\n", path);
        rb_diag_list_free(&diags);
        return 1;
    }
    rb_diag_list_free(&diags);
    memset(&cd, 0, sizeof cd);
    rb_run_design_criteria(&c, &cd);
    for (size_t i = 0; i < c.n_motions; i++) {
        const rb_criteria *crit = cd.factor_criteria;
        for (int k = 0; k < RB_N_CRITERIA; k++) {
            rb_design_factor_result f;
            size_t n_pass = 0, n_fail = 0;
            /* the search the design command makes */
            rb_design_hints hints = rb_run_design_factor_hints();
            if (rb_design_factor_near(&c.model, &c.motions[i].motion, &c.solve, &crit[k],
                                      &c.design, 2, NULL, &hints, &f, NULL) != RB_OK) {
                printf("%s: motion %zu: the search fails\n", path, i + 1);
                bad = 1;
                continue;
            }
            int at_pass = f.level_mps2 > 0
                          ? verdict_at(&c, i, &crit[k], f.level_mps2, &n_pass) : 1;
            int at_fail = f.no_failure ? 0 : verdict_at(&c, i, &crit[k], f.fail_mps2, &n_fail);
            printf("%s: motion %zu %s: level %.9g A*, fails at %.9g A*, confirm_fails %ld, "
                   "confirming runs at the level %zu and at the failing one %zu\n", path,
                   i + 1, k ? "no-break" : "no-yield", f.level_astar, f.fail_astar,
                   f.confirm_fails, n_pass, n_fail);
            /* the failing end may be a pass that its confirmation failed:
             * that is where a search goes on below an unconfirmed pass */
            if (at_pass != 1 || at_fail != 0) {
                printf("  FAIL: the judge at the bracket's ends gives %d (pass) and %d "
                       "(fail)\n", at_pass, at_fail);
                bad = 1;
            }
        }
    }
    rb_case_design_free(&cd);
    rb_case_free(&c);
    return bad;
}

int main(int argc, char **argv)
{
    int bad = 0;
    long runs = 0;
    if (argc > 1 && strcmp(argv[1], "--design") == 0) {
        for (int k = 2; k < argc; k++)
            bad += probe_design(argv[k]);
        printf("judge_probe --design: %d of %d cases differ\n", bad, argc - 2);
        return bad ? 1 : 0;
    }
    for (int k = 1; k < argc; k++)
        bad += probe(argv[k], &runs);
    printf("judge_probe: %ld runs of %d cases, %d cases differ\n", runs, argc - 1, bad);
    return bad ? 1 : 0;
}
