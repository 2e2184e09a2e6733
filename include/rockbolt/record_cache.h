/* A cache of floor motions read from record files, for loading many cases
 * that share records (a batch of an equipment list: a thousand cabinets
 * under the same El Centro floor motion).
 *
 * Reading an AT2 file and passing it through the building filter costs
 * about as much as loading the rest of a case several times over; with a
 * cache it is paid once per distinct (file, reading options, building) and
 * every case gets its own copy of the samples, which it then windows and
 * scales as before. The cache is safe to share between threads. It trusts
 * that a file does not change while the cache lives: make one per run. */
#ifndef ROCKBOLT_RECORD_CACHE_H
#define ROCKBOLT_RECORD_CACHE_H

#include <stddef.h>
#include "rockbolt/motion.h"
#include "rockbolt/record.h"

typedef struct rb_record_cache rb_record_cache;

/* A cache holding at most max_samples samples in all (0: 50 million, about
 * 400 MB); past that, records are read but not kept. NULL when out of
 * memory. */
rb_record_cache *rb_record_cache_new(size_t max_samples);

/* Free the cache and every series it holds; accepts NULL. */
void rb_record_cache_free(rb_record_cache *c);

/* Look up the floor motion of path read with opts and filtered by a
 * building of f_hz and damping xi (f_hz 0: no building). On a hit, out
 * gets a copy (the caller's to free) and 1 is returned; 0 on a miss or
 * when the copy cannot be allocated (out untouched). */
int rb_record_cache_get(rb_record_cache *c, const char *path, const rb_record_opts *opts,
                        double f_hz, double xi, rb_series *out);

/* Keep a copy of s under that key. Silently keeps nothing when the cache
 * is full or memory runs out: a cache only saves work. */
void rb_record_cache_put(rb_record_cache *c, const char *path, const rb_record_opts *opts,
                         double f_hz, double xi, const rb_series *s);

/* Lookups that found their series, and those that did not. */
void rb_record_cache_stats(rb_record_cache *c, long *hits, long *misses);

#endif
