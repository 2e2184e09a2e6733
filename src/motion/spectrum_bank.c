/* A bank of response-spectrum oscillators on a floor given directly,
 * stepped together sample by sample.
 *
 * Each oscillator moves across a sample interval by the exact transition
 * of its state under the floor taken linear between samples (the Nigam-
 * Jennings recurrence, a 2x2 matrix and two load columns): no sub-steps.
 * The loop over oscillators is innermost and branch-free, so that it
 * vectorises, and calls nothing from libm.
 *
 * Peaks between samples. Over an interval the floor is f0 + s t and the
 * response is a particular part linear in t plus a free damped vibration
 * (the homogeneous part):
 *
 *   w u     = (-f(t) + 2 xi s / w) / w  +  e^(-xi w t) (c cos wd t + d sin wd t)
 *   u'' + f = f(t)                      +  e^(-xi w t) (c' cos wd t + d' sin wd t)
 *
 * Between its ends a value y (w u, or u'' + f) departs from the cubic
 * through its exact values and rates by at most (w dt)^4 / 384 times the
 * free part's amplitude (Hermite's remainder: the fourth derivative of y
 * is the free part's, a damped sinusoid of rate w, never above w^4
 * sqrt(c^2 + d^2), c its value and d = (its rate + xi w c) / wd at the
 * start; |c| + |d| is taken for the root; the free part of u'' + f is
 * that of w u's second rate, w times its amplitude), and that cubic departs from
 * its chord by at most a quarter of the larger of |dt y0' - dy| and
 * |dt y1' - dy|. Where the sum stays under the running peak the interval
 * cannot raise it; the few where it does not are walked again in
 * sub-steps of at most `phase` radians with the peaks located on the
 * cubic through exact states (spectrum_step.c), as the sub-stepped walk
 * does everywhere. */

#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "spectrum_bank.h"
#include "spectrum_step.h"

/* A run expects each peak to reach this fraction of the last run's, and
 * walks in sub-steps only the intervals that could raise a peak above
 * that (or above the running peak, when it is higher): the early part of
 * a motion, under peaks still small, is not walked again and again. */
#define SPECTRUM_BANK_HINT 0.8

/* One array per quantity, each of n oscillators: the loop over them reads
 * consecutive doubles. */
enum {
    B_A00, B_A01, B_A10, B_A11,  /* the transition over one sample */
    B_G00, B_G01, B_G10, B_G11,  /* its load columns: in0, in1 per row */
    B_W, B_TW, B_SIG,            /* w, 2 xi w, xi w */
    B_INV_W, B_CS, B_INV_W2, B_INV_WD, /* 1/w, 2 xi / w, 1/w^2, 1/wd */
    B_HERMITE,                   /* (w dt)^4 / 384 */
    B_P0, B_V0, B_P1, B_V1,      /* the state, double-buffered */
    B_PSA, B_SA,                 /* running peaks: w u, absolute accel */
    B_FLAG,                      /* the interval may hold a higher peak */
    B_HINT_P, B_HINT_A,          /* peaks the run is expected to reach */
    B_FIELDS
};

struct rb_spectrum_bank {
    size_t n;
    double *v;                   /* B_FIELDS arrays of n */
    rb_spec_transition *sub;     /* per oscillator, made when first needed */
    unsigned *sub_k;             /* its sub-steps per sample; 0: not made */
    double dt, xi, phase;
    double *f_hz;                /* owned, n */
    int hinted;                  /* B_HINT_P and B_HINT_A are set */
};
typedef struct rb_spectrum_bank bank;

static double *field(const bank *b, int k)
{
    return b->v + (size_t)k * b->n;
}

void rb_spec_bank_free(bank *b)
{
    if (!b)
        return;
    free(b->v);
    free(b->sub);
    free(b->sub_k);
    free(b->f_hz);
    free(b);
}

