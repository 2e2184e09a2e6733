/* What the commands that read one case and write figures and tables from
 * it (fragility, spectrum) share: planning --json, --csv, --svg and --html
 * against the case, and loading the case with its own files added to the
 * plan's inputs, so that no output can replace one. */
#include <stdio.h>
#include "cli.h"
#include "cli_batch.h"

rb_exit rb_cli_plan_case_outputs(const rb_cli_opts *o, rb_outplan *p)
{
    const char *paths[4] = {o->json_path, o->csv_path, o->svg_path, o->html_path};
    static const char *const opts[4] = {"--json", "--csv", "--svg", "--html"};
    rb_diag d;
    rb_diag_clear(&d);
    rb_status st = rb_outplan_add_input(p, o->case_path, &d);
    for (int k = 0; k < 4 && st == RB_OK; k++)
        if (paths[k])
            st = rb_outplan_add(p, opts[k], paths[k], &d);
    return st == RB_OK ? RB_EXIT_PASS : rb_cli_plan_error(st, &d);
}

rb_exit rb_cli_load_case_planned(const rb_cli_opts *o, rb_case *c, rb_outplan *p)
{
    rb_diag_list diags = {0};
    rb_status st = rb_case_load(o->case_path, c, &diags);
    for (size_t i = 0; i < diags.n; i++)
        rb_cli_diag_print(&diags.items[i]);
    if (st != RB_OK && diags.n == 0)
        rb_cli_error(o->case_path, NULL, "cannot load the case: %s", rb_status_str(st));
    rb_diag_list_free(&diags);
    if (st != RB_OK)
        return st == RB_ERR_NOMEM ? RB_EXIT_INTERNAL : RB_EXIT_USAGE;
    /* the records, bases and tables it read are inputs too */
    rb_diag d;
    rb_diag_clear(&d);
    for (size_t i = 0; i < c->n_input_files && st == RB_OK; i++)
        st = rb_outplan_add_input(p, c->input_files[i], &d);
    return st == RB_OK ? RB_EXIT_PASS : rb_cli_plan_error(st, &d);
}
