/* A tiny assert harness for the unit tests: every check prints what it
 * compared, so a failure says which number left which tolerance. */
#ifndef RB_TEST_HARNESS_H
#define RB_TEST_HARNESS_H

#include <math.h>
#include <stdio.h>

static int rb_test_failures;
static int rb_test_checks;

#define CHECK(cond) do { rb_test_checks++; if (!(cond)) { rb_test_failures++; \
    fprintf(stderr, "%s:%d: FAILED: %s\n", __FILE__, __LINE__, #cond); } } while (0)

/* |got - want| <= tol */
#define CHECK_NEAR(got, want, tol) do { double g_ = (got), w_ = (want), t_ = (tol); \
    rb_test_checks++; if (!(fabs(g_ - w_) <= t_)) { rb_test_failures++; \
    fprintf(stderr, "%s:%d: FAILED: %s = %.10g, want %.10g +- %.3g\n", \
            __FILE__, __LINE__, #got, g_, w_, t_); } } while (0)

/* |got - want| <= rel |want| */
#define CHECK_REL(got, want, rel) do { double g_ = (got), w_ = (want), r_ = (rel); \
    rb_test_checks++; if (!(fabs(g_ - w_) <= r_ * fabs(w_))) { rb_test_failures++; \
    fprintf(stderr, "%s:%d: FAILED: %s = %.10g, want %.10g within %.3g relative\n", \
            __FILE__, __LINE__, #got, g_, w_, r_); } } while (0)

#define TEST_MAIN_END() do { \
    printf("%d checks, %d failed\n", rb_test_checks, rb_test_failures); \
    return rb_test_failures ? 1 : 0; } while (0)

#endif
