/* Lognormal fragility fitting (rockbolt/fragility.h) and the seeded
 * generator under it (src/util/rng.h):
 *   - without censoring the fit is the closed form;
 *   - with censoring the fit is a maximum: the log-likelihood falls in
 *     every direction around it;
 *   - capacities drawn from a known lognormal and censored at a level
 *     give back its median and beta within their sampling error, over
 *     many seeds, with no bias beyond it;
 *   - the normal quantile, probabilities and quantiles agree;
 *   - the bootstrap interval is the same for the same seed and holds the
 *     fitted median. */
#include <math.h>
#include <stdlib.h>
#include "harness.h"
#include "rockbolt/fragility.h"
#include "util/rng.h"

static double loglik(const double *c, const int *cens, size_t n, double median, double beta)
{
    double l = 0;
    for (size_t i = 0; i < n; i++) {
        double z = log(c[i] / median) / beta;
        l += cens && cens[i] ? log(1 - rb_normal_cdf(z))
                             : -0.5 * z * z - log(beta) - 0.5 * log(2 * M_PI);
    }
    return l;
}

/* n capacities of lognormal(median, beta), censored at cap */
static void draw(rb_rng *r, size_t n, double median, double beta, double cap, double *c,
                 int *cens)
{
    for (size_t i = 0; i < n; i++) {
        double u;
        do
            u = rb_rng_uniform(r);
        while (u == 0);
        c[i] = median * exp(beta * rb_normal_quantile(u));
        cens[i] = c[i] > cap;
        if (cens[i])
            c[i] = cap;
    }
}

int main(void)
{
    /* the normal distribution */
    CHECK_NEAR(rb_normal_quantile(0.975), 1.959963984540054, 1e-13);
    CHECK_NEAR(rb_normal_quantile(0.5), 0.0, 1e-15);
    CHECK_NEAR(rb_normal_cdf(rb_normal_quantile(1e-6)), 1e-6, 1e-18);

    /* closed form */
    double c5[5] = {0.8, 1.1, 1.3, 0.9, 1.7};
    rb_fragility_fit f;
    CHECK(rb_fragility_mle(c5, NULL, 5, &f) == RB_OK);
    double m = 0, s = 0;
    for (int i = 0; i < 5; i++)
        m += log(c5[i]) / 5;
    for (int i = 0; i < 5; i++)
        s += (log(c5[i]) - m) * (log(c5[i]) - m) / 5;
    CHECK_REL(f.median, exp(m), 1e-14);
    CHECK_REL(f.beta, sqrt(s), 1e-14);
    CHECK_NEAR(rb_fragility_prob(&f, f.median), 0.5, 1e-15);
    CHECK_REL(rb_fragility_quantile(&f, 0.1), f.median * exp(-1.2815515655446004 * f.beta),
              1e-12);
    CHECK_REL(rb_fragility_prob(&f, rb_fragility_quantile(&f, 0.1)), 0.1, 1e-12);

    /* bad samples */
    double one[2] = {1, 1}, neg[3] = {1, -1, 2};
    int all_cens[3] = {1, 1, 0};
    CHECK(rb_fragility_mle(one, NULL, 2, &f) == RB_ERR_INVALID);
    CHECK(rb_fragility_mle(neg, NULL, 3, &f) == RB_ERR_INVALID);
    CHECK(rb_fragility_mle(c5, all_cens, 3, &f) == RB_ERR_INVALID);

    /* recovery, with about a quarter censored */
    const size_t n = 2000;
    const double median = 1.2, beta = 0.4, cap = 1.6;
    double *c = malloc(n * sizeof *c);
    int *cens = malloc(n * sizeof *cens);
    double sum_dm = 0, sum_db = 0, worst_m = 0, worst_b = 0;
    const int seeds = 40;
    for (int k = 0; k < seeds; k++) {
        rb_rng r;
        rb_rng_seed(&r, 1000 + (uint64_t)k);
        draw(&r, n, median, beta, cap, c, cens);
        CHECK(rb_fragility_mle(c, cens, n, &f) == RB_OK);
        /* standard errors of an uncensored sample, widened by a quarter
         * for the information the censoring takes away */
        double se_m = 1.25 * beta / sqrt((double)n), se_b = 1.25 * beta / sqrt(2.0 * n);
        double dm = log(f.median / median) / se_m, db = (f.beta - beta) / se_b;
        sum_dm += dm;
        sum_db += db;
        worst_m = fmax(worst_m, fabs(dm));
        worst_b = fmax(worst_b, fabs(db));
        if (k == 0) {
            /* a maximum: every small step lowers the likelihood */
            double l0 = loglik(c, cens, n, f.median, f.beta);
            CHECK_NEAR(l0, f.loglik, 1e-9 * fabs(l0));
            for (int d = 0; d < 4; d++) {
                double dmed = d == 0 ? 1e-4 : d == 1 ? -1e-4 : 0;
                double dbet = d == 2 ? 1e-4 : d == 3 ? -1e-4 : 0;
                CHECK(loglik(c, cens, n, f.median * exp(dmed), f.beta + dbet) < l0);
            }
            printf("seed 1000: median %.5f beta %.5f after %d EM steps (true 1.2, 0.4)\n",
                   f.median, f.beta, f.iterations);
        }
    }
    printf("over %d seeds: largest |error| / se: median %.2f, beta %.2f; mean %.2f, %.2f\n",
           seeds, worst_m, worst_b, sum_dm / seeds, sum_db / seeds);
    CHECK(worst_m < 4 && worst_b < 4);
    /* no bias: the mean of 40 errors within 3 of its own standard error */
    CHECK(fabs(sum_dm / seeds) < 3 / sqrt((double)seeds));
    CHECK(fabs(sum_db / seeds) < 3 / sqrt((double)seeds));

    /* bootstrap */
    rb_rng r;
    rb_rng_seed(&r, 7);
    draw(&r, 40, median, beta, cap, c, cens);
    double lo, hi, lo2, hi2;
    unsigned skipped;
    CHECK(rb_fragility_mle(c, cens, 40, &f) == RB_OK);
    CHECK(rb_fragility_bootstrap(c, cens, 40, 400, 42, 0.9, &lo, &hi, &skipped) == RB_OK);
    CHECK(rb_fragility_bootstrap(c, cens, 40, 400, 42, 0.9, &lo2, &hi2, NULL) == RB_OK);
    CHECK(lo == lo2 && hi == hi2);
    CHECK(lo < f.median && f.median < hi);
    printf("40 motions: median %.4f, 90 %% bootstrap interval [%.4f, %.4f], %u skipped\n",
           f.median, lo, hi, skipped);

    /* the generator: uniform in [0, 1), below() within range and even */
    long counts[6] = {0};
    double mean = 0;
    int in_range = 1;
    for (int i = 0; i < 60000; i++) {
        double u = rb_rng_uniform(&r);
        in_range &= u >= 0 && u < 1;
        mean += u / 60000;
        counts[rb_rng_below(&r, 6)]++;
    }
    CHECK(in_range);
    CHECK_NEAR(mean, 0.5, 0.01);
    for (int k = 0; k < 6; k++)
        CHECK(counts[k] > 9500 && counts[k] < 10500);
    free(c);
    free(cens);
    TEST_MAIN_END();
}
