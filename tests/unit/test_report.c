/* Report renderers on a hand-made result (no solver): the JSON parses and
 * has the documented fields, absent events and zero denominators are null,
 * a NaN anywhere refuses the report and names the field; the built-in text
 * template renders every name it uses; the history CSV has its columns. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <cjson/cJSON.h>
#include "harness.h"
#include "report_fixture.h"
#include "rockbolt/rockbolt.h"

static report_fixture fx;

static void setup(void)
{
    report_fixture_init(&fx, "x", "harmonic", "harmonic 10 m/s^2");
    fx.cm.motion.amplitude_mps2 = 10;
    fx.cm.motion.duration_s = 2;
    rb_result *res = &fx.res;
    res->peak_floor_mps2 = 10;
    res->weight_n = 454 * RB_G0;
    res->a_star_mps2 = 114.77;
    res->fy_row_n = 62831.7;
    res->max_shear_elastic_n = 2 * res->weight_n;
    res->max_bolt_force_n[RB_RIGHT] = 31415.85;
    res->final_gap_m[0] = res->final_gap_m[1] = 0.0078;
    res->usage[RB_RIGHT] = 0.25;
    res->yielded[RB_RIGHT] = 1;
    res->first_yield_s[RB_RIGHT] = 0.5;
    res->first_yield_s[RB_LEFT] = NAN; /* not yielded: must not be looked at */
    res->break_s[0] = res->break_s[1] = INFINITY;
    res->overturn_s = NAN;
    res->t_end_s = 2;
    res->stage_time_s[1] = 1.5;
    res->stage_time_s[2] = 0.5;
    fx.rm.verdict.pass = 1;
    snprintf(fx.rm.verdict.reason, sizeof fx.rm.verdict.reason, "fine");
    rb_report_conclude(&fx.rep);
}

static const cJSON *at(const cJSON *o, const char *a, const char *b, const char *c)
{
    o = cJSON_GetObjectItemCaseSensitive(o, a);
    if (b)
        o = cJSON_GetObjectItemCaseSensitive(o, b);
    if (c)
        o = cJSON_GetObjectItemCaseSensitive(o, c);
    return o;
}

static void test_json(void)
{
    char *out = NULL;
    rb_diag d;
    cJSON *root;
    const cJSON *m0, *v;
    rb_diag_clear(&d);
    CHECK(rb_report_render_json(&fx.rep, &out, &d) == RB_OK);
    CHECK(out && out[strlen(out) - 1] == '\n');
    root = cJSON_Parse(out);
    CHECK(root != NULL);
    free(out);
    if (!root)
        return;
    CHECK(strcmp(cJSON_GetStringValue(at(root, "format", NULL, NULL)), "rockbolt-report") == 0);
    CHECK(cJSON_GetNumberValue(at(root, "format_version", NULL, NULL)) == 2);
    CHECK(cJSON_IsTrue(at(root, "verdict", "pass", NULL)));
    CHECK_REL(cJSON_GetNumberValue(at(root, "derived", "a_star_g", NULL)), 11.7, 0.01);
    CHECK(strcmp(cJSON_GetStringValue(at(root, "solver", "integrator", NULL)), "auto") == 0);
    m0 = cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(root, "motions"), 0);
    v = at(m0, "result", "bolts", "first_yield_s");
    CHECK(cJSON_IsNull(cJSON_GetObjectItemCaseSensitive(v, "left")));
    CHECK(cJSON_GetNumberValue(cJSON_GetObjectItemCaseSensitive(v, "right")) == 0.5);
    CHECK(cJSON_IsNull(at(m0, "result", "outcome", "overturn_s")));
    CHECK_NEAR(cJSON_GetNumberValue(at(m0, "result", "peaks", "max_shear_elastic_over_w")),
               2, 1e-12);
    CHECK_NEAR(cJSON_GetNumberValue(at(m0, "result", "peaks", "max_shear_elastic_over_v0")),
               2 * RB_G0 / 10, 1e-12);
    v = at(m0, "result", "peaks", "max_bolt_force_over_fy");
    CHECK_NEAR(cJSON_GetNumberValue(cJSON_GetObjectItemCaseSensitive(v, "right")), 0.5, 1e-6);
    CHECK(cJSON_IsNull(at(m0, "motion", "building", NULL)));
    CHECK(at(m0, "history", NULL, NULL) == NULL); /* not asked for */
    cJSON_Delete(root);

    /* no motion: ratios to V0 have no denominator and become null */
    fx.res.peak_floor_mps2 = 0;
    CHECK(rb_report_render_json(&fx.rep, &out, &d) == RB_OK);
    root = cJSON_Parse(out);
    free(out);
    m0 = cJSON_GetArrayItem(cJSON_GetObjectItemCaseSensitive(root, "motions"), 0);
    CHECK(cJSON_IsNull(at(m0, "result", "peaks", "max_shear_elastic_over_v0")));
    cJSON_Delete(root);
    fx.res.peak_floor_mps2 = 10;

    /* a NaN from upstream: no report, the field named */
    fx.res.max_u_m = NAN;
    out = (char *)1;
    CHECK(rb_report_render_json(&fx.rep, &out, &d) == RB_ERR_NONFINITE);
    CHECK(out == NULL);
    CHECK(strstr(d.key, "max_u_m") != NULL);
    fx.res.max_u_m = 0;
}

