/* Building the variable tables a text template sees. */
#include <assert.h>
#include <math.h>
#include <string.h>
#include "report_internal.h"

rb_tvar *rb_tv_add(rb_tvars *t, const char *name, rb_tval_kind kind)
{
    rb_tvar *v;
    assert(t->n < RB_TXT_MAX_VARS);
    v = &t->v[t->n++];
    memset(v, 0, sizeof *v);
    v->name = name;
    v->kind = kind;
    return v;
}

/* A number; NAN (a ratio without a denominator) renders as "n/a". */
void rb_tv_num(rb_tvars *t, const char *name, double x)
{
    rb_tv_add(t, name, isnan(x) ? RB_TVAL_NONE : RB_TVAL_NUM)->num = x;
}

void rb_tv_opt(rb_tvars *t, const char *name, int have, double x)
{
    rb_tv_num(t, name, have ? x : (double)NAN);
}

void rb_tv_int(rb_tvars *t, const char *name, long x)
{
    rb_tv_add(t, name, RB_TVAL_INT)->integer = x;
}

void rb_tv_str(rb_tvars *t, const char *name, const char *s)
{
    rb_tv_add(t, name, s ? RB_TVAL_STR : RB_TVAL_NONE)->str = s;
}

const char *rb_yes_no(int b)
{
    return b ? "yes" : "no";
}
