/* The one name table of each enum that a case file, a report or a list
 * spells out: the case loader parses with it and every report prints with
 * it, so whatever a report writes can be pasted back into a case. Each
 * table lists its names in the order diagnostics offer them and ends with
 * {NULL, 0}. No I/O. */
#ifndef ROCKBOLT_NAMES_H
#define ROCKBOLT_NAMES_H

typedef struct {
    const char *name;
    int value;
} rb_enum_name;

extern const rb_enum_name rb_bolt_model_names[];    /* rb_bolt_model */
extern const rb_enum_name rb_formulation_names[];   /* rb_formulation */
extern const rb_enum_name rb_integrator_names[];    /* rb_integrator */
extern const rb_enum_name rb_criterion_names[];     /* rb_criterion_kind */
extern const rb_enum_name rb_validity_mode_names[]; /* rb_validity_mode */
extern const rb_enum_name rb_confirm_mode_names[];  /* rb_confirm_mode */
extern const rb_enum_name rb_motion_type_names[];   /* rb_motion_kind: harmonic,
                                                       pulse, record (sampled) */
extern const rb_enum_name rb_case_motion_type_names[]; /* rb_case_motion_type (case.h):
                                                       harmonic, pulse, record,
                                                       synthetic */
extern const rb_enum_name rb_axis_names[];          /* rb_axis: h1, h2, v */
extern const rb_enum_name rb_between_names[];       /* rb_between: linear, building, sampled */
extern const rb_enum_name rb_target_type_names[];   /* rb_target_kind: ac156, table */
extern const rb_enum_name rb_ac156_edition_names[]; /* rb_ac156_edition */
extern const rb_enum_name rb_pulse_shape_names[];   /* rb_pulse_shape */
extern const rb_enum_name rb_record_format_names[]; /* rb_record_format */
extern const rb_enum_name rb_anchor_type_names[];   /* rb_anchor_type */
extern const rb_enum_name rb_anchor_threads_names[]; /* rb_anchor_threads */
extern const rb_enum_name rb_anchor_mode_names[];   /* rb_anchor_mode */
extern const rb_enum_name rb_aci17_coef_names[];    /* rb_aci17_coef: si, in-lb */
extern const rb_enum_name rb_seismic_route_names[]; /* rb_seismic_route */
extern const rb_enum_name rb_route_applied_names[]; /* rb_route_applied */
extern const rb_enum_name rb_edge_reinforcement_names[]; /* rb_edge_reinforcement */
extern const rb_enum_name rb_interaction_names[];   /* rb_aci17_interaction_rule */
extern const rb_enum_name rb_limit_state_names[];   /* rb_limit_state (fragility.h) */
extern const rb_enum_name rb_intensity_names[];     /* rb_fragility_intensity: pfa, sa */
/* the same, as the JSON reports spell it: peak_floor_acceleration,
 * spectral_acceleration */
extern const rb_enum_name rb_intensity_report_names[];

/* The name of value in table t; "unknown" when it has none. */
const char *rb_enum_str(const rb_enum_name *t, int value);
/* The value named s: 1 and *value set, or 0. */
int rb_enum_parse(const rb_enum_name *t, const char *s, int *value);

#endif
