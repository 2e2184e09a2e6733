/* The JSON summary of a batch, and reading it back.
 *
 * The reader keeps exactly what the writer needs (the derived parts,
 * counts, governing motion, mean and maximum, are recomputed), and every
 * double is printed in the fewest digits that read back to the same double.
 * So a summary read back and written again is the same text: that is what
 * makes merged shards byte-identical to a single run. cJSON's own printer
 * cannot be used for this: it keeps 15 digits whenever they come back
 * within a relative DBL_EPSILON, which can be an ulp off, and a mean
 * recomputed from such values then differs in its last digits. */
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cjson/cJSON.h>
#include "batch_summary.h"
#include "rockbolt/criteria.h"
#include "rockbolt/names.h"
#include "rockbolt/jsonbuild.h"
#include "rockbolt/jsonprint.h"
#include "util/strbuf.h"
#include "rockbolt/report.h"
#include "rockbolt/textsafe.h"

/* The columns of one group (the run's own, or the design's) of a run or
 * of a case's mean and maximum; none is null. key_max: the aggregates'
 * names (in "max"); bounds NULL: no bound columns (a mean or maximum). */
static int add_columns(cJSON *o, const double *value, const unsigned *bounds, int design,
                       int key_max)
{
    int ok = 1;
    for (size_t k = 0; ok && k < rb_batch_n_columns; k++) {
        const rb_batch_column *col = &rb_batch_columns[k];
        if (col->design != design)
            continue;
        ok = rb_j_add_num(o, key_max ? col->agg_name : col->name, value[k]);
        if (ok && bounds && col->bound_of) {
            char key[64];
            snprintf(key, sizeof key, "%s_bound", col->name);
            ok = cJSON_AddBoolToObject(o, key, (*bounds >> k) & 1u) != NULL;
        }
    }
    return ok;
}

static int add_stat(cJSON *parent, const char *name, const rb_batch_stat *st,
                    int design, int is_max)
{
    cJSON *o = cJSON_AddObjectToObject(parent, name);
    return o && add_columns(o, st->value, NULL, 0, is_max)
        && (!design || add_columns(o, st->value, NULL, 1, is_max));
}

/* The names of the validity checks that warned, as in the reports. */
static int add_warnings(cJSON *o, unsigned warnings)
{
    cJSON *a = cJSON_AddArrayToObject(o, "validity_warnings");
    for (int k = 0; a && k < RB_N_CHECKS; k++) {
        if (!((warnings >> k) & 1u))
            continue;
        cJSON *s = cJSON_CreateString(rb_check_name((rb_check)k));
        if (!s || !cJSON_AddItemToArray(a, s))
            return cJSON_Delete(s), 0;
    }
    return a != NULL;
}

static int add_run(cJSON *arr, const rb_batch_result *r, int design)
{
    cJSON *o = cJSON_CreateObject();
    if (!o || !cJSON_AddItemToArray(arr, o))
        return cJSON_Delete(o), 0;
    int ok = rb_j_add_text(o, "motion", r->motion) != NULL
        && cJSON_AddStringToObject(o, "verdict", r->pass ? "pass" : "fail") != NULL
        && add_columns(o, r->value, &r->bounds, 0, 0)
        && rb_j_add_num(o, "margin", r->margin)
        && cJSON_AddStringToObject(o, "governs",
                                   rb_governs_name((rb_governs_limit)r->limit)) != NULL
        && rb_j_add_text(o, "reason", r->reason) != NULL
        && add_warnings(o, r->warnings);
    /* only with a concrete check, so that other summaries keep their bytes */
    if (ok && r->has_anchor)
        ok = cJSON_AddStringToObject(o, "anchor_mode",
                                     rb_enum_str(rb_anchor_mode_names, r->anchor_mode)) != NULL
             && rb_j_add_num(o, "anchor_utilization", r->anchor_utilization);
    return ok && (!design || add_columns(o, r->value, &r->bounds, 1, 0));
}

