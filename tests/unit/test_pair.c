/* src/core/pair.h: two sums taken side by side (the exact steps' works,
 * bounds and end state) must have, lane by lane, the bits of the same sum
 * taken term by term in scalar arithmetic, or a run would move with the
 * compiler's vectors. Both forms, the vector one and the plain one a
 * compiler without vectors gets, are held to the scalar sums over random
 * terms of mixed signs and scales (where rounding, cancellation and the
 * order of the additions all show), zeros, subnormals and infinities. */
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "harness.h"
#include "../../src/core/pair.h"

/* the plain form under other names, in the same program */
#undef RB_PAIR_H
#define RB_PAIR_PLAIN
#define rb_pair plain_pair
#define rb_pair_make plain_make
#define rb_pair_splat plain_splat
#define rb_pair_mul plain_mul
#define rb_pair_madd plain_madd
#define rb_pair_lane plain_lane
#define rb_pair_load plain_load
#define rb_pair_dup plain_dup
#include "../../src/core/pair.h"
#undef rb_pair
#undef rb_pair_make
#undef rb_pair_splat
#undef rb_pair_mul
#undef rb_pair_madd
#undef rb_pair_lane
#undef rb_pair_load
#undef rb_pair_dup

#define LANE_SEED 0x9E3779B97F4A7C15ULL
#include "lane_terms.h"

enum { N = 21 };

int main(void)
{
    int differ_vec = 0, differ_plain = 0, cases = 0;
    for (int c = 0; c < 20000; c++) {
        int specials = c % 4 == 0;
        double w0[N], w1[N], x[N], y[N];
        for (int k = 0; k < N; k++) {
            w0[k] = term(specials);
            w1[k] = term(specials);
            x[k] = term(specials);
            y[k] = term(specials);
        }
        /* the scalar sums: s += w x y term by term, as the works' pairs */
        double s0 = 0, s1 = 0;
        for (int k = 0; k < N; k++) {
            double xy = x[k] * y[k];
            s0 += w0[k] * xy;
            s1 += w1[k] * xy;
        }
        rb_pair v = rb_pair_splat(0);
        plain_pair p = plain_splat(0);
        for (int k = 0; k < N; k++) {
            v = rb_pair_madd(v, rb_pair_make(w0[k], w1[k]),
                             rb_pair_mul(rb_pair_splat(x[k]), rb_pair_splat(y[k])));
            p = plain_madd(p, plain_make(w0[k], w1[k]),
                           plain_mul(plain_splat(x[k]), plain_splat(y[k])));
        }
        differ_vec += !same_bits(rb_pair_lane(v, 0), s0) || !same_bits(rb_pair_lane(v, 1), s1);
        differ_plain += !same_bits(plain_lane(p, 0), s0) || !same_bits(plain_lane(p, 1), s1);
        /* the products two at a time (x_k y_k and x_k y_k+1 from one
         * product of x_k with y's pair), as the works take them: the sums
         * of w x_k y_k over k and of w x_k y_k+1 */
        double t0 = 0, t1 = 0;
        for (int k = 0; k + 1 < N; k++) {
            t0 += w0[k] * (x[k] * y[k]);
            t1 += w1[k] * (x[k] * y[k + 1]);
        }
        rb_pair tv = rb_pair_splat(0), uv = tv;
        plain_pair tp = plain_splat(0), up = tp;
        for (int k = 0; k + 1 < N; k++) {
            rb_pair q = rb_pair_mul(rb_pair_splat(x[k]), rb_pair_load(y + k));
            tv = rb_pair_madd(tv, rb_pair_splat(w0[k]), rb_pair_dup(q, 0));
            uv = rb_pair_madd(uv, rb_pair_splat(w1[k]), rb_pair_dup(q, 1));
            plain_pair r = plain_mul(plain_splat(x[k]), plain_load(y + k));
            tp = plain_madd(tp, plain_splat(w0[k]), plain_dup(r, 0));
            up = plain_madd(up, plain_splat(w1[k]), plain_dup(r, 1));
        }
        differ_vec += !same_bits(rb_pair_lane(tv, 1), t0) || !same_bits(rb_pair_lane(uv, 0), t1);
        differ_plain += !same_bits(plain_lane(tp, 1), t0) || !same_bits(plain_lane(up, 0), t1);
        cases++;
    }
    printf("%d sums of %d terms: %d differ (vectors), %d differ (plain)\n", cases, N,
           differ_vec, differ_plain);
    CHECK(differ_vec == 0);
    CHECK(differ_plain == 0);
    /* the sums are sensitive to the order: summed backwards, most differ,
     * so agreeing to the bit says the lanes keep the scalar order */
    int backwards = 0;
    for (int c = 0; c < 1000; c++) {
        double w[N], x[N], s = 0, b = 0;
        for (int k = 0; k < N; k++) {
            w[k] = term(0);
            x[k] = term(0);
        }
        rb_pair v = rb_pair_splat(0);
        for (int k = 0; k < N; k++) {
            s += w[k] * x[k];
            v = rb_pair_madd(v, rb_pair_splat(w[k]), rb_pair_splat(x[k]));
        }
        for (int k = N - 1; k >= 0; k--)
            b += w[k] * x[k];
        CHECK(same_bits(rb_pair_lane(v, 0), s) && same_bits(rb_pair_lane(v, 1), s));
        backwards += !same_bits(b, s);
    }
    printf("summed backwards, %d of 1000 sums differ\n", backwards);
    CHECK(backwards > 100);
    TEST_MAIN_END();
}
