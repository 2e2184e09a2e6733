/* The one printer of JSON (rockbolt/jsonprint.h): cJSON's layout, or one
 * laid out for people by an rb_json_layout. Both print strings with cJSON's
 * escapes and then the format characters as escapes. */
#include <stdlib.h>
#include <string.h>
#include "rockbolt/jsonprint.h"
#include "rockbolt/textsafe.h"
#include "util/strbuf.h"

char *rb_json_print(const cJSON *item, int formatted)
{
    char *raw = formatted ? cJSON_Print(item) : cJSON_PrintUnformatted(item);
    char *safe = raw ? rb_json_escape_format(raw) : NULL;
    cJSON_free(raw);
    return safe;
}

static const rb_json_break *break_of(const rb_json_layout *l, int depth, const char *key)
{
    for (size_t i = 0; key && i < l->n_breaks; i++)
        if (l->breaks[i].depth == depth && strcmp(l->breaks[i].key, key) == 0)
            return &l->breaks[i];
    return NULL;
}

/* A scalar as cJSON prints it (a raw value as it was given). */
static void put_scalar(rb_strbuf *b, const cJSON *v)
{
    if (cJSON_IsRaw(v)) {
        rb_strbuf_puts(b, v->valuestring);
        return;
    }
    char *t = cJSON_PrintUnformatted(v);
    if (!t) {
        b->oom = 1;
        return;
    }
    rb_strbuf_puts(b, t);
    cJSON_free(t);
}

static void put_key(rb_strbuf *b, const char *key)
{
    cJSON *k = cJSON_CreateString(key);
    if (!k) {
        b->oom = 1;
        return;
    }
    put_scalar(b, k);
    cJSON_Delete(k);
    rb_strbuf_puts(b, ": ");
}

static void put_value(rb_strbuf *b, const rb_json_layout *l, const cJSON *v, int depth,
                      const rb_json_break *br);

static void put_object(rb_strbuf *b, const rb_json_layout *l, const cJSON *o, int depth)
{
    rb_strbuf_puts(b, "{");
    if (depth == 0)
        rb_strbuf_puts(b, l->open);
    for (const cJSON *m = o->child; m; m = m->next) {
        const rb_json_break *br = break_of(l, depth, m->string);
        if (m != o->child)
            rb_strbuf_puts(b, br && br->before ? br->before : ", ");
        put_key(b, m->string ? m->string : "");
        put_value(b, l, m, depth + 1, br);
    }
    if (depth == 0)
        rb_strbuf_puts(b, l->close);
    rb_strbuf_puts(b, "}");
}

/* depth: of the objects among the value's items; br: the member's break */
static void put_value(rb_strbuf *b, const rb_json_layout *l, const cJSON *v, int depth,
                      const rb_json_break *br)
{
    if (cJSON_IsObject(v)) {
        put_object(b, l, v, depth);
    } else if (cJSON_IsArray(v)) {
        int lines = br && br->items;
        rb_strbuf_puts(b, "[");
        for (const cJSON *it = v->child; it; it = it->next) {
            if (it != v->child)
                rb_strbuf_puts(b, lines ? "," : ", ");
            if (lines)
                rb_strbuf_puts(b, br->items);
            put_value(b, l, it, depth, NULL);
        }
        if (lines && br->close)
            rb_strbuf_puts(b, br->close);
        rb_strbuf_puts(b, "]");
    } else {
        put_scalar(b, v);
    }
}

char *rb_json_print_layout(const cJSON *root, const rb_json_layout *layout)
{
    rb_strbuf b = {0};
    put_object(&b, layout, root, 0);
    rb_strbuf_puts(&b, "\n");
    char *raw = rb_strbuf_take(&b);
    char *safe = raw ? rb_json_escape_format(raw) : NULL;
    free(raw);
    return safe;
}
