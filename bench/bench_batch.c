/* Throughput of a batch review: an equipment list of N cabinets (default
 * 1000; the reference cabinet with varied mass, height, gap ratio and bolt
 * size) under the El Centro floor motion at 0.4 A*, check only, through
 * rb_batch_run as the CLI calls it. Also the cost of loading one row, the
 * part of a case's time that is the batch's own rather than the solver's.
 *
 *   bench_batch [N [THREADS]]      (THREADS 0: every processor) */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "bench_common.h"
#include "rockbolt/batch.h"
#include "rockbolt/record_cache.h"
#include "rockbolt/case.h"

static int write_list(const char *path, int n)
{
    static const char *const bolts[] = {"12.7 mm", "16 mm", "19 mm"};
    FILE *f = fopen(path, "w");
    if (!f)
        return -1;
    fprintf(f, "tag,base,mass,height,gap_ratio,diameter,motion,building_frequency,"
               "building_damping,peak\n");
    for (int i = 0; i < n; i++)
        fprintf(f, "C-%04d,%s/cases/base/reference-cabinet.yaml,%d kg,%.3f m,%.4f,%s,"
                "elcentro,5 Hz,5 %%,0.4 A*\n", i, RB_SOURCE_DIR, 350 + (i * 37) % 251,
                1.6 + 0.6 * ((i * 13) % 101) / 100.0, 0.005 + 0.025 * ((i * 7) % 11) / 10.0,
                bolts[i % 3]);
    return fclose(f) == 0 ? 0 : -1;
}

/* Mean time to load one row, in seconds: with a record cache (as the batch
 * runs it: the record is read and filtered once) or without (every row
 * reads and filters it again). */
static double load_cost(const rb_batch_list *l, size_t n, rb_record_cache *cache)
{
    double t0 = rb_bench_now_s();
    for (size_t i = 0; i < n && i < l->n; i++) {
        const rb_batch_item *it = &l->items[i];
        rb_case c;
        rb_diag_list d = {0};
        if (rb_case_load_overrides(it->base, it->source, it->tag, it->ov, it->n_ov, cache,
                                   &c, &d) != RB_OK) {
            fprintf(stderr, "%s:%d: error: %s\n", it->source, it->line,
                    d.n ? d.items[0].msg : "cannot load");
            rb_diag_list_free(&d);
            return -1;
        }
        rb_case_free(&c);
        rb_diag_list_free(&d);
    }
    return (rb_bench_now_s() - t0) / (double)(n < l->n ? n : l->n);
}

int main(int argc, char **argv)
{
    int n = argc > 1 ? atoi(argv[1]) : 1000;
    int threads = argc > 2 ? atoi(argv[2]) : 0;
    char path[] = "/tmp/rockbolt-bench-batch-XXXXXX.csv";
    int fd = mkstemps(path, 4);
    if (n < 1 || fd < 0) {
        fprintf(stderr, "usage: bench_batch [N [THREADS]]\n");
        return 2;
    }
    close(fd);
    rb_batch_list l = {0};
    rb_batch_summary s;
    rb_batch_opts o;
    rb_diag d;
    rb_diag_clear(&d);
    if (write_list(path, n) != 0 || rb_batch_list_add(&l, path, NULL) != RB_OK) {
        fprintf(stderr, "cannot write or read %s\n", path);
        unlink(path);
        return 1;
    }
    rb_record_cache *cache = rb_record_cache_new(0);
    double per_load = load_cost(&l, 50, NULL);
    double per_load_cached = cache ? load_cost(&l, 50, cache) : -1;
    rb_record_cache_free(cache);
    rb_batch_opts_init(&o);
    o.n_threads = threads;
    double t0 = rb_bench_now_s();
    rb_status st = rb_batch_run(&l, &o, &s, &d);
    double wall = rb_bench_now_s() - t0;
    unlink(path);
    if (st != RB_OK || per_load < 0 || per_load_cached < 0) {
        fprintf(stderr, "batch failed: %s\n", rb_status_str(st));
        return 1;
    }
    rb_batch_counts c;
    rb_batch_count(&s, &c);
    printf("batch: %zu cases (%zu passed, %zu failed, %zu unreadable, %zu errors), "
           "%zu runs, El Centro at 0.4 A*\n", c.cases, c.passed, c.failed,
           c.unreadable, c.errors, c.runs);
    printf("batch: %.3f s wall on %s threads: %.1f cases/s\n", wall,
           threads > 0 ? argv[2] : "all", (double)c.cases / wall);
    printf("batch: loading one row: %.3f ms reading and filtering its record, %.3f ms "
           "with the record cache the batch uses\n", per_load * 1e3, per_load_cached * 1e3);
    rb_batch_summary_free(&s);
    rb_batch_list_free(&l);
    return c.unreadable || c.errors ? 1 : 0;
}
