/* The triaxial AC156 suites of the generator (rockbolt/synth.h), as a
 * laboratory would accept them, with every check computed here apart from
 * the generator's own:
 *   - 7 sets for S_DS 1.0 g on the roof (z/h 1) and 7 for S_DS 2.0 g at
 *     grade (z/h 0), each set H1, H2 (the horizontal RRS) and V (A_FLX-V =
 *     0.67 S_DS, A_RIG-V = 0.27 S_DS), each component its own stream;
 *   - every component meets the laboratory's rules at all 12 offsets of
 *     the 1/72-octave grid, judged here by the laboratory's own sequence
 *     of factors (normalise the least dip to 0.9, then the adjacent dips,
 *     then the third dip of each range; its published analyze_set) on a
 *     grid written here, 0.1 x 2^(k/72) Hz, the RRS written here from the
 *     corner frequencies;
 *   - the rigid end within [0.9, 1.3] of A_RIG from 33.3 to 50 Hz;
 *   - the peak at least 0.95 A_RIG; PGD at most 0.15 m and PGV at most
 *     1.0 m/s, integrated here (trapezoids, and the displacement by
 *     Simpson-like exact steps for a piecewise-linear acceleration);
 *   - the components of a set pairwise uncorrelated: the largest
 *     |normalised cross-correlation| over every lag, summed directly here,
 *     at most 0.3 (and the generator's coherence at most 0.5).
 * Prints what it measured. Usage: synth_sets [SEED]. */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "../unit/harness.h"
#include "rockbolt/synth.h"
#include "set_checks.h"

#define G 9.80665
#define SETS 7

/* AC156's RRS, from its corners (CODES.md; the laboratory's calc_rrs) */
static double rrs(double flx, double rig, double f)
{
    if (f <= 1.3)
        return flx * pow(f / 1.3, log(10.0) / log(13.0));  /* 0.1 A_FLX at 0.1 Hz */
    if (f <= 8.3)
        return flx;
    if (f <= 33.3)
        return flx * pow(f / 8.3, log(rig / flx) / log(33.3 / 8.3));
    return rig;
}

/* the laboratory's analyze_set: the factor by which the TRS clears the
 * rules at one offset (>= 1 passes) */
static double lab_factor(const double *f, const double *q, size_t n)
{
    double f1 = INFINITY;
    for (size_t i = 0; i < n; i++)
        f1 = fmin(f1, q[i]);
    f1 /= 0.9;
    double f2 = INFINITY;
    for (size_t i = 0; i + 1 < n; i++)
        if (q[i] / f1 < 1 && q[i + 1] / f1 < 1)
            f2 = fmin(f2, fmax(q[i], q[i + 1]) / f1);
    if (!isfinite(f2))
        f2 = 1.0;
    double f3 = 1.0;
    for (int high = 0; high < 2; high++) {
        double d[400];
        size_t m = 0;
        for (size_t i = 0; i < n; i++) {
            double r = q[i] / (f1 * f2);
            if ((high ? f[i] > 8.3 : f[i] <= 8.3) && r < 1)
                d[m++] = r;
        }
        if (m >= 3) {
            /* the third smallest */
            for (size_t a = 0; a < 3; a++)
                for (size_t b = a + 1; b < m; b++)
                    if (d[b] < d[a]) {
                        double t = d[a];
                        d[a] = d[b];
                        d[b] = t;
                    }
            f3 = fmin(f3, d[2]);
        }
    }
    return f1 * f2 * f3;
}

typedef struct {
    double sds_g, zh;
    unsigned index;      /* the set */
    rb_synth_component comp;
    unsigned long long seed;
    rb_series s;
    rb_synth_info info;
    rb_status st;
    double flx, rig;
} job;

static void *run(void *arg)
{
    job *j = arg;
    rb_target t;
    if (j->comp == RB_SYNTH_V)
        rb_target_ac156_vertical(&t, j->sds_g * G);
    else
        rb_target_ac156(&t, RB_AC156_2010, j->sds_g * G, j->zh);
    rb_target_ac156_levels(&t, &j->flx, &j->rig);
    rb_synth_opts o;
    rb_synth_opts_init(&o, &t);
    o.seed = j->seed;
    o.index = j->index + (unsigned)j->comp * RB_SYNTH_COMPONENT_STREAM;
    j->st = rb_synth_generate(&o, &j->s, &j->info);
    return NULL;
}

static double worst_margin = INFINITY, worst_tail_lo = INFINITY, worst_tail_hi = 0;
static double worst_peak = INFINITY, worst_pgd = 0, worst_pgv = 0, worst_corr = 0;

static double job_rrs(double f, const void *ctx)
{
    const job *j = ctx;
    return rrs(j->flx, j->rig, f);
}

