/* Model checking and the derived constants of the shear-beam mode.
 *
 * For phi(y) = sin(pi y / 4h) on a beam of height 2h and mass M (thesis
 * eq. 5.3b): M* = M/2, N* = 2M/pi, F* = int m y phi dy = 8 M h / pi^2,
 * K* = M* w^2, C* = 2 xi w M*. I_o of a line mass at the plate centre about
 * a pivot edge is M (4h^2/3 + b^2). Housner's restitution (5.19) is
 * (I_o - 2 M b^2) / I_o. A* (sec. 5.6) is the static floor acceleration that
 * yields one bolt row: (Fy_row l + W b) / (M h). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "rockbolt/model.h"

void rb_model_init(rb_model *m)
{
    memset(m, 0, sizeof *m);
    m->restitution = -1.0;
    m->bolt_model = RB_BOLT_RIGID_PLASTIC;
    m->bolts_per_row = 1;
}

void rb_model_reference(rb_model *m)
{
    rb_model_init(m);
    m->mass_kg = 454.0;
    m->cm_height_m = 0.979;
    m->half_width_m = 0.45;
    m->freq_hz = 5.0;
    m->damping = 0.01;
    m->bolts_per_row = 2;
    m->bolt_area_m2 = 126.7e-6;
    m->yield_stress_pa = 248e6;
    m->toughness_jpm3 = 82700e3;
    m->deformable_length_m = 0.100;
    m->lever_arm_m = 0.78;
    m->gap_m = 0.01 * 0.78;
}

/* A macro so that each message is a literal the compiler checks. */
#define REQUIRE(cond, k, fmt, v) do { if (!(cond)) { if (diag) { \
        rb_diag_set_key(diag, "%s", k); \
        rb_diag_set_msg(diag, fmt, v); } \
        return RB_ERR_INVALID; } } while (0)

static rb_status check_equipment(const rb_model *m, rb_diag *diag)
{
    REQUIRE(isfinite(m->mass_kg) && m->mass_kg > 0, "mass",
            "must be a finite mass > 0 (got %g kg)", m->mass_kg);
    REQUIRE(isfinite(m->cm_height_m) && m->cm_height_m > 0, "cm_height",
            "must be a finite height > 0 (got %g m)", m->cm_height_m);
    REQUIRE(isfinite(m->half_width_m) && m->half_width_m > 0, "half_width",
            "must be a finite width > 0 (got %g m)", m->half_width_m);
    REQUIRE(isfinite(m->inertia_kgm2), "inertia",
            "must be finite (got %g kg m^2)", m->inertia_kgm2);
    REQUIRE(m->inertia_kgm2 <= 0 || m->inertia_kgm2 >= m->mass_kg *
            (m->half_width_m * m->half_width_m + m->cm_height_m * m->cm_height_m) * (1 - 1e-12),
            "inertia", "must be at least M R^2, the point-mass value about the pivot (got "
            "%.4g M R^2)", m->inertia_kgm2 / (m->mass_kg * (m->half_width_m * m->half_width_m
                                                             + m->cm_height_m * m->cm_height_m)));
    REQUIRE(isfinite(m->restitution) && m->restitution <= 1 && m->restitution != 0,
            "restitution", "must be in (0, 1] (got %g)", m->restitution);
    REQUIRE(isfinite(m->gravity_mps2), "gravity", "must be finite (got %g)", m->gravity_mps2);
    if (!m->rigid) {
        REQUIRE(isfinite(m->freq_hz) && m->freq_hz > 0, "frequency",
                "must be a finite frequency > 0 (got %g Hz)", m->freq_hz);
        REQUIRE(m->freq_hz <= 1000, "frequency",
                "must be at most 1000 Hz (got %g Hz)", m->freq_hz);
        REQUIRE(isfinite(m->damping) && m->damping >= 0 && m->damping < 1, "damping",
                "must be in [0, 1) (got %g)", m->damping);
    }
    return RB_OK;
}

