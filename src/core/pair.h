/* Internal: two doubles side by side, for two sums of the same terms
 * (the damping and input works of an exact step, two of its four bounds)
 * taken in one vector operation where the compiler has vectors. Each lane
 * rounds as the scalar operation would (IEEE, no contraction under
 * -std=c11), so a sum taken this way has the bits it has term by term. */
#ifndef RB_PAIR_H
#define RB_PAIR_H

/* RB_PAIR_PLAIN asks for the plain form (test_pair holds both to the
 * scalar sums) */
#if (defined(__GNUC__) || defined(__clang__)) && !defined(RB_PAIR_PLAIN)
typedef double rb_pair __attribute__((vector_size(2 * sizeof(double))));

static inline rb_pair rb_pair_make(double a, double b)
{
    return (rb_pair){a, b};
}

static inline rb_pair rb_pair_splat(double x)
{
    return (rb_pair){x, x};
}

static inline rb_pair rb_pair_mul(rb_pair a, rb_pair b)
{
    return a * b;
}

/* p[0] and p[1] */
static inline rb_pair rb_pair_load(const double *p)
{
    return (rb_pair){p[0], p[1]};
}

/* a lane in both lanes */
static inline rb_pair rb_pair_dup(rb_pair v, int i)
{
    return (rb_pair){v[i], v[i]};
}

/* a + b x, both lanes */
static inline rb_pair rb_pair_madd(rb_pair a, rb_pair b, rb_pair x)
{
    return a + b * x;
}

static inline double rb_pair_lane(rb_pair v, int i)
{
    return v[i];
}
#else
typedef struct {
    double v[2];
} rb_pair;

static inline rb_pair rb_pair_make(double a, double b)
{
    rb_pair v = {{a, b}};
    return v;
}

static inline rb_pair rb_pair_splat(double x)
{
    return rb_pair_make(x, x);
}

static inline rb_pair rb_pair_mul(rb_pair a, rb_pair b)
{
    return rb_pair_make(a.v[0] * b.v[0], a.v[1] * b.v[1]);
}

static inline rb_pair rb_pair_load(const double *p)
{
    return rb_pair_make(p[0], p[1]);
}

static inline rb_pair rb_pair_dup(rb_pair v, int i)
{
    return rb_pair_make(v.v[i], v.v[i]);
}

static inline rb_pair rb_pair_madd(rb_pair a, rb_pair b, rb_pair x)
{
    return rb_pair_make(a.v[0] + b.v[0] * x.v[0], a.v[1] + b.v[1] * x.v[1]);
}

static inline double rb_pair_lane(rb_pair v, int i)
{
    return v.v[i];
}
#endif

#endif
