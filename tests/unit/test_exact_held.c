/* The bounds that let a plate held by a rigid row (stage 4) take exact
 * steps with no check points (docs/solver.md, "Exact steps of a held
 * plate"). A range short of what the step reaches would let a yield, a
 * slack row or a new peak pass unseen inside a step: each must hold at
 * every instant of the step.
 *
 * Over random cabinets (both formulations that step exactly), buildings,
 * held angles (0-0.1 rad, either side), step lengths (0.5-40 ms) and
 * start states, the ranges of the row force, the |shear|, the floor's
 * reaction and |U| are held against the quantities at 4001 instants of
 * the step, computed here from the held stage's physics in the plain
 * frame: the state from the exponential (over the instants' spacing) of
 *     M* U'' = N* c x + s N* g sn - K* U - C* U'
 * (with the building and the ground line, and 1 as a state for the
 * constant), the row force from the moment equation (5.13) and the
 * reactions from Newton's law on the still plate, not from the scaled
 * frame and the forms the steps read. The ranges are also held to be of
 * use: within a few times the force's own swing, on median. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "floor_step_draw.h"
#include "../../src/motion/matexp.h"

static unsigned long long rng_state = 20261129;

enum { K = 4000, CASES = 400, NW = 7 };

int main(void)
{
    rb_series raw = {0};
    if (!floor_draw_record(&raw)) {
        CHECK(0);
        TEST_MAIN_END();
    }
    double width[CASES];
    int n_width = 0, probed = 0;
    double worst = -HUGE_VAL;
    for (int c = 0; c < CASES; c++) {
        floor_draw f;
        if (!floor_draw_case(c, &raw, &rng_state, &f)) {
            CHECK(0);
            break;
        }
        f.m.bolt_model = RB_BOLT_RIGID_PLASTIC;
        CHECK(rb_model_derive(&f.m, &f.d, NULL) == RB_OK);
        int small = f.o.formulation == RB_FORM_SMALL;
        double h = exp(draw_uniform(&rng_state, log(5e-4), log(0.04)));
        int side = draw_uniform(&rng_state, 0, 1) < 0.5 ? -1 : 1;
        double th = draw_uniform(&rng_state, 0, 1) < 0.1 ? 0 : draw_uniform(&rng_state, 0, 0.1);
        double z0[RB_EXACT_DIM];
        floor_draw_state(&rng_state, z0);
        const rb_derived *d = &f.d;
        double c_th = small ? 1 : cos(th), sn = small ? th : sin(th), s = side;
        double us = s * d->Nstar * d->g * sn / d->Kstar;
        double uv[2] = {us + z0[0], z0[1]}, range[RB_HELD_N];
        if (!rb_exact_probe_held(&f.m, &f.mo, &f.o, h, side, th, uv, z0 + 2, range)) {
            rb_series_free(&f.s);
            continue;
        }
        probed++;
        /* the plain frame: w = (U, U', u_b, v_b, g, slope, 1) */
        double A[NW][NW] = {{0}}, At[NW][NW], E[NW][NW];
        double fx[NW] = {0};
        if (f.wb > 0) {
            fx[2] = -f.wb * f.wb;
            fx[3] = -2 * f.xib * f.wb;
        } else
            fx[4] = 1;
        A[0][1] = 1;
        for (int j = 0; j < NW; j++)
            A[1][j] = d->Nstar * c_th * fx[j] / d->Mstar;
        A[1][0] -= d->Kstar / d->Mstar;
        A[1][1] -= d->Cstar / d->Mstar;
        A[1][6] += s * d->Nstar * d->g * sn / d->Mstar;
        if (f.wb > 0) {
            A[2][3] = 1;
            A[3][2] = -f.wb * f.wb;
            A[3][3] = -2 * f.xib * f.wb;
            A[3][4] = -1;
        }
        A[4][5] = 1;
        double w0[NW] = {uv[0], uv[1], z0[2], z0[3], z0[4], z0[5], 1};
        double M = f.m.mass_kg, b = f.m.half_width_m, hh = f.m.cm_height_m, W = d->W;
        double cs = th == 0 ? 1 : cos(th), sns = th == 0 ? 0 : sin(th);
        double lever = small ? f.m.lever_arm_m : f.m.lever_arm_m * cos(th / 2);
        double f_least = HUGE_VAL, f_most = -HUGE_VAL;
        /* the state at each instant from the last, by the exponential of
         * the instants' spacing */
        for (int i = 0; i < NW; i++)
            for (int j = 0; j < NW; j++)
                At[i][j] = A[i][j] * h / K;
        rb_matexp(NW, &At[0][0], &E[0][0]);
        double w[NW];
        for (int k = 0; k <= K; k++) {
            if (k == 0)
                memcpy(w, w0, sizeof w);
            else {
                double v[NW] = {0};
                for (int i = 0; i < NW; i++)
                    for (int j = 0; j < NW; j++)
                        v[i] += E[i][j] * w[j];
                memcpy(w, v, sizeof w);
            }
            double x = 0, udd = 0;
            for (int j = 0; j < NW; j++) {
                x += fx[j] * w[j];
                udd += A[1][j] * w[j];
            }
            /* mirrored: the plate rocks about the edge on side s */
            double xm = s * x, uddm = s * udd;
            double Qth = small ? xm * M * d->R - W * d->R * (d->alpha - th)
                               : xm * M * (hh * cs + b * sns) - W * (b * cs - hh * sns);
            double F = (Qth - d->Fstar * uddm) / lever;
            double H = -M * x + cs * d->Nstar * udd;
            double fv = W - sns * d->Nstar * uddm + F;
            f_least = fmin(f_least, F);
            f_most = fmax(f_most, F);
            double q[4] = {range[RB_HELD_F_LO] - F, F - range[RB_HELD_F_HI],
                           fabs(H) - range[RB_HELD_SHEAR_HI], range[RB_HELD_FLOOR_LO] - fv};
            double size[4] = {fabs(F), fabs(F), fabs(H), fabs(fv)};
            for (int i = 0; i < 4; i++) {
                double over = q[i] / (size[i] + 1e-300);
                worst = fmax(worst, over);
                if (over > 1e-9) {
                    if (rb_test_failures < 5)
                        printf("case %d quantity %d at tau %.6g of %.6g: %.17g past its range\n",
                               c, i, h * k / K, h, q[i]);
                    CHECK(0);
                }
            }
            if (fabs(w[0]) > range[RB_HELD_U_HI] * (1 + 1e-9)) {
                if (rb_test_failures < 5)
                    printf("case %d: |U| %.17g over %.17g\n", c, fabs(w[0]),
                           range[RB_HELD_U_HI]);
                CHECK(0);
            }
        }
        if (f_most > f_least)
            width[n_width++] = (range[RB_HELD_F_HI] - range[RB_HELD_F_LO]) / (f_most - f_least);
        rb_series_free(&f.s);
    }
    rb_series_free(&raw);
    printf("%d of %d random held steps bounded; the nearest to a range: %.3g of the "
           "quantity past it (negative: inside; at most 1e-9 allowed)\n", probed, CASES, worst);
    CHECK(probed >= CASES * 9 / 10);
    if (n_width) {
        qsort(width, (size_t)n_width, sizeof *width, draw_cmp);
        printf("  the force's range over its swing: median %.3f, 90th percentile %.3f\n",
               width[n_width / 2], width[n_width * 9 / 10]);
        CHECK(width[n_width / 2] >= 1 && width[n_width / 2] < 5);
    }
    TEST_MAIN_END();
}
