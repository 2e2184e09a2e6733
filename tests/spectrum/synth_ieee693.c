/* IEEE 693 triaxial sets of the generator (rockbolt/synth.h), checked
 * apart from it: the RRS written here from the published formula (High at
 * damping xi, Moderate half, vertical 80 %), the TRS on the 1/72-octave
 * grid 0.1 x 2^(k/72) Hz written here, the laboratory's rules (no point
 * below 0.9, no two adjacent below 1.0, at most two below 1.0 up to and
 * above 8.3 Hz) at every one of the 12 offsets between the cutoffs 1.1 and
 * 33 Hz with the nearest point outside each, the peak at least 0.9 of the
 * ZPA, the rigid end (33 to 50 Hz) within [0.9, 1.3] of the ZPA line,
 * PGD <= 0.15 m and PGV <= 1.0 m/s integrated here, and the
 * components pairwise uncorrelated (|correlation| over every lag <= 0.3,
 * summed here), for seeds 1 to 3 (or the one given). Prints what it
 * measured. */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "../unit/harness.h"
#include "rockbolt/synth.h"
#include "set_checks.h"

#define G 9.80665

static double rrs_g(double f, double xi, double factor)
{
    double b = (3.21 - 0.68 * log(100 * xi)) / 2.1156, a;
    if (f <= 1.1)
        a = 2.288 * b * f;
    else if (f <= 8)
        a = 2.5 * b;
    else if (f <= 33)
        a = (26.4 * b - 10.56) / f - 0.8 * b + 1.32;
    else
        a = 1.0;
    return factor * a;
}

/* the rules at one offset, directly: 1 when they pass */
static int rules_pass(const double *f, const double *q, size_t n, double *least)
{
    int ok = 1;
    unsigned low = 0, high = 0;
    for (size_t i = 0; i < n; i++) {
        *least = fmin(*least, q[i]);
        ok &= q[i] >= 0.9;
        if (q[i] < 1.0) {
            if (f[i] <= 8.3)
                low++;
            else
                high++;
            if (i + 1 < n && q[i + 1] < 1.0)
                ok = 0;
        }
    }
    return ok && low <= 2 && high <= 2;
}

typedef struct {
    rb_ieee693_level level;
    double xi;
    rb_synth_component comp;
    unsigned long long seed;
    rb_series s;
    rb_synth_info info;
    rb_status st;
} job;

static void *run(void *arg)
{
    job *j = arg;
    rb_target t;
    rb_target_ieee693(&t, j->level, j->xi, j->comp == RB_SYNTH_V);
    rb_synth_opts o;
    rb_synth_opts_init(&o, &t);
    o.seed = j->seed;
    o.index = (unsigned)j->comp * RB_SYNTH_COMPONENT_STREAM;
    j->st = rb_synth_generate(&o, &j->s, &j->info);
    return NULL;
}

typedef struct {
    double xi, factor;
} ieee_rrs_ctx;

static double ieee_rrs(double f, const void *ctx)
{
    const ieee_rrs_ctx *c = ctx;
    return G * rrs_g(f, c->xi, c->factor);
}

