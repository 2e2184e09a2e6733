/* The peaks an exact step on the floor locates between its check points
 * (docs/solver.md, "Peaks on the step's own polynomial"): the total
 * shear's turns found by Newton on the step's polynomial in the step's
 * fraction. A turn missed or misplaced would leave a run's peak shear,
 * friction demand or anchorage demand low, on the side a check must not
 * err on.
 *
 * Over random cabinets (both formulations that step exactly), buildings
 * (none, or 0.5-60 Hz at 0-50 % damping), step lengths (0.5-40 ms, or
 * 0.2-1.5 rad of the fastest oscillation) and
 * start states, the largest |shear| over 2001 instants of the step,
 * computed here from the physics of the floor stage (the total shear
 * -M x'' + N* U'', 5.3c) over states from the system's exponential at
 * each instant, is held to be no more than the largest of the step's
 * ends and its located turns, the shear at each turn taken from the
 * exponential at that instant too (not from the step's polynomial). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "harness.h"
#include "rockbolt/record.h"
#include "rockbolt/solve.h"
#include "../../src/core/exact.h"

static unsigned long long rng_state = 20261128;
static double uniform(double lo, double hi)
{
    rng_state = rng_state * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * (double)(rng_state >> 11) / 9007199254740992.0;
}

enum { K = 2000, CASES = 400 };

typedef struct {
    double mass, wb, xib;
    rb_derived d;
} shear_model;

static double shear_of(const shear_model *s, const double *z)
{
    double x = s->wb > 0 ? -(2 * s->xib * s->wb * z[3] + s->wb * s->wb * z[2]) : z[4];
    double udd = (s->d.Nstar * x - s->d.Kstar * z[0] - s->d.Cstar * z[1]) / s->d.Mstar;
    return fabs(-s->mass * x + s->d.Nstar * udd);
}

int main(void)
{
    rb_record_opts ro;
    rb_diag diag;
    rb_series raw = {0};
    rb_record_opts_init(&ro);
    if (rb_record_read("cases/records/elcentro_1940_ns.at2", &ro, &raw, &diag) != RB_OK) {
        CHECK(0);
        TEST_MAIN_END();
    }
    static double z_at[K + 1][RB_EXACT_DIM];
    int probed = 0, turned = 0, inside = 0;
    double worst = 0;
    for (int c = 0; c < CASES; c++) {
        rb_series s = {0};
        rb_model m;
        rb_motion mo;
        rb_solve_opts o;
        shear_model sm = {0};
        if (rb_series_alloc(&s, raw.n, raw.dt_s) != RB_OK) {
            CHECK(0);
            break;
        }
        for (size_t i = 0; i < raw.n; i++)
            s.accel_mps2[i] = raw.accel_mps2[i];
        if (c % 4) {
            double f = exp(uniform(log(0.5), log(60)));
            sm.xib = c % 8 == 1 ? 0 : uniform(0, 0.5);
            sm.wb = 2 * M_PI * f;
            CHECK(rb_series_building_filter(&s, f, sm.xib) == RB_OK);
        }
        rb_model_reference(&m);
        m.mass_kg = uniform(50, 5000);
        m.freq_hz = exp(uniform(log(0.5), log(50)));
        m.damping = uniform(0, 0.5);
        sm.mass = m.mass_kg;
        CHECK(rb_model_derive(&m, &sm.d, NULL) == RB_OK);
        rb_motion_init(&mo);
        mo.kind = RB_MOTION_SAMPLED;
        mo.series = &s;
        mo.scale = 1;
        mo.duration_s = 10;
        rb_solve_opts_init(&o);
        o.formulation = c % 3 == 2 ? RB_FORM_SMALL : RB_FORM_LARGE;
        /* half of them from 0.2 to 1.5 rad of the fastest oscillation,
         * where a step's shear most often turns inside it */
        double wf = fmax(2 * M_PI * m.freq_hz, sm.wb);
        double h = c % 2 ? exp(uniform(log(5e-4), log(0.04)))
                         : exp(uniform(log(0.2), log(1.5))) / wf;
        double z0[RB_EXACT_DIM] = {
            uniform(-1, 1) * 1e-3, uniform(-1, 1) * 5e-2, uniform(-1, 1) * 5e-2,
            uniform(-1, 1), uniform(-1, 1) * 8, uniform(-1, 1) * 400};
        for (int j = 0; j < RB_EXACT_DIM; j++)
            if (uniform(0, 1) < 0.15)
                z0[j] = 0;
        double bound[4], tau[8], zt[8][RB_EXACT_DIM];
        int n = rb_exact_probe_turns(&m, &mo, &o, h, z0, tau, zt);
        if (n < 0 || !rb_exact_probe(&m, &mo, &o, h, z0, K, bound, z_at)) {
            rb_series_free(&s);
            continue;
        }
        probed++;
        turned += n > 0;
        double most = 0, located = fmax(shear_of(&sm, z_at[0]), shear_of(&sm, z_at[K]));
        for (int k = 0; k <= K; k++)
            most = fmax(most, shear_of(&sm, z_at[k]));
        for (int k = 0; k < n; k++) {
            CHECK(tau[k] > 0 && tau[k] < h);
            located = fmax(located, shear_of(&sm, zt[k]));
        }
        /* the largest instant's shear beyond the located peak, relative to
         * it, past the states' rounding */
        double over = (most - located) / (located + 1e-300);
        worst = fmax(worst, over);
        if (over > 1e-9) {
            if (rb_test_failures < 5)
                printf("case %d (h %.4g, %d turns): the instants reach %.17g, the located "
                       "peak %.17g\n", c, h, n, most, located);
            CHECK(0);
        }
        inside += located > fmax(shear_of(&sm, z_at[0]), shear_of(&sm, z_at[K]));
        rb_series_free(&s);
    }
    rb_series_free(&raw);
    printf("%d of %d random steps with a polynomial, %d with turns, %d peaking inside; the "
           "instants above the located peak by at most %.3g (1e-9 allowed)\n",
           probed, CASES, turned, inside, worst);
    CHECK(probed >= CASES / 2);
    CHECK(inside >= probed / 10);
    TEST_MAIN_END();
}