static rb_status check_anchorage(const rb_model *m, rb_diag *diag)
{
    double width = 2 * m->half_width_m;
    if (m->bolt_model == RB_BOLT_NONE)
        return RB_OK;
    REQUIRE(m->bolts_per_row >= 1, "bolts_per_row", "must be at least 1 (got %g)",
            (double)m->bolts_per_row);
    REQUIRE(isfinite(m->bolt_area_m2) && m->bolt_area_m2 > 0, "bolt_area",
            "must be a finite area > 0 (got %g m^2)", m->bolt_area_m2);
    REQUIRE(isfinite(m->yield_stress_pa) && m->yield_stress_pa > 0, "yield_stress",
            "must be a finite stress > 0 (got %g Pa)", m->yield_stress_pa);
    REQUIRE(isfinite(m->toughness_jpm3) && m->toughness_jpm3 > 0, "toughness",
            "must be a finite energy density > 0 (got %g J/m^3)", m->toughness_jpm3);
    REQUIRE(isfinite(m->deformable_length_m) && m->deformable_length_m > 0,
            "deformable_length", "must be a finite length > 0 (got %g m)",
            m->deformable_length_m);
    REQUIRE(isfinite(m->elastic_modulus_pa) && m->elastic_modulus_pa >= 0,
            "elastic_modulus", "must be finite and >= 0 (got %g Pa)", m->elastic_modulus_pa);
    REQUIRE(isfinite(m->lever_arm_m) && m->lever_arm_m > m->half_width_m
            && m->lever_arm_m <= width, "lever_arm",
            "must put the bolt on the plate, beyond its centre: b < l <= 2b (got %g m)",
            m->lever_arm_m);
    REQUIRE(isfinite(m->gap_m) && m->gap_m >= 0, "gap",
            "must be a finite gap >= 0 (got %g m)", m->gap_m);
    return RB_OK;
}

rb_status rb_model_derive(const rb_model *m, rb_derived *d, rb_diag *diag)
{
    rb_status st = check_equipment(m, diag);
    if (st == RB_OK)
        st = check_anchorage(m, diag);
    if (st != RB_OK)
        return st;
    memset(d, 0, sizeof *d);
    double M = m->mass_kg, h = m->cm_height_m, b = m->half_width_m;
    d->g = m->gravity_mps2 > 0 ? m->gravity_mps2 : RB_G0;
    d->W = M * d->g;
    d->R = hypot(b, h);
    d->alpha = atan2(b, h);
    d->Io = m->inertia_kgm2 > 0 ? m->inertia_kgm2 : M * (4 * h * h / 3 + b * b);
    d->delta = m->restitution > 0 ? m->restitution : (d->Io - 2 * M * b * b) / d->Io;
    REQUIRE(d->delta > 0, "restitution",
            "Housner's value (I_o - 2 M b^2) / I_o is %g: the plate is too wide for "
            "its height; give a restitution", d->delta);
    if (!m->rigid) {
        d->omega = 2 * M_PI * m->freq_hz;
        d->Mstar = M / 2;
        d->Nstar = 2 * M / M_PI;
        d->Fstar = 8 * M * h / (M_PI * M_PI);
        d->Kstar = d->Mstar * d->omega * d->omega;
        d->Cstar = 2 * m->damping * d->omega * d->Mstar;
    }
    d->a_uplift_mps2 = d->W * b / (M * h);
    d->theta0_rad = HUGE_VAL;
    if (m->bolt_model != RB_BOLT_NONE) {
        double E = m->elastic_modulus_pa > 0 ? m->elastic_modulus_pa : 200e9;
        double l = m->lever_arm_m;
        d->fy_row_n = m->bolts_per_row * m->bolt_area_m2 * m->yield_stress_pa;
        d->capacity_j = m->toughness_jpm3 * m->bolts_per_row * m->bolt_area_m2
                        * m->deformable_length_m;
        d->k_row_npm = m->bolts_per_row * E * m->bolt_area_m2 / m->deformable_length_m;
        d->a_star_mps2 = (d->fy_row_n * l + d->W * b) / (M * h);
        REQUIRE(m->gap_m < 2 * l, "gap", "is larger than the chord the plate can open "
                "(gap %g m >= 2 l)", m->gap_m);
        d->theta0_rad = 2 * asin(m->gap_m / (2 * l));
        REQUIRE(d->theta0_rad < d->alpha, "gap",
                "lets the plate rotate past the overturning angle alpha before it meets "
                "the bolts (gap %g m)", m->gap_m);
    }
    return RB_OK;
}