static int add_error(cJSON *o, const rb_batch_case *c)
{
    if (c->verdict == RB_BATCH_PASS || c->verdict == RB_BATCH_FAIL)
        return cJSON_AddNullToObject(o, "error") != NULL;
    cJSON *e = cJSON_AddObjectToObject(o, "error");
    const rb_diag *d = rb_batch_case_error(c);
    return e && rb_j_add_text(e, "file", d->file)
        && rb_j_add_num(e, "line", d->line) && rb_j_add_num(e, "col", d->col)
        && rb_j_add_text(e, "key", d->key)
        && rb_j_add_text(e, "message", d->msg)
        && rb_j_add_num(e, "count", (double)c->n_errors);
}

/* A case's fragility in SI, under the names `rockbolt fragility --json`
 * gives the same numbers. */
static int add_fragility(cJSON *o, const rb_batch_fragility *f)
{
    cJSON *fo = cJSON_AddObjectToObject(o, "fragility"), *ls = NULL;
    if (!fo)
        return 0;
    if (f->error)
        return rb_j_add_text(fo, "error", f->error) != NULL;
    int ok = (!(f->im_freq_hz > 0) || rb_j_add_num(fo, "intensity_freq_hz", f->im_freq_hz))
        && rb_j_add_num(fo, "g_mps2", f->g_mps2) && rb_j_add_num(fo, "level_mps2", f->level_mps2)
        && (f->governing >= 0
            ? cJSON_AddStringToObject(fo, "governing_limit_state",
                                      rb_enum_str(rb_limit_state_names, f->governing))
            : cJSON_AddNullToObject(fo, "governing_limit_state")) != NULL
        && (ls = cJSON_AddArrayToObject(fo, "limit_states")) != NULL;
    for (int k = 0; ok && k < RB_N_LIMITS; k++) {
        const rb_batch_limit *l = &f->limits[k];
        if (!l->present)
            continue;
        cJSON *e = cJSON_CreateObject();
        if (!e || !cJSON_AddItemToArray(ls, e))
            return cJSON_Delete(e), 0;
        ok = cJSON_AddStringToObject(e, "limit_state",
                                     rb_enum_str(rb_limit_state_names, k)) != NULL
            && cJSON_AddBoolToObject(e, "fitted", l->fitted) != NULL;
        if (ok && l->fitted)
            ok = rb_j_add_num(e, "median_mps2", l->median_mps2) && rb_j_add_num(e, "beta", l->beta)
                && rb_j_add_num(e, "median_lo_mps2", l->median_lo_mps2)
                && rb_j_add_num(e, "median_hi_mps2", l->median_hi_mps2)
                && rb_j_add_num(e, "p_at_level", l->p_at_level);
        ok = ok && rb_j_add_num(e, "reached", (double)l->reached)
            && cJSON_AddBoolToObject(e, "confirmed", l->confirmed) != NULL
            && rb_j_add_num(e, "model_limited", (double)l->model_limited);
    }
    return ok;
}

/* "code_static": the code-static numbers of a case with design.code, in SI
 * as `design --json` names them; null without. */
static int add_code(cJSON *o, const rb_batch_case *c)
{
    if (!c->has_code)
        return cJSON_AddNullToObject(o, "code_static") != NULL;
    cJSON *k = cJSON_AddObjectToObject(o, "code_static");
    return k && rb_j_add_num(k, "fp_n", c->code_fp_n)
        && rb_j_add_num(k, "fp_over_wp", c->code_fp_over_wp)
        && rb_j_add_num(k, "tension_n", c->code_tension_n)
        && rb_j_add_num(k, "steel_ratio", c->code_steel_ratio)
        && rb_j_add_num(k, "anchor_utilization", c->code_anchor_utilization);
}

