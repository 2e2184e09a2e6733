/* The engine's per-case state, shared by batch_run.c and batch_case.c. */
#ifndef RB_BATCH_ENGINE_H
#define RB_BATCH_ENGINE_H

#include "batch_internal.h"
#include "rockbolt/case.h"
#include "rockbolt/criteria.h"
#include "rockbolt/design.h"
#include "rockbolt/report.h"
#include "rockbolt/record_cache.h"

/* A case while it is being run; freed as soon as it is concluded. */
typedef struct {
    rb_case c;
    int loaded;
    rb_result *results;      /* n_motions each */
    rb_report_motion *rms;
    rb_status *run_status;
    rb_diag *run_diag;
    size_t remaining;        /* runs not yet done, the fragility counting
                                as one */
    rb_status frag_status;   /* of the case's fragility (--fragility) */
    rb_diag frag_diag;
    /* owned: the fragility's reports as `rockbolt fragility` writes them,
     * for --reports (NULL otherwise, or when the case has none) */
    char *frag_json, *frag_text;
    rb_record_cache *cache;  /* borrowed: the run's record cache */
    const struct rb_sandbox *sandbox; /* borrowed: the list's; NULL: none */
} rb_batch_slot;

/* Load the item into s (verdict and error in bc if it cannot be). */
void rb_batch_case_load(rb_batch_slot *s, const rb_batch_item *it, rb_batch_case *bc);
/* Solve and judge motion m (and its design when asked). */
void rb_batch_case_solve(rb_batch_slot *s, rb_batch_case *bc, size_t m, int design);
/* The case's fragility (batch_fragility.c): rb_run_fragility on n_threads
 * with o's seed, in o's intensity, into bc->fragility; its status in
 * s->frag_status; with o's reports, its JSON and text reports into s. */
void rb_batch_case_fragility(rb_batch_slot *s, rb_batch_case *bc, int n_threads,
                             const rb_batch_opts *o);
/* Conclude the case, write its reports, free s. */
void rb_batch_case_finish(rb_batch_slot *s, rb_batch_case *bc, const rb_batch_opts *o,
                          size_t total);
void rb_batch_slot_free(rb_batch_slot *s);
/* Row tag, or the file stem of a case file (until the case names itself). */
char *rb_batch_default_tag(const rb_batch_item *it);

#endif
