/* libFuzzer harness: batch JSON summaries as merge reads them
 * (rb_batch_summary_parse, then rb_batch_merge of the one shard). A
 * summary that parses renders in every format, and its JSON reads back
 * and renders again byte for byte (what merge promises of shards); a
 * refused one says why and which field; nothing leaks either way. */
#include <stdlib.h>
#include <string.h>
#include "fuzz_common.h"
#include "rockbolt/batch.h"

static void render_all(const rb_batch_summary *s)
{
    for (int f = 0; f < RB_BATCH_N_FORMATS; f++) {
        char *text = rb_batch_render((rb_batch_format)f, s);
        if (!text)
            rb_fuzz_fail("a summary that parses does not render", NULL);
        free(text);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char *text = malloc(size + 1);
    if (!text)
        return 0;
    memcpy(text, data, size);
    text[size] = '\0';
    rb_batch_summary s, again, merged;
    rb_diag d;
    memset(&s, 0, sizeof s);
    memset(&again, 0, sizeof again);
    memset(&merged, 0, sizeof merged);
    rb_diag_clear(&d);
    rb_status st = rb_batch_summary_parse(text, &s, &d);
    free(text);
    if (st != RB_OK) {
        if (st != RB_ERR_PARSE && st != RB_ERR_NOMEM && st != RB_ERR_INVALID
            && st != RB_ERR_LIMIT)
            rb_fuzz_fail("rb_batch_summary_parse returned an unexpected status",
                         rb_status_str(st));
        if (st != RB_ERR_NOMEM && !d.msg[0])
            rb_fuzz_fail("a refused summary does not say why", NULL);
        rb_batch_summary_free(&s);
        return 0;
    }
    /* lines are read as whole numbers in range: a "line" of 8.9e31 was
     * cast to int (undefined; INT_MIN here) */
    for (size_t i = 0; s.cases && i < s.n_cases; i++)
        if (s.cases[i].line < 0)
            rb_fuzz_fail("a case read back with a negative line", NULL);
    render_all(&s);
    char *json = rb_batch_render(RB_BATCH_JSON, &s);
    if (!json)
        rb_fuzz_fail("a summary that parses does not render as JSON", NULL);
    rb_diag_clear(&d);
    if (rb_batch_summary_parse(json, &again, &d) != RB_OK)
        rb_fuzz_fail("a summary's own JSON does not read back", d.msg);
    char *json2 = rb_batch_render(RB_BATCH_JSON, &again);
    if (!json2 || strcmp(json, json2) != 0)
        rb_fuzz_fail("a summary's JSON read back renders differently", NULL);
    free(json2);
    rb_diag_clear(&d);
    if (rb_batch_merge(&s, 1, &merged, &d) == RB_OK) {
        char *m = rb_batch_render(RB_BATCH_JSON, &merged);
        if (!m)
            rb_fuzz_fail("a merged summary does not render", NULL);
        free(m);
    } else if (!d.msg[0]) {
        rb_fuzz_fail("a refused merge does not say why", NULL);
    }
    free(json);
    rb_batch_summary_free(&s);
    rb_batch_summary_free(&again);
    rb_batch_summary_free(&merged);
    return 0;
}