static int add_case(cJSON *arr, const rb_batch_case *c, const rb_batch_summary *s)
{
    int design = s->design;
    cJSON *o = cJSON_CreateObject();
    if (!o || !cJSON_AddItemToArray(arr, o))
        return cJSON_Delete(o), 0;
    int solved = c->verdict == RB_BATCH_PASS || c->verdict == RB_BATCH_FAIL;
    int ok = rb_j_add_num(o, "index", (double)c->index)
        && rb_j_add_text(o, "source", c->source)
        && rb_j_add_num(o, "line", c->line)
        && rb_j_add_text(o, "tag", c->tag)
        && cJSON_AddStringToObject(o, "verdict", rb_batch_verdict_str(c->verdict))
        && rb_j_add_text(o, "reason", c->reason)
        && add_error(o, c);
    if (!ok)
        return 0;
    if (!solved)
        return cJSON_AddNullToObject(o, "governing_motion") != NULL;
    if (!rb_j_add_text(o, "governing_motion",
                  c->runs[rb_batch_governing(c)].motion))
        return 0;
    cJSON *runs = cJSON_AddArrayToObject(o, "runs");
    for (size_t m = 0; ok && runs && m < c->n_runs; m++)
        ok = add_run(runs, &c->runs[m], design);
    rb_batch_stat mean, max;
    rb_batch_stats(c, &mean, &max);
    return ok && runs && add_stat(o, "mean", &mean, design, 0)
        && add_stat(o, "max", &max, design, 1)
        && add_code(o, c)
        && (!s->fragility || !c->fragility || add_fragility(o, c->fragility));
}

/* "digest": the SHA-256 of the case's object as printed without it
 * (batch_digest.c), so that merge can tell an edited row. */
static int add_digest(cJSON *o)
{
    char d[RB_BATCH_DIGEST_CHARS];
    char *text = rb_json_print(o, 0);
    if (!text)
        return 0;
    rb_batch_digest_text(text, d);
    free(text);
    return cJSON_AddStringToObject(o, "digest", d) != NULL;
}

/* The head with an empty list of cases, which comes last; then the cases
 * one at a time, so that the tree of one case is all that is ever held
 * besides the text (a whole list's tree took 5 KB a row). */
void rb_batch_render_json_head(rb_strbuf *b, const rb_batch_summary *s,
                               const rb_batch_counts *n)
{
    char shard[64];
    cJSON *root = cJSON_CreateObject(), *counts;
    int ok = root && cJSON_AddStringToObject(root, "format", "rockbolt-batch")
        && rb_j_add_num(root, "format_version", RB_BATCH_FORMAT_VERSION)
        && cJSON_AddBoolToObject(root, "design", s->design)
        && rb_j_add_num(root, "total", (double)s->total)
        && (!s->inputs_digest[0]
            || cJSON_AddStringToObject(root, "inputs_digest", s->inputs_digest));
    if (ok && s->n_shards > 0) {
        snprintf(shard, sizeof shard, "%zu/%zu", s->shard, s->n_shards);
        ok = cJSON_AddStringToObject(root, "shard", shard) != NULL;
    }
    if (ok && s->fragility) {
        /* the seed as text: a JSON number keeps 53 bits of its 64 */
        char seed[32];
        cJSON *fr = cJSON_AddObjectToObject(root, "fragility");
        snprintf(seed, sizeof seed, "%llu", (unsigned long long)s->seed);
        ok = fr && cJSON_AddStringToObject(fr, "seed", seed)
            && cJSON_AddStringToObject(fr, "intensity",
                                       rb_enum_str(rb_intensity_report_names,
                                                   (int)s->intensity))
            && rb_j_add_num(fr, "resamples", RB_FRAGILITY_RESAMPLES)
            && rb_j_add_num(fr, "interval", RB_FRAGILITY_INTERVAL);
    }
    ok = ok && (counts = cJSON_AddObjectToObject(root, "counts")) != NULL
        && rb_j_add_num(counts, "cases", (double)n->cases)
        && rb_j_add_num(counts, "passed", (double)n->passed)
        && rb_j_add_num(counts, "failed", (double)n->failed)
        && rb_j_add_num(counts, "unreadable", (double)n->unreadable)
        && rb_j_add_num(counts, "errors", (double)n->errors)
        && rb_j_add_num(counts, "runs", (double)n->runs)
        && cJSON_AddArrayToObject(root, "cases") != NULL;
    char *head = ok ? rb_json_print(root, 1) : NULL;
    cJSON_Delete(root);
    size_t hl = head ? strlen(head) : 0;
    if (!head || hl < 4 || strcmp(head + hl - 4, "[]\n}") != 0)
        b->oom = 1;
    else
        rb_strbuf_putn(b, head, hl - 3);
    free(head);
}

