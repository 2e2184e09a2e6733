/* Freeing a case's design results, whose parts the searches fill. */
#include <stdlib.h>
#include <string.h>
#include "rockbolt/design.h"

void rb_motion_design_free(rb_motion_design *md)
{
    if (!md)
        return;
    rb_gap_result_free(&md->gap);
    for (size_t j = 0; j < md->n_sweeps; j++)
        rb_sweep_free(&md->sweeps[j]);
    free(md->sweeps);
    memset(md, 0, sizeof *md);
}

void rb_case_design_free(rb_case_design *d)
{
    size_t i;
    if (!d)
        return;
    for (i = 0; d->motions && i < d->n_motions; i++)
        rb_motion_design_free(&d->motions[i]);
    free(d->motions);
    for (i = 0; i < d->n_sweeps; i++)
        rb_sweep_free(&d->sweeps[i]);
    free(d->sweeps);
    memset(d, 0, sizeof *d);
}
