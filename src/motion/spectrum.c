/* Response spectra, stepped exactly.
 *
 * The oscillator on the floor, u'' + 2 xi w u' + w^2 u = -floor(t), is a
 * linear system driven by a load that is linear between samples: without
 * a building the floor itself, through a building the ground (the floor
 * being the building's response, -(2 xi_b w_b v_b + w_b^2 u_b)). Either
 * way the state moves across a sub-step by the exact transition of the
 * augmented system (state, load, load rate), one matrix exponential per
 * frequency (matexp.c). Displacements are carried as w u so that every
 * entry of the matrix is of order w. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/spectrum.h"
#include "spectrum_step.h"
#include "spectrum_bank.h"

/* Sub-steps of at most this many radians of the fastest mode by default:
 * the peak between two exact states, taken on the cubic through their
 * values and slopes, is then within (0.2)^4 / 384 (4e-6) of the true one. */
#define SPECTRUM_MAX_PHASE 0.2
#define SPECTRUM_COARSEST_PHASE 1.0
/* Samples per period of the highest frequency, for closed-form motions. */
#define SPECTRUM_CLOSED_FORM_RATE 200.0
/* ... and at most this many samples (80 MB): a longer closed form is
 * refused (RB_ERR_LIMIT) rather than sampled more coarsely. */
#define SPECTRUM_MAX_CLOSED_FORM_SAMPLES 1e7

void rb_spectrum_opts_init(rb_spectrum_opts *o)
{
    o->damping = 0.05;
    o->f_min_hz = 0.5;
    o->f_max_hz = 50.0;
    o->per_octave = 12.0;
}

void rb_spectrum_free(rb_spectrum *sp)
{
    if (!sp)
        return;
    free(sp->freq_hz);
    free(sp->psa_mps2);
    free(sp->sa_mps2);
    memset(sp, 0, sizeof *sp);
}

rb_status rb_spectrum_alloc(rb_spectrum *sp, const double *freq_hz, size_t n,
                            double damping)
{
    memset(sp, 0, sizeof *sp);
    if (n == 0 || n > RB_SPECTRUM_MAX_POINTS || !(damping >= 0 && damping < 1))
        return RB_ERR_INVALID;
    for (size_t i = 0; i < n; i++)
        if (!(freq_hz[i] > 0 && isfinite(freq_hz[i])) || (i && !(freq_hz[i] > freq_hz[i - 1])))
            return RB_ERR_INVALID;
    sp->freq_hz = malloc(n * sizeof *sp->freq_hz);
    sp->psa_mps2 = calloc(n, sizeof *sp->psa_mps2);
    sp->sa_mps2 = calloc(n, sizeof *sp->sa_mps2);
    if (!sp->freq_hz || !sp->psa_mps2 || !sp->sa_mps2) {
        rb_spectrum_free(sp);
        return RB_ERR_NOMEM;
    }
    memcpy(sp->freq_hz, freq_hz, n * sizeof *freq_hz);
    sp->n = n;
    sp->damping = damping;
    sp->step_phase = SPECTRUM_MAX_PHASE;
    return RB_OK;
}

rb_status rb_spectrum_grid(const rb_spectrum_opts *o, rb_spectrum *sp)
{
    memset(sp, 0, sizeof *sp);
    if (!(o->f_min_hz > 0) || !(o->f_max_hz > o->f_min_hz) || !isfinite(o->f_max_hz)
        || !(o->per_octave > 0) || !isfinite(o->per_octave))
        return RB_ERR_INVALID;
    double octaves = log2(o->f_max_hz / o->f_min_hz);
    double points = floor(octaves * o->per_octave + 1e-9) + 1;
    if (!(points <= RB_SPECTRUM_MAX_POINTS))
        return RB_ERR_INVALID;
    size_t n = (size_t)points;
    double *f = malloc(n * sizeof *f);
    if (!f)
        return RB_ERR_NOMEM;
    for (size_t k = 0; k < n; k++)
        f[k] = o->f_min_hz * exp2((double)k / o->per_octave);
    rb_status st = rb_spectrum_alloc(sp, f, n, o->damping);
    free(f);
    return st;
}

/* The peaks of one oscillator under the series, stepped in sub-steps of
 * at most `phase` radians of the fastest mode: the cascade through a
 * building (or a floor given directly, for the tests that hold the bank
 * to it). */
