/* The laboratory's acceptance (rockbolt/accept.h), rule by rule, on
 * spectra written here as ratios to an AC156 RRS (S_DS 1 g, z/h 1):
 *   - the low cutoff max(1.3, min(3.5, 0.75 f)) rounded up to 0.1 Hz;
 *   - the grid is 0.1 2^(k/72) Hz and holds, for every offset, the point
 *     below the low cutoff and above the high one;
 *   - 1.1 everywhere passes with margin 1.1; one point at 0.85 fails its
 *     offset only (margin 0.85 / 0.9) and the other 11 pass; two adjacent
 *     points of one offset at 0.95 fail (margin 0.95); three points below
 *     1.0 in one range fail, two pass; the offset's point just below the
 *     low cutoff counts; a point above 1.3 is reported, and fails only
 *     under max_ratio;
 *   - the summary of a sine of whole periods against its closed forms
 *     (PGV 2 A / w, displacement A t / w at the end, Arias pi A^2 T / 4 g). */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "harness.h"
#include "rockbolt/accept.h"

#define G 9.80665

static long index_of(double f)
{
    return lround(log2(f / 0.1) * 72.0);
}

static int offset_of(double f)
{
    return (int)(((index_of(f) % 12) + 12) % 12);
}

/* sp's ordinates at ratio q to the target */
static void fill(const rb_target *t, rb_spectrum *sp, double q)
{
    for (size_t i = 0; i < sp->n; i++)
        sp->sa_mps2[i] = q * rb_target_at(t, sp->freq_hz[i]);
}

/* the index in sp of the first point of offset j at or above f */
static size_t point_at(const rb_spectrum *sp, int j, double f)
{
    for (size_t i = 0; i < sp->n; i++)
        if (sp->freq_hz[i] >= f && offset_of(sp->freq_hz[i]) == j)
            return i;
    return sp->n;
}

static void set_ratio(const rb_target *t, rb_spectrum *sp, size_t i, double q)
{
    sp->sa_mps2[i] = q * rb_target_at(t, sp->freq_hz[i]);
}

static void check_cutoff(void)
{
    CHECK_NEAR(rb_accept_low_cutoff(1.0), 1.3, 1e-12);
    CHECK_NEAR(rb_accept_low_cutoff(1.3 / 0.75), 1.3, 1e-12);
    CHECK_NEAR(rb_accept_low_cutoff(1.8), 1.4, 1e-12);     /* 1.35 up */
    CHECK_NEAR(rb_accept_low_cutoff(3.0), 2.3, 1e-12);     /* 2.25 up */
    CHECK_NEAR(rb_accept_low_cutoff(4.0), 3.0, 1e-12);
    CHECK_NEAR(rb_accept_low_cutoff(20.0), 3.5, 1e-12);
    CHECK_NEAR(rb_accept_low_cutoff(NAN), 1.3, 0);
    CHECK_NEAR(rb_accept_low_cutoff(0.0), 1.3, 0);
}

