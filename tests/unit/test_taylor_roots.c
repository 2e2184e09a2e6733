/* The roots the Taylor steps find on their own series: where theta passes
 * a guard's level and where a rate changes sign. Each event of a Taylor
 * step is placed by these, so a root found in the wrong place, outside its
 * bracket, or by a path that gives up early would move every transition.
 * The series here are known functions whose roots are known in closed
 * form: the parabola of a hop (the rising side, where Newton's step points
 * away from the landing, is where the secant fallback takes over), a start
 * from rest (theta ~ c tau^2, whose Newton steps only halve the distance),
 * and a sine carried to 24 terms. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "harness.h"
#include "../../src/core/taylor.h"

/* theta(tau) = sum th[k] tau^k, theta' its derivative */
static void angle_series(rb_taylor *ts, const double *th, int order)
{
    memset(ts, 0, sizeof *ts);
    ts->order = order;
    ts->rocking = 1;
    for (int k = 0; k <= order; k++) {
        ts->p[k][RB_TS_TH] = th[k];
        if (k + 1 <= order)
            ts->p[k][RB_TS_THD] = (k + 1) * th[k + 1];
    }
}

static double theta(const rb_taylor *ts, double tau)
{
    return rb_taylor_one(ts, tau, RB_Y_TH);
}

/* A root of theta - level in [a, b]: inside the bracket and within tol of
 * the closed form. */
static void check_angle_root(const char *what, const rb_taylor *ts, double a, double b,
                             double level, double fa, double want)
{
    double fb = theta(ts, b) - level;
    double tol = 1e-13;
    double got = rb_taylor_angle_root(ts, a, b, level, fa, fb, 0.125 * tol);
    printf("%-40s root %.17g, want %.17g (error %.2e)\n", what, got, want, got - want);
    CHECK(got >= a && got <= b);
    CHECK_NEAR(got, want, tol);
}

/* A hop after a floor impact: theta = v tau - q tau^2 leaves 0 rising and
 * lands on the floor slack -s at tau* = (v + sqrt(v^2 + 4 q s)) / (2 q). */
static void hop(void)
{
    double v = 0.02, q = 9.0, s = 1e-11;
    double th[3] = {0, v, -q};
    rb_taylor ts;
    angle_series(&ts, th, 2);
    double land = (v + sqrt(v * v + 4 * q * s)) / (2 * q);
    /* from the impact itself, the start nudged off the level */
    check_angle_root("hop, bracket from the impact", &ts, 0, 1.5 * land, -s, s, land);
    /* from a check point on the rising side, the bracket's far end well past
     * the landing: the secant hugs nothing, Newton points backwards */
    check_angle_root("hop, bracket from the rising side", &ts, 0.2 * land, 4 * land, -s,
                     theta(&ts, 0.2 * land) + s, land);
    /* the same, mirrored: rocking about the other edge */
    double mth[3] = {0, -v, q};
    angle_series(&ts, mth, 2);
    check_angle_root("hop, mirrored", &ts, 0.2 * land, 4 * land, s,
                     theta(&ts, 0.2 * land) - s, land);
}

/* An uplift from rest: theta = c tau^2 (theta' = 0 at the start) passing a
 * small level L at sqrt(L / c). */
static void from_rest(void)
{
    double c = 40.0, level = 1e-11;
    double th[3] = {0, 0, c};
    rb_taylor ts;
    angle_series(&ts, th, 2);
    check_angle_root("start from rest", &ts, 0, 2.4e-3, level, -level, sqrt(level / c));
}

/* theta = A sin(w tau) to 24 terms over a fifth of a period: the first
 * crossing of A/2 is at asin(1/2) / w. */
static void sine(void)
{
    double A = 0.02, w = 2 * M_PI * 3.0, th[25] = {0};
    double term = A; /* A w^k / k! */
    for (int k = 0; k <= 24; k++) {
        if (k > 0)
            term *= w / k;
        if (k % 2 == 1)
            th[k] = (k % 4 == 1 ? 1 : -1) * term;
    }
    rb_taylor ts;
    angle_series(&ts, th, 24);
    double b = 0.2 / 3.0;
    check_angle_root("sine, 24 terms", &ts, 0, b, 0.5 * A, -0.5 * A, asin(0.5) / w);
    /* the rate: theta' = A w cos(w tau) is zero at a quarter period */
    double a = 0.2 / 3.0, bb = 0.3 / 3.0, want = 0.25 / 3.0;
    double fa = rb_taylor_one(&ts, a, RB_Y_THD), fb = rb_taylor_one(&ts, bb, RB_Y_THD);
    double got = rb_taylor_rate_root(&ts, RB_Y_THD, a, bb, fa, fb, 1e-14);
    printf("%-40s root %.17g, want %.17g (error %.2e)\n", "sine's rate", got, want,
           got - want);
    CHECK(got >= a && got <= bb);
    /* the series is summed to about 1e-16 of A w there, and the root of a
     * cosine moves by that over A w^2 */
    CHECK_NEAR(got, want, 1e-12);
}

int main(void)
{
    hop();
    from_rest();
    sine();
    TEST_MAIN_END();
}
