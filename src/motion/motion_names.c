/* The name tables of the enums of rb_motion (motion.h, spectrum.h, floors.h), each
 * declared beside its enum. */
#include "rockbolt/floors.h"
#include "rockbolt/motion.h"
#include "rockbolt/spectrum.h"

const rb_enum_name rb_target_type_names[] = {
    {"ac156", RB_TARGET_AC156}, {"table", RB_TARGET_TABLE}, {"ieee693", RB_TARGET_IEEE693},
    {"gr63", RB_TARGET_GR63}, {NULL, 0}};
const rb_enum_name rb_ieee693_level_names[] = {
    {"high", RB_IEEE693_HIGH}, {"moderate", RB_IEEE693_MODERATE}, {NULL, 0}};
const rb_enum_name rb_ac156_edition_names[] = {
    {"2010", RB_AC156_2010}, {"2024", RB_AC156_2024}, {NULL, 0}};
const rb_enum_name rb_pulse_shape_names[] = {
    {"rectangular", RB_PULSE_RECT}, {"triangular-decreasing", RB_PULSE_TRI_DEC},
    {"triangular-increasing", RB_PULSE_TRI_INC}, {"half-sine", RB_PULSE_HALF_SINE},
    {NULL, 0}};
const rb_enum_name rb_floor_axis_names[] = {
    {"h1", RB_FLOOR_H1}, {"h2", RB_FLOOR_H2}, {"v", RB_FLOOR_V}, {NULL, 0}};
const rb_enum_name rb_between_names[] = {
    {"linear", RB_BETWEEN_LINEAR}, {"building", RB_BETWEEN_BUILDING},
    {"sampled", RB_BETWEEN_SAMPLED}, {NULL, 0}};
