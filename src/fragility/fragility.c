/* Lognormal fragility fitting (rockbolt/fragility.h).
 *
 * In x = ln capacity the capacities are normal (mu, beta); a censored
 * motion contributes P(x > c) = 1 - Phi((c - mu) / beta). The EM
 * iteration (Dempster, Laird and Rubin 1977) replaces each censored x by
 * its expectation given x > c, E[x] = mu + beta lambda(z) and
 * E[x^2] = mu^2 + beta^2 + beta (c + mu) lambda(z), with z = (c - mu) / beta
 * and lambda the inverse Mills ratio phi(z) / (1 - Phi(z)); each step
 * raises the likelihood, and the fixed point is the maximum. It is a few
 * lines where a general optimiser (and its library) would be more. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <stdio.h>
#include "rockbolt/fragility.h"
#include "rockbolt/names.h"
#include "util/rng.h"

const rb_enum_name rb_intensity_names[] = {
    {"pfa", RB_IM_PFA}, {"sa", RB_IM_SA}, {NULL, 0}};
const rb_enum_name rb_intensity_report_names[] = {
    {"peak_floor_acceleration", RB_IM_PFA}, {"spectral_acceleration", RB_IM_SA},
    {NULL, 0}};
const rb_enum_name rb_limit_state_names[] = {
    {"first-yield", RB_LIMIT_FIRST_YIELD}, {"usage", RB_LIMIT_USAGE},
    {"overturn", RB_LIMIT_OVERTURN}, {"lift-off", RB_LIMIT_LIFT_OFF},
    {"anchorage", RB_LIMIT_ANCHORAGE}, {NULL, 0}};

#define EM_MAX_ITERATIONS 10000
#define EM_TOLERANCE 1e-12

double rb_normal_cdf(double z)
{
    return 0.5 * erfc(-z / M_SQRT2);
}

double rb_normal_quantile(double p)
{
    if (!(p > 0 && p < 1))
        return p == 0 ? -INFINITY : p == 1 ? INFINITY : NAN;
    /* bisection on the monotone cdf: slow beside a rational approximation,
     * but exact to rounding and called a handful of times per fit */
    double lo = -40, hi = 40, z = 0;
    for (int i = 0; i < 200 && hi - lo > 1e-15 * (1 + fabs(z)); i++) {
        z = 0.5 * (lo + hi);
        if (rb_normal_cdf(z) < p)
            lo = z;
        else
            hi = z;
    }
    return 0.5 * (lo + hi);
}

/* phi(z) / (1 - Phi(z)), also far in the tail */
static double inverse_mills(double z)
{
    double q = 0.5 * erfc(z / M_SQRT2);
    if (q > 1e-300)
        return exp(-0.5 * z * z) / sqrt(2 * M_PI) / q;
    return z + 1 / z;   /* the asymptote, past where q underflows */
}

static double loglik(const double *x, const int *cens, size_t n, double mu, double beta)
{
    double l = 0;
    for (size_t i = 0; i < n; i++) {
        double z = (x[i] - mu) / beta;
        if (cens && cens[i])
            l += log(0.5 * erfc(z / M_SQRT2));
        else
            l += -0.5 * z * z - log(beta) - 0.5 * log(2 * M_PI);
    }
    return l;
}

/* The fit in ln space: mu, beta from x[], cens[] (may be NULL). */
static rb_status fit_ln(const double *x, const int *cens, size_t n, rb_fragility_fit *out)
{
    double s = 0, ss = 0;
    size_t nu = 0;
    for (size_t i = 0; i < n; i++)
        if (!(cens && cens[i])) {
            s += x[i];
            nu++;
        }
    if (nu < 2)
        return RB_ERR_INVALID;
    double mu = s / nu;
    for (size_t i = 0; i < n; i++)
        if (!(cens && cens[i]))
            ss += (x[i] - mu) * (x[i] - mu);
    double beta = sqrt(ss / nu);
    if (!(beta > 0))
        return RB_ERR_INVALID;
    int it = 0;
    if (nu < n) {
        for (it = 1; it <= EM_MAX_ITERATIONS; it++) {
            double s1 = 0, s2 = 0;
            for (size_t i = 0; i < n; i++) {
                if (cens && cens[i]) {
                    double z = (x[i] - mu) / beta, lam = inverse_mills(z);
                    s1 += mu + beta * lam;
                    s2 += mu * mu + beta * beta + beta * (x[i] + mu) * lam;
                } else {
                    s1 += x[i];
                    s2 += x[i] * x[i];
                }
            }
            double mu1 = s1 / n, var = s2 / n - mu1 * mu1;
            double beta1 = var > 0 ? sqrt(var) : beta;
            int done = fabs(mu1 - mu) <= EM_TOLERANCE * (1 + fabs(mu))
                       && fabs(beta1 - beta) <= EM_TOLERANCE * beta;
            mu = mu1;
            beta = beta1;
            if (done)
                break;
        }
    }
    out->median = exp(mu);
    out->beta = beta;
    out->iterations = it;
    out->loglik = loglik(x, cens, n, mu, beta);
    return RB_OK;
}