void rb_batch_render_json_case(rb_strbuf *b, const rb_batch_summary *s, const rb_batch_case *c,
                               size_t pos)
{
    cJSON *one = cJSON_CreateArray();
    char *text = one && add_case(one, c, s) && add_digest(one->child)
                 ? rb_json_print(one->child, 1) : NULL;
    cJSON_Delete(one);
    if (!text) {
        b->oom = 1;
        return;
    }
    /* cJSON's own layout of an array item two levels down: ", " between
     * items, each line of the item two tabs further in */
    if (pos > 0)
        rb_strbuf_puts(b, ", ");
    for (const char *p = text, *nl; *p; p = nl + 1) {
        nl = strchr(p, '\n');
        if (!nl) {
            rb_strbuf_puts(b, p);
            break;
        }
        rb_strbuf_putn(b, p, (size_t)(nl - p) + 1);
        rb_strbuf_puts(b, "\t\t");
    }
    free(text);
}

void rb_batch_render_json_tail(rb_strbuf *b, const rb_batch_summary *s,
                               const rb_batch_counts *n)
{
    (void)s, (void)n;
    rb_strbuf_puts(b, "]\n}\n");
}

/* ---- Reading --------------------------------------------------------------- */

typedef struct {
    rb_diag *diag;
    int bad;
} rd_ctx;

static void rd_fail(rd_ctx *r, const char *key, const char *msg)
{
    if (r->bad++)
        return;
    if (r->diag) {
        rb_diag_set_key(r->diag, "%s", key);
        rb_diag_set_msg(r->diag, "%s", msg);
    }
}

static double rd_num(rd_ctx *r, const cJSON *o, const char *k)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, k);
    if (!cJSON_IsNumber(v)) {
        rd_fail(r, k, "expected a number");
        return 0;
    }
    return v->valuedouble;
}

/* A number or null; has = 0 for null. */
static double rd_opt(rd_ctx *r, const cJSON *o, const char *k, int *has)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, k);
    *has = cJSON_IsNumber(v);
    if (!*has && !cJSON_IsNull(v))
        rd_fail(r, k, "expected a number or null");
    return *has ? v->valuedouble : 0;
}

static size_t rd_size(rd_ctx *r, const cJSON *o, const char *k)
{
    double v = rd_num(r, o, k);
    if (!(v >= 0 && v < 9e15) || v != floor(v)) {
        rd_fail(r, k, "expected a whole number >= 0");
        return 0;
    }
    return (size_t)v;
}

/* A line or column: a double past INT_MAX cast to int is undefined (a
 * "line" of 8.9e31 in a summary, found by the merge fuzzer). */
static int rd_int(rd_ctx *r, const cJSON *o, const char *k)
{
    double v = rd_num(r, o, k);
    if (!(v >= 0 && v <= INT_MAX) || v != floor(v)) {
        rd_fail(r, k, "expected a whole number from 0 to 2147483647");
        return 0;
    }
    return (int)v;
}

static char *rd_str(rd_ctx *r, const cJSON *o, const char *k)
{
    const cJSON *v = cJSON_GetObjectItemCaseSensitive(o, k);
    if (!cJSON_IsString(v)) {
        rd_fail(r, k, "expected a string");
        return NULL;
    }
    char *s = rb_batch_strdup(v->valuestring);
    if (!s)
        rd_fail(r, k, "out of memory");
    return s;
}

static void rd_copy(rd_ctx *r, const cJSON *o, const char *k, char *dst, size_t n)
{
    char *s = rd_str(r, o, k);
    snprintf(dst, n, "%s", s ? s : "");
    free(s);
}

