/* Scheduling efficiency of a batch at many threads, SIMULATED from
 * measured per-row times: the list runs on one thread through rb_batch_run,
 * each row's CPU time is read from the progress calls (a row is done when the
 * count of done cases moves), and the row jobs are then dealt to P
 * simulated threads, each taking the next row when it frees:
 *
 *   one pool:   rows in list order, a row handed out only within 256 rows
 *               of the first unfinished one (the streamed window of
 *               src/batch/batch_run.c);
 *   chunks:     256-row chunks with a barrier after each (the former
 *               engine), for comparison;
 *   longest:    rows longest first by their measured time, no window: the
 *               bound any cost estimate could reach.
 *
 * Efficiency = the rows' total time / (P x the simulated wall time). The
 * simulation leaves out what threads share (memory bandwidth, the record
 * cache's lock, the sink): it says what the order and the window cost,
 * not what a 16-core machine measures.
 *
 *   bench_sched LIST.csv        (e.g. from bench/varied-list.sh) */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "bench_common.h"
#include "rockbolt/batch.h"

#define WINDOW 256
#define CHUNK 256

typedef struct {
    double *t_done;  /* time at which the k-th case was done */
    size_t n, cap;
    size_t last_cases;
} times;

/* The process's CPU time: the rows run one after another on one thread, so
 * it is their own time, whatever else the machine runs meanwhile. */
static double cpu_now_s(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void on_progress(void *ctx, const rb_batch_progress *p)
{
    times *t = ctx;
    if (p->cases_done == t->last_cases || t->n == t->cap)
        return;
    t->last_cases = p->cases_done;
    t->t_done[t->n++] = cpu_now_s();
}

/* The thread that frees first. */
static size_t first_free(const double *free_at, size_t p)
{
    size_t b = 0;
    for (size_t i = 1; i < p; i++)
        if (free_at[i] < free_at[b])
            b = i;
    return b;
}

/* Rows in the order given; window > 0: row k starts only once rows
 * 0 .. k - window are all done. Returns the wall time. */
static double simulate(const double *row, const size_t *order, size_t n, size_t p,
                       size_t window)
{
    double *free_at = calloc(p, sizeof *free_at), *finish = calloc(n, sizeof *finish);
    double *prefix_done = calloc(n, sizeof *prefix_done), wall = 0;
    if (!free_at || !finish || !prefix_done)
        exit(1);
    for (size_t k = 0; k < n; k++) {
        size_t th = first_free(free_at, p);
        double start = free_at[th];
        if (window && k >= window && prefix_done[k - window] > start)
            start = prefix_done[k - window];
        finish[k] = start + row[order[k]];
        free_at[th] = finish[k];
        prefix_done[k] = k ? (finish[k] > prefix_done[k - 1] ? finish[k] : prefix_done[k - 1])
                           : finish[k];
        if (finish[k] > wall)
            wall = finish[k];
    }
    free(free_at);
    free(finish);
    free(prefix_done);
    return wall;
}

/* Chunks of CHUNK rows in list order, a barrier after each. */
static double simulate_chunks(const double *row, const size_t *order, size_t n, size_t p)
{
    double wall = 0;
    for (size_t at = 0; at < n; at += CHUNK)
        wall += simulate(row, order + at, n - at < CHUNK ? n - at : CHUNK, p, 0);
    return wall;
}

static const double *sort_key;

static int longer_first(const void *a, const void *b)
{
    double x = sort_key[*(const size_t *)a], y = sort_key[*(const size_t *)b];
    return x < y ? 1 : x > y ? -1 : 0;
}

int main(int argc, char **argv)
{
    if (argc != 2) {
        fprintf(stderr, "usage: bench_sched LIST.csv\n");
        return 2;
    }
    rb_batch_list l = {0};
    if (rb_batch_list_add(&l, argv[1], NULL) != RB_OK || l.n == 0) {
        fprintf(stderr, "cannot read %s\n", argv[1]);
        return 1;
    }
    times t = {calloc(l.n, sizeof(double)), 0, l.n, 0};
    rb_batch_opts o;
    rb_batch_summary s;
    rb_diag d;
    rb_diag_clear(&d);
    rb_batch_opts_init(&o);
    o.n_threads = 1;
    o.progress = on_progress;
    o.progress_ctx = &t;
    double t0 = cpu_now_s();
    rb_status st = rb_batch_run(&l, &o, &s, &d);
    rb_batch_summary_free(&s);
    rb_batch_list_free(&l);
    if (st != RB_OK || t.n == 0) {
        fprintf(stderr, "batch failed: %s\n", rb_status_str(st));
        return 1;
    }
    size_t n = t.n;
    double *row = malloc(n * sizeof *row), total = 0, longest = 0;
    size_t *order = malloc(n * sizeof *order), *by_time = malloc(n * sizeof *by_time);
    if (!row || !order || !by_time)
        return 1;
    /* on one thread the rows run in list order, one after another */
    for (size_t k = 0; k < n; k++) {
        row[k] = t.t_done[k] - (k ? t.t_done[k - 1] : t0);
        total += row[k];
        longest = row[k] > longest ? row[k] : longest;
        order[k] = by_time[k] = k;
    }
    sort_key = row;
    qsort(by_time, n, sizeof *by_time, longer_first);
    printf("measured on one thread (CPU time): %zu rows, %.3f s, %.2f ms a row on average, the "
           "longest %.2f ms\n", n, total, 1e3 * total / (double)n, 1e3 * longest);
    printf("SIMULATED efficiency (total / (threads x wall)):\n");
    printf("threads  one pool (window %d)  chunks of %d  longest first\n", WINDOW, CHUNK);
    static const size_t threads[] = {2, 4, 8, 16, 32};
    for (size_t i = 0; i < sizeof threads / sizeof threads[0]; i++) {
        size_t p = threads[i];
        double pool = simulate(row, order, n, p, WINDOW);
        double chunks = simulate_chunks(row, order, n, p);
        double lf = simulate(row, by_time, n, p, 0);
        printf("%7zu  %19.1f %%  %11.1f %%  %12.1f %%\n", p,
               100 * total / ((double)p * pool), 100 * total / ((double)p * chunks),
               100 * total / ((double)p * lf));
    }
    free(row);
    free(order);
    free(by_time);
    free(t.t_done);
    return 0;
}
