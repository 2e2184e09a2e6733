/* The response spectra of a case's motions: the floor each motion gives
 * the solver (records through their building, scaled; synthetic motions
 * as generated; closed forms sampled), and for a synthetic motion how
 * well it follows its target at the target's own check points. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/run.h"

#define STANDARD_GRAVITY 9.80665

static rb_status motion_fit(const rb_case_motion *cm, rb_motion_spectrum *ms)
{
    rb_spectrum check;
    rb_status st = rb_target_check_grid(cm->target, &check);
    if (st == RB_OK)
        st = rb_spectrum_of_motion(&cm->motion, &check);
    if (st == RB_OK)
        st = rb_target_compare(cm->target, &check, &ms->fit);
    rb_spectrum_free(&check);
    ms->has_target = st == RB_OK;
    return st;
}

rb_status rb_run_spectra(const rb_case *c, const rb_spectrum_opts *o, rb_case_spectra *out,
                         rb_diag *diag)
{
    memset(out, 0, sizeof *out);
    out->opts = *o;
    out->g_mps2 = STANDARD_GRAVITY;
    rb_spectrum grid;
    rb_status st = rb_spectrum_grid(o, &grid);
    if (st != RB_OK)
        return rb_diag_set(diag, st, NULL, 0, 0, "spectrum", "a grid from %g to %g Hz at "
                           "1/%g octave with damping %g: needs 0 < from < to, at most %d "
                           "points and 0 <= damping < 1", o->f_min_hz, o->f_max_hz,
                           o->per_octave, o->damping, RB_SPECTRUM_MAX_POINTS);
    out->motions = calloc(c->n_motions, sizeof *out->motions);
    if (!out->motions) {
        rb_spectrum_free(&grid);
        return RB_ERR_NOMEM;
    }
    out->n_motions = c->n_motions;
    for (size_t i = 0; i < c->n_motions && st == RB_OK; i++) {
        const rb_case_motion *cm = &c->motions[i];
        rb_motion_spectrum *ms = &out->motions[i];
        st = rb_spectrum_alloc(&ms->sp, grid.freq_hz, grid.n, grid.damping);
        if (st == RB_OK)
            st = rb_spectrum_of_motion(&cm->motion, &ms->sp);
        if (st == RB_OK && cm->target)
            st = motion_fit(cm, ms);
        if (st == RB_ERR_LIMIT) {
            rb_diag_set(diag, st, NULL, 0, 0, cm->name ? cm->name : "motion",
                        "a closed-form motion is sampled 200 times per period of the "
                        "grid's top frequency (%g Hz): its %g s would take over 10 million "
                        "samples (the limit); lower --to or shorten the run",
                        o->f_max_hz, cm->motion.duration_s);
            break;
        }
        if (st != RB_OK) {
            rb_diag_set(diag, st, NULL, 0, 0, cm->name ? cm->name : "motion",
                        "no response spectrum for this motion (%s)", rb_status_str(st));
            break;
        }
        ms->peak_mps2 = rb_motion_peak(&cm->motion);
        if (cm->motion.kind == RB_MOTION_SAMPLED && cm->motion.series) {
            rb_series_arias(cm->motion.series, &ms->arias_mps, &ms->arias_t5_s,
                            &ms->arias_t95_s);
            ms->arias_mps *= cm->motion.scale * cm->motion.scale;
        }
    }
    rb_spectrum_free(&grid);
    return st;
}
