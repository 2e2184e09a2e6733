/* Private interface between the case_*.c files of the case loader.
 *
 * Loading a case goes: case_yaml.c reads each file into a small tree of
 * nodes that keep their file and 1-based line/column (libyaml marks), with
 * hostile-input limits; case_extends.c follows `extends:` and deep-merges
 * the base trees; case_schema.c and case_motion.c walk the merged tree and
 * fill the rb_case, reporting every problem against the node it came from;
 * case_validate.c runs the physics checks of rb_model_derive, resolves A*
 * and reads, filters and scales the records. case.c ties them together and
 * owns the diagnostics. Nodes are owned by their parent; the loader owns the
 * root and the list of file names the nodes point into. */
#ifndef RB_CASE_INTERNAL_H
#define RB_CASE_INTERNAL_H

#include <stddef.h>
#include "rockbolt/names.h"
#include "rockbolt/case.h"
#include "rockbolt/record.h"
#include "rockbolt/record_cache.h"
#include "rockbolt/sandbox.h"
#include "rockbolt/units.h"

#define RB_CASE_MAX_DEPTH 32         /* nesting of mappings and sequences */
#define RB_CASE_MAX_SCALAR 4096      /* bytes in one scalar */
#define RB_CASE_MAX_EXTENDS 8        /* files in one extends chain */
#define RB_CASE_MAX_FILES 64         /* files read for one case */
#define RB_CASE_MAX_MOTIONS 1000
#define RB_CASE_KEY_MAX 128          /* sizeof rb_diag.key */
/* Bounds that keep a hostile case cheap; none is near a real case. A 4 MiB
 * file of "1," would otherwise make 2 million nodes (over 200 MB), and one
 * mapping of 200 000 keys took minutes, since duplicate keys are found by
 * a linear search. The largest real case (1000 motions) has ~30 000 nodes. */
#define RB_CASE_MAX_NODES 100000     /* keys, values and lists in one load */
#define RB_CASE_MAX_KEYS 1024        /* keys in one mapping */
/* Diagnostics kept per load; a case with thousands of errors gets the
 * first ones and a count, and sorting them stays cheap. */
#define RB_CASE_MAX_DIAGS 200
/* Samples in all the records of one case together: the reader's own cap
 * is per file, and 1000 motions may name the same large record. */
#define RB_CASE_MAX_SAMPLES 10000000u
/* Bytes of record files read for one case together, as large as one
 * record file may be: a record named by many motions is read once (the
 * record cache), but motions that read one file with other options (units,
 * format) read it again, and 20 reads of a 260 MB record took 160 s. */
#define RB_CASE_MAX_RECORD_BYTES (256ull * 1024 * 1024)
/* design.resolution, relative to max(1 A*, scan_end): doubles near 1 are
 * 2.2e-16 apart, so 1e-9 leaves the bisection seven digits to spare. */
#define RB_DESIGN_MIN_RESOLUTION 1e-9
/* Ranges narrowed to what the solver takes (docs/robustness.md, "Limits
 * of the model's inputs"): outside them runs overflowed, underflowed or
 * chattered and stopped with exit 3, some only when a report was asked. */
#define RB_CASE_MIN_FREQ_HZ 0.1          /* equipment.frequency */
#define RB_CASE_MIN_BOLT_LENGTH_M 1e-3   /* anchorage.deformable_length */
#define RB_CASE_MAX_BOLT_LENGTH_M 10.0
#define RB_CASE_MIN_GAP_RATIO 1e-9       /* a gap is 0 or this much of l */
#define RB_CASE_MIN_TOLERANCE 1e-13      /* what double precision can meet */
#define RB_CASE_MIN_REST_FRACTION 1e-12  /* analysis.rest_fraction's range */
#define RB_CASE_MAX_REST_FRACTION 1e-3
#define RB_CASE_MIN_TIME_S 1e-3          /* durations, run times, ramps */
#define RB_CASE_MIN_RECORD_PEAK 1e-6     /* m/s^2: a record scaled to `peak` */
#define RB_CASE_MIN_MASS_KG 1.0          /* equipment.mass */
#define RB_CASE_MAX_MASS_KG 1e9
#define RB_CASE_MIN_YIELD_PA 1e6         /* anchorage.yield_stress */
#define RB_CASE_MAX_YIELD_PA 1e10
#define RB_CASE_MIN_TOUGHNESS 1e3        /* J/m^3, anchorage.toughness */
#define RB_CASE_MAX_TOUGHNESS 1e10
#define RB_CASE_MIN_MODULUS_PA 1e9       /* anchorage.elastic_modulus */
#define RB_CASE_MAX_MODULUS_PA 1e12
#define RB_CASE_MIN_DIAMETER_M 1e-3      /* anchorage.diameter; area alike */
#define RB_CASE_MAX_DIAMETER_M 0.2
#define RB_CASE_MAX_ACCEL_G 1000.0       /* amplitude, peak: 1000 g */
#define RB_CASE_MAX_MOTION_FREQ_HZ 1000.0 /* a harmonic's frequency */
#define RB_CASE_MIN_BUILDING_HZ 0.01     /* a record's building filter */
#define RB_CASE_MAX_BUILDING_HZ 100.0
/* Work bounds, checked before anything is solved. One simulated hour is
 * ten times the longest strong-motion records (a few minutes) and takes
 * about half a second to solve; 1e5 s took 14 s and 1e9 s would take 40
 * hours. */
