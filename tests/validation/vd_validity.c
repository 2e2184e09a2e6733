/* The validity section of docs/validation.md: every thesis case run as
 * `rockbolt check` runs it, with the status of each check of the model's
 * own assumptions (docs/solver.md, Validity). */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/run.h"
#include "vd.h"

static int by_name(const void *a, const void *b)
{
    return strcmp(*(char *const *)a, *(char *const *)b);
}

/* The case files of dir, sorted; *n set; NULL when there are none. */
static char **case_files(const char *dir, size_t *n)
{
    DIR *d = opendir(dir);
    struct dirent *e;
    char **names = NULL;
    size_t cap = 0;
    *n = 0;
    while (d && (e = readdir(d)) != NULL) {
        size_t len = strlen(e->d_name);
        if (len < 6 || strcmp(e->d_name + len - 5, ".yaml") != 0)
            continue;
        if (*n == cap) {
            char **p = realloc(names, (cap = cap ? 2 * cap : 64) * sizeof *p);
            if (!p)
                break;
            names = p;
        }
        if (!(names[*n] = malloc(len + 1)))
            break;
        memcpy(names[(*n)++], e->d_name, len + 1);
    }
    if (d)
        closedir(d);
    if (*n)
        qsort(names, *n, sizeof *names, by_name);
    return names;
}

static const char *status_cell(const rb_verdict *v, rb_check k)
{
    switch (v->check[k]) {
    case RB_CHECK_OK: return "ok";
    case RB_CHECK_WARNING: return "**warning**";
    case RB_CHECK_NOT_CHECKED: return "-";
    }
    return "?";
}

static int write_case(FILE *fp, const char *root, const char *name, int counts[3])
{
    char path[4200];
    rb_case c;
    rb_diag_list diags = {0};
    snprintf(path, sizeof path, "%s/cases/thesis/%s", root, name);
    if (rb_case_load(path, &c, &diags) != RB_OK) {
        rb_diag_list_free(&diags);
        return fprintf(fp, "| `%s` | - | does not load | | | | |\n", name) >= 0;
    }
    rb_diag_list_free(&diags);
    int ok = 1;
    for (size_t i = 0; ok && i < c.n_motions; i++) {
        rb_result r;
        rb_report_motion rm;
        rb_diag d;
        rb_diag_clear(&d);
        char mname[64];
        if (c.n_motions > 1)
            snprintf(mname, sizeof mname, " #%zu", i + 1);
        else
            mname[0] = '\0';
        if (rb_run_motion(&c, i, 0, &r, &rm, &d) != RB_OK) {
            ok = fprintf(fp, "| `%s`%s | run fails: %s | | | | |\n", name, mname, d.msg) >= 0;
            rb_result_free(&r);
            continue;
        }
        char head[RB_HEADLINE_MAX];
        rb_report_headline(rm.verdict.pass, rm.verdict.warnings, head, sizeof head);
        counts[0]++;
        counts[1] += rm.verdict.warnings != 0;
        counts[2] += (rm.verdict.warnings >> RB_CHECK_LIFT_OFF) & 1u;
        ok = fprintf(fp, "| `%s`%s | %s | %s (%.3g W) | %s (%.3g) | %s", name, mname, head,
                     status_cell(&rm.verdict, RB_CHECK_LIFT_OFF),
                     r.min_vertical_reaction_n / r.weight_n,
                     status_cell(&rm.verdict, RB_CHECK_SLIDING), r.max_friction_demand,
                     status_cell(&rm.verdict, RB_CHECK_BOLT_IMPACT)) >= 0;
        if (ok && r.rigid_bolts)
            ok = fprintf(fp, " (%.3g Fy)", r.max_bolt_impact_n / r.fy_row_n) >= 0;
        ok = ok && fputs(" |\n", fp) >= 0;
        rb_result_free(&r);
    }
    rb_case_free(&c);
    return ok;
}

int vd_validity_write(FILE *fp, const char *root)
{
    char dir[4200];
    size_t n;
    int counts[3] = {0, 0, 0};
    snprintf(dir, sizeof dir, "%s/cases/thesis", root);
    char **names = case_files(dir, &n);
    int ok = fputs("\n## Validity of the model on the thesis cases\n\n"
        "Every case of `cases/thesis/` as `rockbolt check` runs it, with the checks of "
        "the model's own assumptions (docs/solver.md, Validity): *lift-off* (the least "
        "vertical floor reaction, over W), *sliding* (the friction demand where the "
        "floor presses with more than 5 % of W; a check only where the case gives a "
        "friction coefficient, which no thesis case does) and *bolt impact* (the "
        "elastic impact force a real bolt row would take where the rigid bolts stop "
        "the plate, over Fy). The thesis's model checks none of them. Most rocking "
        "runs warn: the coupled frame mode accelerates the body hard enough that the "
        "floor would have to pull the base down, and a rigid stop at the bolt heads "
        "hides an impact force of several times Fy. Read the verdicts of those rows as "
        "the thesis's model gives them, not as a prediction of what a real cabinet "
        "does.\n\n"
        "| case | verdict | lift-off | sliding | bolt impact |\n"
        "|---|---|---|---|---|\n", fp) >= 0;
    for (size_t i = 0; i < n; i++) {
        ok = ok && write_case(fp, root, names[i], counts);
        free(names[i]);
    }
    free(names);
    return ok && fprintf(fp, "\n%d runs: %d with a validity warning, %d of them lift-off.\n",
                         counts[0], counts[1], counts[2]) >= 0;
}