rb_status rb_spec_bank_new(const double *f_hz, size_t n, double xi, double dt, double phase,
                           bank **out)
{
    bank *b = *out = calloc(1, sizeof *b);
    if (!b)
        return RB_ERR_NOMEM;
    b->n = n;
    b->dt = dt;
    b->xi = xi;
    b->phase = phase;
    b->v = calloc((size_t)B_FIELDS * n, sizeof *b->v);
    b->sub = malloc(n * sizeof *b->sub);
    b->sub_k = calloc(n, sizeof *b->sub_k);
    b->f_hz = malloc(n * sizeof *b->f_hz);
    if (!b->v || !b->sub || !b->sub_k || !b->f_hz) {
        rb_spec_bank_free(b);
        *out = NULL;
        return RB_ERR_NOMEM;
    }
    memcpy(b->f_hz, f_hz, n * sizeof *f_hz);
    double wd_of_w = sqrt(1.0 - xi * xi);
    for (size_t j = 0; j < n; j++) {
        double w = 2.0 * M_PI * f_hz[j], a[4], bv[2];
        rb_spec_transition tr;
        rb_spec_system(w, xi, 0.0, 0.0, 2, a, bv);
        rb_spec_transition_init(&tr, 2, a, bv, dt);
        field(b, B_A00)[j] = tr.phi[0];
        field(b, B_A01)[j] = tr.phi[1];
        field(b, B_A10)[j] = tr.phi[2];
        field(b, B_A11)[j] = tr.phi[3];
        field(b, B_G00)[j] = tr.in0[0];
        field(b, B_G01)[j] = tr.in1[0];
        field(b, B_G10)[j] = tr.in0[1];
        field(b, B_G11)[j] = tr.in1[1];
        field(b, B_W)[j] = w;
        field(b, B_TW)[j] = 2.0 * xi * w;
        field(b, B_SIG)[j] = xi * w;
        field(b, B_INV_W)[j] = 1.0 / w;
        field(b, B_CS)[j] = 2.0 * xi / w;
        field(b, B_INV_W2)[j] = 1.0 / (w * w);
        field(b, B_INV_WD)[j] = 1.0 / (w * wd_of_w);
        double th = w * dt;
        field(b, B_HERMITE)[j] = th * th * th * th / 384.0;
    }
    return RB_OK;
}

int rb_spec_bank_fits(const bank *b, const double *f_hz, size_t n, double xi, double dt,
                      double phase)
{
    return b && b->n == n && b->xi == xi && b->dt == dt && b->phase == phase
           && memcmp(b->f_hz, f_hz, n * sizeof *f_hz) == 0;
}

/* The sub-step transition of oscillator j, made on first use and kept. */
static const rb_spec_transition *sub_of(bank *b, size_t j)
{
    if (!b->sub_k[j])
        rb_spec_sub_transition(&b->sub[j], field(b, B_W)[j], b->xi, b->dt, b->phase,
                               &b->sub_k[j]);
    return &b->sub[j];
}

/* Walk oscillator j across the interval from (p, v) under the floor f0 to
 * f1 in sub-steps, raising its peaks where the cubic finds them. */
static void refine(bank *b, size_t j, double p, double v, double f0, double f1)
{
    double w = field(b, B_W)[j];
    const rb_spec_transition *sub = sub_of(b, j);
    unsigned k = b->sub_k[j];
    double h = b->dt / k, slope = (f1 - f0) / k, x[2] = {p, v};
    rb_spec_tracker t = {.w = w, .xi = b->xi, .psa = field(b, B_PSA)[j],
                         .sa = field(b, B_SA)[j]};
    rb_spec_tracker_read(&t, p, v, -f0);
    for (unsigned i = 0; i < k; i++) {
        double ga = f0 + slope * i, gb = (i + 1 == k) ? f1 : f0 + slope * (i + 1);
        rb_spec_transition_apply(sub, x, ga, gb);
        rb_spec_tracker_step(&t, x[0], x[1], -gb, h);
    }
    field(b, B_PSA)[j] = t.psa;
    field(b, B_SA)[j] = t.sa;
}

/* An upper bound of |y| over an interval for the cubic through y0 and y1
 * with the rates times the interval hd0 and hd1 (spectrum_step.c's
 * cubic_bound, branch-free). */
static inline double cubic_bound(double y0, double hd0, double y1, double hd1)
{
    double dy = y1 - y0, a0 = fabs(y0), a1 = fabs(y1);
    double e0 = fabs(hd0 - dy), e1 = fabs(hd1 - dy);
    return (a0 > a1 ? a0 : a1) + 0.25 * (e0 > e1 ? e0 : e1);
}

/* One sample interval for every oscillator: the state from (p0, v0) to
 * (p1, v1), the peaks at the interval's end, and whether the interval can
 * hold a peak above them (flag > 0); whether any can. Every array a parameter of its own: restrict on the bank's fields
 * as locals was not taken, and the loop stayed scalar for want of alias
 * checks. c: the coefficients, B_A00 to B_INV_WD arrays of n. */
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__)
/* Four oscillators a vector where the processor has AVX2, two elsewhere:
 * the same operations in the same order, no FMA (not in the target, and
 * ISO C mode does not contract), so the same bits on every machine. */
