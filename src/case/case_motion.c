/* The floor motions of a case: `motion:` (one) or `motions:` (a list).
 *
 * Each motion is a mapping with a `type:` (harmonic, pulse, record or
 * synthetic, the last in case_synth.c) that
 * decides which other keys it takes. Closed-form values go straight into an
 * rb_motion in SI; what needs the model (amplitudes in A*) or the disk
 * (record files) is kept in an rb_cmotion with the node it came from, and
 * finished by case_validate.c. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "case_internal.h"
#include "rockbolt/datadir.h"

const rb_enum_name rb_case_motion_type_names[] = {
    {"harmonic", RB_CASE_MOTION_HARMONIC}, {"pulse", RB_CASE_MOTION_PULSE},
    {"record", RB_CASE_MOTION_RECORD}, {"synthetic", RB_CASE_MOTION_SYNTHETIC}, {NULL, 0}};

/* spectrum, low_cutoff, max_ratio: the target a motion is judged against
 * and how (case_accept.c) */
static const char *const harmonic_keys[] = {
    "type", "name", "polarity", "amplitude", "frequency", "duration", "ramp",
    "vertical", "spectrum", "low_cutoff", "max_ratio", NULL};
static const char *const pulse_keys[] = {
    "type", "name", "polarity", "shape", "amplitude", "duration", "run_time",
    "vertical", "spectrum", "low_cutoff", "max_ratio", NULL};
static const char *const record_keys[] = {
    "type", "name", "polarity", "file", "format", "units", "dt", "building",
    "peak", "window", "run_time", "vertical", "spectrum", "low_cutoff", "max_ratio", NULL};
static const char *const building_keys[] = {"frequency", "damping", NULL};
const char *const *const rb_case_harmonic_keys = harmonic_keys;
const char *const *const rb_case_pulse_keys = pulse_keys;
const char *const *const rb_case_record_keys = record_keys;
const char *const *const rb_case_building_keys = building_keys;

/* A vertical runs as long as the motion it belongs to, and reaches the
 * floor unfiltered (the building is rigid vertically): no duration,
 * run_time or building of its own. */
static const char *const vertical_harmonic_keys[] = {
    "type", "polarity", "amplitude", "frequency", "ramp", NULL};
static const char *const vertical_pulse_keys[] = {
    "type", "polarity", "shape", "amplitude", "duration", NULL};
static const char *const vertical_record_keys[] = {
    "type", "polarity", "file", "format", "units", "dt", "peak", "window", NULL};
const char *const *const rb_case_vertical_harmonic_keys = vertical_harmonic_keys;
const char *const *const rb_case_vertical_pulse_keys = vertical_pulse_keys;
const char *const *const rb_case_vertical_record_keys = vertical_record_keys;

/* A time > 0 within the case's time limits (rb_cv_time_range); 1 if it is,
 * also when it is absent and not required. */
static int cmotion_time(rb_cctx *c, rb_ynode *map, const char *path,
                           const char *key, int required, int zero_ok, double *out)
{
    char k[RB_CASE_KEY_MAX];
    const rb_ynode *v = rb_cv_number(c, map, path, key, required, RB_DIM_TIME, 0,
                                     zero_ok, (double)NAN, 0, out);
    if (!v)
        return !required && !rb_ymap_find(map, key);
    rb_case_keypath(k, path, key);
    return rb_cv_time_range(c, v, k, *out, zero_ok);
}

/* A floor acceleration > 0, possibly in A*; returns the node or NULL. */
static const rb_ynode *cmotion_accel(rb_cctx *c, rb_ynode *map,
                                        const char *path, const char *key,
                                        int required, rb_quantity *q)
{
    char k[RB_CASE_KEY_MAX];
    rb_ynode *v = rb_cv_get(c, map, path, key, required,
                            "a floor acceleration such as '0.4 A*' or '0.3 g'");
    if (!v)
        return NULL;
    rb_case_keypath(k, path, key);
    if (!rb_cv_quantity(c, v, k, RB_DIM_ACCEL, q))
        return NULL;
    if (!(q->value > 0)) {
        rb_cctx_error(c, v, k, "must be > 0 (got '%s')", v->text);
        return NULL;
    }
    return v;
}

