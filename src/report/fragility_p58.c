/* A case's anchorage fragility as a row of the fragility CSV that the
 * SimCenter damage and loss library and pelicun read (FEMA P-58's
 * component fragilities): an ID, whether the row is incomplete, the
 * demand (peak floor acceleration in g, at the cabinet's own floor, along
 * the direction of shaking) and per limit state a lognormal median and
 * dispersion, with LS1's damage states and their weights. FEMA P-58
 * leaves the anchorage entries of anchored equipment for the user to
 * fill; these are the numbers rockbolt computes for them. */
#include <stdlib.h>
#include "rockbolt/jsonnum.h"
#include "rockbolt/report.h"
#include "rockbolt/textsafe.h"
#include "util/strbuf.h"

rb_limit_state rb_p58_limit(int ls, unsigned present, const int fitted[RB_N_LIMITS],
                            const double median[RB_N_LIMITS])
{
    if (ls != 0)
        return RB_LIMIT_OVERTURN;
    /* P-58's anchorage failure is the anchorage's, steel or concrete: with
     * concrete: the concrete check's state drives it where it comes first
     * (a shallow cast-in anchorage that is not ductile fails it at the
     * bolts' first yield), the bolts' usage where the concrete outlasts
     * them */
    unsigned both = present & ((1u << RB_LIMIT_USAGE) | (1u << RB_LIMIT_ANCHORAGE));
    int k = rb_fragility_governing(both, fitted, median);
    return k < 0 ? RB_LIMIT_USAGE : (rb_limit_state)k;
}

char *rb_p58_render_head(void)
{
    rb_strbuf b = {0};
    rb_strbuf_puts(&b, "ID,Incomplete,Demand-Type,Demand-Unit,Demand-Offset,"
                       "Demand-Directional");
    for (int k = 1; k <= RB_P58_N_LS; k++)
        rb_strbuf_printf(&b, ",LS%d-Family,LS%d-Theta_0,LS%d-Theta_1,"
                         "LS%d-DamageStateWeights", k, k, k, k);
    /* after P-58's own columns, which a loss tool reads by name: the
     * fragility's flags of each limit state */
    for (int k = 1; k <= RB_P58_N_LS; k++)
        rb_strbuf_printf(&b, ",LS%d-Confirmed,LS%d-ModelLimited", k, k);
    rb_strbuf_puts(&b, "\n");
    return rb_strbuf_take(&b);
}

static void number(rb_strbuf *b, double v)
{
    char buf[RB_JSONNUM_MAX];
    rb_json_number(v, buf);
    rb_strbuf_puts(b, buf);
}

char *rb_p58_render_row(const rb_p58_row *r)
{
    static const double defaults[2] = {RB_P58_DEFAULT_W1, RB_P58_DEFAULT_W2};
    const double *w = r->n_weights ? r->weights : defaults;
    size_t nw = r->n_weights ? r->n_weights : 2;
    int incomplete = 0;
    for (int k = 0; k < RB_P58_N_LS; k++)
        incomplete |= !r->fitted[k];
    rb_strbuf b = {0};
    char *id = rb_csv_field(r->id, 0);
    if (!id)
        return NULL;
    /* offset 0: the floor the cabinet stands on; directional 1: the fit
     * is for shaking along the base width, the direction rocking takes */
    rb_strbuf_printf(&b, "%s,%d,Peak Floor Acceleration,g,0,1", id, incomplete);
    free(id);
    for (int k = 0; k < RB_P58_N_LS; k++) {
        if (!r->fitted[k]) {
            /* left blank, as the P-58 entries the user is to fill are */
            rb_strbuf_puts(&b, ",,,,");
            continue;
        }
        rb_strbuf_puts(&b, ",lognormal,");
        number(&b, r->median_g[k]);
        rb_strbuf_puts(&b, ",");
        number(&b, r->beta[k]);
        rb_strbuf_puts(&b, ",");
        /* a single damage state needs no weights */
        for (size_t i = 0; k == 0 && i < nw; i++) {
            if (i)
                rb_strbuf_puts(&b, " | ");
            number(&b, w[i]);
        }
    }
    for (int k = 0; k < RB_P58_N_LS; k++) {
        if (r->fitted[k])
            rb_strbuf_printf(&b, ",%d,%zu", r->confirmed[k] != 0, r->model_limited[k]);
        else
            rb_strbuf_puts(&b, ",,");
    }
    rb_strbuf_puts(&b, "\n");
    return rb_strbuf_take(&b);
}

char *rb_fragility_render_p58(const rb_case *c, const rb_case_fragility *f)
{
    rb_p58_row r = {0};
    r.id = c->fragility.p58_id ? c->fragility.p58_id : c->name ? c->name : "";
    r.weights = c->fragility.weights;
    r.n_weights = c->fragility.n_weights;
    double median[RB_N_LIMITS];
    for (int k = 0; k < RB_N_LIMITS; k++)
        median[k] = f->fit[k].median;
    for (int k = 0; k < RB_P58_N_LS; k++) {
        rb_limit_state ls = rb_p58_limit(k, f->present, f->fitted, median);
        r.fitted[k] = f->fitted[ls];
        r.median_g[k] = f->fit[ls].median / f->g_mps2;
        r.beta[k] = f->fit[ls].beta;
        r.confirmed[k] = (f->confirmed >> ls) & 1u;
        r.model_limited[k] = rb_case_fragility_model_limited(f, ls);
    }
    char *head = rb_p58_render_head(), *row = rb_p58_render_row(&r);
    rb_strbuf b = {0};
    if (head && row) {
        rb_strbuf_puts(&b, head);
        rb_strbuf_puts(&b, row);
    } else {
        b.oom = 1;
    }
    free(head);
    free(row);
    return rb_strbuf_take(&b);
}
