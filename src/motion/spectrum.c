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
#include "matexp.h"

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
/* The free period after the samples is stepped as the samples are for at
 * most this long, then at the phase step: a period counted in sample
 * steps made a 1e-6 Hz oscillator take 2e8 steps per spectrum. Periods up
 * to 10 s (0.1 Hz and up) are stepped as they always were. */
#define SPECTRUM_TAIL_FINE_S 10.0

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

/* The exact transition over a sub-step of the state x (2 or 4 values)
 * under a load g linear across it: x1 = phi x0 + g0 g0 + g1 g1. */
typedef struct {
    size_t m;
    double phi[16], in0[4], in1[4];
} transition;

/* The state's rates: A x + B g. Without a building x = (w u, v); with one
 * x = (w_b u_b, v_b, w u, v) and g is the ground. */
static void system_matrix(double w, double xi, double wb, double xib,
                          size_t m, double *a, double *b)
{
    memset(a, 0, m * m * sizeof *a);
    size_t o = m - 2;           /* the oscillator's first index */
    if (m == 4) {
        a[0 * 4 + 1] = wb;
        a[1 * 4 + 0] = -wb;
        a[1 * 4 + 1] = -2.0 * xib * wb;
        /* the oscillator's load is -floor = w_b (w_b u_b) + 2 xi_b w_b v_b */
        a[3 * 4 + 0] = wb;
        a[3 * 4 + 1] = 2.0 * xib * wb;
        b[0] = 0.0;
        b[1] = -1.0;
        b[2] = 0.0;
        b[3] = 0.0;
    } else {
        b[0] = 0.0;
        b[1] = -1.0;
    }
    a[o * m + o + 1] = w;
    a[(o + 1) * m + o] = -w;
    a[(o + 1) * m + o + 1] = -2.0 * xi * w;
}

static void transition_init(transition *tr, size_t m, const double *a,
                            const double *b, double h)
{
    /* augmented (x, g, h g'), in units of the sub-step */
    size_t n = m + 2;
    double big[RB_MATEXP_MAX * RB_MATEXP_MAX] = {0}, e[RB_MATEXP_MAX * RB_MATEXP_MAX];
    for (size_t i = 0; i < m; i++) {
        for (size_t j = 0; j < m; j++)
            big[i * n + j] = h * a[i * m + j];
        big[i * n + m] = h * b[i];
    }
    big[m * n + m + 1] = 1.0;
    rb_matexp(n, big, e);
    tr->m = m;
    for (size_t i = 0; i < m; i++) {
        for (size_t j = 0; j < m; j++)
            tr->phi[i * m + j] = e[i * n + j];
        tr->in0[i] = e[i * n + m] - e[i * n + m + 1];
        tr->in1[i] = e[i * n + m + 1];
    }
}

static void transition_apply(const transition *tr, double *x, double g0, double g1)
{
    if (tr->m == 2) {   /* the common case, unrolled */
        double p = x[0], v = x[1];
        x[0] = tr->phi[0] * p + tr->phi[1] * v + tr->in0[0] * g0 + tr->in1[0] * g1;
        x[1] = tr->phi[2] * p + tr->phi[3] * v + tr->in0[1] * g0 + tr->in1[1] * g1;
        return;
    }
    double y[4];
    size_t m = tr->m;
    for (size_t i = 0; i < m; i++) {
        double s = tr->in0[i] * g0 + tr->in1[i] * g1;
        for (size_t j = 0; j < m; j++)
            s += tr->phi[i * m + j] * x[j];
        y[i] = s;
    }
    memcpy(x, y, m * sizeof *x);
}

/* The largest |y| on [0, h] of the cubic with values y0, y1 and slopes
 * d0, d1 at the ends, given that the ends are already counted. */
static double cubic_peak(double y0, double d0, double y1, double d1, double h)
{
    double b = h * d0, c = 3.0 * (y1 - y0) - h * (2.0 * d0 + d1);
    double d = 2.0 * (y0 - y1) + h * (d0 + d1);
    double roots[2];
    int nr = 0;
    if (fabs(d) < 1e-14 * (fabs(b) + fabs(c))) {
        if (c != 0.0)
            roots[nr++] = -b / (2.0 * c);
    } else {
        double disc = c * c - 3.0 * d * b;
        if (disc >= 0) {
            /* the stable pair of roots of 3 d s^2 + 2 c s + b */
            double q = -(c + copysign(sqrt(disc), c));
            if (q != 0.0) {
                roots[nr++] = q / (3.0 * d);
                roots[nr++] = b / q;
            }
        }
    }
    double best = 0.0;
    for (int i = 0; i < nr; i++) {
        double s = roots[i];
        if (s > 0.0 && s < 1.0) {
            double y = y0 + s * (b + s * (c + s * d));
            if (fabs(y) > best)
                best = fabs(y);
        }
    }
    return best;
}

/* An upper bound of |y| on [0, h] for that cubic, cheap enough to skip
 * cubic_peak where it cannot raise the peak: the cubic departs from the
 * chord by h s (1 - s) [(1 - s)(d0 - m) - s (d1 - m)], m the chord's slope,
 * so by at most a quarter of the larger of |h d0 - dy| and |h d1 - dy|. */
static double cubic_bound(double y0, double d0, double y1, double d1, double h)
{
    double dy = y1 - y0;
    return fmax(fabs(y0), fabs(y1)) + 0.25 * fmax(fabs(h * d0 - dy), fabs(h * d1 - dy));
}

typedef struct {
    double w, xi;
    double psa, sa;          /* peaks so far, as w u and absolute accel */
    double p, v, acc, jerk;  /* w u, v, absolute accel and its rate now */
} tracker;

