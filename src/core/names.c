/* The name tables of the enums of rb_core (model.h, solve.h, criteria.h),
 * each declared beside its enum. */
#include "rockbolt/criteria.h"
#include "rockbolt/model.h"
#include "rockbolt/solve.h"

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
const char *const rb_criterion_titles[RB_N_CRITERIA] = {
    [RB_CRIT_NO_YIELD] = "bolts elastic", [RB_CRIT_NO_BREAK] = "bolts not breaking"};
const rb_enum_name rb_validity_mode_names[] = {
    {"warn", RB_VALIDITY_WARN}, {"fail", RB_VALIDITY_FAIL}, {NULL, 0}};
const rb_enum_name rb_confirm_mode_names[] = {
    {"marginal", RB_CONFIRM_MARGINAL}, {"always", RB_CONFIRM_ALWAYS},
    {"off", RB_CONFIRM_OFF}, {NULL, 0}};
const rb_enum_name rb_seismic_route_names[] = {
    {"auto", RB_ROUTE_AUTO}, {"ductile", RB_ROUTE_DUCTILE},
    {"attachment", RB_ROUTE_ATTACHMENT}, {"omega", RB_ROUTE_OMEGA}, {NULL, 0}};
const rb_enum_name rb_route_applied_names[] = {
    {"none", RB_ROUTE_APPLIED_NONE}, {"exempt", RB_ROUTE_APPLIED_EXEMPT},
    {"ductile", RB_ROUTE_APPLIED_DUCTILE}, {"attachment", RB_ROUTE_APPLIED_ATTACHMENT},
    {"omega", RB_ROUTE_APPLIED_OMEGA}, {"dynamic", RB_ROUTE_APPLIED_DYNAMIC}, {NULL, 0}};
