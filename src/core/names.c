/* The name tables of include/rockbolt/names.h. */
#include <string.h>
#include "rockbolt/criteria.h"
#include "rockbolt/floors.h"
#include "rockbolt/model.h"
#include "rockbolt/motion.h"
#include "rockbolt/names.h"
#include "rockbolt/anchor.h"
#include "rockbolt/fragility.h"
#include "rockbolt/record.h"
#include "rockbolt/solve.h"
#include "rockbolt/spectrum.h"

const rb_enum_name rb_bolt_model_names[] = {
    {"rigid-plastic", RB_BOLT_RIGID_PLASTIC}, {"non-yielding", RB_BOLT_NONYIELDING},
    {"elastic-plastic", RB_BOLT_ELASTIC_PLASTIC}, {"none", RB_BOLT_NONE}, {NULL, 0}};
const rb_enum_name rb_formulation_names[] = {
    {"large", RB_FORM_LARGE}, {"small", RB_FORM_SMALL},
    {"consistent", RB_FORM_CONSISTENT}, {NULL, 0}};
const rb_enum_name rb_integrator_names[] = {
    {"auto", RB_INTEGRATOR_AUTO}, {"rk45", RB_INTEGRATOR_RK45}, {NULL, 0}};
const rb_enum_name rb_criterion_names[] = {
    {"no-yield", RB_CRIT_NO_YIELD}, {"no-break", RB_CRIT_NO_BREAK}, {NULL, 0}};
const rb_enum_name rb_validity_mode_names[] = {
    {"warn", RB_VALIDITY_WARN}, {"fail", RB_VALIDITY_FAIL}, {NULL, 0}};
const rb_enum_name rb_confirm_mode_names[] = {
    {"marginal", RB_CONFIRM_MARGINAL}, {"always", RB_CONFIRM_ALWAYS},
    {"off", RB_CONFIRM_OFF}, {NULL, 0}};
/* the critical excitation of chapter 3 has no case type: tests build it */
const rb_enum_name rb_motion_type_names[] = {
    {"harmonic", RB_MOTION_HARMONIC}, {"pulse", RB_MOTION_PULSE},
    {"record", RB_MOTION_SAMPLED}, {"critical", RB_MOTION_CRITICAL}, {NULL, 0}};
const rb_enum_name rb_case_motion_type_names[] = {
    {"harmonic", 0}, {"pulse", 1}, {"record", 2}, {"synthetic", 3}, {NULL, 0}};
const rb_enum_name rb_axis_names[] = {
    {"h1", RB_AXIS_H1}, {"h2", RB_AXIS_H2}, {"v", RB_AXIS_V}, {NULL, 0}};
const rb_enum_name rb_between_names[] = {
    {"linear", RB_BETWEEN_LINEAR}, {"building", RB_BETWEEN_BUILDING},
    {"sampled", RB_BETWEEN_SAMPLED}, {NULL, 0}};
const rb_enum_name rb_target_type_names[] = {
    {"ac156", RB_TARGET_AC156}, {"table", RB_TARGET_TABLE}, {NULL, 0}};
const rb_enum_name rb_ac156_edition_names[] = {
    {"2010", RB_AC156_2010}, {"2024", RB_AC156_2024}, {NULL, 0}};
const rb_enum_name rb_pulse_shape_names[] = {
    {"rectangular", RB_PULSE_RECT}, {"triangular-decreasing", RB_PULSE_TRI_DEC},
    {"triangular-increasing", RB_PULSE_TRI_INC}, {"half-sine", RB_PULSE_HALF_SINE},
    {NULL, 0}};

const rb_enum_name rb_record_format_names[] = {
    {"auto", RB_REC_AUTO}, {"at2", RB_REC_AT2}, {"cosmos", RB_REC_COSMOS_V2},
    {"two-column", RB_REC_TWO_COLUMN}, {"one-column", RB_REC_ONE_COLUMN}, {NULL, 0}};