static void check_component(const job *j)
{
    CHECK(j->st == RB_OK);
    if (j->st != RB_OK)
        return;
    const rb_series *s = &j->s;
    /* the TRS on a grid written here */
    double fq[800];
    size_t n = 0;
    for (int k = 0;; k++) {
        double f = 0.1 * pow(2.0, k / 72.0);
        if (f > 50.0 * (1 + 1e-9))
            break;
        if (f >= 1.0)
            fq[n++] = f;
    }
    rb_spectrum sp;
    CHECK(rb_spectrum_alloc(&sp, fq, n, 0.05) == RB_OK);
    CHECK(rb_spectrum_of_series(s, 1.0, &sp) == RB_OK);
    int k0 = (int)lround(log2(fq[0] / 0.1) * 72);
    for (int off = 0; off < 12; off++) {
        double f[80], q[80];
        size_t m = offset_ratios(fq, sp.sa_mps2, n, k0, off, 1.3, 33.3, job_rrs, j, f, q,
                                 NULL);
        double factor = lab_factor(f, q, m);
        CHECK(factor >= 1.0);
        worst_margin = fmin(worst_margin, factor);
    }
    for (size_t i = 0; i < n; i++) {
        if (fq[i] <= 33.3)
            continue;
        double r = sp.sa_mps2[i] / j->rig;
        CHECK(r >= 0.9 && r <= 1.3);
        worst_tail_lo = fmin(worst_tail_lo, r);
        worst_tail_hi = fmax(worst_tail_hi, r);
    }
    rb_spectrum_free(&sp);
    set_peaks pk = motion_peaks(s);
    double peak = pk.pga, pgv = pk.pgv, pgd = pk.pgd;
    CHECK(peak >= 0.95 * j->rig);
    CHECK(pgd <= 0.15);
    CHECK(pgv <= 1.0);
    worst_peak = fmin(worst_peak, peak / j->rig);
    worst_pgd = fmax(worst_pgd, pgd);
    worst_pgv = fmax(worst_pgv, pgv);
    /* what the generator says of it agrees */
    CHECK(j->info.summary.accept.pass);
    CHECK_REL(j->info.summary.pgd_m, pgd, 1e-9);
    CHECK_REL(j->info.summary.pga_mps2, peak, 1e-12);
}

static void check_suite(double sds_g, double zh, unsigned long long seed)
{
    job jobs[SETS * 3];
    pthread_t th[2];
    for (unsigned i = 0; i < SETS * 3; i++) {
        memset(&jobs[i], 0, sizeof jobs[i]);
        jobs[i].sds_g = sds_g;
        jobs[i].zh = zh;
        jobs[i].index = i / 3;
        jobs[i].comp = (rb_synth_component)(i % 3);
        jobs[i].seed = seed;
    }
    for (unsigned i = 0; i < SETS * 3; i += 2) {
        unsigned k = i + 1 < SETS * 3 ? 2 : 1;
        for (unsigned t = 0; t < k; t++)
            pthread_create(&th[t], NULL, run, &jobs[i + t]);
        for (unsigned t = 0; t < k; t++)
            pthread_join(th[t], NULL);
    }
    for (unsigned i = 0; i < SETS * 3; i++)
        check_component(&jobs[i]);
    for (unsigned set = 0; set < SETS; set++) {
        const job *c = &jobs[set * 3];
        if (c[0].st || c[1].st || c[2].st)
            continue;
        static const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
        for (int p = 0; p < 3; p++) {
            const rb_series *a = &c[pairs[p][0]].s, *b = &c[pairs[p][1]].s;
            double r = set_correlation(a, b);
            rb_synth_pair tool;
            CHECK(rb_synth_independence(a, b, &tool) == RB_OK);
            CHECK(r <= 0.3);
            CHECK_NEAR(tool.correlation, r, 1e-9);
            CHECK(tool.coherence <= 0.5);
            worst_corr = fmax(worst_corr, r);
        }
    }
    printf("S_DS %.1f g, z/h %g: 7 sets, least lab factor over the 12 offsets %.3f, "
           "rigid end %.3f to %.3f A_RIG, least peak %.3f A_RIG, PGD <= %.3f m, "
           "PGV <= %.3f m/s, correlation <= %.3f\n", sds_g, zh, worst_margin, worst_tail_lo,
           worst_tail_hi, worst_peak, worst_pgd, worst_pgv, worst_corr);
    for (unsigned i = 0; i < SETS * 3; i++)
        rb_series_free(&jobs[i].s);
}

int main(int argc, char **argv)
{
    unsigned long long seed = argc > 1 ? strtoull(argv[1], NULL, 10) : 1;
    check_suite(1.0, 1.0, seed);
    worst_margin = worst_tail_lo = worst_peak = INFINITY;
    worst_tail_hi = worst_pgd = worst_pgv = worst_corr = 0;
    check_suite(2.0, 0.0, seed);
    TEST_MAIN_END();
}