#define RB_CASE_MAX_RUN_S 3600.0         /* simulated time of one motion */
#define RB_CASE_MIN_DT_S 1e-5            /* a record's sample interval */
#define RB_CASE_MAX_DT_S 1.0
/* History rows of all motions together, at the interval in effect (the
 * case's output_interval, else 0.01 s): 10 million rows hold about 1 GB. */
#define RB_CASE_MAX_HISTORY_ROWS 10000000.0
#define RB_CASE_HISTORY_DT_DEFAULT_S 0.01

typedef enum { RB_YNODE_SCALAR, RB_YNODE_MAP, RB_YNODE_SEQ } rb_ynode_kind;

typedef struct rb_ynode rb_ynode;

typedef struct {
    char *key;          /* owned */
    int line, col;      /* of the key, 1-based */
    rb_ynode *value;    /* owned */
    int used;           /* set once the schema has read the entry */
} rb_yentry;

struct rb_ynode {
    rb_ynode_kind kind;
    const char *file;   /* borrowed from rb_cctx.files */
    int line, col;      /* start mark, 1-based */
    char *text;         /* scalar: owned, NUL-terminated */
    int plain;          /* scalar: 1 when unquoted */
    rb_yentry *entries; /* map: owned array */
    rb_ynode **items;   /* seq: owned array of owned nodes */
    size_t n, cap;      /* entries or items */
};

/* A model field as rb_model_derive names it, and where the case gave it. */
typedef struct {
    const char *field;        /* rb_model_derive's diag->key */
    char key[RB_CASE_KEY_MAX];/* dotted YAML key */
    const rb_ynode *node;     /* value node, borrowed */
} rb_cfield;

#define RB_CASE_MAX_FIELDS 24

/* A motion as read from the case, before A* and records are resolved. */
typedef struct rb_cmotion {
    char key[RB_CASE_KEY_MAX];  /* "motion" or "motions[2]" */
    const rb_ynode *map;        /* the motion's mapping */
    rb_motion motion;           /* closed-form fields already in SI */
    char *name;                 /* owned, may be NULL */
    rb_quantity amplitude;      /* harmonic, pulse */
    const rb_ynode *amplitude_node;
    int has_duration;           /* run time given */
    const rb_ynode *file_node;  /* record */
    rb_record_opts ropts;
    double building_freq_hz, building_damping; /* 0: no building */
    rb_quantity peak;
    const rb_ynode *peak_node;  /* NULL: no scaling */
    double window[2];
    int has_window;
    /* synthetic (case_synth.c) */
    int synthetic;
    rb_target_kind target_kind;
    rb_ac156_edition edition;
    rb_ieee693_level ieee693_level;
    rb_quantity sds;
    const rb_ynode *sds_node;
    double z_over_h;
    rb_ac156_building building;   /* spectrum.ta, r, ie, omega0 (0: not given) */
    rb_quantity sds2;             /* spectrum.envelope (value 0: none) */
    double z_over_h2;
    const rb_ynode *table_node;   /* spectrum.file */
    double table_units_to_mps2, table_damping; /* table_damping: IEEE 693's too */
    double tolerance_below, tolerance_above;   /* a table's `tolerance` */
    long count;                   /* motions made from this entry, >= 1 */
    const rb_ynode *count_node;
    unsigned long long seed;
    double total_s, strong_s, synth_dt_s;
    rb_synth_components components;  /* AC156: triaxial by default */
    const rb_ynode *components_node;
    double table_displacement_m, table_velocity_mps; /* `table:` */
    const rb_ynode *synth_dt_node;  /* NULL: the default */
    const rb_ynode *synth_total_node, *synth_strong_node; /* alike */
    /* a record's, harmonic's or pulse's `spectrum:`: judged against it */
    int judged;
    /* `low_cutoff` (auto, or a frequency; 0: the target's own) and
     * `max_ratio` (0: none) of the acceptance (case_accept.c) */
    int low_cutoff_auto;
    double low_cutoff_hz, max_ratio;
    const rb_ynode *low_cutoff_node, *max_ratio_node;
    /* `vertical:` (case_motion.c): the floor's vertical acceleration as
     * read, owned, NULL for none; is_vertical marks the vertical itself */
    struct rb_cmotion *vertical;
    int is_vertical;
    int ok;                     /* 0 when the motion had errors */
} rb_cmotion;