__attribute__((target_clones("avx2", "default")))
#endif
static int bank_step(size_t n, const double *restrict c, const double *restrict p0,
                     const double *restrict v0, double *restrict p1, double *restrict v1,
                     double *restrict psa, double *restrict sa, double *restrict flag,
                     const double *restrict hint_p, const double *restrict hint_a,
                     double f0, double f1, double dt)
{
#define C(k) c[(size_t)(k) * n + j]
    double s = (f1 - f0) / dt, h = dt;
    unsigned long long any = 0;
    for (size_t j = 0; j < n; j++) {
        double p = p0[j], v = v0[j], w = C(B_W), tw = C(B_TW);
        double pn = C(B_A00) * p + C(B_A01) * v + C(B_G00) * f0 + C(B_G01) * f1;
        double vn = C(B_A10) * p + C(B_A11) * v + C(B_G10) * f0 + C(B_G11) * f1;
        p1[j] = pn;
        v1[j] = vn;
        /* w u and the absolute acceleration y, with their rates, at both
         * ends: (w u)' = w v, y' = -(2 xi w (y - f) + w^2 v) */
        double ya = -(tw * v + w * p), yb = -(tw * vn + w * pn);
        double ja = -(tw * (ya - f0) + w * w * v), jb = -(tw * (yb - f1) + w * w * vn);
        double ap = fabs(pn), aa = fabs(yb);
        double mp = psa[j] > ap ? psa[j] : ap, ma = sa[j] > aa ? sa[j] : aa;
        psa[j] = mp;
        sa[j] = ma;
        /* the free part at the start, the state less the particular part:
         * its amplitude in w u (|c| + |d| >= sqrt(c^2 + d^2)), and w times
         * that in u'' (a damped sinusoid's rate has w times its amplitude) */
        double ph = p - (C(B_CS) * s - f0) * C(B_INV_W), vh = v + s * C(B_INV_W2);
        double dp = (w * vh + C(B_SIG) * ph) * C(B_INV_WD);
        double ep = C(B_HERMITE) * (fabs(ph) + fabs(dp));
        double bp = cubic_bound(p, h * w * v, pn, h * w * vn) + ep;
        double ba = cubic_bound(ya, h * ja, yb, h * jb) + w * ep;
        double hp = hint_p[j], ha = hint_a[j];
        double fp = bp - (mp > hp ? mp : hp), fa = ba - (ma > ha ? ma : ha);
        double fl = fp > fa ? fp : fa;
        flag[j] = fl;
        any |= fl > 0.0 ? ~0ull : 0ull;
    }
#undef C
    return any != 0;
}

rb_status rb_spec_bank_run(bank *b, const rb_series *s, double *psa, double *sa)
{
    const double *g = s->accel_mps2;
    size_t n = b->n;
    /* from rest: the state, and with it the absolute acceleration, is 0;
     * so are the running peaks */
    memset(field(b, B_P0), 0, (size_t)(B_HINT_P - B_P0) * n * sizeof *b->v);
    if (!b->hinted)
        memset(field(b, B_HINT_P), 0, 2 * n * sizeof *b->v);
    double *p0 = field(b, B_P0), *v0 = field(b, B_V0);
    double *p1 = field(b, B_P1), *v1 = field(b, B_V1);
    double *flag = field(b, B_FLAG);
    double *psa_run = field(b, B_PSA), *sa_run = field(b, B_SA);
    double *hint_p = field(b, B_HINT_P), *hint_a = field(b, B_HINT_A);
    for (size_t i = 1; i < s->n; i++) {
        if (bank_step(n, b->v, p0, v0, p1, v1, psa_run, sa_run, flag, hint_p, hint_a,
                      g[i - 1], g[i], s->dt_s))
            for (size_t j = 0; j < n; j++)
                if (flag[j] > 0.0)
                    refine(b, j, p0[j], v0[j], g[i - 1], g[i]);
        double *t = p0;
        p0 = p1;
        p1 = t;
        t = v0;
        v0 = v1;
        v1 = t;
    }
    for (size_t j = 0; j < n; j++) {
        double w = field(b, B_W)[j], y[2] = {p0[j], v0[j]};
        rb_spec_tracker t = {.w = w, .xi = b->xi, .psa = psa_run[j], .sa = sa_run[j]};
        rb_spec_free_tail_with(&t, y, b->f_hz[j], s->dt_s, b->phase, sub_of(b, j),
                               b->sub_k[j]);
        psa[j] = w * t.psa;
        sa[j] = t.sa;
        psa_run[j] = t.psa;
        sa_run[j] = t.sa;
    }
    /* Intervals whose bound stayed under a hint were not walked: that is
     * right where the peak reached the hint (the interval could not raise
     * it), and the run is made again without hints where one did not. */
    int short_of_hint = 0;
    for (size_t j = 0; j < n; j++)
        short_of_hint |= psa_run[j] < hint_p[j] || sa_run[j] < hint_a[j];
    if (b->hinted && short_of_hint) {
        b->hinted = 0;
        return rb_spec_bank_run(b, s, psa, sa);
    }
    for (size_t j = 0; j < n; j++) {
        hint_p[j] = SPECTRUM_BANK_HINT * psa_run[j];
        hint_a[j] = SPECTRUM_BANK_HINT * sa_run[j];
    }
    b->hinted = 1;
    return RB_OK;
}

rb_status rb_spec_bank_peaks(const rb_series *s, const double *f_hz, size_t n, double xi,
                             double phase, double *psa, double *sa)
{
    bank *b;
    rb_status st = rb_spec_bank_new(f_hz, n, xi, s->dt_s, phase, &b);
    if (st == RB_OK)
        st = rb_spec_bank_run(b, s, psa, sa);
    rb_spec_bank_free(b);
    return st;
}