static void check_rules(void)
{
    rb_target t;
    rb_target_ac156(&t, RB_AC156_2010, G, 1.0);
    rb_accept_rules r;
    rb_accept_rules_init(&r, &t);
    CHECK_NEAR(r.low_cutoff_hz, 1.3, 0);
    CHECK_NEAR(r.high_cutoff_hz, 33.3, 0);
    CHECK_NEAR(r.damping, 0.05, 0);
    rb_spectrum sp;
    CHECK(rb_accept_grid(&r, &sp) == RB_OK);
    /* 1/72 octave from 0.1 Hz; the first point is 12 steps under the
     * first at or above 1.3 Hz, the last at 50 Hz or under */
    long k_first = (long)ceil(log2(13.0) * 72 - 1e-9);
    CHECK(index_of(sp.freq_hz[0]) == k_first - 12);
    CHECK(sp.freq_hz[sp.n - 1] <= 50.0 && sp.freq_hz[sp.n - 1] * exp2(1.0 / 72) > 50.0);
    for (size_t i = 1; i < sp.n; i++)
        CHECK_NEAR(sp.freq_hz[i] / sp.freq_hz[i - 1], exp2(1.0 / 72), 1e-12);

    rb_accept_result a;
    fill(&t, &sp, 1.1);
    CHECK(rb_accept_judge(&r, &t, &sp, &a) == RB_OK);
    CHECK(a.pass);
    CHECK_NEAR(a.margin, 1.1, 1e-12);
    CHECK(!a.above_guide);
    CHECK_NEAR(a.tail_min_ratio, 1.1, 1e-12);
    /* every offset holds its 1/6-octave points within 1.3 to 33.3 Hz and
     * one outside each end: 28 or 29 within, 30 or 31 in all */
    for (int j = 0; j < 12; j++)
        CHECK(a.offset[j].n_points >= 30 && a.offset[j].n_points <= 31);

    /* one point at 0.85 at offset 5, 4 Hz */
    size_t i = point_at(&sp, 5, 4.0);
    set_ratio(&t, &sp, i, 0.85);
    CHECK(rb_accept_judge(&r, &t, &sp, &a) == RB_OK);
    CHECK(!a.pass);
    CHECK(a.worst == 5);
    CHECK_NEAR(a.margin, 0.85 / 0.9, 1e-12);
    CHECK_NEAR(a.min_ratio, 0.85, 1e-12);
    for (int j = 0; j < 12; j++)
        CHECK(a.offset[j].pass == (j != 5));

    /* two adjacent points of offset 7 at 0.95 (12 grid steps apart) */
    fill(&t, &sp, 1.1);
    i = point_at(&sp, 7, 12.0);
    set_ratio(&t, &sp, i, 0.95);
    set_ratio(&t, &sp, i + 12, 0.96);
    CHECK(rb_accept_judge(&r, &t, &sp, &a) == RB_OK);
    CHECK(!a.pass && a.worst == 7 && a.offset[7].adjacent_below);
    CHECK_NEAR(a.margin, 0.96, 1e-12);

    /* two points of offset 2 below 1.0 under 8.3 Hz, not adjacent: pass;
     * a third: fail, margin the third smallest */
    fill(&t, &sp, 1.1);
    i = point_at(&sp, 2, 1.5);
    set_ratio(&t, &sp, i, 0.93);
    set_ratio(&t, &sp, i + 24, 0.97);
    CHECK(rb_accept_judge(&r, &t, &sp, &a) == RB_OK);
    CHECK(a.pass && a.offset[2].below_one_low == 2);
    CHECK_NEAR(a.margin, 0.93 / 0.9, 1e-12);
    set_ratio(&t, &sp, i + 48, 0.98);
    CHECK(sp.freq_hz[i + 48] <= 8.3);
    CHECK(rb_accept_judge(&r, &t, &sp, &a) == RB_OK);
    CHECK(!a.pass && a.worst == 2 && a.offset[2].below_one_low == 3);
    CHECK_NEAR(a.margin, 0.98, 1e-12);
    /* the same three split by 8.3 Hz: two above, one below is fine */
    fill(&t, &sp, 1.1);
    i = point_at(&sp, 2, 8.3);
    CHECK(sp.freq_hz[i - 12] <= 8.3 && sp.freq_hz[i] > 8.3);
    set_ratio(&t, &sp, i - 36, 0.98);
    set_ratio(&t, &sp, i, 0.97);
    set_ratio(&t, &sp, i + 24, 0.99);
    CHECK(rb_accept_judge(&r, &t, &sp, &a) == RB_OK);
    CHECK(a.pass);
    set_ratio(&t, &sp, i + 48, 0.99);
    CHECK(rb_accept_judge(&r, &t, &sp, &a) == RB_OK);
    CHECK(!a.pass && a.offset[2].below_one_high == 3);

    /* the point of offset 9 just below 1.3 Hz counts; the one below it
     * does not */
    fill(&t, &sp, 1.1);
    i = point_at(&sp, 9, 1.3);
    set_ratio(&t, &sp, i - 12, 0.8);
    CHECK(rb_accept_judge(&r, &t, &sp, &a) == RB_OK);
    CHECK(!a.pass && a.worst == 9);
    CHECK_NEAR(a.min_ratio, 1.1, 1e-12);     /* outside the cutoffs */
    fill(&t, &sp, 1.1);
    if (i >= 24) {
        set_ratio(&t, &sp, i - 24, 0.5);
        CHECK(rb_accept_judge(&r, &t, &sp, &a) == RB_OK);
        CHECK(a.pass);
    }

    /* 1.5 at 20 Hz: reported; fails under max_ratio 1.3 */
    fill(&t, &sp, 1.1);
    i = point_at(&sp, 0, 20.0);
    set_ratio(&t, &sp, i, 1.5);
    CHECK(rb_accept_judge(&r, &t, &sp, &a) == RB_OK);
    CHECK(a.pass && a.above_guide);
    CHECK_NEAR(a.max_ratio, 1.5, 1e-12);
    r.max_ratio = 1.3;
    CHECK(rb_accept_judge(&r, &t, &sp, &a) == RB_OK);
    CHECK(!a.pass && !a.offset[0].pass && a.offset[1].pass);
    rb_spectrum_free(&sp);

    /* rules out of range */
    r.low_cutoff_hz = 40;
    CHECK(rb_accept_grid(&r, &sp) == RB_ERR_INVALID);
    rb_accept_rules_init(&r, &t);
    r.damping = 1.0;
    CHECK(rb_accept_grid(&r, &sp) == RB_ERR_INVALID);
}

static void check_summary(void)
{
    double A = 2.0, f = 2.0, w = 2 * M_PI * f, T = 10.0, dt = 0.001;
    rb_series s;
    size_t n = (size_t)llround(T / dt) + 1;
    CHECK(rb_series_alloc(&s, n, dt) == RB_OK);
    for (size_t i = 0; i < n; i++)
        s.accel_mps2[i] = A * sin(w * (double)i * dt);
    rb_motion_summary m;
    CHECK(rb_motion_summarise(&s, NULL, NULL, &m) == RB_OK);
    CHECK_REL(m.pga_mps2, A, 1e-9);
    /* v = A/w (1 - cos w t), d = A/w (t - sin(w t)/w): the chords lose
     * (w dt)^2 / 12 of them */
    CHECK_REL(m.pgv_mps, 2 * A / w, 1e-4);
    CHECK_REL(m.end_displacement_m, A * T / w, 1e-4);
    CHECK_REL(m.pgd_m, A * T / w, 1e-4);
    CHECK_REL(m.arias_mps, M_PI / (2 * G) * A * A * T / 2, 1e-4);
    CHECK_NEAR(m.arias_t95_s - m.arias_t5_s, 0.9 * T, 0.02);
    CHECK(!m.has_target && m.peak_ok);
    /* with a target: a 2 Hz sine does not envelope AC156 */
    rb_target t;
    rb_target_ac156(&t, RB_AC156_2010, G, 0.0);
    CHECK(rb_motion_summarise(&s, &t, NULL, &m) == RB_OK);
    CHECK(m.has_target && !m.accept.pass && !m.peak_ok);
    rb_series_free(&s);
}

int main(void)
{
    check_cutoff();
    check_rules();
    check_summary();
    TEST_MAIN_END();
}
