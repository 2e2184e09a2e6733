/* The JSON printer's layout for people (rb_json_print_layout): the lines
 * break where the layout says and nowhere else, the text reads back as the
 * same tree, and text from the inputs is escaped as every output escapes
 * it. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <cjson/cJSON.h>
#include "harness.h"
#include "rockbolt/jsonbuild.h"
#include "rockbolt/jsonprint.h"

static const rb_json_break breaks[] = {
    {0, "case", ",\n  ", NULL, NULL},
    {0, "rows", ",\n  ", "\n    ", "\n  "},
    {1, "cells", NULL, "\n      ", ""},
    {1, "tail", ", \n     ", NULL, NULL},
};
static const rb_json_layout layout = {"\n  ", "\n", breaks, 4};

static cJSON *tree(rb_jctx *cx, size_t n_rows)
{
    static const double v[3] = {1.5, INFINITY, -2e-300};
    cJSON *root = cJSON_CreateObject();
    rb_j_oom(cx, root);
    rb_j_str(cx, root, "format", "x");
    rb_j_int(cx, root, "version", 1);
    /* a right-to-left override and a byte that is not UTF-8 */
    rb_j_text(cx, root, "case", "a\xe2\x80\xae" "b\xff");
    rb_j_uint(cx, root, "seed", 18446744073709551615ull);
    rb_j_nums(cx, root, "v", v, 3);
    cJSON *inner = rb_j_obj(cx, root, "inner");
    rb_j_num(cx, inner, "case", 2); /* the same key one level down: no break */
    rb_j_bool(cx, inner, "ok", 1);
    cJSON *rows = rb_j_arr(cx, root, "rows");
    for (size_t i = 0; i < n_rows; i++) {
        cJSON *r = rb_j_item(cx, rows);
        rb_j_int(cx, r, "i", (long long)i);
        cJSON *cells = rb_j_arr(cx, r, "cells");
        for (size_t k = 0; k < i; k++)
            rb_j_item(cx, cells);
        rb_j_null(cx, r, "tail");
    }
    return root;
}

static char *laid_out(size_t n_rows)
{
    rb_jctx cx = {.st = RB_OK, .where = "test"};
    cJSON *root = tree(&cx, n_rows);
    CHECK(cx.st == RB_OK);
    char *s = rb_json_print_layout(root, &layout);
    cJSON_Delete(root);
    return s;
}

static void test_bytes(void)
{
    char *s = laid_out(3);
    const char *want =
        "{\n  \"format\": \"x\", \"version\": 1,\n"
        "  \"case\": \"a\\u202eb\\\\xff\", \"seed\": 18446744073709551615, "
        "\"v\": [1.5, null, -2e-300], \"inner\": {\"case\": 2, \"ok\": true},\n"
        "  \"rows\": [\n"
        "    {\"i\": 0, \"cells\": [], \n     \"tail\": null},\n"
        "    {\"i\": 1, \"cells\": [\n      {}], \n     \"tail\": null},\n"
        "    {\"i\": 2, \"cells\": [\n      {},\n      {}], \n     \"tail\": null}\n"
        "  ]\n}\n";
    CHECK(s && strcmp(s, want) == 0);
    if (s && strcmp(s, want) != 0)
        fprintf(stderr, "got:\n%s\nwant:\n%s\n", s, want);
    free(s);
    s = laid_out(0);
    CHECK(s && strstr(s, "\"rows\": [\n  ]\n}\n") != NULL);
    free(s);
}

/* Whatever the layout, the text is the tree cJSON itself prints. */
static void test_reads_back(void)
{
    rb_jctx cx = {.st = RB_OK, .where = "test"};
    cJSON *root = tree(&cx, 4);
    char *s = rb_json_print_layout(root, &layout);
    char *plain = rb_json_print(root, 0);
    cJSON *back = s ? cJSON_Parse(s) : NULL, *want = plain ? cJSON_Parse(plain) : NULL;
    CHECK(back && want && cJSON_Compare(back, want, 1));
    cJSON_Delete(back);
    cJSON_Delete(want);
    cJSON_Delete(root);
    free(s);
    free(plain);
}

int main(void)
{
    test_bytes();
    test_reads_back();
    TEST_MAIN_END();
}
