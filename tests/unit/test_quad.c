/* src/core/simd.h: the quads that read a Taylor step's series four at a
 * time must give, lane by lane, the bits of the scalar Horner chain
 * v = v tau + p_k, or a report would move with the compiler's vectors and
 * the processor's AVX. Both forms, the vector one and the plain one a
 * compiler without vectors gets, are held to the scalar chains over
 * random series of mixed signs and scales (where rounding and
 * cancellation show), zeros, subnormals and infinities, with the series
 * at unaligned places, as a row of a step's table puts them. */
#include <math.h>
#include <stdint.h>
#include <string.h>
#include "harness.h"
#include "../../src/core/simd.h"

enum { ORDERS = 33, WIDTH = 13 };

/* the vector form: four chains of a table of rows WIDTH wide, from
 * column c */
static void chains_vec(const double (*p)[WIDTH], int n, int c, double tau, double *out)
{
    rb_quad t = rb_quad_splat(tau), v = rb_quad_load(p[n] + c);
    for (int k = n - 1; k >= 0; k--)
        v = rb_quad_horner(v, t, rb_quad_load(p[k] + c));
    rb_quad_store(out, v);
}

/* the plain form under other names, in the same program */
#undef RB_SIMD_H
#undef RB_INLINE
#undef RB_SIMD_AVX
#undef rb_quad_splat
#undef rb_quad_load
#undef rb_quad_store
#undef rb_quad_horner
#define RB_PAIR_PLAIN
#define rb_quad plain_quad
#define rb_quad_splat plain_splat
#define rb_quad_load plain_load
#define rb_quad_store plain_store
#define rb_quad_horner plain_horner
#define rb_simd_avx plain_simd_avx
#include "../../src/core/simd.h"

static void chains_plain(const double (*p)[WIDTH], int n, int c, double tau, double *out)
{
    plain_quad t = plain_splat(tau), v = plain_load(p[n] + c);
    for (int k = n - 1; k >= 0; k--)
        v = plain_horner(v, t, plain_load(p[k] + c));
    plain_store(out, v);
}

#define LANE_SEED 0x2545F4914F6CDD1DULL
#include "lane_terms.h"

int main(void)
{
    static double p[ORDERS][WIDTH];
    int differ_vec = 0, differ_plain = 0, chains = 0, differ_reversed = 0;
    CHECK(!plain_simd_avx());
    for (int c = 0; c < 20000; c++) {
        int specials = c % 4 == 0, n = (int)(uniform() * ORDERS);
        int col = (int)(uniform() * (WIDTH - 3));
        double tau = (uniform() < 0.5 ? -1 : 1) * pow(10.0, 6 * uniform() - 5);
        for (int k = 0; k <= n; k++)
            for (int i = 0; i < WIDTH; i++)
                p[k][i] = term(specials);
        double vec[4], plain[4];
        chains_vec((const double (*)[WIDTH])p, n, col, tau, vec);
        chains_plain((const double (*)[WIDTH])p, n, col, tau, plain);
        for (int i = 0; i < 4; i++) {
            double v = p[n][col + i], r = p[0][col + i];
            for (int k = n - 1; k >= 0; k--)
                v = v * tau + p[k][col + i];
            /* the same terms summed from the other end, which differs
             * in its rounding: agreeing to the bit says the lanes keep the
             * scalar order */
            double t = 1;
            for (int k = 1; k <= n; k++) {
                t *= tau;
                r += p[k][col + i] * t;
            }
            differ_vec += !same_bits(vec[i], v);
            differ_plain += !same_bits(plain[i], v);
            differ_reversed += !same_bits(r, v);
            chains++;
        }
    }
    printf("%d chains of up to %d orders: %d differ (vectors), %d differ (plain); summed "
           "by powers instead, %d differ\n", chains, ORDERS, differ_vec, differ_plain,
           differ_reversed);
    CHECK(differ_vec == 0);
    CHECK(differ_plain == 0);
    CHECK(differ_reversed > chains / 10);
    TEST_MAIN_END();
}