static int read_harmonic(rb_cctx *c, rb_ynode *map, rb_cmotion *cm)
{
    const char *p = cm->key;
    rb_motion *m = &cm->motion;
    int ok = 1;
    m->kind = RB_MOTION_HARMONIC;
    cm->amplitude_node = cmotion_accel(c, map, p, "amplitude", 1, &cm->amplitude);
    ok &= cm->amplitude_node != NULL;
    ok &= rb_cv_number(c, map, p, "frequency", 1, RB_DIM_FREQUENCY, 0, 0,
                       RB_CASE_MAX_MOTION_FREQ_HZ, 1, &m->freq_hz) != NULL;
    if (!cm->is_vertical)
        ok &= cmotion_time(c, map, p, "duration", 1, 0, &m->duration_s);
    ok &= cmotion_time(c, map, p, "ramp", 0, 1, &m->ramp_s);
    rb_cv_unknown_keys(c, map, p, cm->is_vertical ? vertical_harmonic_keys : harmonic_keys);
    return ok;
}

static int read_pulse(rb_cctx *c, rb_ynode *map, rb_cmotion *cm)
{
    const char *p = cm->key;
    char k[RB_CASE_KEY_MAX];
    rb_motion *m = &cm->motion;
    int ok = 1, i;
    m->kind = RB_MOTION_PULSE;
    rb_ynode *v = rb_cv_get(c, map, p, "shape", 1, "one of rectangular, "
                            "triangular-decreasing, triangular-increasing, half-sine");
    rb_case_keypath(k, p, "shape");
    if (v && rb_cv_enum_table(c, v, k, rb_pulse_shape_names, 0, &i))
        m->pulse = (rb_pulse_shape)i;
    else
        ok = 0;
    cm->amplitude_node = cmotion_accel(c, map, p, "amplitude", 1, &cm->amplitude);
    ok &= cm->amplitude_node != NULL;
    ok &= cmotion_time(c, map, p, "duration", 1, 0, &m->pulse_s);
    if (!cm->is_vertical)
        ok &= cmotion_time(c, map, p, "run_time", 1, 0, &m->duration_s);
    rb_cv_unknown_keys(c, map, p, cm->is_vertical ? vertical_pulse_keys : pulse_keys);
    return ok;
}

/* window: [start, end] in seconds of the record, start >= 0, end > start. */
static int read_window(rb_cctx *c, const rb_ynode *v, rb_cmotion *cm)
{
    char k[RB_CASE_KEY_MAX];
    rb_quantity q[2];
    rb_case_keypath(k, cm->key, "window");
    if (v->kind != RB_YNODE_SEQ || v->n != 2) {
        rb_cctx_error(c, v, k, "expected [start, end], e.g. '[0 s, 10 s]', "
                      "found %s", v->kind == RB_YNODE_SEQ
                      ? "a sequence of another length" : rb_ynode_kind_str(v));
        return 0;
    }
    if (!rb_cv_quantity(c, v->items[0], k, RB_DIM_TIME, &q[0])
        || !rb_cv_quantity(c, v->items[1], k, RB_DIM_TIME, &q[1]))
        return 0;
    if (q[0].value < 0 || q[1].value <= q[0].value) {
        rb_cctx_error(c, v, k, "needs 0 <= start < end (got [%s, %s])",
                      v->items[0]->text, v->items[1]->text);
        return 0;
    }
    cm->window[0] = q[0].value;
    cm->window[1] = q[1].value;
    cm->has_window = 1;
    return 1;
}

static int read_building(rb_cctx *c, rb_ynode *v, rb_cmotion *cm)
{
    char k[RB_CASE_KEY_MAX];
    rb_case_keypath(k, cm->key, "building");
    if (!rb_cv_map(c, v, k))
        return 0;
    int ok = rb_cv_number(c, v, k, "frequency", 1, RB_DIM_FREQUENCY,
                          RB_CASE_MIN_BUILDING_HZ, 1, RB_CASE_MAX_BUILDING_HZ, 1,
                          &cm->building_freq_hz) != NULL;
    ok &= rb_cv_number(c, v, k, "damping", 1, RB_DIM_RATIO, 0, 1, 1, 0,
                       &cm->building_damping) != NULL;
    rb_cv_unknown_keys(c, v, k, building_keys);
    return ok;
}

