/* Internal: a hot loop of the solver compiled twice, for the baseline
 * instruction set and for AVX, the one taken chosen when it runs. AVX is
 * asked for without FMA, so no product and sum are fused: every lane
 * rounds as the baseline's scalar or SSE2 operation does, and the two
 * give the same bits (test_taylor_step holds them to it over random
 * steps). Wider registers and three-operand forms are what is gained. */
#ifndef RB_SIMD_H
#define RB_SIMD_H
#include <string.h>

/* a body both variants inline, so that its callees are compiled for each */
#if defined(__GNUC__) || defined(__clang__)
#define RB_INLINE static inline __attribute__((always_inline))
#else
#define RB_INLINE static inline
#endif

#if (defined(__GNUC__) || defined(__clang__)) && (defined(__x86_64__) || defined(__i386__)) \
    && !defined(RB_PAIR_PLAIN)
#define RB_SIMD_AVX __attribute__((target("avx")))
/* libgcc's check includes the operating system's saving of the AVX
 * registers (XCR0), not only the processor's flag */
static inline int rb_simd_avx(void)
{
    return __builtin_cpu_supports("avx");
}
#else
#define RB_SIMD_AVX
static inline int rb_simd_avx(void)
{
    return 0;
}
#endif


/* Four doubles side by side (one AVX register, two SSE2 ones in the
 * baseline variant): lanes round as scalars do. Loads and stores may be
 * unaligned. */
/* RB_PAIR_PLAIN asks for the plain form, as in pair.h (test_quad holds
 * both to the scalar chains) */
#if (defined(__GNUC__) || defined(__clang__)) && !defined(RB_PAIR_PLAIN)
/* macros, not functions: a quad passed to or returned from a function is
 * where GCC and Clang note that the ABI changes with AVX */
typedef double rb_quad __attribute__((vector_size(4 * sizeof(double))));
typedef double rb_quad_unaligned
    __attribute__((vector_size(4 * sizeof(double)), aligned(sizeof(double)), may_alias));
#define rb_quad_splat(x) ((rb_quad){(x), (x), (x), (x)})
#define rb_quad_load(p) (*(const rb_quad_unaligned *)(p))
#define rb_quad_store(p, q) (*(rb_quad_unaligned *)(p) = (q))
/* a x + b, lane by lane */
#define rb_quad_horner(a, x, b) ((a) * (x) + (b))
#else
typedef struct {
    double v[4];
} rb_quad;

RB_INLINE rb_quad rb_quad_splat(double x)
{
    rb_quad q = {{x, x, x, x}};
    return q;
}

RB_INLINE rb_quad rb_quad_load(const double *p)
{
    rb_quad q;
    memcpy(q.v, p, sizeof q.v);
    return q;
}

RB_INLINE void rb_quad_store(double *p, rb_quad q)
{
    memcpy(p, q.v, sizeof q.v);
}

RB_INLINE rb_quad rb_quad_horner(rb_quad a, rb_quad x, rb_quad b)
{
    for (int i = 0; i < 4; i++)
        a.v[i] = a.v[i] * x.v[i] + b.v[i];
    return a;
}
#endif

#endif