static void rd_warnings(rd_ctx *r, const cJSON *o, unsigned *warnings)
{
    const cJSON *a = cJSON_GetObjectItemCaseSensitive(o, "validity_warnings"), *it;
    *warnings = 0;
    if (!cJSON_IsArray(a)) {
        rd_fail(r, "validity_warnings", "expected a list of check names");
        return;
    }
    cJSON_ArrayForEach(it, a) {
        rb_check k;
        if (!cJSON_IsString(it) || !rb_check_parse(it->valuestring, &k)) {
            rd_fail(r, "validity_warnings", "expected lift-off, sliding or bolt impact");
            return;
        }
        *warnings |= 1u << k;
    }
}

/* A number, or NaN for the null that a non-finite one was written as. */
static double rd_num_or_nan(rd_ctx *r, const cJSON *o, const char *k)
{
    int has;
    double v = rd_opt(r, o, k, &has);
    return has ? v : (double)NAN;
}

/* The columns of one group of a run, as add_columns writes them: a number,
 * or null for none. A group the summary does not have is none. */
static void rd_columns(rd_ctx *r, const cJSON *o, rb_batch_result *run, int design)
{
    for (size_t k = 0; k < rb_batch_n_columns; k++) {
        const rb_batch_column *col = &rb_batch_columns[k];
        if (col->design != design)
            continue;
        run->value[k] = rd_num_or_nan(r, o, col->name);
        if (col->bound_of) {
            char key[64];
            snprintf(key, sizeof key, "%s_bound", col->name);
            const cJSON *bound = cJSON_GetObjectItemCaseSensitive(o, key);
            if (cJSON_IsTrue(bound) && isfinite(run->value[k]))
                run->bounds |= 1u << k;
        }
    }
}

static void rd_run(rd_ctx *r, const cJSON *o, rb_batch_result *run, int design)
{
    char *v;
    run->motion = rd_str(r, o, "motion");
    v = rd_str(r, o, "verdict");
    run->pass = v && strcmp(v, "pass") == 0;
    if (v && !run->pass && strcmp(v, "fail") != 0)
        rd_fail(r, "verdict", "expected pass or fail");
    free(v);
    rd_columns(r, o, run, 0);
    run->margin = rd_num(r, o, "margin");
    const cJSON *gv = cJSON_GetObjectItemCaseSensitive(o, "governs");
    int lim = -1;
    for (int k = 0; cJSON_IsString(gv) && k < RB_N_GOVERNS; k++)
        if (strcmp(gv->valuestring, rb_governs_name((rb_governs_limit)k)) == 0)
            lim = k;
    if (lim < 0)
        rd_fail(r, "governs", "expected the name of a limit");
    run->limit = lim < 0 ? 0 : lim;
    run->reason = rd_str(r, o, "reason");
    rd_warnings(r, o, &run->warnings);
    const cJSON *am = cJSON_GetObjectItemCaseSensitive(o, "anchor_mode");
    if (am) {
        run->has_anchor = 1;
        if (!cJSON_IsString(am)
            || !rb_enum_parse(rb_anchor_mode_names, am->valuestring, &run->anchor_mode))
            rd_fail(r, "anchor_mode", "expected a mode of the concrete check");
        run->anchor_utilization = rd_num(r, o, "anchor_utilization");
    }
    if (design)
        rd_columns(r, o, run, 1);
    else
        rb_batch_columns_fill(run, NULL, 1);
}

/* A case's digest must be that of the case as this writer prints it (its
 * numbers in the writer's own shortest form): a row edited by hand (a
 * verdict, a number, a name) no longer matches. dg is the file's digest. */
