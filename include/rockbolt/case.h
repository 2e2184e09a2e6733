/* Case files: the YAML description of one equipment check (library rb_case).
 *
 * rb_case_load parses a case with libyaml, converts every quantity to SI
 * through units.h, validates it, reads the record files it names and builds
 * ready-to-run rb_motion values. Errors name file, line, column and key. */
#ifndef ROCKBOLT_CASE_H
#define ROCKBOLT_CASE_H

#include <stddef.h>
#include "rockbolt/model.h"
#include "rockbolt/motion.h"
#include "rockbolt/solve.h"
#include "rockbolt/criteria.h"
#include "rockbolt/units.h"
#include "rockbolt/anchor.h"
#include "rockbolt/spectrum.h"
#include "rockbolt/synth.h"
#include "rockbolt/names.h"
#include "rockbolt/asce7.h"
#include "rockbolt/design.h"  /* the design settings a case carries */

/* One floor motion of a case, ready for rb_solve_run. For records the
 * samples are already filtered, windowed and scaled to target_peak_mps2 in
 * place, so motion.scale is 1; motion.duration_s is the case's run_time or
 * the record's length. Amplitudes given in A* are already multiplied out. */
/* A motion's `type:` in the case file (rockbolt/names.h
 * rb_case_motion_type_names). */
typedef enum {
    RB_CASE_MOTION_HARMONIC = 0,
    RB_CASE_MOTION_PULSE,
    RB_CASE_MOTION_RECORD,
    RB_CASE_MOTION_SYNTHETIC
} rb_case_motion_type;
extern const rb_enum_name rb_case_motion_type_names[];

/* A target spectrum a case names, shared by the motions made from it,
 * and the laboratory's acceptance of each: rb_accept_rules_init's with the
 * motion's `low_cutoff` and `max_ratio` (docs/case-format.md). */
typedef struct {
    rb_target target;
    rb_target vertical;   /* AC156's vertical, for a triaxial suite */
    char *file;           /* owned: a table's path as resolved, else NULL */
    rb_accept_rules rules, vertical_rules;
} rb_case_target;

typedef struct rb_case_motion {
    rb_case_motion_type type;
    char *name;           /* owned; from the case or the record file name */
    char *source;         /* owned; record path as resolved, or a description */
    rb_series series;     /* owned; used when motion.kind == RB_MOTION_SAMPLED */
    rb_motion motion;     /* motion.series points at series above */
    double target_peak_mps2; /* 0 when the case did not ask for scaling */
    double building_freq_hz, building_damping; /* 0 when no building filter */
    /* synthetic: the target (borrowed from rb_case.targets), the motion's
     * place in its suite and seed, and what the generator made */
    const rb_target *target;
    /* with a target: how its acceptance is judged (borrowed from
     * rb_case.targets, as target); a record, harmonic or pulse has a target
     * only when its `spectrum:` names one, and is judged, not matched */
    const rb_accept_rules *rules;
    unsigned synth_index;
    unsigned long long synth_seed;
    rb_synth_info synth;
    /* `vertical:`: the floor's vertical acceleration, owned, NULL for
     * none; motion.vertical points at its motion. A triaxial set's V is
     * here too (type synthetic, its target the suite's vertical). */
    struct rb_case_motion *vertical;
    /* a triaxial set's H2, out of the model's plane: kept for export, not
     * solved (owned; n == 0 without); its description, and the set's
     * independence: H1-H2, H1-V, H2-V */
    rb_series h2;
    rb_synth_info h2_synth;
    int has_set;
    rb_synth_pair independence[3];
} rb_case_motion;

#define RB_CASE_MAX_SWEEPS 8

/* The most damage states a FEMA P-58 limit state's weights name. */
#define RB_P58_MAX_WEIGHTS 5

/* fragility: the anchorage fragility as a loss tool reads it
 * (`fragility --p58`, docs/fragility.md). */
typedef struct {
    char *p58_id;             /* owned: the row's ID; NULL: the case name */
    double weights[RB_P58_MAX_WEIGHTS]; /* of the anchorage failure's mutually
                                 exclusive damage states, summing to 1 */
    size_t n_weights;         /* 0: FEMA P-58's 0.7 and 0.3 */
} rb_case_fragility_opts;

/* project: who and what the calculation is for, printed on the cover of
 * the PDF calculation package (docs/pdf.md). Each owned, one line of 1 to
 * 200 characters, or NULL when not given. */
typedef struct {
    char *project, *client, *engineer, *checker, *date, *revision, *job_number;
    int given;                /* the section was there */
} rb_case_project;
/* Free the texts of p and set them to NULL. */
void rb_case_project_free(rb_case_project *p);

