/* The record cache: a case loaded through it gets exactly the samples it
 * would get reading the record itself, a second case sharing the record is
 * a hit, and a different building is a different entry. Readers copy
 * outside the lock: threads reading one entry while another thread adds
 * entries (the list grows and moves) each get that entry's samples. */
#include <math.h>
#include <pthread.h>
#include <string.h>
#include "harness.h"
#include "rockbolt/case.h"
#include "rockbolt/record_cache.h"

static int load(const char *path, rb_record_cache *cache, rb_case *c)
{
    rb_diag_list dl = {0};
    rb_status st = rb_case_load_cached(path, cache, NULL, c, &dl);
    rb_diag_list_free(&dl);
    return st == RB_OK;
}

static int same_series(const rb_series *a, const rb_series *b)
{
    return a->n == b->n && a->dt_s == b->dt_s && a->t0_s == b->t0_s
           && memcmp(a->accel_mps2, b->accel_mps2, a->n * sizeof *a->accel_mps2) == 0;
}

enum { N_READERS = 4, N_GETS = 300, N_PUTS = 60, N_SAMPLES = 4000 };

typedef struct {
    rb_record_cache *cache;
    const rb_series *want;
    int wrong, missed;
} reader;

static void *read_many(void *arg)
{
    reader *r = arg;
    rb_record_opts o;
    rb_record_opts_init(&o);
    for (int i = 0; i < N_GETS; i++) {
        rb_series got = {0};
        if (!rb_record_cache_get(r->cache, "shared", &o, 0, 0, &got)) {
            r->missed++;
            continue;
        }
        r->wrong += !same_series(&got, r->want);
        rb_series_free(&got);
    }
    return NULL;
}

/* One entry read by N_READERS threads while the main thread adds N_PUTS
 * others, each a different building. */
static void concurrent(void)
{
    rb_record_cache *cache = rb_record_cache_new(0);
    rb_series s = {0}, other = {0};
    rb_record_opts o;
    rb_record_opts_init(&o);
    CHECK(rb_series_alloc(&s, N_SAMPLES, 0.01) == RB_OK);
    CHECK(rb_series_alloc(&other, N_SAMPLES, 0.01) == RB_OK);
    for (size_t i = 0; i < N_SAMPLES; i++) {
        s.accel_mps2[i] = sin(0.01 * (double)i);
        other.accel_mps2[i] = -1.0;
    }
    rb_record_cache_put(cache, "shared", &o, 0, 0, &s);
    reader r[N_READERS];
    pthread_t th[N_READERS];
    int started = 0;
    for (int k = 0; k < N_READERS; k++) {
        r[k] = (reader){cache, &s, 0, 0};
        started += pthread_create(&th[k], NULL, read_many, &r[k]) == 0;
    }
    CHECK(started == N_READERS);
    for (int i = 0; i < N_PUTS; i++)
        rb_record_cache_put(cache, "other", &o, 1.0 + i, 0.05, &other);
    int wrong = 0, missed = 0;
    for (int k = 0; k < started; k++) {
        pthread_join(th[k], NULL);
        wrong += r[k].wrong;
        missed += r[k].missed;
    }
    CHECK(wrong == 0 && missed == 0);
    long hits = -1, misses = -1;
    rb_record_cache_stats(cache, &hits, &misses);
    CHECK(hits == (long)started * N_GETS && misses == 0);
    rb_series_free(&s);
    rb_series_free(&other);
    rb_record_cache_free(cache);
}

int main(void)
{
    concurrent();
    rb_record_cache *cache = rb_record_cache_new(0);
    rb_case plain, first, second, taft;
    long hits = -1, misses = -1;
    CHECK(cache != NULL);
    CHECK(load("cases/reference-elcentro.yaml", NULL, &plain));
    CHECK(load("cases/reference-elcentro.yaml", cache, &first));
    CHECK(load("cases/reference-elcentro.yaml", cache, &second));
    rb_record_cache_stats(cache, &hits, &misses);
    CHECK(hits == 1 && misses == 1);
    CHECK(same_series(&plain.motions[0].series, &first.motions[0].series));
    CHECK(same_series(&plain.motions[0].series, &second.motions[0].series));
    /* each case owns its copy: scaling one must not touch the cache */
    CHECK(first.motions[0].series.accel_mps2 != second.motions[0].series.accel_mps2);
    /* four motions on two records in both polarities: two reads, two hits */
    CHECK(load("cases/reference-suite.yaml", cache, &taft));
    rb_record_cache_stats(cache, &hits, &misses);
    CHECK(hits == 4 && misses == 2);
    CHECK(same_series(&taft.motions[0].series, &plain.motions[0].series));
    rb_case_free(&plain);
    rb_case_free(&first);
    rb_case_free(&second);
    rb_case_free(&taft);
    rb_record_cache_free(cache);
    TEST_MAIN_END();
}