static void rd_digest(rd_ctx *r, const cJSON *dg, const rb_batch_case *c,
                      const rb_batch_summary *s)
{
    char want[RB_BATCH_DIGEST_CHARS], msg[400];
    cJSON *arr = cJSON_CreateArray();
    char *text = arr && add_case(arr, c, s)
        ? rb_json_print(cJSON_GetArrayItem(arr, 0), 0) : NULL;
    /* counted from 1, as merge's other messages count cases */
    snprintf(msg, sizeof msg, "case %zu (tag '%.100s') ", c->index + 1, c->tag ? c->tag : "?");
    if (!text) {
        rd_fail(r, "digest", "out of memory");
    } else if (!cJSON_IsString(dg)) {
        strncat(msg, "has no digest (written by an older rockbolt, or edited)",
                sizeof msg - strlen(msg) - 1);
        rd_fail(r, "digest", msg);
    } else {
        rb_batch_digest_text(text, want);
        if (strcmp(want, dg->valuestring) != 0) {
            strncat(msg, "does not match its digest: the row was changed after "
                    "rockbolt wrote it", sizeof msg - strlen(msg) - 1);
            rd_fail(r, "digest", msg);
        }
    }
    free(text);
    cJSON_Delete(arr);
}

#define LIMITS_EXPECTED "expected first-yield, usage, overturn, lift-off and, with " \
    "concrete:, anchorage, in that order"

/* Limit state entry e, which must come after limit state *last. */
static void rd_limit(rd_ctx *r, const cJSON *e, int *last, rb_batch_fragility *f)
{
    const cJSON *name = cJSON_GetObjectItemCaseSensitive(e, "limit_state");
    const cJSON *fitted = cJSON_GetObjectItemCaseSensitive(e, "fitted");
    int k = -1;
    if (!cJSON_IsString(name) || !rb_enum_parse(rb_limit_state_names, name->valuestring, &k)
        || k <= *last) {
        rd_fail(r, "limit_state", LIMITS_EXPECTED);
        return;
    }
    *last = k;
    rb_batch_limit *l = &f->limits[k];
    l->present = 1;
    if (!cJSON_IsBool(fitted)) {
        rd_fail(r, "fitted", "expected true or false");
        return;
    }
    l->fitted = cJSON_IsTrue(fitted);
    if (l->fitted) {
        l->median_mps2 = rd_num(r, e, "median_mps2");
        l->beta = rd_num(r, e, "beta");
        l->median_lo_mps2 = rd_num_or_nan(r, e, "median_lo_mps2");
        l->median_hi_mps2 = rd_num_or_nan(r, e, "median_hi_mps2");
        l->p_at_level = rd_num(r, e, "p_at_level");
    }
    l->reached = rd_size(r, e, "reached");
    const cJSON *confirmed = cJSON_GetObjectItemCaseSensitive(e, "confirmed");
    if (!cJSON_IsBool(confirmed)) {
        rd_fail(r, "confirmed", "expected true or false");
        return;
    }
    l->confirmed = cJSON_IsTrue(confirmed);
    l->model_limited = rd_size(r, e, "model_limited");
}

static void rd_fragility(rd_ctx *r, const cJSON *o, rb_batch_case *c)
{
    const cJSON *f = cJSON_GetObjectItemCaseSensitive(o, "fragility"), *e;
    if (!cJSON_IsObject(f)) {
        rd_fail(r, "fragility", "expected an object");
        return;
    }
    if (!(c->fragility = calloc(1, sizeof *c->fragility))) {
        rd_fail(r, "fragility", "out of memory");
        return;
    }
    c->fragility->governing = -1;
    if (cJSON_GetObjectItemCaseSensitive(f, "error")) {
        c->fragility->error = rd_str(r, f, "error");
        return;
    }
    if (cJSON_GetObjectItemCaseSensitive(f, "intensity_freq_hz"))
        c->fragility->im_freq_hz = rd_num(r, f, "intensity_freq_hz");
    c->fragility->g_mps2 = rd_num(r, f, "g_mps2");
    c->fragility->level_mps2 = rd_num(r, f, "level_mps2");
    const cJSON *ls = cJSON_GetObjectItemCaseSensitive(f, "limit_states");
    if (!cJSON_IsArray(ls)) {
        rd_fail(r, "limit_states", "expected a list of the limit states");
        return;
    }
    int last = -1;
    cJSON_ArrayForEach(e, ls)
        rd_limit(r, e, &last, c->fragility);
    /* every case with a fragility has the four; the anchorage's is the
     * only one a case may lack */
    for (int k = 0; k < RB_N_LIMITS; k++)
        if (k != RB_LIMIT_ANCHORAGE && !c->fragility->limits[k].present)
            rd_fail(r, "limit_states", LIMITS_EXPECTED);
    const cJSON *gv = cJSON_GetObjectItemCaseSensitive(f, "governing_limit_state");
    int gk = -1;
    if (!cJSON_IsNull(gv)
        && (!cJSON_IsString(gv) || !rb_enum_parse(rb_limit_state_names, gv->valuestring, &gk)
            || !c->fragility->limits[gk].fitted))
        rd_fail(r, "governing_limit_state", "expected null or the name of a fitted limit "
                "state of the case");
    c->fragility->governing = gk;
}