typedef struct {
    char *path;               /* owned; the file as given */
    char *name;               /* owned; case name (defaults to the file stem) */
    char *description;        /* owned; may be NULL */
    rb_model model;
    rb_solve_opts solve;
    rb_criteria criteria;
    rb_design_opts design;
    rb_sweep_opts sweeps[RB_CASE_MAX_SWEEPS]; /* design.sweeps */
    size_t n_sweeps;
    int has_code;             /* design.code given */
    rb_code_inputs code;
    /* concrete: given (ACI 318-19 Chapter 17, rockbolt/anchor.h): the slab
     * and anchors, and their strengths, computed at load */
    int has_concrete;
    rb_anchor_inputs anchor_in;
    rb_anchor_strength anchor;
    /* with design.code too: the 17.8 utilization of the code-static demand
     * (T and the anchor design force, with Omega_0p) against every mode,
     * steel included, and its clause (rb_aci17_interaction_by) */
    int has_anchor_static;
    double anchor_static_utilization;
    int anchor_static_clause;
    rb_case_fragility_opts fragility; /* fragility: */
    rb_case_project project;  /* project: */
    rb_case_motion *motions;  /* owned array of n_motions (>= 1) */
    size_t n_motions;
    rb_case_target *targets;  /* owned array: the motions' targets */
    size_t n_targets;
    int write_history;        /* analysis.history: true */
    /* The units of the text report and the figures (the JSON report is
     * always SI): RB_UNITS_SI or RB_UNITS_US, from output_units:, else US
     * when more of the case's quantities were written in US customary
     * units than in SI ones (docs/case-format.md, Output units). */
    rb_unit_system output_units;
    /* Every file the load read: the case file, its bases, then the records
     * of the motions, each once, as resolved (the paths diagnostics use).
     * Owned. A caller about to write output files compares them with
     * these, so that no report ever overwrites an input. */
    char **input_files;
    size_t n_input_files;
} rb_case;

/* One diagnostic per problem; a load reports all it finds. */
typedef struct {
    rb_diag *items;  /* owned */
    size_t n, cap;
} rb_diag_list;

void rb_diag_list_free(rb_diag_list *l);
/* A new diagnostic at the end of l, zeroed; NULL when out of memory. */
rb_diag *rb_diag_list_add(rb_diag_list *l);

/* The most bytes of one case file (the case, a base) the loader reads:
 * a larger one is refused before it is read. */
#define RB_CASE_MAX_FILE_BYTES (4u * 1024u * 1024u)

/* Load and validate a case. Returns RB_OK, or RB_ERR_PARSE / RB_ERR_INVALID
 * / RB_ERR_IO with every problem found appended to diags. On error *out is
 * left empty (nothing to free, but rb_case_free is safe).
 * Also RB_ERR_LIMIT (file over 4 MiB, value over 4096 bytes, nesting over
 * 32, extends chain over 8) and RB_ERR_NOMEM. Each diag has file (as given,
 * or a base/record path resolved from it), 1-based line and col (0 when the
 * file itself could not be opened), a non-empty dotted key
 * ("anchorage.yield_stress", "motions[2].peak"; "case" for the file as a
 * whole) and a message; diags are in reading order. The format is in
 * docs/case-format.md. */
rb_status rb_case_load(const char *path, rb_case *out, rb_diag_list *diags);

/* rb_case_load, taking records from cache (may be NULL) and putting there
 * those it had to read: for many cases that share records. Every file the
 * case reads (itself, its bases, records and spectrum tables) must lie in
 * sandbox (rockbolt/sandbox.h; NULL: anywhere, as with rb_case_load). */
struct rb_record_cache;
struct rb_sandbox;
rb_status rb_case_load_cached(const char *path, struct rb_record_cache *cache,
                              const struct rb_sandbox *sandbox, rb_case *out,
                              rb_diag_list *diags);

/* rb_case_load_cached for a case document rockbolt made itself in memory
 * (rb_case_load_overrides), named name in diagnostics: it is not a file,
 * so not held to sandbox (rockbolt/sandbox.h) nor listed among the
 * inputs; the bases and records it names are. */
rb_status rb_case_load_text(const char *name, const char *text, size_t len,
                            struct rb_record_cache *cache,
                            const struct rb_sandbox *sandbox, rb_case *out,
                            rb_diag_list *diags);

/* Free what a case owns; accepts NULL. */
void rb_case_free(rb_case *c);

/* Whether the loader generates synthetic motions (1, the default), or,
 * once it has checked everything a suite takes, gives each motion samples
 * of zero (0), whose sets' independence (AC156 5.2.2.7.3) it does not
 * measure. For the case fuzzer, which tests the loader: a suite takes
 * seconds to generate (27 s for cases/ac156-roof.yaml under the fuzzer's
 * sanitizers), the loader microseconds. Process-wide: set it before any
 * load, not while one runs. */
void rb_case_set_generate(int on);

/* Told as the loader generates a suite's motions: done of total, counting
 * each component it generates (a triaxial set is three; a component the
 * record cache held is not counted), one call at a time from the
 * generating threads. A 1 000-set AC156 suite takes minutes of a core:
 * this is what a terminal's progress line reads. NULL (the default) for
 * none. Process-wide, as rb_case_set_generate: set it around one load,
 * never while loads run side by side (a batch's rows). */
typedef void (*rb_case_generate_progress_fn)(void *ctx, size_t done, size_t total);
void rb_case_set_generate_progress(rb_case_generate_progress_fn fn, void *ctx);

#endif