/* Loader state for one rb_case_load call. */
typedef struct {
    rb_diag_list *diags;
    size_t n_errors;
    int nomem;                  /* an allocation failed somewhere */
    int fatal;                  /* syntax or limit error: stop walking */
    rb_status status;           /* worst status so far */
    char *files[RB_CASE_MAX_FILES]; /* owned: every file name nodes use */
    size_t n_files;
    rb_cfield fields[RB_CASE_MAX_FIELDS];
    size_t n_fields;
    rb_cmotion *motions;        /* owned array */
    size_t n_motions;
    int gap_is_ratio;           /* the gap was given as gap_ratio */
    double gap_ratio;
    int model_errors;           /* errors in equipment/anchorage/gap */
    size_t n_nodes;             /* YAML nodes made, against RB_CASE_MAX_NODES */
    size_t first_diag;          /* this load's first index in diags */
    size_t n_dropped;           /* errors past RB_CASE_MAX_DIAGS, not kept */
    rb_diag dropped;            /* the first of them */
    size_t n_samples;           /* record samples held, RB_CASE_MAX_SAMPLES */
    rb_record_cache *cache;     /* borrowed; NULL: own_records */
    const rb_sandbox *sandbox;  /* borrowed: every file read must lie in
                                   it; NULL: anywhere */
    rb_record_cache *own_records; /* owned: a case loaded without a cache
                                   keeps its records here, so that motions
                                   naming one record read it once */
    unsigned long long record_bytes; /* read, against RB_CASE_MAX_RECORD_BYTES */
    double history_dt_s;        /* output_interval, or the default */
    const rb_ynode *history_dt_node; /* NULL: not given */
    rb_unit_system units;       /* the case's output units, which its
                                   messages about values print in */
    const rb_ynode *sweep_maps[RB_CASE_MAX_SWEEPS]; /* design.sweeps, by index */
    int overrides;              /* the root document is a list row's
                                   overrides: its `motion:` applies to each
                                   motion of a base's `motions:` list */
    /* criteria: concrete: -1 not given, else 0 or 1 */
    int judge_concrete;
    rb_ynode *concrete_node;        /* concrete: and anchorage:, for the */
    rb_ynode *anchorage_node;       /* check's errors */
    rb_ynode *seismic_route_node;   /* concrete.seismic_route, when given */
    int bolt_by_area;               /* anchorage.area given, not diameter */
    int anchor_coef_given;          /* concrete: coefficients: was given */
} rb_cctx;

/* --- case_concrete.c --------------------------------------------------- */
/* concrete: and the anchorage keys of the concrete check (an: anchorage:,
 * may be NULL); the strengths are computed by rb_case_resolve_concrete
 * once the model is whole. */
void rb_case_read_concrete(rb_cctx *c, rb_ynode *root, rb_ynode *an, rb_case *cs);
void rb_case_resolve_concrete(rb_cctx *c, rb_case *cs);

/* --- case_ctx.c: diagnostics and key paths ------------------------------ */
/* Append an error at file:line:col under key (may be ""). */
void rb_cctx_error_at(rb_cctx *c, rb_status st, const char *file, int line,
                      int col, const char *key, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 7, 8)))
#endif
    ;