rb_status rb_fragility_mle(const double *capacity, const int *censored, size_t n,
                           rb_fragility_fit *out)
{
    *out = (rb_fragility_fit){0};
    double *x = malloc((n ? n : 1) * sizeof *x);
    if (!x)
        return RB_ERR_NOMEM;
    rb_status st = RB_OK;
    for (size_t i = 0; i < n && st == RB_OK; i++) {
        if (!(capacity[i] > 0) || !isfinite(capacity[i]))
            st = RB_ERR_INVALID;
        else
            x[i] = log(capacity[i]);
    }
    if (st == RB_OK)
        st = fit_ln(x, censored, n, out);
    free(x);
    return st;
}

double rb_fragility_prob(const rb_fragility_fit *f, double im)
{
    if (!(im > 0))
        return 0;
    return rb_normal_cdf(log(im / f->median) / f->beta);
}

double rb_fragility_quantile(const rb_fragility_fit *f, double p)
{
    return f->median * exp(f->beta * rb_normal_quantile(p));
}

static int cmp_double(const void *a, const void *b)
{
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

rb_status rb_fragility_bootstrap(const double *capacity, const int *censored, size_t n,
                                 unsigned n_boot, uint64_t seed, double level,
                                 double *lo, double *hi, unsigned *skipped)
{
    rb_fragility_fit whole;
    rb_status st = rb_fragility_mle(capacity, censored, n, &whole);
    if (st != RB_OK)
        return st;
    if (n_boot == 0 || !(level > 0 && level < 1))
        return RB_ERR_INVALID;
    double *x = malloc(n * sizeof *x), *med = malloc(n_boot * sizeof *med);
    int *c = malloc(n * sizeof *c);
    if (!x || !med || !c) {
        free(x), free(med), free(c);
        return RB_ERR_NOMEM;
    }
    rb_rng rng;
    rb_rng_seed(&rng, seed);
    unsigned ok = 0, bad = 0;
    for (unsigned b = 0; b < n_boot; b++) {
        for (size_t i = 0; i < n; i++) {
            size_t k = (size_t)rb_rng_below(&rng, n);
            x[i] = log(capacity[k]);
            c[i] = censored ? censored[k] : 0;
        }
        rb_fragility_fit f;
        if (fit_ln(x, c, n, &f) == RB_OK)
            med[ok++] = f.median;
        else
            bad++;
    }
    if (skipped)
        *skipped = bad;
    if (ok < (n_boot + 1) / 2) {
        st = RB_ERR_INVALID;
    } else {
        qsort(med, ok, sizeof *med, cmp_double);
        double tail = 0.5 * (1 - level);
        size_t ilo = (size_t)floor(tail * (ok - 1) + 0.5);
        size_t ihi = (size_t)floor((1 - tail) * (ok - 1) + 0.5);
        *lo = med[ilo];
        *hi = med[ihi];
    }
    free(x), free(med), free(c);
    return st;
}

int rb_fragility_governing(unsigned judged, const int fitted[RB_N_LIMITS],
                           const double median[RB_N_LIMITS])
{
    int best = -1;
    for (int k = 0; k < RB_N_LIMITS; k++)
        if ((judged >> k) & 1u && fitted[k] && (best < 0 || median[k] < median[best]))
            best = k;
    return best;
}

int rb_case_fragility_has(const rb_case_fragility *f, int k)
{
    return k >= 0 && k < RB_N_LIMITS && (f->present >> k) & 1u;
}

size_t rb_case_fragility_model_limited(const rb_case_fragility *f, int k)
{
    size_t n = 0;
    for (size_t m = 0; rb_case_fragility_has(f, k) && m < f->n_motions; m++)
        n += f->motions[m].model_limited[k] != 0;
    return n;
}

void rb_limit_states_str(unsigned mask, char *buf, size_t n)
{
    size_t len = 0;
    if (!n)
        return;
    snprintf(buf, n, "none");
    for (int k = 0; k < RB_N_LIMITS && len < n; k++)
        if ((mask >> k) & 1u)
            len += (size_t)snprintf(buf + len, n - len, "%s%s", len ? ", " : "",
                                    rb_enum_str(rb_limit_state_names, k));
}

void rb_case_fragility_free(rb_case_fragility *f)
{
    if (!f)
        return;
    free(f->motions);
    memset(f, 0, sizeof *f);
}

void rb_fragility_sweep_free(rb_fragility_sweep *s)
{
    if (!s)
        return;
    for (size_t i = 0; s->points && i < s->n_points; i++)
        rb_case_fragility_free(&s->points[i]);
    free(s->points);
    free(s->gap_ratios);
    memset(s, 0, sizeof *s);
}
