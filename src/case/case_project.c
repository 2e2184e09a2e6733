/* The project: section of a case (docs/case-format.md): who and what a
 * calculation is for, printed in the cover block of the PDF calculation
 * package (`--pdf`, docs/pdf.md). Text only; nothing here is computed. */
#include <stdlib.h>
#include <string.h>
#include "case_internal.h"

/* A cover line holds about this many characters at its font; longer text
 * is not a name or a number but a paragraph pasted into the wrong key. */
#define PROJECT_TEXT_MAX 200

static const char *const project_keys[] = {
    "project", "client", "engineer", "checker", "date", "revision", "job_number", NULL};
const char *const *const rb_case_project_keys = project_keys;

static char **field_of(rb_case_project *p, size_t k)
{
    char **fields[] = {&p->project, &p->client, &p->engineer, &p->checker,
                       &p->date, &p->revision, &p->job_number};
    return fields[k];
}

/* One line of printable text: a line break or a control character would
 * break the cover's layout, and is refused where the user wrote it. */
static int one_line(const char *s)
{
    for (; *s; s++)
        if ((unsigned char)*s < 0x20 || *s == 0x7f)
            return 0;
    return 1;
}

void rb_case_read_project(rb_cctx *c, rb_ynode *map, rb_case *cs)
{
    char key[RB_CASE_KEY_MAX];
    for (size_t k = 0; project_keys[k]; k++) {
        rb_ynode *v = rb_cv_get(c, map, "project", project_keys[k], 0, "");
        char **out = field_of(&cs->project, k);
        rb_case_keypath(key, "project", project_keys[k]);
        if (!v || !rb_cv_string(c, v, key, out))
            continue;
        size_t n = strlen(*out);
        if (n == 0 || n > PROJECT_TEXT_MAX)
            rb_cctx_error(c, v, key, "expected one line of 1 to %d characters (got %zu)",
                          PROJECT_TEXT_MAX, n);
        else if (!one_line(*out))
            rb_cctx_error(c, v, key, "expected one line of text, without line breaks "
                          "or control characters");
    }
    cs->project.given = 1;
    rb_cv_unknown_keys(c, map, "project", project_keys);
}

void rb_case_project_free(rb_case_project *p)
{
    for (size_t k = 0; project_keys[k]; k++) {
        free(*field_of(p, k));
        *field_of(p, k) = NULL;
    }
}
