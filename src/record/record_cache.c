/* The record cache: a short list of (key, series) behind one mutex. A
 * batch has a handful of distinct motions, so a linear search is the
 * right structure. The lock is held only to look up: an entry's samples
 * are written once, before it is listed, and freed only with the cache,
 * so a reader copies them after letting the lock go (the list itself may
 * move when it grows, which is why the entry's series header is taken
 * under the lock). */
#include <pthread.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/record_cache.h"
#include "util/grow.h"

#define RB_CACHE_DEFAULT_SAMPLES 50000000u

typedef struct {
    char *path;               /* owned */
    rb_record_opts opts;
    double f_hz, xi;
    rb_series series;         /* owned */
} entry;

struct rb_record_cache {
    pthread_mutex_t lock;
    entry *items;             /* owned array of n */
    size_t n, cap;
    size_t samples, max_samples;
    long hits, misses;
};

rb_record_cache *rb_record_cache_new(size_t max_samples)
{
    rb_record_cache *c = calloc(1, sizeof *c);
    if (!c)
        return NULL;
    if (pthread_mutex_init(&c->lock, NULL) != 0) {
        free(c);
        return NULL;
    }
    c->max_samples = max_samples ? max_samples : RB_CACHE_DEFAULT_SAMPLES;
    return c;
}

void rb_record_cache_free(rb_record_cache *c)
{
    size_t i;
    if (!c)
        return;
    for (i = 0; i < c->n; i++) {
        free(c->items[i].path);
        rb_series_free(&c->items[i].series);
    }
    free(c->items);
    pthread_mutex_destroy(&c->lock);
    free(c);
}

/* Field by field: the options struct may have padding. */
static int same_key(const entry *e, const char *path, const rb_record_opts *o,
                    double f_hz, double xi)
{
    return strcmp(e->path, path) == 0 && e->opts.format == o->format
           && e->opts.units_to_mps2 == o->units_to_mps2 && e->opts.dt_s == o->dt_s
           && e->opts.max_points == o->max_points && e->opts.sandbox == o->sandbox
           && e->f_hz == f_hz && e->xi == xi;
}

static int copy_series(const rb_series *from, rb_series *to)
{
    return rb_series_copy(from, to) == RB_OK;
}

int rb_record_cache_get(rb_record_cache *c, const char *path, const rb_record_opts *opts,
                        double f_hz, double xi, rb_series *out)
{
    size_t i;
    int found = 0;
    rb_series shared;
    if (!c)
        return 0;
    pthread_mutex_lock(&c->lock);
    for (i = 0; i < c->n && !found; i++)
        if (same_key(&c->items[i], path, opts, f_hz, xi)) {
            shared = c->items[i].series;
            found = 1;
        }
    pthread_mutex_unlock(&c->lock);
    if (found)
        found = copy_series(&shared, out);
    pthread_mutex_lock(&c->lock);
    if (found)
        c->hits++;
    else
        c->misses++;
    pthread_mutex_unlock(&c->lock);
    return found;
}

void rb_record_cache_put(rb_record_cache *c, const char *path, const rb_record_opts *opts,
                         double f_hz, double xi, const rb_series *s)
{
    size_t i;
    entry e;
    if (!c || !s->n)
        return;
    pthread_mutex_lock(&c->lock);
    /* another thread may have read the same record meanwhile */
    for (i = 0; i < c->n; i++)
        if (same_key(&c->items[i], path, opts, f_hz, xi))
            goto done;
    if (s->n > c->max_samples - c->samples)
        goto done;
    if (c->n == c->cap) {
        entry *items = rb_grow(c->items, &c->cap, sizeof *items, 8);
        if (!items)
            goto done;
        c->items = items;
    }
    memset(&e, 0, sizeof e);
    e.opts = *opts;
    e.f_hz = f_hz;
    e.xi = xi;
    if (!(e.path = malloc(strlen(path) + 1)))
        goto done;
    strcpy(e.path, path);
    if (!copy_series(s, &e.series)) {
        free(e.path);
        goto done;
    }
    c->items[c->n++] = e;
    c->samples += s->n;
done:
    pthread_mutex_unlock(&c->lock);
}

void rb_record_cache_stats(rb_record_cache *c, long *hits, long *misses)
{
    pthread_mutex_lock(&c->lock);
    *hits = c->hits;
    *misses = c->misses;
    pthread_mutex_unlock(&c->lock);
}
