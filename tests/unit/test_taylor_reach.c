/* The bound a rocking Taylor step uses to read its guards at its end
 * alone (solve.c, angle_clear): rb_taylor_reach, the sum of |p_k| h^k, and
 * rb_taylor_stays_off, which says a component cannot reach a level at any
 * instant of the step as the dense output's Horner passes read it (the
 * range of the first three terms, widened by the reach of the rest). A
 * level it wrongly called clear would be a missed floor impact, bolt
 * contact or overturning, so every "clear" is held against dense sampling
 * of the same series: random series of every order, signs and scales,
 * with levels placed around the reach and a hair outside the range's
 * ends; series whose terms all have one sign, which reach their bound at
 * the step's end; and parabolas that turn inside the step, whose vertex
 * is the range's end. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>
#include "harness.h"
#include "../../src/core/taylor.h"

static uint64_t rng = 0x2545F4914F6CDD1DULL;

static double uniform(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) / 9007199254740992.0;
}

static const int lanes[2] = {RB_TS_TH, RB_TS_THD};
static const int comps[2] = {RB_Y_TH, RB_Y_THD};

/* The reach summed term by term with pow, apart from the library's loop. */
static double reach_by_terms(const double *c, int order, double h)
{
    double r = 0;
    for (int k = 1; k <= order; k++)
        r += fabs(c[k]) * pow(h, k);
    return r;
}

/* Every sampled reading (v - level) on the start's side; returns the
 * largest |v - p0| seen. */
static double sample_side(const rb_taylor *ts, int comp, double h, double level, int *wrong)
{
    double p0 = rb_taylor_one(ts, 0, comp), seen = 0;
    for (int i = 0; i <= 4000; i++) {
        double tau = i == 4000 ? h : h * i / 4000.0;
        double v = rb_taylor_one(ts, tau, comp);
        seen = fmax(seen, fabs(v - p0));
        if (!((v - level) * (p0 - level) > 0))
            (*wrong)++;
    }
    return seen;
}

static void random_series(void)
{
    int clear = 0, wrong = 0, tight = 0, edge_clear = 0;
    double worst_ratio = 0, worst_sum = 0;
    for (int trial = 0; trial < 2000; trial++) {
        rb_taylor ts;
        memset(&ts, 0, sizeof ts);
        ts.order = 1 + (int)(uniform() * RB_TAYLOR_MAX);
        ts.rocking = 1;
        int lane = trial & 1;
        double h = pow(10, -4 + 2.7 * uniform());
        double scale = pow(10, -6 + 6 * uniform()), c[RB_TAYLOR_MAX + 1];
        /* terms of a series converging over the step: |p_k| h^k about
         * scale q^k, some terms zero */
        double q = 0.2 + 0.7 * uniform();
        for (int k = 0; k <= ts.order; k++) {
            double mag = k == 0 ? scale * 4 * (uniform() - 0.5)
                                : scale * pow(q, k) / pow(h, k) * uniform();
            c[k] = uniform() < 0.1 && k > 0 ? 0 : (uniform() < 0.5 ? -mag : mag);
            ts.p[k][lanes[lane]] = c[k];
        }
        double reach = rb_taylor_reach(&ts, comps[lane], h);
        double by_terms = reach_by_terms(c, ts.order, h);
        worst_sum = fmax(worst_sum, fabs(reach - by_terms) / fmax(by_terms, DBL_MIN));
        /* levels on both sides, from well inside the reach to past it */
        for (int j = 0; j < 8; j++) {
            double f = 0.25 + 1.0 * uniform(), side = j & 1 ? 1 : -1;
            double level = c[0] + side * f * reach;
            if (!rb_taylor_stays_off(&ts, comps[lane], h, level))
                continue;
            clear++;
            double seen = sample_side(&ts, comps[lane], h, level, &wrong);
            if (reach > 0)
                worst_ratio = fmax(worst_ratio, seen / reach);
            tight += f < 1.01;
        }
        /* a hair outside the range's ends: the parabola's ends and vertex
         * are the extremes a step reaches, up to the tail and rounding */
        double lo, hi;
        rb_taylor_range(&ts, comps[lane], h, &lo, &hi);
        for (int j = 0; j < 2; j++) {
            double end = j ? hi : lo, level = end + (j ? 1 : -1) * 1e-9 * fabs(end);
            if (!rb_taylor_stays_off(&ts, comps[lane], h, level))
                continue;
            edge_clear++;
            sample_side(&ts, comps[lane], h, level, &wrong);
        }
    }
    printf("random series: %d levels called clear (%d within 1 %% of the reach, %d a "
           "hair outside the range), %d readings on the wrong side; largest sampled "
           "move / reach 1 %+.2e; reach against the sum by terms %.2e\n",
           clear, tight, edge_clear, wrong, worst_ratio - 1, worst_sum);
    CHECK(clear > 1000);
    CHECK(edge_clear > 3000);
    CHECK(wrong == 0);
    /* the sampled readings carry their own rounding */
    CHECK(worst_ratio <= 1 + 1e-12);
    CHECK(worst_sum <= 1e-13);
}

