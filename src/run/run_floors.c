/* The floor accelerations of a case's motions as the cabinet feels them,
 * sampled for a shake table (`rockbolt motion`): the samples the solver
 * is driven by, polarity and scale applied, from t = 0 to the end of the
 * run; a closed form sampled finely. What describes each component is
 * rb_motion_summarise's (peaks, Arias, the laboratory's acceptance). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/run.h"

#define STANDARD_GRAVITY 9.80665

/* The samples of a sampled motion inside [0, run_s], as the solver reads
 * them, polarity and scale applied: the motion's own series (its building
 * kept) cut at the end of the run. A series whose first sample is not at
 * 0 starts on its own step (zeros before it, as rb_series_at gives 0
 * there; its building, if any, is then not kept); samples before 0 are
 * never reached. */
static rb_status sampled(const rb_motion *m, double run_s, rb_series *out, const char **why)
{
    const rb_series *s = m->series;
    double k0 = s->t0_s / s->dt_s, first = nearbyint(k0);
    if (!(fabs(k0 - first) <= 1e-6 * fmax(1.0, fabs(k0)))) {
        *why = "its first sample is not on its own time step from t = 0";
        return RB_ERR_INVALID;
    }
    double last = floor(run_s / s->dt_s * (1 + 1e-12) + 1e-9);
    double end = fmin(first + (double)s->n - 1, last);
    if (end < 0) {
        *why = "its samples all come before t = 0";
        return RB_ERR_INVALID;
    }
    if (end + 1 > RB_FLOOR_MAX_SAMPLES) {
        *why = "it takes more than 10 million samples up to the end of its run";
        return RB_ERR_LIMIT;
    }
    double f = (double)m->polarity * m->scale;
    rb_status st;
    if (first == 0) {
        st = rb_series_copy(s, out);
        if (st == RB_OK)
            rb_series_scale(out, f);
        if (st == RB_OK && end + 1 < (double)out->n)
            st = rb_series_window(out, 0.0, end * s->dt_s);
        return st;
    }
    st = rb_series_alloc(out, (size_t)end + 1, s->dt_s);
    for (size_t i = 0; st == RB_OK && i < out->n; i++) {
        double k = (double)i - first;
        out->accel_mps2[i] = k >= 0 && k < (double)s->n ? f * s->accel_mps2[(size_t)k] : 0.0;
    }
    return st;
}

/* A closed form sampled RB_FLOOR_CLOSED_FORM_RATE times per period or
 * pulse over the run. */
static rb_status closed(const rb_motion *m, double run_s, rb_series *out, const char **why)
{
    double span = m->kind == RB_MOTION_HARMONIC ? 1.0 / m->freq_hz : m->pulse_s;
    double dt = span / RB_FLOOR_CLOSED_FORM_RATE;
    double n = floor(run_s / dt + 1e-9) + 1;
    if (!(dt > 0) || !(n <= RB_FLOOR_MAX_SAMPLES)) {
        *why = "sampled 200 times per period (a harmonic) or duration (a pulse), it "
               "takes more than 10 million samples up to the end of its run";
        return RB_ERR_LIMIT;
    }
    rb_status st = rb_series_alloc(out, (size_t)n, dt);
    for (size_t i = 0; st == RB_OK && i < out->n; i++)
        out->accel_mps2[i] = rb_motion_accel(m, (double)i * dt, 0.0);
    return st;
}