/* Append an error at node n (whose file and mark are used). */
void rb_cctx_error(rb_cctx *c, const rb_ynode *n, const char *key,
                   const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;
/* Keep a copy of a file name for nodes to point at; NULL on NOMEM. */
const char *rb_cctx_file(rb_cctx *c, const char *name);
/* dst = path.key (or key when path is empty), truncated to fit. */
void rb_case_keypath(char *dst, const char *path, const char *key);
/* At the end of a load: put its diagnostics (from index first on) in
 * reading order, the case file before its bases, then by line and column;
 * then say how many were dropped over RB_CASE_MAX_DIAGS. */
void rb_cctx_finish(rb_cctx *c, size_t first);

/* --- case_yaml.c: files to trees ---------------------------------------- */
/* Read one YAML file into a tree whose root is a mapping. file is the
 * name used in diagnostics. On failure appends diags and returns non-OK;
 * *root is NULL. where (may be NULL) is the node that named the file, used
 * when the file cannot be opened. */
rb_status rb_yaml_read_tree(rb_cctx *c, const char *file, const rb_ynode *where,
                            const char *where_key, rb_ynode **root);
/* The same for text already in memory, named file in diagnostics; takes
 * buf (malloc'ed) and frees it. */
rb_status rb_yaml_parse_text(rb_cctx *c, const char *file, unsigned char *buf, size_t len,
                             rb_ynode **root);
void rb_ynode_free(rb_ynode *n);
/* The entry for key in map, or NULL. */
rb_yentry *rb_ymap_find(const rb_ynode *map, const char *key);
/* "a mapping", "a sequence", "a number or text", "nothing" (null). */
const char *rb_ynode_kind_str(const rb_ynode *n);
/* 1 if n is a plain null scalar ("", "~", "null"). */
int rb_ynode_is_null(const rb_ynode *n);

/* --- case_top.c ---------------------------------------------------------- */
/* 1 if key is one a case file may give at its top level (rb_case_top_keys). */
int rb_case_top_key(const char *key);
/* The keys each section of the schema reads, NULL-terminated, where the
 * readers keep them (case_schema.c, case_concrete.c, case_design.c,
 * case_motion.c, case_synth.c, case_fragility.c, case_project.c); case_keys.c walks them
 * to say which dotted keys a list column may name. */
extern const char *const *const rb_case_top_keys, *const *const rb_case_equipment_keys,
    *const *const rb_case_anchorage_keys, *const *const rb_case_criteria_keys,
    *const *const rb_case_analysis_keys, *const *const rb_case_concrete_keys,
    *const *const rb_case_product_keys, *const *const rb_case_design_keys,
    *const *const rb_case_code_keys, *const *const rb_case_fragility_keys,
    *const *const rb_case_harmonic_keys, *const *const rb_case_pulse_keys,
    *const *const rb_case_record_keys, *const *const rb_case_building_keys,
    *const *const rb_case_synthetic_keys, *const *const rb_case_ac156_keys,
    *const *const rb_case_table_keys, *const *const rb_case_project_keys,
    *const *const rb_case_synth_table_keys, *const *const rb_case_ieee693_keys,
    *const *const rb_case_gr63_keys,
    *const *const rb_case_envelope_keys, *const *const rb_case_tolerance_keys,
    *const *const rb_case_vertical_harmonic_keys, *const *const rb_case_vertical_pulse_keys,
    *const *const rb_case_vertical_record_keys;

/* --- case_extends.c ----------------------------------------------------- */
/* Read file and everything it extends, merged; *root is the merged tree. */
rb_status rb_case_read_merged(rb_cctx *c, const char *file, rb_ynode **root);
/* The same for a document in memory (a list row's overrides), named name
 * in diagnostics; takes text (malloc'ed) and frees it. */
rb_status rb_case_read_merged_text(rb_cctx *c, const char *name, unsigned char *text,
                                   size_t len, rb_ynode **root);

/* --- case_synth.c: synthetic motions ------------------------------------ */
/* Read a `type: synthetic` motion's keys into cm; 0 after an error. */
int rb_case_read_synthetic(rb_cctx *c, rb_ynode *map, rb_cmotion *cm);
/* Read a motion's `spectrum:` (a synthetic motion's target, or the one a
 * record, harmonic or pulse is judged against) into cm; 0 after an error. */
int rb_case_read_spectrum(rb_cctx *c, rb_ynode *sp, rb_cmotion *cm);
/* Make the target cm names (reading a table file); 0 after an error. */
int rb_case_make_target(rb_cctx *c, const rb_cmotion *cm, rb_case_target *ct);
/* Check what generating cm's suite of count motions takes (the options
 * the generator accepts, the case's sample budget, which it charges), so
 * that a case is refused before any motion is generated; 0 after an
 * error. */
int rb_case_check_suite(rb_cctx *c, const rb_cmotion *cm, const rb_case_target *ct,
                        size_t count);
/* The run time of each motion of cm's suite, known before it is made. */
double rb_case_suite_duration(const rb_cmotion *cm);
/* Generate cm's suite of count motions into out[0..count), once
 * rb_case_check_suite passed; 0 after an error, reported at the first
 * motion that could not be made. */
int rb_case_build_suite(rb_cctx *c, const rb_cmotion *cm, const rb_case_target *ct,
                        rb_case_motion *out, size_t count);

/* --- case_accept.c: the acceptance of a motion against its target ------ */
/* A motion's `low_cutoff` and `max_ratio` into cm (a motion that is not
 * synthetic must have a `spectrum` to take them); 0 after an error. */
int rb_case_read_accept(rb_cctx *c, rb_ynode *map, rb_cmotion *cm);
/* ct's rules and vertical_rules: rb_accept_rules_init's with cm's low
 * cutoff (auto: rb_accept_low_cutoff of m's fixed-base frequency, none when
 * rigid or m NULL) and max_ratio; 0 after an error (the low cutoff at or
 * above the target's high cutoff). */
int rb_case_accept_rules(rb_cctx *c, const rb_cmotion *cm, const rb_model *m,
                         rb_case_target *ct);

/* --- case_value.c: typed values ----------------------------------------- */
/* A file a case names, relative to the directory of the file that named
 * it, or "shipped:NAME" in the data directory (rockbolt/datadir.h); NULL
 * when out of memory. */
char *rb_case_input_path(const rb_ynode *v);
/* A copy of s; NULL, with c->nomem set, when out of memory. */
char *rb_case_strdup(rb_cctx *c, const char *s);
/* Look up key in map and mark it used. Missing and required: error at the
 * map naming path.key and what was expected. Returns the value or NULL. */
rb_ynode *rb_cv_get(rb_cctx *c, rb_ynode *map, const char *path,
                    const char *key, int required, const char *expected);
/* Convert a scalar node. Each returns 1 on success, 0 after an error. */
int rb_cv_quantity(rb_cctx *c, const rb_ynode *v, const char *key, rb_dim dim,
                   rb_quantity *out);
int rb_cv_bool(rb_cctx *c, const rb_ynode *v, const char *key, int *out);
int rb_cv_int(rb_cctx *c, const rb_ynode *v, const char *key, long lo,
              long hi, long *out);
int rb_cv_enum(rb_cctx *c, const rb_ynode *v, const char *key,
               const char *const names[], int *out);
/* The same over a name table of rockbolt/names.h: *out is the enum value.
 * Only the first n_parse names may be given (0: all of them). */
#define RB_CV_ENUM_MAX 16
int rb_cv_enum_table(rb_cctx *c, const rb_ynode *v, const char *key,
                     const rb_enum_name *table, size_t n_parse, int *out);
int rb_cv_string(rb_cctx *c, const rb_ynode *v, const char *key, char **out);
/* A mapping value (error if it is not one). */
int rb_cv_map(rb_cctx *c, const rb_ynode *v, const char *key);
/* A time (given at node v under key) within the case's time limits:
 * RB_CASE_MIN_TIME_S to RB_CASE_MAX_RUN_S, or also 0 when zero_ok. 1 if it
 * is, 0 after an error. */
int rb_cv_time_range(rb_cctx *c, const rb_ynode *v, const char *key, double t,
                     int zero_ok);
/* Quantity by key: get + convert + range check (lo < x, or lo <= x when
 * lo_incl; x < hi or x <= hi when hi_incl; NAN bounds are open). Returns
 * the node on success, NULL if missing or bad. */
const rb_ynode *rb_cv_number(rb_cctx *c, rb_ynode *map, const char *path,
                             const char *key, int required, rb_dim dim,
                             double lo, int lo_incl, double hi, int hi_incl,
                             double *out);
/* Report every entry of map not marked used, suggesting the nearest of
 * valid (NULL-terminated) when it is close. */
void rb_cv_unknown_keys(rb_cctx *c, const rb_ynode *map, const char *path,
                        const char *const valid[]);
/* Remember where a model field came from, for rb_model_derive's diags. */
void rb_cv_note_field(rb_cctx *c, const char *field, const char *key,
                      const rb_ynode *node);

/* --- case_schema.c / case_motion.c / case_validate.c --------------------- */
void rb_case_read_schema(rb_cctx *c, rb_ynode *root, rb_case *cs);
/* case_fragility.c: the fragility: section */
void rb_case_read_fragility(rb_cctx *c, rb_ynode *map, rb_case *cs);
void rb_case_read_project(rb_cctx *c, rb_ynode *map, rb_case *cs);   /* case_project.c */
void rb_case_read_motions(rb_cctx *c, rb_ynode *root);
void rb_case_read_design(rb_cctx *c, rb_ynode *d, rb_case *cs);   /* case_design.c */
void rb_case_resolve(rb_cctx *c, rb_case *cs, const rb_ynode *root);
void rb_cmotion_free(rb_cmotion *m);

#endif
