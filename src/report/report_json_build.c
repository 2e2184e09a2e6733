/* Helpers that build the JSON report's cJSON tree: each call is a no-op
 * once a problem has been met, so builders need not check every call, and
 * the first problem (allocation failure, or a non-finite number with the
 * key it was meant for) is what the report returns. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cjson/cJSON.h>
#include "rockbolt/version.h"
#include "rockbolt/jsonnum.h"
#include "rockbolt/textsafe.h"
#include "report_json_build.h"

void rb_j_oom(rb_jctx *cx, const void *added)
{
    if (!added && cx->st == RB_OK)
        cx->st = RB_ERR_NOMEM;
}

cJSON *rb_j_obj(rb_jctx *cx, cJSON *parent, const char *key)
{
    cJSON *o = cx->st == RB_OK ? cJSON_AddObjectToObject(parent, key) : NULL;
    rb_j_oom(cx, o);
    return o;
}

cJSON *rb_j_arr(rb_jctx *cx, cJSON *parent, const char *key)
{
    cJSON *a = cx->st == RB_OK ? cJSON_AddArrayToObject(parent, key) : NULL;
    rb_j_oom(cx, a);
    return a;
}

void rb_j_append(rb_jctx *cx, cJSON *arr, cJSON *item)
{
    if (cx->st != RB_OK || !arr || !item || !cJSON_AddItemToArray(arr, item)) {
        cJSON_Delete(item);
        if (cx->st == RB_OK)
            cx->st = RB_ERR_NOMEM;
    }
}

cJSON *rb_j_item(rb_jctx *cx, cJSON *arr)
{
    cJSON *o = cx->st == RB_OK ? cJSON_CreateObject() : NULL;
    rb_j_append(cx, arr, o);
    return cx->st == RB_OK ? o : NULL;
}

void rb_j_num(rb_jctx *cx, cJSON *o, const char *key, double v)
{
    if (cx->st != RB_OK)
        return;
    if (!isfinite(v)) {
        cx->st = RB_ERR_NONFINITE;
        snprintf(cx->bad_key, sizeof cx->bad_key, "%s.%s", cx->where, key);
        return;
    }
    char buf[RB_JSONNUM_MAX];
    rb_json_number(v, buf);
    rb_j_oom(cx, cJSON_AddRawToObject(o, key, buf));
}

int rb_j_add_num(cJSON *o, const char *key, double v)
{
    char buf[RB_JSONNUM_MAX];
    rb_json_number_or_null(v, buf);
    return cJSON_AddRawToObject(o, key, buf) != NULL;
}

void rb_j_num_or_null(rb_jctx *cx, cJSON *o, const char *key, double v)
{
    if (cx->st == RB_OK && !rb_j_add_num(o, key, v))
        cx->st = RB_ERR_NOMEM;
}

void rb_j_null(rb_jctx *cx, cJSON *o, const char *key)
{
    if (cx->st == RB_OK)
        rb_j_oom(cx, cJSON_AddNullToObject(o, key));
}

/* A value that may legitimately be absent: written only when have. */
void rb_j_opt(rb_jctx *cx, cJSON *o, const char *key, int have, double v)
{
    if (have)
        rb_j_num(cx, o, key, v);
    else
        rb_j_null(cx, o, key);
}

/* A normalised form: NAN (no denominator) becomes null. */
void rb_j_norm(rb_jctx *cx, cJSON *o, const char *key, double v)
{
    rb_j_opt(cx, o, key, !isnan(v), v);
}

/* theta0 is +infinity when there are no bolts (the plate never meets a
 * bolt head): that is "no such angle", not a bug. */
void rb_j_theta0(rb_jctx *cx, cJSON *o, double v)
{
    rb_j_opt(cx, o, "theta0_rad", !(isinf(v) && v > 0), v);
}