/* Terms all of one sign: the series moves by its whole reach at h, so a
 * level a hair past the reach is clear and one a hair short is not (it is
 * crossed, and the sampling at h shows it). */
static void one_sign(void)
{
    int wrong = 0;
    for (int order = 1; order <= RB_TAYLOR_MAX; order++) {
        rb_taylor ts;
        memset(&ts, 0, sizeof ts);
        ts.order = order;
        ts.rocking = 1;
        double h = 0.02, c[RB_TAYLOR_MAX + 1];
        c[0] = 1e-3;
        for (int k = 1; k <= order; k++)
            c[k] = 1e-3 * pow(0.7, k) / pow(h, k);
        for (int k = 0; k <= order; k++)
            ts.p[k][RB_TS_TH] = c[k];
        double reach = rb_taylor_reach(&ts, RB_Y_TH, h);
        double past = c[0] + reach * (1 + 1e-9), short_of = c[0] + reach * (1 - 1e-9);
        CHECK(rb_taylor_stays_off(&ts, RB_Y_TH, h, past));
        CHECK(!rb_taylor_stays_off(&ts, RB_Y_TH, h, short_of));
        sample_side(&ts, RB_Y_TH, h, past, &wrong);
        /* the end itself lies past short_of: a "clear" there would be wrong */
        CHECK(rb_taylor_one(&ts, h, RB_Y_TH) > short_of);
    }
    printf("one-sign series, orders 1-%d: %d readings past a level called clear\n",
           RB_TAYLOR_MAX, wrong);
    CHECK(wrong == 0);
}

/* Parabolas (order 2, no tail) that turn inside the step: the range's
 * end is the vertex, p0 - p1^2 / (4 p2), so a level a hair past it is
 * clear and one a hair short of it is crossed (the sampling reads the
 * vertex itself, at h / 2). */
static void turning(void)
{
    int wrong = 0;
    for (int sign = -1; sign <= 1; sign += 2) {
        rb_taylor ts;
        memset(&ts, 0, sizeof ts);
        ts.order = 2;
        ts.rocking = 1;
        double h = 0.01, p0 = 1e-3, p1 = sign * 0.1, p2 = -sign * 10.0;
        ts.p[0][RB_TS_TH] = p0;
        ts.p[1][RB_TS_TH] = p1;
        ts.p[2][RB_TS_TH] = p2;
        double vertex = p0 - p1 * p1 / (4 * p2);
        double past = vertex + sign * 1e-9 * vertex, short_of = vertex - sign * 1e-9 * vertex;
        CHECK(rb_taylor_stays_off(&ts, RB_Y_TH, h, past));
        CHECK(!rb_taylor_stays_off(&ts, RB_Y_TH, h, short_of));
        sample_side(&ts, RB_Y_TH, h, past, &wrong);
        CHECK(sign * (rb_taylor_one(&ts, 0.5 * h, RB_Y_TH) - short_of) > 0);
        /* the reach alone would have called the start's own side reachable */
        CHECK(rb_taylor_stays_off(&ts, RB_Y_TH, h, p0 - sign * 0.6 * rb_taylor_reach(&ts, RB_Y_TH, h)));
    }
    CHECK(wrong == 0);
}

/* A series that starts on its level is never clear (a guard a transition
 * left on its boundary), nor is any level when the step is not finite. */
static void edges(void)
{
    rb_taylor ts;
    memset(&ts, 0, sizeof ts);
    ts.order = 3;
    ts.rocking = 1;
    ts.p[0][RB_TS_TH] = 0.01;
    ts.p[1][RB_TS_TH] = 0.5;
    CHECK(!rb_taylor_stays_off(&ts, RB_Y_TH, 0.01, 0.01));
    CHECK(rb_taylor_stays_off(&ts, RB_Y_TH, 0.01, 0.0));
    /* a step that leaves its level (the floor, a bolt head) is clear of
     * it behind: its start is closer to it than the reach */
    ts.p[0][RB_TS_TH] = 1e-4;
    CHECK(rb_taylor_reach(&ts, RB_Y_TH, 0.01) > 1e-4);
    CHECK(rb_taylor_stays_off(&ts, RB_Y_TH, 0.01, 0.0));
    ts.p[2][RB_TS_TH] = NAN;
    CHECK(!rb_taylor_stays_off(&ts, RB_Y_TH, 0.01, 0.0));
    ts.p[2][RB_TS_TH] = INFINITY;
    CHECK(!rb_taylor_stays_off(&ts, RB_Y_TH, 0.01, 0.0));
}

int main(void)
{
    random_series();
    one_sign();
    turning();
    edges();
    TEST_MAIN_END();
}