/* units: the acceleration unit of the record's numbers ("g", "cm/s^2"). */
static int read_record_units(rb_cctx *c, const rb_ynode *v, rb_cmotion *cm)
{
    char k[RB_CASE_KEY_MAX], text[64], msg[300];
    rb_quantity q;
    rb_case_keypath(k, cm->key, "units");
    if (v->kind != RB_YNODE_SCALAR || rb_ynode_is_null(v)) {
        rb_cctx_error(c, v, k, "expected an acceleration unit such as 'g' or "
                      "'cm/s^2', found %s", rb_ynode_kind_str(v));
        return 0;
    }
    snprintf(text, sizeof text, "1 %.50s", v->text);
    if (rb_unit_parse(text, RB_DIM_ACCEL, &q, msg, sizeof msg) != RB_OK
        || q.relative_a_star) {
        rb_cctx_error(c, v, k, "%s", q.relative_a_star
                      ? "a record's units must be absolute (g, m/s^2, cm/s^2, "
                        "gal, in/s^2, ft/s^2), not A*" : msg);
        return 0;
    }
    cm->ropts.units_to_mps2 = q.value;
    return 1;
}

static int read_record(rb_cctx *c, rb_ynode *map, rb_cmotion *cm)
{
    const char *p = cm->key;
    char k[RB_CASE_KEY_MAX];
    int ok = 1, i;
    rb_motion *m = &cm->motion;
    m->kind = RB_MOTION_SAMPLED;
    rb_record_opts_init(&cm->ropts);
    cm->ropts.sandbox = c->sandbox;
    rb_ynode *v = rb_cv_get(c, map, p, "file", 1, "the record file, relative "
                            "to this case file, or shipped:NAME");
    const rb_shipped_record *sr = NULL;
    rb_case_keypath(k, p, "file");
    char *dummy = NULL;
    if (v && rb_cv_string(c, v, k, &dummy) && dummy[0])
        cm->file_node = v;
    else if (v && dummy)
        rb_cctx_error(c, v, k, "expected a file name, found an empty text");
    if (cm->file_node && strncmp(dummy, RB_SHIPPED_PREFIX,
                                 strlen(RB_SHIPPED_PREFIX)) == 0
        && !(sr = rb_shipped_find(dummy + strlen(RB_SHIPPED_PREFIX)))) {
        rb_cctx_error(c, v, k, "no shipped record called '%.100s' (shipped: %s)",
                      dummy + strlen(RB_SHIPPED_PREFIX), rb_shipped_names());
        cm->file_node = NULL;
    }
    ok &= cm->file_node != NULL;
    free(dummy);
    /* a shipped record brings its format, sample interval and units; the
     * case's own keys still win */
    if (sr) {
        rb_quantity q;
        char msg[200];
        if (rb_enum_parse(rb_record_format_names, sr->format, &i))
            cm->ropts.format = (rb_record_format)i;
        if (sr->dt && rb_unit_parse(sr->dt, RB_DIM_TIME, &q, msg, sizeof msg) == RB_OK)
            cm->ropts.dt_s = q.value;
        if (sr->units) {
            char text[64];
            snprintf(text, sizeof text, "1 %s", sr->units);
            if (rb_unit_parse(text, RB_DIM_ACCEL, &q, msg, sizeof msg) == RB_OK)
                cm->ropts.units_to_mps2 = q.value;
        }
    }
    rb_case_keypath(k, p, "format");
    if ((v = rb_cv_get(c, map, p, "format", 0, ""))) {
        if (rb_cv_enum_table(c, v, k, rb_record_format_names, 0, &i))
            cm->ropts.format = (rb_record_format)i;
        else
            ok = 0;
    }
    if ((v = rb_cv_get(c, map, p, "units", 0, "")))
        ok &= read_record_units(c, v, cm);
    if (rb_ymap_find(map, "dt")) {
        const rb_ynode *dv = rb_cv_number(c, map, p, "dt", 0, RB_DIM_TIME, 0, 0,
                                          (double)NAN, 0, &cm->ropts.dt_s);
        rb_case_keypath(k, p, "dt");
        if (dv && (cm->ropts.dt_s < RB_CASE_MIN_DT_S || cm->ropts.dt_s > RB_CASE_MAX_DT_S)) {
            rb_cctx_error(c, dv, k, "must be between %g ms and %g s (got '%s')",
                          RB_CASE_MIN_DT_S * 1e3, RB_CASE_MAX_DT_S, dv->text);
            dv = NULL;
        }
        ok &= dv != NULL;
    }
    if (!cm->is_vertical && (v = rb_cv_get(c, map, p, "building", 0, "")))
        ok &= read_building(c, v, cm);
    if (rb_ymap_find(map, "peak")) {
        cm->peak_node = cmotion_accel(c, map, p, "peak", 0, &cm->peak);
        ok &= cm->peak_node != NULL;
    }
    if ((v = rb_cv_get(c, map, p, "window", 0, "")))
        ok &= read_window(c, v, cm);
    if (!cm->is_vertical && rb_ymap_find(map, "run_time")) {
        cm->has_duration = 1;
        ok &= cmotion_time(c, map, p, "run_time", 0, 0, &m->duration_s);
    }
    rb_cv_unknown_keys(c, map, p, cm->is_vertical ? vertical_record_keys : record_keys);
    return ok;
}

