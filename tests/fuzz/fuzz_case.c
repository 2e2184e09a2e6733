/* libFuzzer harness: the case loader (rb_case_load: YAML, units, extends,
 * schema, validation, and the records a case names).
 *
 * Each input is written to a/t/e/case.yaml in a scratch tree that looks
 * enough like the repository for the seeds to get past their `extends:`
 * and `file:` lines: cases/ and tests/errors/ name the reference base and
 * records as base/..., records/..., ../../cases/... and ../../../cases/...,
 * and all of these lead to one copy of the base and to short copies of the
 * shipped records (64 samples, so a record case costs microseconds, not a
 * millisecond of parsing). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "fuzz_common.h"
#include "rockbolt/case.h"
#include "rockbolt/model.h"

#ifndef RB_SOURCE_DIR
#define RB_SOURCE_DIR "."
#endif

#define RB_FUZZ_RECORD_POINTS 64

static void link_in(const char *target, const char *rel)
{
    char path[512];
    rb_fuzz_path(path, sizeof path, rel);
    if (symlink(target, path) != 0)
        rb_fuzz_fail("cannot make a scratch link", path);
}

static void copy_base(void)
{
    char buf[16384];
    FILE *f = fopen(RB_SOURCE_DIR "/cases/base/reference-cabinet.yaml", "rb");
    size_t n = f ? fread(buf, 1, sizeof buf, f) : 0;
    if (f)
        fclose(f);
    rb_fuzz_write("cases/base/reference-cabinet.yaml", (const uint8_t *)buf, n);
}

/* The first samples of a shipped record, in g, as AT2 or one column. */
static void copy_record(const char *name, int at2)
{
    char src[512], text[8192];
    rb_series s;
    rb_record_opts o;
    rb_record_opts_init(&o);
    o.units_to_mps2 = RB_G0;
    o.dt_s = at2 ? 0.0 : 0.01;
    o.format = at2 ? RB_REC_AT2 : RB_REC_ONE_COLUMN;
    snprintf(src, sizeof src, "%s/cases/records/%s", RB_SOURCE_DIR, name);
    size_t len = 0;
    if (rb_record_read(src, &o, &s, NULL) == RB_OK) {
        size_t n = s.n < RB_FUZZ_RECORD_POINTS ? s.n : RB_FUZZ_RECORD_POINTS;
        if (at2)
            len += (size_t)snprintf(text, sizeof text, "short copy of %s\nfor the "
                                    "case fuzzer\nACCELERATION IN UNITS OF G\nNPTS= "
                                    "%zu, DT= %.5f SEC\n", name, n, s.dt_s);
        for (size_t i = 0; i < n && len < sizeof text - 40; i++)
            len += (size_t)snprintf(text + len, sizeof text - len, "%.7e%s",
                                    s.accel_mps2[i] / RB_G0, at2 && (i + 1) % 5 ? " " : "\n");
        rb_series_free(&s);
    }
    char rel[256];
    snprintf(rel, sizeof rel, "cases/records/%s", name);
    rb_fuzz_write(rel, (const uint8_t *)text, len);
}

static void make_sandbox(void)
{
    char path[512];
    copy_base();
    copy_record("elcentro_1940_ns.at2", 1);
    copy_record("elcentro_1940_ns_ngawest2.at2", 1);
    copy_record("elcentro_1940_ns_peknold.at2", 1);
    copy_record("taft_1952_s69e.txt", 0);
    rb_fuzz_write("a/t/e/case.yaml", (const uint8_t *)"", 0);
    rb_fuzz_path(path, sizeof path, "cases");
    link_in(path, "a/cases");
    rb_fuzz_path(path, sizeof path, "cases/base");
    link_in(path, "a/t/e/base");
    rb_fuzz_path(path, sizeof path, "cases/records");
    link_in(path, "a/t/e/records");
    link_in(RB_SOURCE_DIR "/tests/errors/include", "a/t/e/include");
}

static void check_loaded(const rb_case *c, const rb_diag_list *l)
{
    if (l->n != 0)
        rb_fuzz_fail("a case that loads has diagnostics", l->items[0].msg);
    if (c->n_motions < 1 || !c->motions || !c->name || !c->path)
        rb_fuzz_fail("a case that loads has no motion or no name", NULL);
    if (c->n_input_files < 1 || strcmp(c->input_files[0], c->path) != 0)
        rb_fuzz_fail("a case that loads does not list itself as its first input",
                     NULL);
    for (size_t i = 0; i < c->n_motions; i++) {
        const rb_case_motion *m = &c->motions[i];
        if (!(m->motion.duration_s > 0.0) || !isfinite(m->motion.duration_s))
            rb_fuzz_fail("a loaded motion has a bad duration", m->name);
        if (m->motion.kind != RB_MOTION_SAMPLED)
            continue;
        if (m->motion.series != &m->series || m->series.n == 0)
            rb_fuzz_fail("a loaded record motion has no samples", m->name);
        for (size_t k = 0; k < m->series.n; k++)
            if (!isfinite(m->series.accel_mps2[k]))
                rb_fuzz_fail("a loaded record motion has a non-finite sample", m->name);
    }
}

static void check_refused(rb_status st, const rb_case *c, const rb_diag_list *l)
{
    if (st != RB_ERR_IO && st != RB_ERR_PARSE && st != RB_ERR_INVALID
        && st != RB_ERR_LIMIT && st != RB_ERR_NOMEM)
        rb_fuzz_fail("rb_case_load returned an unexpected status", rb_status_str(st));
    if (l->n == 0 && st != RB_ERR_NOMEM)
        rb_fuzz_fail("a refused case has no diagnostic", rb_status_str(st));
    if (c->motions || c->path || c->name)
        rb_fuzz_fail("a refused case left allocations behind", NULL);
    for (size_t i = 0; i < l->n; i++) {
        const rb_diag *d = &l->items[i];
        if (!d->file[0] || !d->key[0] || !d->msg[0] || d->line < 0 || d->col < 0)
            rb_fuzz_fail("a diagnostic lacks its file, key, message or position",
                         d->msg);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static int ready;
    char path[512];
    if (!ready) {
        make_sandbox();
        /* the loader is under test, not the generator: a suite's checks
         * run, its samples are zeros */
        rb_case_set_generate(0);
        ready = 1;
    }
    rb_fuzz_write("a/t/e/case.yaml", data, size);
    rb_fuzz_path(path, sizeof path, "a/t/e/case.yaml");
    rb_case c;
    rb_diag_list l = {0};
    rb_status st = rb_case_load(path, &c, &l);
    /* For reading a reproducer: what the loader made of it. */
    if (getenv("RB_FUZZ_VERBOSE"))
        fprintf(stderr, "rb_case_load: %s, %zu motions, %zu diags%s%s\n",
                rb_status_str(st), c.n_motions, l.n, l.n ? "; first: " : "",
                l.n ? l.items[0].msg : "");
    if (st == RB_OK)
        check_loaded(&c, &l);
    else
        check_refused(st, &c, &l);
    rb_case_free(&c);
    rb_diag_list_free(&l);
    return 0;
}
