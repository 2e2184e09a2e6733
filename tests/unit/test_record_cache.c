/* The record cache: a case loaded through it gets exactly the samples it
 * would get reading the record itself, a second case sharing the record is
 * a hit, and a different building is a different entry. */
#include <string.h>
#include "harness.h"
#include "rockbolt/case.h"
#include "rockbolt/record_cache.h"

static int load(const char *path, rb_record_cache *cache, rb_case *c)
{
    rb_diag_list dl = {0};
    rb_status st = rb_case_load_cached(path, cache, c, &dl);
    rb_diag_list_free(&dl);
    return st == RB_OK;
}

static int same_series(const rb_series *a, const rb_series *b)
{
    return a->n == b->n && a->dt_s == b->dt_s && a->t0_s == b->t0_s
           && memcmp(a->accel_mps2, b->accel_mps2, a->n * sizeof *a->accel_mps2) == 0;
}

int main(void)
{
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