/* polarity: +1 (as recorded) or -1 (reversed). */
static void read_polarity(rb_cctx *c, const rb_ynode *v, const char *key,
                             int *out)
{
    if (v->kind == RB_YNODE_SCALAR && (strcmp(v->text, "1") == 0
                                       || strcmp(v->text, "+1") == 0)) {
        *out = 1;
    } else if (v->kind == RB_YNODE_SCALAR && strcmp(v->text, "-1") == 0) {
        *out = -1;
    } else if (v->kind == RB_YNODE_SCALAR) {
        rb_cctx_error(c, v, key, "expected +1 or -1, found '%s'", v->text);
    } else {
        rb_cctx_error(c, v, key, "expected +1 or -1, found %s",
                      rb_ynode_kind_str(v));
    }
}

/* `vertical:` of a harmonic, pulse or record motion: the floor's vertical
 * acceleration, positive upward, itself a harmonic, pulse or record
 * (docs/case-format.md). Into a new cm->vertical; 0 after an error. */
static int read_vertical(rb_cctx *c, rb_ynode *map, rb_cmotion *cm)
{
    char k[RB_CASE_KEY_MAX];
    int t;
    rb_cmotion *vm = calloc(1, sizeof *vm);
    if (!vm) {
        c->nomem = 1;
        return 0;
    }
    cm->vertical = vm;
    rb_motion_init(&vm->motion);
    rb_case_keypath(vm->key, cm->key, "vertical");
    vm->map = map;
    vm->is_vertical = 1;
    if (!rb_cv_map(c, map, vm->key))
        return 0;
    rb_ynode *v = rb_cv_get(c, map, vm->key, "polarity", 0, "");
    rb_case_keypath(k, vm->key, "polarity");
    if (v)
        read_polarity(c, v, k, &vm->motion.polarity);
    v = rb_cv_get(c, map, vm->key, "type", 1, "harmonic, pulse or record");
    rb_case_keypath(k, vm->key, "type");
    if (!v || !rb_cv_enum_table(c, v, k, rb_case_motion_type_names, 0, &t)) {
        for (size_t i = 0; i < map->n; i++)
            map->entries[i].used = 1;
        return 0;
    }
    /* the place for a vertical generated with its horizontal (AC156's
     * triaxial suites): until then a vertical is given, not made */
    if (t == RB_CASE_MOTION_SYNTHETIC) {
        rb_cctx_error(c, v, k, "a synthetic vertical is not generated yet: give a "
                      "harmonic, pulse or record");
        for (size_t i = 0; i < map->n; i++)
            map->entries[i].used = 1;
        return 0;
    }
    vm->ok = t == RB_CASE_MOTION_HARMONIC ? read_harmonic(c, map, vm)
             : t == RB_CASE_MOTION_PULSE   ? read_pulse(c, map, vm)
                                           : read_record(c, map, vm);
    return vm->ok;
}

/* A record's, harmonic's or pulse's `spectrum` (the target it is judged
 * against, not matched to) and its acceptance keys (case_accept.c). */
static int read_judged(rb_cctx *c, rb_ynode *map, rb_cmotion *cm)
{
    rb_ynode *v = rb_cv_get(c, map, cm->key, "spectrum", 0, "");
    int ok = 1;
    if (v) {
        cm->judged = 1;
        ok = rb_case_read_spectrum(c, v, cm);
    }
    return rb_case_read_accept(c, map, cm) && ok;
}