static void check_component(const job *j)
{
    CHECK(j->st == RB_OK);
    if (j->st != RB_OK)
        return;
    double factor = (j->level == RB_IEEE693_MODERATE ? 0.5 : 1.0)
                    * (j->comp == RB_SYNTH_V ? 0.8 : 1.0);
    double fq[800];
    size_t n = 0;
    for (int k = 0;; k++) {
        double f = 0.1 * pow(2.0, k / 72.0);
        if (f > 50.0 * (1 + 1e-9))
            break;
        if (f >= 0.9)
            fq[n++] = f;
    }
    rb_spectrum sp;
    CHECK(rb_spectrum_alloc(&sp, fq, n, j->xi) == RB_OK);
    CHECK(rb_spectrum_of_series(&j->s, 1.0, &sp) == RB_OK);
    int k0 = (int)lround(log2(fq[0] / 0.1) * 72);
    double least = INFINITY, most = 0;
    int offsets = 0;
    ieee_rrs_ctx rc = {j->xi, factor};
    for (int off = 0; off < 12; off++) {
        double f[80], q[80];
        size_t m = offset_ratios(fq, sp.sa_mps2, n, k0, off, 1.1, 33.0, ieee_rrs, &rc, f, q,
                                 &most);
        int ok = rules_pass(f, q, m, &least);
        CHECK(ok);
        offsets += ok;
    }
    /* the rigid end: from 33 to 50 Hz within [0.9, 1.3] of the ZPA line */
    double rig_lo = INFINITY, rig_hi = 0;
    for (size_t i = 0; i < n; i++)
        if (fq[i] > 33.0) {
            double q = sp.sa_mps2[i] / ieee_rrs(fq[i], &rc);
            rig_lo = fmin(rig_lo, q);
            rig_hi = fmax(rig_hi, q);
        }
    CHECK(rig_lo >= 0.9 && rig_hi <= 1.3);
    CHECK(fabs(ieee_rrs(40.0, &rc) - factor * G) < 1e-12);
    rb_spectrum_free(&sp);
    set_peaks pk = motion_peaks(&j->s);
    double peak = pk.pga, pgv = pk.pgv, pgd = pk.pgd;
    CHECK(peak >= 0.9 * factor * G);
    CHECK(pgd <= 0.15);
    CHECK(pgv <= 1.0);
    CHECK(j->info.summary.accept.pass);
    printf("IEEE 693 %s at %g %%, %s: %d of 12 offsets pass, TRS / RRS %.3f to %.3f, "
           "rigid end %.3f to %.3f, peak %.3f of the ZPA, PGD %.3f m, PGV %.3f m/s\n",
           j->level == RB_IEEE693_HIGH ? "high" : "moderate", 100 * j->xi,
           j->comp == RB_SYNTH_H1 ? "H1" : j->comp == RB_SYNTH_H2 ? "H2" : "V", offsets,
           least, most, rig_lo, rig_hi, peak / (factor * G), pgd, pgv);
}

static void check_set(rb_ieee693_level level, double xi, unsigned long long seed)
{
    job jobs[3];
    pthread_t th[3];
    for (int i = 0; i < 3; i++) {
        memset(&jobs[i], 0, sizeof jobs[i]);
        jobs[i].level = level;
        jobs[i].xi = xi;
        jobs[i].seed = seed;
        jobs[i].comp = (rb_synth_component)i;
        pthread_create(&th[i], NULL, run, &jobs[i]);
    }
    for (int i = 0; i < 3; i++)
        pthread_join(th[i], NULL);
    for (int i = 0; i < 3; i++)
        check_component(&jobs[i]);
    if (!jobs[0].st && !jobs[1].st && !jobs[2].st) {
        static const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
        for (int p = 0; p < 3; p++) {
            double r = set_correlation(&jobs[pairs[p][0]].s, &jobs[pairs[p][1]].s);
            printf("  correlation %d-%d %.3f\n", pairs[p][0], pairs[p][1], r);
            CHECK(r <= 0.3);
        }
    }
    for (int i = 0; i < 3; i++)
        rb_series_free(&jobs[i].s);
}

int main(int argc, char **argv)
{
    /* seeds 1 to 3, or the one given: at 2 % damping seeds 1 and 2 left
     * components unmatched while the correction grid was 1/12 octave,
     * coarser than a 2 % oscillator's half-power band (docs/motion.md) */
    unsigned long long first = argc > 1 ? strtoull(argv[1], NULL, 10) : 1;
    unsigned long long last = argc > 1 ? first : 3;
    for (unsigned long long seed = first; seed <= last; seed++) {
        printf("seed %llu\n", seed);
        check_set(RB_IEEE693_MODERATE, 0.05, seed);
        check_set(RB_IEEE693_MODERATE, 0.02, seed);
    }
    TEST_MAIN_END();
}
