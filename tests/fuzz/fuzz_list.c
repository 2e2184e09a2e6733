/* libFuzzer harness: equipment lists (rb_batch_list_read_csv), read as UTF-8,
 * and also as cp1252 (--encoding) when RB_FUZZ_LIST_CP1252 is set. Whatever the bytes, the read gives items or
 * runs out of memory; every item names the list; a bad item carries a
 * message and a place, a good one a base; tags and sources are valid
 * UTF-8 (the summaries are JSON), and freeing the list frees them all. */
#include <stdlib.h>
#include <string.h>
#include "fuzz_common.h"
#include "rockbolt/batch.h"
#include "rockbolt/textsafe.h"

static int utf8_ok(const char *s)
{
    return !s || rb_utf8_invalid_at(s, strlen(s)) == strlen(s);
}

static void read_as(const char *path, const char *encoding)
{
    rb_batch_list l;
    memset(&l, 0, sizeof l);
    l.encoding = encoding;
    rb_status st = rb_batch_list_read_csv(&l, path, NULL);
    if (st != RB_OK && st != RB_ERR_NOMEM)
        rb_fuzz_fail("rb_batch_list_read_csv returned an unexpected status", rb_status_str(st));
    for (size_t i = 0; i < l.n; i++) {
        const rb_batch_item *it = &l.items[i];
        if (!it->source || strcmp(it->source, path) != 0)
            rb_fuzz_fail("an item does not name its list", it->source);
        if (!utf8_ok(it->tag))
            rb_fuzz_fail("a tag is not valid UTF-8", NULL);
        if (it->bad) {
            if (!it->error || !it->error->msg[0] || !it->error->key[0])
                rb_fuzz_fail("a bad item has no message or key", NULL);
            if (it->error->line < 0 || it->error->col < 0)
                rb_fuzz_fail("a bad item has a negative position", it->error->msg);
        } else {
            if (!it->base || !it->base[0] || it->line < 2)
                rb_fuzz_fail("a good item has no base or no row line", NULL);
            for (size_t k = 0; k < it->n_ov; k++)
                if (!it->ov[k].key || !it->ov[k].value)
                    rb_fuzz_fail("an override lacks its key or value", NULL);
        }
    }
    rb_batch_list_free(&l);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    char path[512];
    rb_fuzz_write("list.csv", data, size);
    rb_fuzz_path(path, sizeof path, "list.csv");
    read_as(path, NULL);
    /* --encoding goes through iconv, whose iconv_open costs 0.4 s an input
     * under the sanitizers (2 inputs a second): only when asked for */
    if (getenv("RB_FUZZ_LIST_CP1252"))
        read_as(path, "cp1252");
    return 0;
}