static rb_status component(const rb_motion *m, double run_s, const rb_target *target,
                           const rb_accept_rules *rules, rb_floor_component *fc,
                           const char **why)
{
    rb_status st;
    memset(fc, 0, sizeof *fc);
    fc->present = 1;
    if (m->kind == RB_MOTION_CRITICAL) {
        *why = "the critical excitation follows the cabinet's own rotation: it has no "
               "floor acceleration of its own to write";
        return RB_ERR_INVALID;
    }
    if (m->kind == RB_MOTION_SAMPLED) {
        st = m->series ? sampled(m, run_s, &fc->s, why) : RB_ERR_INVALID;
        fc->between = st == RB_OK && fc->s.bld.omega_rps > 0 ? RB_BETWEEN_BUILDING
                                                             : RB_BETWEEN_LINEAR;
    } else {
        st = closed(m, run_s, &fc->s, why);
        fc->between = RB_BETWEEN_SAMPLED;
    }
    if (st != RB_OK)
        return st;
    if (target && rules)
        fc->rules = *rules;
    else if (target)
        rb_accept_rules_init(&fc->rules, target);
    st = rb_motion_summarise(&fc->s, target, target ? &fc->rules : NULL, &fc->sum);
    if (st == RB_OK && target) {
        /* the TRS again, for the figure: the summary keeps only its verdict */
        st = rb_accept_grid(&fc->rules, &fc->trs);
        if (st == RB_OK)
            st = rb_spectrum_of_series(&fc->s, 1.0, &fc->trs);
    }
    if (st == RB_OK)
        fc->target = target;
    else
        *why = "no summary of it (its response spectrum against its target)";
    return st;
}

rb_status rb_run_floors(const rb_case *c, rb_case_floors *out, rb_diag *diag)
{
    memset(out, 0, sizeof *out);
    out->g_mps2 = STANDARD_GRAVITY;
    out->motions = calloc(c->n_motions ? c->n_motions : 1, sizeof *out->motions);
    if (!out->motions)
        return RB_ERR_NOMEM;
    out->n_motions = c->n_motions;
    rb_status st = RB_OK;
    for (size_t i = 0; i < c->n_motions && st == RB_OK; i++) {
        const rb_case_motion *cm = &c->motions[i];
        rb_floor_motion *fm = &out->motions[i];
        const char *why = NULL;
        rb_floor_axis at = RB_FLOOR_H1;
        fm->run_s = cm->motion.duration_s;
        st = component(&cm->motion, fm->run_s, cm->target, cm->rules, &fm->axis[RB_FLOOR_H1],
                       &why);
        if (st == RB_OK && cm->has_set && cm->h2.n > 0) {
            /* H2 is the set's other horizontal, matched to the same RRS;
             * a reversed polarity turns the cabinet (or the set) half
             * round about the vertical, which reverses both horizontals */
            rb_motion h2;
            rb_motion_init(&h2);
            h2.kind = RB_MOTION_SAMPLED;
            h2.series = &cm->h2;
            h2.polarity = cm->motion.polarity;
            at = RB_FLOOR_H2;
            st = component(&h2, fm->run_s, cm->target, cm->rules, &fm->axis[RB_FLOOR_H2], &why);
        }
        if (st == RB_OK && cm->motion.vertical) {
            at = RB_FLOOR_V;
            st = component(cm->motion.vertical, fm->run_s,
                           cm->vertical ? cm->vertical->target : NULL,
                           cm->vertical ? cm->vertical->rules : NULL, &fm->axis[RB_FLOOR_V],
                           &why);
        }
        if (st != RB_OK && st != RB_ERR_NOMEM)
            rb_diag_set(diag, st, NULL, 0, 0, cm->name ? cm->name : "motion",
                        "%s cannot be written: %s", at == RB_FLOOR_V ? "its vertical"
                        : at == RB_FLOOR_H2 ? "its second horizontal" : "the motion", why ? why : rb_status_str(st));
    }
    return st;
}

int rb_case_floors_fail(const rb_case_floors *f)
{
    for (size_t i = 0; i < f->n_motions; i++)
        for (int a = 0; a < RB_FLOOR_AXES; a++) {
            const rb_floor_component *fc = &f->motions[i].axis[a];
            if (fc->present && fc->sum.has_target && !(fc->sum.accept.pass && fc->sum.peak_ok))
                return 1;
        }
    return 0;
}

void rb_case_floors_free(rb_case_floors *f)
{
    if (!f)
        return;
    for (size_t i = 0; f->motions && i < f->n_motions; i++)
        for (int a = 0; a < RB_FLOOR_AXES; a++) {
            rb_series_free(&f->motions[i].axis[a].s);
            rb_spectrum_free(&f->motions[i].axis[a].trs);
        }
    free(f->motions);
    memset(f, 0, sizeof *f);
}
