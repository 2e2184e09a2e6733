/* A batch case's fragility: the same rb_run_fragility call as `rockbolt
 * fragility`, with the same resamples and seed, so that a row's numbers
 * are the command's to the last bit; only what the summary shows is kept.
 * A case that has no fragility by its nature (no bolts) keeps its verdict
 * and says why; a search that fails makes the case an error, as a failed
 * design search does. */
#include <stdio.h>
#include <stdlib.h>
#include "batch_engine.h"
#include "rockbolt/report.h"
#include "rockbolt/run.h"

static void keep(const rb_case *c, const rb_case_fragility *f, rb_batch_fragility *out)
{
    out->g_mps2 = f->g_mps2;
    out->level_mps2 = f->level_mps2;
    out->im_freq_hz = f->intensity == RB_IM_SA ? f->im_freq_hz : 0;
    for (size_t i = 0; i < c->fragility.n_weights; i++)
        out->p58_weights[i] = c->fragility.weights[i];
    out->n_p58_weights = c->fragility.n_weights;
    out->governing = f->governing;
    for (int k = 0; k < RB_N_LIMITS; k++) {
        rb_batch_limit *l = &out->limits[k];
        l->present = rb_case_fragility_has(f, k);
        l->fitted = f->fitted[k];
        l->median_mps2 = f->fit[k].median;
        l->beta = f->fit[k].beta;
        l->median_lo_mps2 = f->median_lo[k];
        l->median_hi_mps2 = f->median_hi[k];
        l->p_at_level = f->p_at_level[k];
        l->reached = 0;
        l->confirmed = (f->confirmed >> k) & 1u;
        l->model_limited = rb_case_fragility_model_limited(f, k);
        for (size_t m = 0; l->present && m < f->n_motions; m++)
            l->reached += f->motions[m].censored[k] == 0;
    }
}

void rb_batch_case_fragility(rb_batch_slot *s, rb_batch_case *bc, int n_threads,
                             const rb_batch_opts *o)
{
    rb_case_fragility f;
    rb_diag_clear(&s->frag_diag);
    bc->fragility = calloc(1, sizeof *bc->fragility);
    if (!bc->fragility) {
        s->frag_status = RB_ERR_NOMEM;
        return;
    }
    bc->fragility->governing = -1;
    s->frag_status = rb_run_fragility(&s->c, n_threads, o->seed, RB_FRAGILITY_RESAMPLES,
                                      &f, &s->frag_diag, NULL, NULL);
    /* restated in Sa(f0) as `fragility --intensity sa` does; a case without
     * an f0 (a rigid cabinet) has no fragility in it and says why */
    if (s->frag_status == RB_OK && o->intensity != f.intensity)
        s->frag_status = rb_run_fragility_intensity(&s->c, o->intensity, &f, &s->frag_diag);
    if (s->frag_status == RB_OK) {
        keep(&s->c, &f, bc->fragility);
        if (o->reports_dir) {
            s->frag_json = rb_fragility_render_json(&s->c, &f);
            s->frag_text = rb_fragility_render_text(&s->c, &f);
            if (!s->frag_json || !s->frag_text)
                s->frag_status = RB_ERR_NOMEM;
        }
    } else if (s->frag_status == RB_ERR_INVALID) {
        char why[sizeof s->frag_diag.key + sizeof s->frag_diag.msg + 2];
        snprintf(why, sizeof why, "%s%s%s", s->frag_diag.key,
                 s->frag_diag.key[0] ? ": " : "", s->frag_diag.msg);
        bc->fragility->error = rb_batch_strdup(why);
        s->frag_status = bc->fragility->error ? RB_OK : RB_ERR_NOMEM;
    }
    rb_case_fragility_free(&f);
}
