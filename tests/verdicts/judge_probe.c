/* The design searches' run against the case pipeline, on case files:
 *
 *   judge_probe CASE.yaml...
 *
 * For every motion of every case, the pipeline's run (rb_run_motion, as
 * check and batch make it) and the searches' run at the motion's own level
 * (rb_design_run_at) must give the same verdict and the same numbers: the
 * "verdict", "validity" and "result" parts of the motion's JSON report are
 * compared as text. Prints one line per mismatch and a count; exit 1 when
 * anything differs or a case does not run. */
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
    if (rb_report_json_render(&rep, &json, NULL) != RB_OK)
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

int main(int argc, char **argv)
{
    int bad = 0;
    long runs = 0;
    for (int k = 1; k < argc; k++)
        bad += probe(argv[k], &runs);
    printf("judge_probe: %ld runs of %d cases, %d cases differ\n", runs, argc - 1, bad);
    return bad ? 1 : 0;
}