static void read_motion(rb_cctx *c, rb_ynode *map, rb_cmotion *cm)
{
    char k[RB_CASE_KEY_MAX];
    int t;
    rb_motion_init(&cm->motion);
    cm->map = map;
    if (!rb_cv_map(c, map, cm->key))
        return;
    rb_ynode *v = rb_cv_get(c, map, cm->key, "name", 0, "");
    rb_case_keypath(k, cm->key, "name");
    if (v)
        rb_cv_string(c, v, k, &cm->name);
    v = rb_cv_get(c, map, cm->key, "polarity", 0, "");
    rb_case_keypath(k, cm->key, "polarity");
    if (v)
        read_polarity(c, v, k, &cm->motion.polarity);
    v = rb_cv_get(c, map, cm->key, "type", 1, "harmonic, pulse, record or synthetic");
    rb_case_keypath(k, cm->key, "type");
    if (!v || !rb_cv_enum_table(c, v, k, rb_case_motion_type_names, 0, &t)) {
        for (size_t i = 0; i < map->n; i++)
            map->entries[i].used = 1;   /* no type: its keys cannot be judged */
        return;
    }
    if (t == RB_CASE_MOTION_SYNTHETIC) {
        /* an AC156 suite's sets bring their own vertical (components) */
        if ((v = rb_cv_get(c, map, cm->key, "vertical", 0, ""))) {
            rb_case_keypath(k, cm->key, "vertical");
            rb_cctx_error(c, v, k, "a synthetic suite takes no vertical: an ac156 "
                          "suite's sets are triaxial (components: triaxial, the "
                          "default), each with its own generated vertical");
        }
        cm->ok = rb_case_read_synthetic(c, map, cm);
        return;
    }
    rb_ynode *vv = rb_cv_get(c, map, cm->key, "vertical", 0, "");
    /* before the type's own keys, which report what is left unread */
    int judged_ok = read_judged(c, map, cm);
    if (t == RB_CASE_MOTION_HARMONIC)
        cm->ok = read_harmonic(c, map, cm);
    else if (t == RB_CASE_MOTION_PULSE)
        cm->ok = read_pulse(c, map, cm);
    else
        cm->ok = read_record(c, map, cm);
    cm->ok &= judged_ok;
    if (vv && !read_vertical(c, vv, cm))
        cm->ok = 0;
}

void rb_case_read_motions(rb_cctx *c, rb_ynode *root)
{
    int which = 0;
    rb_yentry *e1 = rb_ymap_find(root, "motion"), *e2 = rb_ymap_find(root, "motions");
    if (e1 && e2) {
        const rb_yentry *later = e1->line > e2->line ? e1 : e2;
        rb_cctx_error(c, later->value, later->key,
                      "give either 'motion' or 'motions', not both");
        e1->used = e2->used = 1;
        return;
    }
    if (!e1 && !e2) {
        rb_cctx_error(c, root, "motion", "missing required key 'motion' or "
                      "'motions' (the floor motion: type harmonic, pulse, record or "
                      "synthetic)");
        return;
    }
    which = e2 != NULL;
    rb_ynode *v = which ? e2->value : e1->value;
    (which ? e2 : e1)->used = 1;
    size_t n = 1;
    if (which) {
        if (v->kind == RB_YNODE_SEQ && v->n > RB_CASE_MAX_MOTIONS) {
            rb_cctx_error_at(c, RB_ERR_LIMIT, v->file, v->line, v->col, "motions",
                             "expected a list of 1 to %d motions, found %zu (the "
                             "limit is %d)", RB_CASE_MAX_MOTIONS, v->n,
                             RB_CASE_MAX_MOTIONS);
            return;
        }
        if (v->kind != RB_YNODE_SEQ || v->n == 0) {
            rb_cctx_error(c, v, "motions", "expected a list of 1 to %d motions, "
                          "found %s", RB_CASE_MAX_MOTIONS, v->kind == RB_YNODE_SEQ
                          ? "an empty list" : rb_ynode_kind_str(v));
            return;
        }
        n = v->n;
    }
    c->motions = calloc(n, sizeof *c->motions);
    if (!c->motions) {
        c->nomem = 1;
        return;
    }
    c->n_motions = n;
    for (size_t i = 0; i < n; i++) {
        rb_cmotion *cm = &c->motions[i];
        if (which)
            snprintf(cm->key, sizeof cm->key, "motions[%zu]", i + 1);
        else
            snprintf(cm->key, sizeof cm->key, "motion");
        read_motion(c, which ? v->items[i] : v, cm);
    }
}
