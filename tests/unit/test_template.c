/* Template engine: values and formats, sections over lists and values,
 * standalone-line removal, errors with positions; and the compiled-in
 * templates are byte-identical to templates/ (run from the source root),
 * and the header version agrees with the build's. */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include <string.h>
#include "harness.h"
#include "rockbolt/rockbolt.h"

static const rb_tvar top_vars[] = {
    { "x", RB_TVAL_NUM, 3.14159, 0, NULL },
    { "n", RB_TVAL_INT, 0, 42, NULL },
    { "s", RB_TVAL_STR, 0, 0, "hello" },
    { "none", RB_TVAL_NONE, 0, 0, NULL },
    { "tiny", RB_TVAL_NUM, -0.0001, 0, NULL },
    { "zero", RB_TVAL_INT, 0, 0, NULL },
    { "empty", RB_TVAL_STR, 0, 0, "" },
};
static const rb_tvar item_vars[2][2] = {
    { { "name", RB_TVAL_STR, 0, 0, "a" }, { "v", RB_TVAL_NUM, 1.5, 0, NULL } },
    { { "name", RB_TVAL_STR, 0, 0, "b" }, { "v", RB_TVAL_NUM, -2.25, 0, NULL } },
};
static rb_tscope items[2];
static rb_tlist lists[2];
static rb_tscope top;

static void setup(void)
{
    items[0].vars = item_vars[0];
    items[0].n_vars = 2;
    items[1].vars = item_vars[1];
    items[1].n_vars = 2;
    lists[0].name = "items";
    lists[0].items = items;
    lists[0].n = 2;
    lists[1].name = "nothing";
    lists[1].items = NULL;
    lists[1].n = 0;
    top.vars = top_vars;
    top.n_vars = sizeof top_vars / sizeof top_vars[0];
    top.lists = lists;
    top.n_lists = 2;
}

/* Render and compare; prints both on a mismatch. */
static int renders(const char *tmpl, const char *want)
{
    char *out = NULL;
    rb_diag d;
    int ok;
    rb_diag_clear(&d);
    if (rb_template_render(tmpl, &top, &out, &d) != RB_OK) {
        fprintf(stderr, "render failed: %d:%d %s: %s\n", d.line, d.col, d.key, d.msg);
        return 0;
    }
    ok = strcmp(out, want) == 0;
    if (!ok)
        fprintf(stderr, "template [%s]\n got  [%s]\n want [%s]\n", tmpl, out, want);
    free(out);
    return ok;
}

/* Expect a parse error at line:col. */
static int fails_at(const char *tmpl, int line, int col)
{
    char *out = (char *)1;
    rb_diag d;
    rb_status st;
    rb_diag_clear(&d);
    st = rb_template_render(tmpl, &top, &out, &d);
    if (st != RB_ERR_PARSE || out != NULL || d.line != line || d.col != col) {
        fprintf(stderr, "template [%s]: status %d at %d:%d (%s), want error at %d:%d\n",
                tmpl, (int)st, d.line, d.col, d.msg, line, col);
        free(out == (char *)1 ? NULL : out);
        return 0;
    }
    return 1;
}

static void test_values(void)
{
    CHECK(renders("plain text", "plain text"));
    CHECK(renders("", ""));
    CHECK(renders("{{x}}|{{n}}|{{s}}", "3.14159|42|hello"));
    CHECK(renders("{{x:%.2f}} {{x:%8.3f}} {{x:%-8.1f}}|", "3.14    3.142 3.1     |"));
    CHECK(renders("{{x:%+.1f}} {{x:%.3e}} {{x:%.3g}}", "+3.1 3.142e+00 3.14"));
    CHECK(renders("{{n:%5d}}|{{n:%-5d}}|{{n:%+d}}|{{n:%.1f}}", "   42|42   |+42|42.0"));
    CHECK(renders("[{{s:%8s}}][{{s:%-8s}}][{{s:%.3s}}]", "[   hello][hello   ][hel]"));
    CHECK(renders("[{{none}}][{{none:%6.2f}}][{{none:%-5s}}]", "[n/a][   n/a][n/a  ]"));
    CHECK(renders("{{tiny:%.2f}} {{tiny:%.5f}}", "0.00 -0.00010"));
    CHECK(renders("{{ x:%.1f }}", "3.1"));
    CHECK(renders("a {{! a comment }}b", "a b"));
}