const rb_enum_name rb_anchor_type_names[] = {
    {"cast-in-headed", RB_ANCHOR_CAST_IN_HEADED}, {"expansion", RB_ANCHOR_EXPANSION},
    {"expansion-displacement", RB_ANCHOR_EXPANSION_DISPLACEMENT}, {"screw", RB_ANCHOR_SCREW},
    {"undercut", RB_ANCHOR_UNDERCUT}, {"adhesive", RB_ANCHOR_ADHESIVE}, {NULL, 0}};

const rb_enum_name rb_anchor_threads_names[] = {
    {"partial", RB_THREADS_PARTIAL}, {"full-length", RB_THREADS_FULL_LENGTH},
    {"upset", RB_THREADS_UPSET}, {NULL, 0}};

const rb_enum_name rb_anchor_mode_names[] = {
    {"steel-tension", RB_ANCHOR_STEEL_N}, {"breakout-tension", RB_ANCHOR_BREAKOUT_N},
    {"pullout", RB_ANCHOR_PULLOUT_N}, {"side-face-blowout", RB_ANCHOR_SIDEFACE_N},
    {"bond", RB_ANCHOR_BOND_N}, {"steel-shear", RB_ANCHOR_STEEL_V}, {"breakout-shear", RB_ANCHOR_BREAKOUT_V},
    {"pryout", RB_ANCHOR_PRYOUT_V}, {NULL, 0}};

const rb_enum_name rb_aci17_coef_names[] = {
    {"si", RB_ACI17_SI}, {"in-lb", RB_ACI17_INLB}, {NULL, 0}};

const rb_enum_name rb_seismic_route_names[] = {
    {"auto", RB_ROUTE_AUTO}, {"ductile", RB_ROUTE_DUCTILE},
    {"attachment", RB_ROUTE_ATTACHMENT}, {"omega", RB_ROUTE_OMEGA}, {NULL, 0}};

const rb_enum_name rb_route_applied_names[] = {
    {"none", RB_ROUTE_APPLIED_NONE}, {"exempt", RB_ROUTE_APPLIED_EXEMPT},
    {"ductile", RB_ROUTE_APPLIED_DUCTILE}, {"attachment", RB_ROUTE_APPLIED_ATTACHMENT},
    {"omega", RB_ROUTE_APPLIED_OMEGA}, {"dynamic", RB_ROUTE_APPLIED_DYNAMIC}, {NULL, 0}};

const rb_enum_name rb_edge_reinforcement_names[] = {
    {"none", RB_EDGE_REINF_NONE}, {"bar", RB_EDGE_REINF_BAR},
    {"bar-and-stirrups", RB_EDGE_REINF_BAR_STIRRUPS}, {NULL, 0}};

const rb_enum_name rb_interaction_names[] = {
    {"trilinear", RB_ACI17_TRILINEAR}, {"power", RB_ACI17_POWER}, {NULL, 0}};


const rb_enum_name rb_intensity_names[] = {
    {"pfa", RB_IM_PFA}, {"sa", RB_IM_SA}, {NULL, 0}};
const rb_enum_name rb_intensity_report_names[] = {
    {"peak_floor_acceleration", RB_IM_PFA}, {"spectral_acceleration", RB_IM_SA},
    {NULL, 0}};
const rb_enum_name rb_limit_state_names[] = {
    {"first-yield", RB_LIMIT_FIRST_YIELD}, {"usage", RB_LIMIT_USAGE},
    {"overturn", RB_LIMIT_OVERTURN}, {"lift-off", RB_LIMIT_LIFT_OFF},
    {"anchorage", RB_LIMIT_ANCHORAGE}, {NULL, 0}};

const char *rb_enum_str(const rb_enum_name *t, int value)
{
    for (; t->name; t++)
        if (t->value == value)
            return t->name;
    return "unknown";
}

int rb_enum_parse(const rb_enum_name *t, const char *s, int *value)
{
    for (; t->name; t++)
        if (strcmp(t->name, s) == 0) {
            *value = t->value;
            return 1;
        }
    return 0;
}
