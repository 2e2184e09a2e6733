/* "rockbolt init [FILE] [--ac156]": write the commented starter case (the
 * shipped templates/starter.yaml or, with --ac156, templates/ac156.yaml,
 * or their compiled-in copies) so a new user starts from a file that runs. An existing file is never replaced: the write
 * links a finished temporary file into place, which fails if the name is
 * taken. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "cli.h"
#include "rockbolt/outfile.h"
#include "rockbolt/template.h"

rb_exit rb_cli_init_run(const rb_cli_opts *o)
{
    char *text = NULL;
    rb_diag d;
    rb_status st;
    rb_diag_clear(&d);
    st = rb_outfile_check(o->init_path, &d);
    if (st == RB_OK)
        st = rb_template_load(o->init_ac156 ? "ac156.yaml" : "starter.yaml", &text, NULL,
                              &d);
    if (st != RB_OK) {
        rb_cli_diag_print(&d);
        return st == RB_ERR_IO ? RB_EXIT_USAGE : RB_EXIT_INTERNAL;
    }
    st = rb_outfile_write_all(o->init_path, text, strlen(text), 1, &d);
    free(text);
    if (st != RB_OK) {
        rb_cli_diag_print(&d);
        return st == RB_ERR_IO ? RB_EXIT_USAGE : RB_EXIT_INTERNAL;
    }
    if (!o->quiet)
        printf("wrote %s; edit it, then run: rockbolt check %s\n",
               o->init_path, o->init_path);
    return RB_EXIT_PASS;
}