static void test_sections(void)
{
    CHECK(renders("{{#items}}<{{name}}={{v:%.2f}} {{s}}>{{/items}}",
                  "<a=1.50 hello><b=-2.25 hello>"));
    CHECK(renders("{{#nothing}}x{{/nothing}}|{{^nothing}}empty{{/nothing}}", "|empty"));
    CHECK(renders("{{#items}}{{^items}}never{{/items}}{{/items}}", ""));
    CHECK(renders("{{#s}}yes {{s}}{{/s}}{{#empty}}no{{/empty}}{{#none}}no{{/none}}",
                  "yes hello"));
    CHECK(renders("{{#zero}}no{{/zero}}{{^zero}}zero{{/zero}}{{#n}}+{{/n}}", "zero+"));
    /* standalone tags take their line, indented or not */
    CHECK(renders("head\n{{#items}}\n- {{name}}\n{{/items}}\ntail\n",
                  "head\n- a\n- b\ntail\n"));
    CHECK(renders("head\n  {{#items}}  \n- {{name}}\n  {{/items}}\ntail",
                  "head\n- a\n- b\ntail"));
    CHECK(renders("{{! first line comment }}\nline\n", "line\n"));
    CHECK(renders("{{#items}}\n{{/items}}\nend", "end"));
    CHECK(renders("x {{#items}}{{name}}{{/items}}\n", "x ab\n"));
    CHECK(renders("{{! c1 }}\n{{! c2 }}\nz", "z"));
}

static void test_errors(void)
{
    CHECK(fails_at("abc {{nope}}", 1, 5));
    CHECK(fails_at("l1\nl2 {{x", 2, 4));
    CHECK(fails_at("{{x:%q}}", 1, 1));
    CHECK(fails_at("{{x:%.2f extra}}", 1, 1));
    CHECK(fails_at("{{x:%n}}", 1, 1));
    CHECK(fails_at("{{x:%99f}}", 1, 1));
    CHECK(fails_at("{{x:%d}}", 1, 1));
    CHECK(fails_at("{{s:%f}}", 1, 1));
    CHECK(fails_at("{{n:%s}}", 1, 1));
    CHECK(fails_at("a\n{{#items}}x", 2, 1));
    CHECK(fails_at("{{/items}}", 1, 1));
    CHECK(fails_at("{{#items}}{{/nothing}}", 1, 11));
    CHECK(fails_at("{{bad name}}", 1, 1));
    CHECK(fails_at("{{#items:%d}}{{/items}}", 1, 1));
    CHECK(fails_at("{{#missing}}{{/missing}}", 1, 1));
}

/* The compiled-in copies must equal the shipped files byte for byte. */
static void check_builtin(const char *name)
{
    char path[256], *file = NULL;
    const char *builtin = rb_template_builtin(name);
    FILE *fp;
    long n;
    snprintf(path, sizeof path, "templates/%s", name);
    fp = fopen(path, "rb");
    if (!fp) {
        /* a template not shipped yet must not be compiled in either */
        CHECK(builtin == NULL);
        return;
    }
    fseek(fp, 0, SEEK_END);
    n = ftell(fp);
    rewind(fp);
    file = calloc((size_t)n + 1, 1);
    CHECK(file && fread(file, 1, (size_t)n, fp) == (size_t)n);
    fclose(fp);
    CHECK(builtin != NULL);
    if (builtin && file && strcmp(builtin, file) != 0)
        fprintf(stderr, "%s differs from its compiled-in copy: "
                "rebuild\n", path);
    CHECK(builtin && file && strcmp(builtin, file) == 0);
    free(file);
}

static void test_builtin_and_load(void)
{
    char *text = NULL;
    const char *origin = NULL;
    rb_diag d;
    check_builtin("report.txt");
    check_builtin("starter.yaml");
    check_builtin("calc.txt");
    CHECK(rb_template_builtin("nonexistent.txt") == NULL);
    /* a directory without the file falls through to the source tree or
     * the built-in copy; both equal the shipped file */
    setenv("RB_TEMPLATE_DIR", "/nonexistent-rb-template-dir", 1);
    CHECK(rb_template_load("report.txt", &text, &origin, &d) == RB_OK);
    CHECK(text && strcmp(text, rb_template_builtin("report.txt")) == 0);
    CHECK(origin && strcmp(origin, "RB_TEMPLATE_DIR") != 0);
    free(text);
    setenv("RB_TEMPLATE_DIR", "templates", 1);
    CHECK(rb_template_load("report.txt", &text, &origin, &d) == RB_OK);
    CHECK(origin && strcmp(origin, "RB_TEMPLATE_DIR") == 0);
    free(text);
    CHECK(rb_template_load("nonexistent.txt", &text, &origin, &d) == RB_ERR_INVALID);
    CHECK(text == NULL);
    unsetenv("RB_TEMPLATE_DIR");
}

int main(void)
{
    setup();
    test_values();
    test_sections();
    test_errors();
    test_builtin_and_load();
    CHECK(strcmp(RB_VERSION_STRING, RB_VERSION) == 0);
    TEST_MAIN_END();
}
