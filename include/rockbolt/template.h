/* Templates (library rb_report): the text report and the PDF package are
 * template text filled with a case's variables.
 *
 * A template is text with placeholders:
 *   {{name}}              the value of a variable, in its default format
 *   {{name:%8.3f}}        with a printf-style format: optional flags '-' and
 *                         '+', width, precision and one of f e g d s
 *   {{#list}}..{{/list}}  the enclosed text once per item of a list, with
 *                         the item's variables in scope (outer ones still
 *                         visible)
 *   {{! comment }}        nothing
 * A section or comment tag alone on its line removes the whole line. A
 * missing value (RB_TVAL_NONE) or a non-finite number renders as "n/a" in
 * the field width. Unknown names are errors, so a typo in a template cannot
 * silently drop a number. */
#ifndef ROCKBOLT_TEMPLATE_H
#define ROCKBOLT_TEMPLATE_H

#include <stddef.h>
#include "rockbolt/status.h"

typedef enum {
    RB_TVAL_NONE = 0,  /* no value: rendered "n/a" */
    RB_TVAL_NUM,       /* double; default format %g */
    RB_TVAL_INT,       /* long; default format %d */
    RB_TVAL_STR        /* string; default format %s */
} rb_tval_kind;

typedef struct {
    const char *name;  /* borrowed */
    rb_tval_kind kind;
    double num;
    long integer;
    const char *str;   /* borrowed */
} rb_tvar;

typedef struct rb_tscope rb_tscope;

/* A named list: items[i] is the scope of the i-th repetition. */
typedef struct {
    const char *name;        /* borrowed */
    const rb_tscope *items;  /* borrowed array of n */
    size_t n;
} rb_tlist;

/* Variables and lists visible at one level; lookups fall back to parent. */
struct rb_tscope {
    const rb_tvar *vars;
    size_t n_vars;
    const rb_tlist *lists;
    size_t n_lists;
    const rb_tscope *parent; /* set by the renderer for list items */
};

/* Render tmpl with the variables of scope. *out is owned by the caller
 * (free()). Returns RB_ERR_PARSE for a malformed template or an unknown
 * name (diag->line/col point into the template, diag->key names the tag),
 * RB_ERR_NOMEM. *out is NULL on error. */
rb_status rb_template_render(const char *tmpl, const rb_tscope *scope,
                             char **out, rb_diag *diag);

/* The compiled-in copy of a shipped template ("report.txt",
 * "starter.yaml"), or NULL if there is none by that name. Static storage. */
const char *rb_template_builtin(const char *name);

/* Load the template called name: from $RB_TEMPLATE_DIR/name if the variable
 * is set and the file exists, else from the source tree's templates/ when
 * present, else the built-in copy. *text is owned by the caller (free());
 * *origin (may be NULL) gets a static description of where it came from:
 * "RB_TEMPLATE_DIR", "source tree" or "built-in". Returns RB_ERR_IO when
 * a file exists but cannot be read, RB_ERR_INVALID for an unknown name. */
rb_status rb_template_load(const char *name, char **text, const char **origin,
                           rb_diag *diag);

#endif
