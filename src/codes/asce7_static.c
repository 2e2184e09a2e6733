/* The code-static comparison: the component force of ASCE 7-16 sec. 13.3.1
 * or ASCE 7-22 eq. 13.3-1, applied at the centre of mass, turned into the
 * tension of the far bolt row by the same overturning equilibrium that
 * defines A*, and compared with the ACI 318-19 design steel strength of the
 * row in tension. docs/design.md gives the clauses. */
#include <math.h>
#include <string.h>
#include "rockbolt/asce7.h"
#include "rockbolt/spectrum.h"

/* ACI 318-19 17.6.1.2: futa is taken as at most 1.9 fya and 125 ksi. */
#define RB_FUTA_CAP_PA 861.8e6
/* ACI 318-19 17.5.3: phi for a ductile steel element in tension. */
#define RB_PHI_STEEL_TENSION 0.75

void rb_code_inputs_init(rb_code_inputs *in)
{
    memset(in, 0, sizeof *in);
    in->edition = RB_ASCE7_22;
    in->ip = 1.0;
    in->anchorage_in_concrete = 1;
    in->omega0p = 2.0;
}

static int bad(double v, double lo)
{
    return !isfinite(v) || !(v > lo);
}

static rb_status check_inputs(const rb_model *m, const rb_code_inputs *in, rb_diag *diag)
{
    const char *key = NULL;
    if (in->edition != RB_ASCE7_16 && in->edition != RB_ASCE7_22)
        key = "edition";
    else if (bad(in->sds, 0))
        key = "sds";
    else if (bad(in->ip, 0))
        key = "ip";
    else if (!(in->z_over_h >= 0 && in->z_over_h <= 1))
        key = "z_over_h";
    else if (in->edition == RB_ASCE7_16 && bad(in->ap, 0))
        key = "ap";
    else if (in->edition == RB_ASCE7_16 && bad(in->rp, 0))
        key = "rp";
    else if (in->edition == RB_ASCE7_22 && bad(in->car, 0))
        key = "car";
    else if (in->edition == RB_ASCE7_22 && bad(in->rpo, 0))
        key = "rpo";
    else if (in->edition == RB_ASCE7_22 && !in->at_or_below_grade
             && (bad(in->r, 0) || bad(in->ie, 0) || bad(in->omega0, 0)))
        key = "r, ie, omega0";
    else if (in->anchorage_in_concrete && bad(in->omega0p, 0))
        key = "omega0p";
    else if (bad(in->futa_pa, 0))
        key = "futa";
    else if (m->bolt_model == RB_BOLT_NONE || m->bolts_per_row < 1)
        key = "anchorage";
    else if (!(in->ase_m2 > 0) && bad(m->bolt_area_m2, 0))
        key = "ase";
    if (!key)
        return RB_OK;
    return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, key,
                       "missing or out of range for the code-static comparison");
}

/* ASCE 7-22 sec. 13.3.1.1 and 13.3.1.2: Hf and Rmu, one rule with the
 * AC156-24 spectrum's (rockbolt/spectrum.h). */
static double hf_7_22(const rb_code_inputs *in)
{
    return rb_asce722_hf(in->z_over_h, in->ta_s, in->at_or_below_grade);
}

static double rmu_7_22(const rb_code_inputs *in)
{
    return rb_asce722_rmu(in->r, in->ie, in->omega0, in->at_or_below_grade);
}

/* Fp from eq. 13.3-1 and its bounds (13.3-2, 13.3-3), both editions. */
static void component_force(const rb_code_inputs *in, double wp, rb_code_result *out)
{
    if (in->edition == RB_ASCE7_16) {
        out->hf = 1.0 + 2.0 * in->z_over_h;
        out->rmu = 1.0;
        out->fp_formula_n = 0.4 * in->ap * in->sds * wp * out->hf / (in->rp / in->ip);
    } else {
        out->hf = hf_7_22(in);
        out->rmu = rmu_7_22(in);
        out->fp_formula_n = 0.4 * in->sds * in->ip * wp * (out->hf / out->rmu)
                            * (in->car / in->rpo);
    }
    out->fp_max_n = 1.6 * in->sds * in->ip * wp;
    out->fp_min_n = 0.3 * in->sds * in->ip * wp;
    out->fp_n = out->fp_formula_n;
    out->bound = 0;
    if (out->fp_n > out->fp_max_n)
        out->fp_n = out->fp_max_n, out->bound = 1;
    else if (out->fp_n < out->fp_min_n)
        out->fp_n = out->fp_min_n, out->bound = -1;
}

rb_status rb_code_static(const rb_model *model, const rb_code_inputs *in,
                         rb_code_result *out, rb_diag *diag)
{
    rb_derived d;
    rb_status st;
    memset(out, 0, sizeof *out);
    if (!model || !in)
        return rb_diag_set(diag, RB_ERR_INVALID, NULL, 0, 0, "", "missing model or code inputs");
    if ((st = rb_model_derive(model, &d, diag)) != RB_OK
        || (st = check_inputs(model, in, diag)) != RB_OK)
        return st;
    component_force(in, d.W, out);
    out->fp_anchor_n = out->fp_n * (in->anchorage_in_concrete ? in->omega0p : 1.0);
    out->fp_over_wp = out->fp_n / d.W;
    out->accel_mps2 = out->fp_over_wp * d.g;
    out->a_star_mps2 = d.a_star_mps2;
    out->accel_astar = out->accel_mps2 / d.a_star_mps2;
    /* overturning about the plate edge, resisted by (0.9 - 0.2 SDS) D */
    out->tension_raw_n = (out->fp_anchor_n * model->cm_height_m
                          - (0.9 - 0.2 * in->sds) * d.W * model->half_width_m)
                         / model->lever_arm_m;
    out->tension_n = fmax(0.0, out->tension_raw_n);
    double ase = in->ase_m2 > 0 ? in->ase_m2 : model->bolt_area_m2;
    out->futa_used_pa = fmin(in->futa_pa, fmin(1.9 * model->yield_stress_pa, RB_FUTA_CAP_PA));
    out->phi_nsa_n = RB_PHI_STEEL_TENSION * model->bolts_per_row * ase * out->futa_used_pa;
    out->ratio = out->tension_n / out->phi_nsa_n;
    return RB_OK;
}