static void test_text(void)
{
    char *out = NULL;
    rb_diag d;
    rb_diag_clear(&d);
    CHECK(rb_report_render_text(&fx.rep, rb_template_builtin("report.txt"), &out, &d) == RB_OK);
    if (d.msg[0])
        fprintf(stderr, "template: %d:%d %s: %s\n", d.line, d.col, d.key, d.msg);
    {
        static const char first[] = "PASS: 1 motion meets the no-break criterion\n";
        CHECK(out && strncmp(out, first, sizeof first - 1) == 0);
    }
    CHECK(out && strstr(out, "= 2.000 W") != NULL);
    CHECK(out && strstr(out, "first yield (s)               n/a      0.500") != NULL);
    free(out);
    fx.rm.verdict.pass = 0;
    rb_report_conclude(&fx.rep);
    CHECK(!fx.rep.pass && strcmp(fx.rep.reason, "motion 'harmonic': fine") == 0);
    fx.rm.verdict.pass = 1;
    rb_report_conclude(&fx.rep);
}

static void test_history(void)
{
    double t[2] = { 0, 0.01 }, z[2] = { 0, 1.5 };
    int stage[2] = { 1, 2 };
    rb_history h = {.n = 2, .cap = 2, .t = t, .accel = z, .theta = z, .u = z,
                    .bolt_force_left = z, .bolt_force_right = z, .shear_elastic = z,
                    .shear_total = z, .vertical = z, .energy_left = z, .energy_right = z,
                    .kinetic = z, .potential = z, .strain = z, .stage = stage};
    FILE *fp = tmpfile();
    char buf[1024] = {0};
    rb_diag d;
    fx.res.history = &h;
    CHECK(fp && rb_history_write_csv(fp, &fx.rep, &d) == RB_OK);
    rewind(fp);
    CHECK(fread(buf, 1, sizeof buf - 1, fp) > 0);
    CHECK(strncmp(buf, "motion,t_s,accel_mps2,", 22) == 0);
    CHECK(strstr(buf, "\n1,0.01,1.5,1.5,1.5,1.5,1.5,1.5,1.5,1.5,1.5,1.5,1.5,1.5,2\n") != NULL);
    fclose(fp);
    z[1] = NAN;
    fp = tmpfile();
    CHECK(fp && rb_history_write_csv(fp, &fx.rep, &d) == RB_ERR_NONFINITE);
    fclose(fp);
    fx.res.history = NULL;
}

int main(void)
{
    setup();
    test_json();
    test_text();
    test_history();
    TEST_MAIN_END();
}