void rb_j_bool(rb_jctx *cx, cJSON *o, const char *key, int v)
{
    if (cx->st == RB_OK)
        rb_j_oom(cx, cJSON_AddBoolToObject(o, key, v != 0));
}

void rb_j_str(rb_jctx *cx, cJSON *o, const char *key, const char *s)
{
    if (cx->st != RB_OK)
        return;
    if (s)
        rb_j_oom(cx, cJSON_AddStringToObject(o, key, s));
    else
        rb_j_null(cx, o, key);
}

cJSON *rb_j_add_text(cJSON *o, const char *key, const char *s)
{
    if (!s)
        s = "";
    if (rb_utf8_invalid_at(s, strlen(s)) == strlen(s))
        return cJSON_AddStringToObject(o, key, s);
    char *t = rb_utf8_fix(s);
    cJSON *r = t ? cJSON_AddStringToObject(o, key, t) : NULL;
    free(t);
    return r;
}

void rb_j_text(rb_jctx *cx, cJSON *o, const char *key, const char *s)
{
    if (cx->st == RB_OK)
        rb_j_oom(cx, rb_j_add_text(o, key, s));
}

static void add_raw(rb_jctx *cx, cJSON *o, const char *key, const char *text)
{
    if (cx->st == RB_OK)
        rb_j_oom(cx, cJSON_AddRawToObject(o, key, text));
}

void rb_j_int(rb_jctx *cx, cJSON *o, const char *key, long long v)
{
    char buf[24];
    snprintf(buf, sizeof buf, "%lld", v);
    add_raw(cx, o, key, buf);
}

void rb_j_uint(rb_jctx *cx, cJSON *o, const char *key, unsigned long long v)
{
    char buf[24];
    snprintf(buf, sizeof buf, "%llu", v);
    add_raw(cx, o, key, buf);
}

void rb_j_nums(rb_jctx *cx, cJSON *o, const char *key, const double *v, size_t n)
{
    cJSON *a = rb_j_arr(cx, o, key);
    char buf[RB_JSONNUM_MAX];
    for (size_t i = 0; i < n && cx->st == RB_OK; i++) {
        rb_json_number_or_null(v[i], buf);
        rb_j_append(cx, a, cJSON_CreateRaw(buf));
    }
}

void rb_j_pair(rb_jctx *cx, cJSON *o, const char *key, const double v[2])
{
    cJSON *p = rb_j_obj(cx, o, key);
    rb_j_num(cx, p, "left", v[RB_LEFT]);
    rb_j_num(cx, p, "right", v[RB_RIGHT]);
}

void rb_j_pair_or_null(rb_jctx *cx, cJSON *o, const char *key, const double v[2])
{
    cJSON *p = rb_j_obj(cx, o, key);
    rb_j_num_or_null(cx, p, "left", v[RB_LEFT]);
    rb_j_num_or_null(cx, p, "right", v[RB_RIGHT]);
}

void rb_j_pair_norm(rb_jctx *cx, cJSON *o, const char *key, const double v[2])
{
    cJSON *p = rb_j_obj(cx, o, key);
    rb_j_norm(cx, p, "left", v[RB_LEFT]);
    rb_j_norm(cx, p, "right", v[RB_RIGHT]);
}

void rb_j_pair_bool(rb_jctx *cx, cJSON *o, const char *key, const int v[2])
{
    cJSON *p = rb_j_obj(cx, o, key);
    rb_j_bool(cx, p, "left", v[RB_LEFT]);
    rb_j_bool(cx, p, "right", v[RB_RIGHT]);
}

/* Times of events per row: null where the event did not happen. */
void rb_j_pair_when(rb_jctx *cx, cJSON *o, const char *key, const int happened[2],
                        const double t[2])
{
    cJSON *p = rb_j_obj(cx, o, key);
    rb_j_opt(cx, p, "left", happened[RB_LEFT], t[RB_LEFT]);
    rb_j_opt(cx, p, "right", happened[RB_RIGHT], t[RB_RIGHT]);
}