void rb_spec_substep_peaks(const rb_series *s, double f_hz, double xi, double phase,
                           double *psa, double *sa)
{
    const rb_series_building *bld = &s->bld;
    int building = bld->ground_mps2 != NULL;
    size_t m = building ? 4 : 2, o = m - 2;
    double w = 2.0 * M_PI * f_hz, wb = building ? bld->omega_rps : 0.0;
    double fastest = w > wb ? w : wb;
    unsigned k = (unsigned)ceil(fastest * s->dt_s / phase);
    if (k < 1)
        k = 1;
    double h = s->dt_s / k;
    double a[16], b[4];
    rb_spec_transition tr;
    rb_spec_system(w, xi, wb, bld->xi, m, a, b);
    rb_spec_transition_init(&tr, m, a, b, h);

    const double *g = building ? bld->ground_mps2 : s->accel_mps2;
    double x[4] = {0};
    if (building) {
        x[0] = bld->omega_rps * bld->u_m[0];
        x[1] = bld->v_mps[0];
    }
    rb_spec_tracker t = {.w = w, .xi = xi};
    /* the load on the oscillator: -floor; through a building, a state */
#define OSC_LOAD(xs, gi) (building ? wb * (xs)[0] + 2.0 * bld->xi * wb * (xs)[1] : -(gi))
    rb_spec_tracker_read(&t, x[o], x[o + 1], OSC_LOAD(x, g[0]));
    for (size_t i = 1; i < s->n; i++) {
        double g0 = g[i - 1], slope = (g[i] - g0) / k;
        for (unsigned j = 0; j < k; j++) {
            double ga = g0 + slope * j, gb = (j + 1 == k) ? g[i] : g0 + slope * (j + 1);
            rb_spec_transition_apply(&tr, x, ga, gb);
            rb_spec_tracker_step(&t, x[o], x[o + 1], OSC_LOAD(x, gb), h);
        }
    }
#undef OSC_LOAD
    rb_spec_free_tail(&t, x + o, f_hz, s->dt_s, phase);
    *psa = w * t.psa;
    *sa = t.sa;
}

/* The phase sp's sub-steps are taken at. */
static double phase_of(const rb_spectrum *sp)
{
    double phase = sp->step_phase;
    if (!(phase > 0) || phase > SPECTRUM_COARSEST_PHASE)
        phase = phase > SPECTRUM_COARSEST_PHASE ? SPECTRUM_COARSEST_PHASE : SPECTRUM_MAX_PHASE;
    return phase;
}

static void scale_ordinates(rb_spectrum *sp, double scale)
{
    for (size_t i = 0; i < sp->n; i++) {
        sp->psa_mps2[i] *= fabs(scale);
        sp->sa_mps2[i] *= fabs(scale);
    }
}

rb_status rb_spectrum_bank_new(const rb_spectrum *sp, double dt_s, rb_spectrum_bank **out)
{
    *out = NULL;
    if (!sp || sp->n == 0 || !(dt_s > 0))
        return RB_ERR_INVALID;
    return rb_spec_bank_new(sp->freq_hz, sp->n, sp->damping, dt_s, phase_of(sp), out);
}

void rb_spectrum_bank_free(rb_spectrum_bank *b)
{
    rb_spec_bank_free(b);
}

rb_status rb_spectrum_of_series_banked(rb_spectrum_bank *b, const rb_series *s,
                                       double scale, rb_spectrum *sp)
{
    if (!s || s->n < 1 || !sp || sp->n == 0 || !(s->dt_s > 0) || s->bld.ground_mps2
        || !rb_spec_bank_fits(b, sp->freq_hz, sp->n, sp->damping, s->dt_s, phase_of(sp)))
        return rb_spectrum_of_series(s, scale, sp);
    rb_status st = rb_spec_bank_run(b, s, sp->psa_mps2, sp->sa_mps2);
    if (st == RB_OK)
        scale_ordinates(sp, scale);
    return st;
}

rb_status rb_spectrum_of_series(const rb_series *s, double scale, rb_spectrum *sp)
{
    if (!s || s->n < 1 || !sp || sp->n == 0 || !(s->dt_s > 0))
        return RB_ERR_INVALID;
    double phase = phase_of(sp);
    if (!s->bld.ground_mps2) {
        rb_status st = rb_spec_bank_peaks(s, sp->freq_hz, sp->n, sp->damping, phase,
                                          sp->psa_mps2, sp->sa_mps2);
        if (st != RB_OK)
            return st;
    } else {
        for (size_t i = 0; i < sp->n; i++)
            rb_spec_substep_peaks(s, sp->freq_hz[i], sp->damping, phase, &sp->psa_mps2[i],
                                  &sp->sa_mps2[i]);
    }
    scale_ordinates(sp, scale);
    return RB_OK;
}

rb_status rb_spectrum_of_motion(const rb_motion *m, rb_spectrum *sp)
{
    if (!m || !sp || sp->n == 0)
        return RB_ERR_INVALID;
    if (m->kind == RB_MOTION_SAMPLED)
        return m->series ? rb_spectrum_of_series(m->series, m->scale, sp) : RB_ERR_INVALID;
    if (m->kind == RB_MOTION_CRITICAL || !(m->duration_s > 0))
        return RB_ERR_INVALID;
    double dt = 1.0 / (SPECTRUM_CLOSED_FORM_RATE * sp->freq_hz[sp->n - 1]);
    double n = ceil(m->duration_s / dt) + 1;
    if (!(n <= SPECTRUM_MAX_CLOSED_FORM_SAMPLES))
        return RB_ERR_LIMIT;
    rb_series s;
    rb_status st = rb_series_alloc(&s, (size_t)n, dt);
    if (st != RB_OK)
        return st;
    rb_motion plain = *m;
    plain.polarity = 1;
    for (size_t i = 0; i < s.n; i++)
        s.accel_mps2[i] = rb_motion_accel(&plain, (double)i * dt, 0.0);
    st = rb_spectrum_of_series(&s, 1.0, sp);
    rb_series_free(&s);
    return st;
}

void rb_case_spectra_free(rb_case_spectra *s)
{
    if (!s)
        return;
    for (size_t i = 0; s->motions && i < s->n_motions; i++)
        rb_spectrum_free(&s->motions[i].sp);
    free(s->motions);
    memset(s, 0, sizeof *s);
}