/* "code_static" (rb_batch_case.has_code): null or absent when the case has
 * no design.code. */
static void rd_code(rd_ctx *r, const cJSON *o, rb_batch_case *c)
{
    const cJSON *k = cJSON_GetObjectItemCaseSensitive(o, "code_static");
    if (!k || cJSON_IsNull(k))
        return;
    if (!cJSON_IsObject(k)) {
        rd_fail(r, "code_static", "expected an object or null");
        return;
    }
    c->has_code = 1;
    c->code_fp_n = rd_num(r, k, "fp_n");
    c->code_fp_over_wp = rd_num(r, k, "fp_over_wp");
    c->code_tension_n = rd_num(r, k, "tension_n");
    c->code_steel_ratio = rd_num(r, k, "steel_ratio");
    c->code_anchor_utilization = rd_num_or_nan(r, k, "anchor_utilization");
}

static void rd_case(rd_ctx *r, const cJSON *o, rb_batch_case *c, const rb_batch_summary *s)
{
    int design = s->design;
    char *v;
    c->index = rd_size(r, o, "index");
    c->source = rd_str(r, o, "source");
    c->line = rd_int(r, o, "line");
    c->tag = rd_str(r, o, "tag");
    c->reason = rd_str(r, o, "reason");
    v = rd_str(r, o, "verdict");
    if (v && !rb_batch_verdict_parse(v, &c->verdict))
        rd_fail(r, "verdict", "expected pass, fail, unreadable or error");
    free(v);
    if (r->bad)
        return;
    if (c->verdict != RB_BATCH_PASS && c->verdict != RB_BATCH_FAIL) {
        const cJSON *e = cJSON_GetObjectItemCaseSensitive(o, "error");
        if (!cJSON_IsObject(e)) {
            rd_fail(r, "error", "expected an object");
            return;
        }
        rb_diag d;
        rb_diag_clear(&d);
        rd_copy(r, e, "file", d.file, sizeof d.file);
        d.line = rd_int(r, e, "line");
        d.col = rd_int(r, e, "col");
        rd_copy(r, e, "key", d.key, sizeof d.key);
        rd_copy(r, e, "message", d.msg, sizeof d.msg);
        if (!rb_batch_case_set_error(c, &d))
            rd_fail(r, "error", "out of memory");
        c->n_errors = rd_size(r, e, "count");
        return;
    }
    const cJSON *runs = cJSON_GetObjectItemCaseSensitive(o, "runs"), *it;
    int n = cJSON_GetArraySize(runs);
    if (!cJSON_IsArray(runs) || n < 1) {
        rd_fail(r, "runs", "expected a list of runs");
        return;
    }
    if (!(c->runs = calloc((size_t)n, sizeof *c->runs))) {
        rd_fail(r, "runs", "out of memory");
        return;
    }
    c->n_runs = (size_t)n;
    size_t m = 0;
    cJSON_ArrayForEach(it, runs)
        rd_run(r, it, &c->runs[m++], design);
    rd_code(r, o, c);
    if (s->fragility)
        rd_fragility(r, o, c);
}

