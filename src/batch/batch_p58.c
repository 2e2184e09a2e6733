/* The batch's FEMA P-58 rows (--p58): one per item of the work list, each
 * case's fragility as `fragility --p58` writes it, its ID the item's tag
 * (unique in a list, where every row shares its base's p58_id). An item
 * with no fragility (unreadable, an error, no bolts) still gets its row,
 * incomplete and blank, so that the file has a row for every item. */
#include <stdlib.h>
#include "batch_summary.h"
#include "rockbolt/report.h"

void rb_batch_render_p58_head(rb_strbuf *b, const rb_batch_summary *s, const rb_batch_counts *n)
{
    (void)s;
    (void)n;
    char *h = rb_p58_render_head();
    if (!h) {
        b->oom = 1;
        return;
    }
    rb_strbuf_puts(b, h);
    free(h);
}

void rb_batch_render_p58_case(rb_strbuf *b, const rb_batch_summary *s, const rb_batch_case *c,
                              size_t pos)
{
    (void)s;
    (void)pos;
    const rb_batch_fragility *f = c->fragility && !c->fragility->error ? c->fragility
                                                                       : NULL;
    rb_p58_row r = {0};
    r.id = c->tag ? c->tag : "";
    if (f) {
        r.weights = f->p58_weights;
        r.n_weights = f->n_p58_weights;
        unsigned present = 0;
        int fitted[RB_N_LIMITS];
        double median[RB_N_LIMITS];
        for (int k = 0; k < RB_N_LIMITS; k++) {
            present |= (unsigned)(f->limits[k].present != 0) << k;
            fitted[k] = f->limits[k].fitted;
            median[k] = f->limits[k].median_mps2;
        }
        for (int k = 0; k < RB_P58_N_LS; k++) {
            const rb_batch_limit *l = &f->limits[rb_p58_limit(k, present, fitted, median)];
            r.fitted[k] = l->fitted;
            r.median_g[k] = l->median_mps2 / f->g_mps2;
            r.beta[k] = l->beta;
            r.confirmed[k] = l->confirmed;
            r.model_limited[k] = l->model_limited;
        }
    }
    char *row = rb_p58_render_row(&r);
    if (!row) {
        b->oom = 1;
        return;
    }
    rb_strbuf_puts(b, row);
    free(row);
}

void rb_batch_render_p58_tail(rb_strbuf *b, const rb_batch_summary *s, const rb_batch_counts *n)
{
    (void)b;
    (void)s;
    (void)n;
}
