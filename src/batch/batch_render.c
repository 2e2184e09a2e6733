/* The summary formats, each as head, cases and tail (the pieces are
 * in batch_table.c, batch_json.c, batch_junit.c and batch_p58.c), so that a streamed
 * batch and a whole summary are written by the same code. */
#include <stdlib.h>
#include "batch_summary.h"

typedef void (*end_fn)(rb_strbuf *b, const rb_batch_summary *s, const rb_batch_counts *n);
typedef void (*case_fn)(rb_strbuf *b, const rb_batch_summary *s, const rb_batch_case *c,
                        size_t pos);

static const struct {
    end_fn head;
    case_fn one;
    end_fn tail;
} formats[RB_BATCH_N_FORMATS] = {
    [RB_BATCH_TEXT] = {rb_batch_render_text_head, rb_batch_render_text_case,
                       rb_batch_render_text_tail},
    [RB_BATCH_CSV] = {rb_batch_render_csv_head, rb_batch_render_csv_case,
                       rb_batch_render_csv_tail},
    [RB_BATCH_JSON] = {rb_batch_render_json_head, rb_batch_render_json_case,
                       rb_batch_render_json_tail},
    [RB_BATCH_JUNIT] = {rb_batch_render_junit_head, rb_batch_render_junit_case,
                       rb_batch_render_junit_tail},
    [RB_BATCH_P58] = {rb_batch_render_p58_head, rb_batch_render_p58_case,
                       rb_batch_render_p58_tail},
};

static int known(rb_batch_format f)
{
    return (unsigned)f < RB_BATCH_N_FORMATS;
}

char *rb_batch_render_head(rb_batch_format f, const rb_batch_summary *s,
                           const rb_batch_counts *n)
{
    rb_strbuf b = {0};
    if (!known(f))
        return NULL;
    formats[f].head(&b, s, n);
    return rb_strbuf_take(&b);
}

char *rb_batch_render_case(rb_batch_format f, const rb_batch_summary *s,
                           const rb_batch_case *c, size_t pos)
{
    rb_strbuf b = {0};
    if (!known(f))
        return NULL;
    formats[f].one(&b, s, c, pos);
    return rb_strbuf_take(&b);
}

char *rb_batch_render_tail(rb_batch_format f, const rb_batch_summary *s,
                           const rb_batch_counts *n)
{
    rb_strbuf b = {0};
    if (!known(f))
        return NULL;
    formats[f].tail(&b, s, n);
    return rb_strbuf_take(&b);
}

char *rb_batch_render(rb_batch_format f, const rb_batch_summary *s)
{
    rb_strbuf b = {0};
    rb_batch_counts n;
    if (!known(f) || s->streamed)
        return NULL;
    rb_batch_count(s, &n);
    formats[f].head(&b, s, &n);
    for (size_t i = 0; i < s->n_cases && !b.oom; i++)
        formats[f].one(&b, s, &s->cases[i], i);
    formats[f].tail(&b, s, &n);
    return rb_strbuf_take(&b);
}