/* The oscillator's absolute acceleration -(2 xi w v + w^2 u) and its
 * rate, for its load (-floor) now. */
static void tracker_read(tracker *t, double pw, double v, double load)
{
    double dv = -t->w * pw - 2.0 * t->xi * t->w * v + load;
    t->p = pw;
    t->v = v;
    t->acc = -(2.0 * t->xi * t->w * v + t->w * pw);
    t->jerk = -(2.0 * t->xi * t->w * dv + t->w * t->w * v);
}

/* Count the sub-step that ends in (pw, v, load), from the state before. */
static void tracker_step(tracker *t, double pw, double v, double load, double h)
{
    double p0 = t->p, dp0 = t->w * t->v, a0 = t->acc, j0 = t->jerk;
    tracker_read(t, pw, v, load);
    double dp1 = t->w * t->v;
    if (fabs(pw) > t->psa)
        t->psa = fabs(pw);
    if (fabs(t->acc) > t->sa)
        t->sa = fabs(t->acc);
    if (dp0 * dp1 <= 0.0 && cubic_bound(p0, dp0, pw, dp1, h) > t->psa) {
        double c = cubic_peak(p0, dp0, pw, dp1, h);
        if (c > t->psa)
            t->psa = c;
    }
    if (j0 * t->jerk <= 0.0 && cubic_bound(a0, j0, t->acc, t->jerk, h) > t->sa) {
        double c = cubic_peak(a0, j0, t->acc, t->jerk, h);
        if (c > t->sa)
            t->sa = c;
    }
}

/* The peaks of one oscillator under the series. */
static void oscillator_peaks(const rb_series *s, double f_hz, double xi, double phase,
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
    transition tr, free_tr;
    system_matrix(w, xi, wb, bld->xi, m, a, b);
    transition_init(&tr, m, a, b, h);
    /* after the samples the floor is zero: the oscillator alone */
    double a2[4], b2[2];
    system_matrix(w, xi, 0.0, 0.0, 2, a2, b2);
    unsigned kf = (unsigned)ceil(w * s->dt_s / phase);
    double hf = s->dt_s / (kf ? kf : 1);
    transition_init(&free_tr, 2, a2, b2, hf);

    const double *g = building ? bld->ground_mps2 : s->accel_mps2;
    double x[4] = {0};
    if (building) {
        x[0] = bld->omega_rps * bld->u_m[0];
        x[1] = bld->v_mps[0];
    }
    tracker t = {.w = w, .xi = xi};
    /* the load on the oscillator: -floor; through a building, a state */
#define OSC_LOAD(xs, gi) (building ? wb * (xs)[0] + 2.0 * bld->xi * wb * (xs)[1] : -(gi))
    tracker_read(&t, x[o], x[o + 1], OSC_LOAD(x, g[0]));
    for (size_t i = 1; i < s->n; i++) {
        double g0 = g[i - 1], slope = (g[i] - g0) / k;
        for (unsigned j = 0; j < k; j++) {
            double ga = g0 + slope * j, gb = (j + 1 == k) ? g[i] : g0 + slope * (j + 1);
            transition_apply(&tr, x, ga, gb);
            tracker_step(&t, x[o], x[o + 1], OSC_LOAD(x, gb), h);
        }
    }
#undef OSC_LOAD
    /* the floor drops to zero at the end (as the solver's does), then one
     * free period, where the peak of a slow oscillator may still come */
    double y[2] = {x[o], x[o + 1]};
    tracker_read(&t, y[0], y[1], 0.0);
    double period = 1.0 / f_hz, rest = 0.0;
    size_t steps;
    if (period > SPECTRUM_TAIL_FINE_S) {
        steps = (size_t)ceil(SPECTRUM_TAIL_FINE_S / hf);
        rest = period - (double)steps * hf;
    } else {
        steps = (size_t)ceil(period / hf);
    }
    for (size_t i = 0; i < steps; i++) {
        transition_apply(&free_tr, y, 0.0, 0.0);
        tracker_step(&t, y[0], y[1], 0.0, hf);
    }
    if (rest > 0) {
        /* no load: the transition is exact at any step, and the cubic's
         * error depends only on the phase a step covers */
        size_t nb = (size_t)ceil(rest * w / phase);
        double hb = rest / (double)(nb ? nb : 1);
        transition free_long;
        transition_init(&free_long, 2, a2, b2, hb);
        for (size_t i = 0; i < nb; i++) {
            transition_apply(&free_long, y, 0.0, 0.0);
            tracker_step(&t, y[0], y[1], 0.0, hb);
        }
    }
    *psa = w * t.psa;
    *sa = t.sa;
}

rb_status rb_spectrum_of_series(const rb_series *s, double scale, rb_spectrum *sp)
{
    if (!s || s->n < 1 || !sp || sp->n == 0 || !(s->dt_s > 0))
        return RB_ERR_INVALID;
    double phase = sp->step_phase;
    if (!(phase > 0) || phase > SPECTRUM_COARSEST_PHASE)
        phase = phase > SPECTRUM_COARSEST_PHASE ? SPECTRUM_COARSEST_PHASE : SPECTRUM_MAX_PHASE;
    for (size_t i = 0; i < sp->n; i++) {
        oscillator_peaks(s, sp->freq_hz[i], sp->damping, phase, &sp->psa_mps2[i],
                         &sp->sa_mps2[i]);
        sp->psa_mps2[i] *= fabs(scale);
        sp->sa_mps2[i] *= fabs(scale);
    }
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
