/* Time-history CSV (--history): the rb_history rows of every motion of a
 * case in one file, for plotting the response against the thesis's
 * figures. One header line; SI units in the column names; the motion's
 * 1-based index first so one file holds all motions. Numbers are written
 * with %.10g: enough digits to re-plot, stable across runs. */
#include <math.h>
#include <stdio.h>
#include "rockbolt/report.h"

static const char *const columns =
    "motion,t_s,accel_mps2,theta_rad,u_m,bolt_force_left_n,bolt_force_right_n,"
    "shear_elastic_n,shear_total_n,energy_left_j,energy_right_j,kinetic_j,"
    "potential_j,strain_j,stage\n";

#define HIST_NUM_COLS 13

static rb_status write_rows(FILE *fp, size_t motion, const rb_history *h,
                            rb_diag *diag)
{
    size_t i;
    int c;
    for (i = 0; i < h->n; i++) {
        const double v[HIST_NUM_COLS] = {
            h->t[i], h->accel[i], h->theta[i], h->u[i], h->bolt_force_left[i],
            h->bolt_force_right[i], h->shear_elastic[i], h->shear_total[i],
            h->energy_left[i], h->energy_right[i], h->kinetic[i],
            h->potential[i], h->strain[i]
        };
        fprintf(fp, "%zu", motion);
        for (c = 0; c < HIST_NUM_COLS; c++) {
            if (!isfinite(v[c])) {
                if (diag) {
                    rb_diag_set_msg(diag, "non-finite value in the history of motion %zu "
                                    "at row %zu (a bug: please report it)", motion, i + 1);
                }
                return RB_ERR_NONFINITE;
            }
            fprintf(fp, ",%.10g", v[c]);
        }
        fprintf(fp, ",%d\n", h->stage[i]);
    }
    return RB_OK;
}

rb_status rb_history_write_csv(FILE *fp, const rb_report *r, rb_diag *diag)
{
    size_t m;
    rb_status st = RB_OK;
    fputs(columns, fp);
    for (m = 0; m < r->n_motions && st == RB_OK; m++) {
        const rb_history *h = r->motions[m].result->history;
        if (h)
            st = write_rows(fp, m + 1, h, diag);
    }
    if (st == RB_OK && ferror(fp)) {
        if (diag)
            rb_diag_set_msg(diag, "cannot write the history");
        st = RB_ERR_IO;
    }
    return st;
}