/* "fragility": {"seed": "N", "resamples", "interval"} when it was asked for. */
static void rd_fragility_head(rd_ctx *r, const cJSON *root, rb_batch_summary *out)
{
    const cJSON *f = cJSON_GetObjectItemCaseSensitive(root, "fragility");
    if (!f)
        return;
    const cJSON *seed = cJSON_GetObjectItemCaseSensitive(f, "seed");
    char *end = NULL;
    unsigned long long v = 0;
    if (cJSON_IsString(seed) && seed->valuestring[0] >= '0' && seed->valuestring[0] <= '9') {
        errno = 0;
        v = strtoull(seed->valuestring, &end, 10);
    }
    if (!end || *end || errno) {
        rd_fail(r, "fragility.seed", "expected the seed as a string of digits");
        return;
    }
    if (rd_num(r, f, "resamples") != RB_FRAGILITY_RESAMPLES
        || rd_num(r, f, "interval") != RB_FRAGILITY_INTERVAL) {
        rd_fail(r, "fragility", "another bootstrap (resamples, interval) than this "
                "rockbolt's");
        return;
    }
    /* summaries from before the intensity could be chosen are in pfa */
    const cJSON *im = cJSON_GetObjectItemCaseSensitive(f, "intensity");
    int imv = RB_IM_PFA;
    if (im && (!cJSON_IsString(im)
               || !rb_enum_parse(rb_intensity_report_names, im->valuestring, &imv))) {
        rd_fail(r, "fragility.intensity",
                "expected peak_floor_acceleration or spectral_acceleration");
        return;
    }
    out->fragility = 1;
    out->seed = v;
    out->intensity = (rb_fragility_intensity)imv;
}

rb_status rb_batch_read_json_head(const cJSON *root, rb_batch_summary *out, rb_diag *diag)
{
    rd_ctx r = {diag, 0};
    memset(out, 0, sizeof *out);
    const cJSON *fmt = cJSON_GetObjectItemCaseSensitive(root, "format");
    if (!cJSON_IsString(fmt) || strcmp(fmt->valuestring, "rockbolt-batch") != 0)
        rd_fail(&r, "format", "not a rockbolt batch summary");
    else if (rd_num(&r, root, "format_version") != RB_BATCH_FORMAT_VERSION)
        rd_fail(&r, "format_version", "written by another version of the format");
    out->design = cJSON_IsTrue(cJSON_GetObjectItemCaseSensitive(root, "design"));
    rd_fragility_head(&r, root, out);
    out->total = rd_size(&r, root, "total");
    const cJSON *dg = cJSON_GetObjectItemCaseSensitive(root, "inputs_digest");
    if (!cJSON_IsString(dg) || strlen(dg->valuestring) != RB_BATCH_DIGEST_CHARS - 1)
        rd_fail(&r, "inputs_digest", "expected the digest of the work list "
                "(written by an older rockbolt, or edited)");
    else
        memcpy(out->inputs_digest, dg->valuestring, RB_BATCH_DIGEST_CHARS);
    const cJSON *sh = cJSON_GetObjectItemCaseSensitive(root, "shard");
    if (cJSON_IsString(sh) && sscanf(sh->valuestring, "%zu/%zu", &out->shard,
                                     &out->n_shards) != 2)
        rd_fail(&r, "shard", "expected i/n");
    return r.bad ? RB_ERR_PARSE : RB_OK;
}

rb_status rb_batch_read_json_case(const cJSON *o, const rb_batch_summary *s,
                                  rb_batch_case *c, rb_diag *diag)
{
    rd_ctx r = {diag, 0};
    memset(c, 0, sizeof *c);
    rd_case(&r, o, c, s);
    if (!r.bad)
        rd_digest(&r, cJSON_GetObjectItemCaseSensitive(o, "digest"), c, s);
    if (r.bad) {
        rb_batch_case_free(c);
        return RB_ERR_PARSE;
    }
    return RB_OK;
}
