/* `type: synthetic` motions: a target spectrum (AC156 or a table) and the
 * suite of spectrum-compatible motions generated for it (rockbolt/synth.h).
 * One entry with `count: N` becomes N motions, named NAME-1 to NAME-N,
 * each from its own random stream of the seed. */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "case_internal.h"
#include "rockbolt/names.h"
#include "rockbolt/record.h"
#include "rockbolt/record_cache.h"
#include "util/pool.h"

#define SYNTH_MIN_TOTAL_S RB_SYNTH_MIN_TOTAL_S
#define SYNTH_MAX_TOTAL_S RB_SYNTH_MAX_TOTAL_S
#define SYNTH_MIN_DT_S RB_SYNTH_MIN_DT_S
#define SYNTH_MAX_DT_S RB_SYNTH_MAX_DT_S
#define SYNTH_STANDARD_G 9.80665
/* a table's tolerance unless it states its own: AC156's band */
#define AC156_LIKE_BELOW 0.9
#define AC156_LIKE_ABOVE 1.3

static const char *const synthetic_keys[] = {
    "type", "name", "polarity", "spectrum", "count", "seed", "duration", "strong", "dt",
    "run_time", "components", "table", "low_cutoff", "max_ratio", NULL};
static const char *const synth_table_keys[] = {"displacement", "velocity", NULL};
static const char *const ac156_keys[] = {"type", "sds", "z_over_h", "edition", "ta", "r",
                                         "ie", "omega0", "envelope", NULL};
static const char *const envelope_keys[] = {"sds", "z_over_h", NULL};
static const char *const table_keys[] = {"type", "file", "units", "damping", "tolerance",
                                         NULL};
static const char *const tolerance_keys[] = {"below", "above", NULL};
static const char *const ieee693_keys[] = {"type", "level", "damping", NULL};
static const char *const gr63_keys[] = {"type", "file", "units", NULL};
const char *const *const rb_case_synthetic_keys = synthetic_keys;
const char *const *const rb_case_ac156_keys = ac156_keys;
const char *const *const rb_case_table_keys = table_keys;
const char *const *const rb_case_ieee693_keys = ieee693_keys;
const char *const *const rb_case_gr63_keys = gr63_keys;
const char *const *const rb_case_envelope_keys = envelope_keys;
const char *const *const rb_case_tolerance_keys = tolerance_keys;
const char *const *const rb_case_synth_table_keys = synth_table_keys;

/* `table: {displacement, velocity}`: the table's envelope (0: no limit) */
static int read_envelope(rb_cctx *c, rb_ynode *map, rb_cmotion *cm)
{
    char k[RB_CASE_KEY_MAX];
    cm->table_displacement_m = RB_SYNTH_TABLE_DISPLACEMENT_M;
    cm->table_velocity_mps = RB_SYNTH_TABLE_VELOCITY_MPS;
    rb_ynode *v = rb_cv_get(c, map, cm->key, "table", 0, "");
    if (!v)
        return 1;
    rb_case_keypath(k, cm->key, "table");
    if (!rb_cv_map(c, v, k))
        return 0;
    int ok = 1;
    if (rb_ymap_find(v, "displacement"))
        ok &= rb_cv_number(c, v, k, "displacement", 0, RB_DIM_LENGTH, 0, 1, 100, 1,
                           &cm->table_displacement_m) != NULL;
    if (rb_ymap_find(v, "velocity"))
        ok &= rb_cv_number(c, v, k, "velocity", 0, RB_DIM_VELOCITY, 0, 1, 100, 1,
                           &cm->table_velocity_mps) != NULL;
    rb_cv_unknown_keys(c, v, k, synth_table_keys);
    return ok;
}

/* `components: horizontal | triaxial`: AC156 and IEEE 693 sets are
 * triaxial by default; a table has no vertical spectrum */
static int read_components(rb_cctx *c, rb_ynode *map, rb_cmotion *cm)
{
    char k[RB_CASE_KEY_MAX];
    int i;
    cm->components = cm->target_kind == RB_TARGET_AC156 || cm->target_kind == RB_TARGET_IEEE693
                     ? RB_SYNTH_TRIAXIAL : RB_SYNTH_HORIZONTAL;
    rb_ynode *v = rb_cv_get(c, map, cm->key, "components", 0, "");
    if (!v)
        return 1;
    rb_case_keypath(k, cm->key, "components");
    cm->components_node = v;
    if (!rb_cv_enum_table(c, v, k, rb_synth_components_names, 0, &i))
        return 0;
    cm->components = (rb_synth_components)i;
    if (cm->components == RB_SYNTH_TRIAXIAL && cm->target_kind == RB_TARGET_TABLE) {
        rb_cctx_error(c, v, k, "a table target has no vertical spectrum: triaxial sets "
                      "are made for an ac156 or ieee693 spectrum; give 'horizontal'");
        return 0;
    }
    return 1;
}

/* S_DS and z/h of a level (the spectrum's own, or its `envelope`) */
static int read_level(rb_cctx *c, rb_ynode *sp, const char *k, rb_quantity *sds,
                      const rb_ynode **sds_node, double *z_over_h)
{
    char kk[RB_CASE_KEY_MAX];
    int ok = 1;
    rb_ynode *v = rb_cv_get(c, sp, k, "sds", 1, "S_DS as an acceleration, e.g. '1.0 g'");
    rb_case_keypath(kk, k, "sds");
    if (v && rb_cv_quantity(c, v, kk, RB_DIM_ACCEL, sds)) {
        if (sds->relative_a_star) {
            rb_cctx_error(c, v, kk, "S_DS is a site value: give it in g or m/s^2, not A*");
            ok = 0;
        } else if (!(sds->value > 0)
                   || sds->value > RB_CASE_MAX_ACCEL_G * SYNTH_STANDARD_G) {
            rb_cctx_error(c, v, kk, "must be > 0 and at most %g g (got '%s')",
                          RB_CASE_MAX_ACCEL_G, v->text);
            ok = 0;
        }
        if (sds_node)
            *sds_node = v;
    } else {
        ok = 0;
    }
    ok &= rb_cv_number(c, sp, k, "z_over_h", 1, RB_DIM_RATIO, 0, 1, 1, 1, z_over_h) != NULL;
    return ok;
}

/* AC156-24's building (ASCE 7-22's T_a, R, I_e, Omega_0): R, I_e and
 * Omega_0 together or not at all; not in the 2010 form */
static int read_building(rb_cctx *c, rb_ynode *sp, const char *k, rb_cmotion *cm)
{
    static const char *const keys[] = {"ta", "r", "ie", "omega0"};
    char kk[RB_CASE_KEY_MAX];
    int ok = 1, given[4] = {0, 0, 0, 0};
    double *out[4] = {&cm->building.ta_s, &cm->building.r, &cm->building.ie,
                      &cm->building.omega0};
    for (int i = 0; i < 4; i++) {
        if (!rb_ymap_find(sp, keys[i]))
            continue;
        given[i] = 1;
        rb_case_keypath(kk, k, keys[i]);
        if (cm->edition != RB_AC156_2024) {
            rb_ynode *v = rb_cv_get(c, sp, k, keys[i], 0, "");
            rb_cctx_error(c, v, kk, "the building's %s enters AC156-24's H_f and R_mu "
                          "only: give 'edition: 2024' or remove it", keys[i]);
            ok = 0;
            continue;
        }
        ok &= rb_cv_number(c, sp, k, keys[i], 0, i == 0 ? RB_DIM_TIME : RB_DIM_RATIO, 0, 0,
                           i == 0 ? 100 : 1000, 1, out[i]) != NULL;
    }
    if (ok && (given[1] || given[2] || given[3]) && !(given[1] && given[2] && given[3])) {
        rb_case_keypath(kk, k, given[1] ? (given[2] ? "omega0" : "ie") : "r");
        rb_cctx_error_at(c, RB_ERR_INVALID, sp->file, sp->line, sp->col, kk, "R_mu takes "
                         "the building's r, ie and omega0 together: give all three, or "
                         "none for R_mu = 1.3");
        ok = 0;
    }
    return ok;
}

static int read_ac156(rb_cctx *c, rb_ynode *sp, const char *k, rb_cmotion *cm)
{
    char kk[RB_CASE_KEY_MAX];
    int ok = 1, i;
    rb_ynode *v;
    ok &= read_level(c, sp, k, &cm->sds, &cm->sds_node, &cm->z_over_h);
    cm->edition = RB_AC156_2010;
    if ((v = rb_cv_get(c, sp, k, "edition", 0, ""))) {
        rb_case_keypath(kk, k, "edition");
        if (rb_cv_enum_table(c, v, kk, rb_ac156_edition_names, 0, &i))
            cm->edition = (rb_ac156_edition)i;
        else
            ok = 0;
    }
    ok &= read_building(c, sp, k, cm);
    if ((v = rb_cv_get(c, sp, k, "envelope", 0, ""))) {
        rb_case_keypath(kk, k, "envelope");
        if (rb_cv_map(c, v, kk)) {
            ok &= read_level(c, v, kk, &cm->sds2, NULL, &cm->z_over_h2);
            rb_cv_unknown_keys(c, v, kk, envelope_keys);
        } else {
            ok = 0;
        }
    }
    rb_cv_unknown_keys(c, sp, k, ac156_keys);
    return ok;
}

/* IEEE 693's beta takes ln(100 xi): its damping is bounded away from 0 */
#define IEEE693_MIN_DAMPING 0.005
#define IEEE693_MAX_DAMPING 0.2

static int read_ieee693(rb_cctx *c, rb_ynode *sp, const char *k, rb_cmotion *cm)
{
    char kk[RB_CASE_KEY_MAX];
    int ok = 1, i;
    rb_ynode *v = rb_cv_get(c, sp, k, "level", 1, "high or moderate");
    rb_case_keypath(kk, k, "level");
    if (v && rb_cv_enum_table(c, v, kk, rb_ieee693_level_names, 0, &i))
        cm->ieee693_level = (rb_ieee693_level)i;
    else
        ok = 0;
    cm->table_damping = 0.05;
    if (rb_ymap_find(sp, "damping"))
        ok &= rb_cv_number(c, sp, k, "damping", 0, RB_DIM_RATIO, IEEE693_MIN_DAMPING, 1,
                           IEEE693_MAX_DAMPING, 1, &cm->table_damping) != NULL;
    rb_cv_unknown_keys(c, sp, k, ieee693_keys);
    return ok;
}

/* A table's `file` and `units` (a table target's, GR-63's) */
static int read_table_file(rb_cctx *c, rb_ynode *sp, const char *k, rb_cmotion *cm)
{
    char kk[RB_CASE_KEY_MAX], text[64], msg[300];
    int ok = 1;
    char *name = NULL;
    rb_ynode *v = rb_cv_get(c, sp, k, "file", 1, "the table file (frequency in Hz, "
                            "spectral acceleration), relative to this case file");
    rb_case_keypath(kk, k, "file");
    if (v && rb_cv_string(c, v, kk, &name) && name[0])
        cm->table_node = v;
    else if (v && name)
        rb_cctx_error(c, v, kk, "expected a file name, found an empty text");
    free(name);
    ok &= cm->table_node != NULL;
    cm->table_units_to_mps2 = SYNTH_STANDARD_G;
    if ((v = rb_cv_get(c, sp, k, "units", 0, ""))) {
        rb_quantity q;
        rb_case_keypath(kk, k, "units");
        snprintf(text, sizeof text, "1 %.50s", v->kind == RB_YNODE_SCALAR ? v->text : "");
        if (v->kind != RB_YNODE_SCALAR
            || rb_unit_parse(text, RB_DIM_ACCEL, &q, msg, sizeof msg) != RB_OK
            || q.relative_a_star) {
            rb_cctx_error(c, v, kk, "expected an absolute acceleration unit such as 'g' "
                          "or 'm/s^2'");
            ok = 0;
        } else {
            cm->table_units_to_mps2 = q.value;
        }
    }
    return ok;
}

/* GR-63-CORE's check of a given waveform: the user's RRS table, at the
 * standard's 2 % (rb_target_gr63) */
static int read_gr63(rb_cctx *c, rb_ynode *sp, const char *k, rb_cmotion *cm)
{
    int ok = read_table_file(c, sp, k, cm);
    cm->table_damping = RB_GR63_DAMPING;
    rb_ynode *v = rb_cv_get(c, sp, k, "damping", 0, "");
    if (v) {
        char kk[RB_CASE_KEY_MAX];
        rb_case_keypath(kk, k, "damping");
        rb_cctx_error(c, v, kk, "GR-63-CORE's TRS is at 2 %% damping, which the check "
                      "takes: remove damping (a table at another damping is type: table)");
        ok = 0;
    }
    rb_cv_unknown_keys(c, sp, k, gr63_keys);
    return ok;
}

static int read_table(rb_cctx *c, rb_ynode *sp, const char *k, rb_cmotion *cm)
{
    char kk[RB_CASE_KEY_MAX];
    rb_ynode *v;
    int ok = read_table_file(c, sp, k, cm);
    cm->table_damping = 0.05;
    if (rb_ymap_find(sp, "damping"))
        ok &= rb_cv_number(c, sp, k, "damping", 0, RB_DIM_RATIO, 0, 0, 0.5, 1,
                           &cm->table_damping) != NULL;
    cm->tolerance_below = AC156_LIKE_BELOW;
    cm->tolerance_above = AC156_LIKE_ABOVE;
    if ((v = rb_cv_get(c, sp, k, "tolerance", 0, ""))) {
        rb_case_keypath(kk, k, "tolerance");
        if (rb_cv_map(c, v, kk)) {
            if (rb_ymap_find(v, "below"))
                ok &= rb_cv_number(c, v, kk, "below", 0, RB_DIM_RATIO, RB_TARGET_MIN_BELOW,
                                   1, 1.0, 1, &cm->tolerance_below) != NULL;
            if (rb_ymap_find(v, "above"))
                ok &= rb_cv_number(c, v, kk, "above", 0, RB_DIM_RATIO, RB_TARGET_MIN_ABOVE,
                                   1, RB_TARGET_MAX_ABOVE, 1, &cm->tolerance_above) != NULL;
            rb_cv_unknown_keys(c, v, kk, tolerance_keys);
        } else {
            ok = 0;
        }
    }
    rb_cv_unknown_keys(c, sp, k, table_keys);
    return ok;
}

int rb_case_read_spectrum(rb_cctx *c, rb_ynode *sp, rb_cmotion *cm)
{
    char k[RB_CASE_KEY_MAX], kk[RB_CASE_KEY_MAX];
    int t;
    rb_case_keypath(k, cm->key, "spectrum");
    if (!rb_cv_map(c, sp, k))
        return 0;
    rb_ynode *v = rb_cv_get(c, sp, k, "type", 1, cm->synthetic ? "ac156, ieee693 or table"
                            : "ac156, ieee693, table or gr63");
    rb_case_keypath(kk, k, "type");
    if (!v || !rb_cv_enum_table(c, v, kk, rb_target_type_names, 0, &t)) {
        for (size_t i = 0; i < sp->n; i++)
            sp->entries[i].used = 1;   /* no type: its keys cannot be judged */
        return 0;
    }
    cm->target_kind = (rb_target_kind)t;
    if (t == RB_TARGET_GR63 && cm->synthetic) {
        rb_cctx_error(c, v, kk, "GR-63-CORE prescribes its own waveform: rockbolt checks a "
                      "given one against it (a record's 'spectrum: {type: gr63, file: "
                      "...}'), it does not generate one; give ac156, ieee693 or table");
        for (size_t i = 0; i < sp->n; i++)
            sp->entries[i].used = 1;
        return 0;
    }
    if (t == RB_TARGET_GR63)
        return read_gr63(c, sp, k, cm);
    if (t == RB_TARGET_AC156)
        return read_ac156(c, sp, k, cm);
    return t == RB_TARGET_IEEE693 ? read_ieee693(c, sp, k, cm) : read_table(c, sp, k, cm);
}

int rb_case_read_synthetic(rb_cctx *c, rb_ynode *map, rb_cmotion *cm)
{
    const char *p = cm->key;
    char k[RB_CASE_KEY_MAX];
    int ok = 1;
    cm->synthetic = 1;
    cm->motion.kind = RB_MOTION_SAMPLED;
    rb_ynode *v = rb_cv_get(c, map, p, "spectrum", 1, "the target spectrum, e.g. "
                            "{type: ac156, sds: 1.0 g, z_over_h: 0.5}");
    ok &= v && rb_case_read_spectrum(c, v, cm);
    ok &= rb_case_read_accept(c, map, cm);
    ok &= read_components(c, map, cm);
    ok &= read_envelope(c, map, cm);
    cm->count = 1;
    if ((v = rb_cv_get(c, map, p, "count", 0, ""))) {
        rb_case_keypath(k, p, "count");
        ok &= rb_cv_int(c, v, k, 1, RB_CASE_MAX_MOTIONS, &cm->count);
        cm->count_node = v;
    }
    if ((v = rb_cv_get(c, map, p, "seed", 0, ""))) {
        long seed = 0;
        rb_case_keypath(k, p, "seed");
        ok &= rb_cv_int(c, v, k, 0, 2147483647L, &seed);
        cm->seed = (unsigned long long)seed;
    }
    cm->total_s = 30.0;
    if (rb_ymap_find(map, "duration")) {
        cm->synth_total_node = rb_cv_number(c, map, p, "duration", 0, RB_DIM_TIME,
                                            SYNTH_MIN_TOTAL_S, 1, SYNTH_MAX_TOTAL_S, 1,
                                            &cm->total_s);
        ok &= cm->synth_total_node != NULL;
    }
    cm->strong_s = rb_synth_default_strong(cm->total_s);
    if (rb_ymap_find(map, "strong")) {
        const rb_ynode *sv = rb_cv_number(c, map, p, "strong", 0, RB_DIM_TIME,
                                          SYNTH_MIN_TOTAL_S, 1, SYNTH_MAX_TOTAL_S, 1,
                                          &cm->strong_s);
        cm->synth_strong_node = sv;
        rb_case_keypath(k, p, "strong");
        if (sv && cm->strong_s > cm->total_s) {
            rb_cctx_error(c, sv, k, "the strong part (%g s) cannot be longer than the "
                          "motion (duration %g s)", cm->strong_s, cm->total_s);
            sv = NULL;
        }
        ok &= sv != NULL;
    }
    cm->synth_dt_s = 0.005;
    if (rb_ymap_find(map, "dt")) {
        cm->synth_dt_node = rb_cv_number(c, map, p, "dt", 0, RB_DIM_TIME, SYNTH_MIN_DT_S, 1,
                                         SYNTH_MAX_DT_S, 1, &cm->synth_dt_s);
        ok &= cm->synth_dt_node != NULL;
    }
    if (rb_ymap_find(map, "run_time")) {
        cm->has_duration = 1;
        const rb_ynode *rv = rb_cv_number(c, map, p, "run_time", 0, RB_DIM_TIME, 0, 0,
                                          (double)NAN, 0, &cm->motion.duration_s);
        rb_case_keypath(k, p, "run_time");
        ok &= rv && rb_cv_time_range(c, rv, k, cm->motion.duration_s, 0);
    }
    rb_cv_unknown_keys(c, map, p, synthetic_keys);
    return ok;
}

int rb_case_make_target(rb_cctx *c, const rb_cmotion *cm, rb_case_target *ct)
{
    memset(ct, 0, sizeof *ct);
    if (cm->target_kind == RB_TARGET_AC156) {
        rb_target_ac156(&ct->target, cm->edition, cm->sds.value, cm->z_over_h);
        rb_target_ac156_more(&ct->target, &cm->building, cm->sds2.value, cm->z_over_h2);
        /* the vertical has no height term: the larger S_DS's */
        rb_target_ac156_vertical(&ct->vertical, fmax(cm->sds.value, cm->sds2.value));
        return 1;
    }
    if (cm->target_kind == RB_TARGET_IEEE693) {
        rb_target_ieee693(&ct->target, cm->ieee693_level, cm->table_damping, 0);
        rb_target_ieee693(&ct->vertical, cm->ieee693_level, cm->table_damping, 1);
        return 1;
    }
    char k[RB_CASE_KEY_MAX];
    const rb_ynode *v = cm->table_node;
    rb_case_keypath(k, cm->key, "spectrum.file");
    ct->file = rb_case_input_path(v);
    if (!ct->file) {
        c->nomem = 1;
        return 0;
    }
    double *f, *a;
    size_t n;
    rb_diag rd;
    rb_diag_clear(&rd);
    rb_status st = rb_spectrum_table_read(ct->file, c->sandbox, cm->table_units_to_mps2,
                                          RB_SPECTRUM_MAX_POINTS, &f, &a, &n, &rd);
    if (st != RB_OK) {
        rb_status as = st == RB_ERR_NOMEM ? st : RB_ERR_IO;
        if (rd.line > 0 && rd.col > 0)
            rb_cctx_error_at(c, as, v->file, v->line, v->col, k, "cannot read spectrum "
                             "table '%s' (line %d, column %d: %s)", ct->file, rd.line,
                             rd.col, rd.msg);
        else if (rd.line > 0)
            rb_cctx_error_at(c, as, v->file, v->line, v->col, k, "cannot read spectrum "
                             "table '%s' (line %d: %s)", ct->file, rd.line, rd.msg);
        else
            rb_cctx_error_at(c, as, v->file, v->line, v->col, k, "cannot read spectrum "
                             "table '%s' (%s)", ct->file,
                             rd.msg[0] ? rd.msg : rb_status_str(st));
        return 0;
    }
    if (cm->target_kind == RB_TARGET_GR63) {
        if (!(f[0] <= RB_GR63_FROM_HZ)) {
            rb_cctx_error_at(c, RB_ERR_INVALID, v->file, v->line, v->col, k, "GR-63-CORE's "
                             "RRS is checked from %g Hz: the table '%s' starts at %g Hz; "
                             "state it from %g Hz or below", RB_GR63_FROM_HZ, ct->file,
                             f[0], RB_GR63_FROM_HZ);
            free(f);
            free(a);
            return 0;
        }
        rb_target_gr63(&ct->target, f, a, n);
        return 1;
    }
    rb_target_table(&ct->target, f, a, n, cm->table_damping);
    rb_target_tolerance(&ct->target, cm->tolerance_below, cm->tolerance_above);
    return 1;
}

/* Everything a generated motion depends on, as the record cache's name for
 * it (no file has such a name: it starts with "synthetic:"); 0 when it
 * does not fit, and the motion is then not cached. */
static int cache_key(const rb_cmotion *cm, const rb_target *t, const rb_accept_rules *r,
                     const char *file, unsigned index, char *key, size_t n)
{
    int len = snprintf(key, n, "synthetic:%d:%d:%d:%d:%.17g:%.17g:%.17g:%s:%.17g:%.17g|%llu|"
                       "%u|%.17g|%.17g|%.17g|%.17g|%.17g|%.17g:%.17g:%.17g:%.17g:%.17g:"
                       "%.17g|%.17g:%.17g", (int)t->kind, (int)t->edition,
                       (int)t->level, t->vertical, t->sds_mps2, t->z_over_h, t->damping, file ? file : "",
                       cm->table_units_to_mps2, t->band_upper * 1000 + t->band_lower, cm->seed, index,
                       cm->total_s, cm->strong_s, cm->synth_dt_s, cm->table_displacement_m,
                       cm->table_velocity_mps, t->building.ta_s, t->building.r,
                       t->building.ie, t->building.omega0, t->sds2_mps2, t->z_over_h2,
                       r->low_cutoff_hz, r->max_ratio);
    return len > 0 && (size_t)len < n;
}

/* One motion of a suite: found in the record cache, or generated ahead of
 * its place in the case beside the others (rb_case_build_suite). */
typedef struct {
    rb_synth_opts o;
    rb_series series;          /* owned until build_one takes it */
    rb_synth_info info;
    rb_status st;
    int cached, generated;
    char key[4700];
    int keyed;
} suite_job;

/* The job of the motion `index` of a suite, component `comp` (its own
 * stream; H1 keeps the index a horizontal suite had). */
static void job_init(const rb_cmotion *cm, const rb_case_target *ct, unsigned index,
                     rb_synth_component comp, unsigned retry, suite_job *j)
{
    rb_synth_opts_init(&j->o, comp == RB_SYNTH_V ? &ct->vertical : &ct->target);
    j->o.dt_s = cm->synth_dt_s;
    j->o.total_s = cm->total_s;
    j->o.strong_s = cm->strong_s;
    j->o.seed = cm->seed;
    j->o.index = index + ((unsigned)comp + 3 * retry) * RB_SYNTH_COMPONENT_STREAM;
    j->o.table_displacement_m = cm->table_displacement_m;
    j->o.table_velocity_mps = cm->table_velocity_mps;
    /* the motion's own acceptance (its low cutoff, its max_ratio) */
    j->o.rules = comp == RB_SYNTH_V ? &ct->vertical_rules : &ct->rules;
    j->keyed = cache_key(cm, j->o.target, j->o.rules, ct->file, j->o.index, j->key,
                         sizeof j->key);
}

static int generate_on = 1;
static rb_case_generate_progress_fn progress_fn;
static void *progress_ctx;

void rb_case_set_generate(int on)
{
    generate_on = on;
}

void rb_case_set_generate_progress(rb_case_generate_progress_fn fn, void *ctx)
{
    progress_fn = fn;
    progress_ctx = ctx;
}

/* The jobs of one suite handed to the pool, and how many of those it
 * generates are done, for the progress hook. */
typedef struct {
    suite_job *jobs;
    size_t to_generate, done;
    pthread_mutex_t lock;
} suite_jobs;

static void generate_one(suite_job *j)
{
    if (!j->cached && !generate_on) {
        size_t n = (size_t)llround(j->o.total_s / j->o.dt_s) + 1;
        j->st = rb_series_alloc(&j->series, n, j->o.dt_s);
        memset(&j->info, 0, sizeof j->info);
        j->generated = 1;
    } else if (!j->cached) {
        j->st = rb_synth_generate(&j->o, &j->series, &j->info);
        j->generated = 1;
    }
}

static rb_status generate_job(void *ctx, size_t i)
{
    suite_jobs *s = ctx;
    suite_job *j = &s->jobs[i];
    generate_one(j);
    if (!j->cached && progress_fn) {
        pthread_mutex_lock(&s->lock);
        progress_fn(progress_ctx, ++s->done, s->to_generate);
        pthread_mutex_unlock(&s->lock);
    }
    return RB_OK;
}

static const char *const component_names[] = {"H1", "H2", "V"};
/* A set's component drawn again at most this often for independence. */
#define SYNTH_SET_RETRIES 4

/* Take the generated (or cached) series of a job into *series and *info,
 * described; 0 after an error, which names the motion, the component and
 * what it could not meet. */
static int take_job(rb_cctx *c, const rb_cmotion *cm, unsigned index,
                    rb_synth_component comp, int set, suite_job *job, rb_series *series,
                    rb_synth_info *info)
{
    char k[RB_CASE_KEY_MAX], what[16] = "";
    const rb_target *t = job->o.target;
    const rb_ynode *at = cm->map;
    rb_case_keypath(k, cm->key, "spectrum");
    if (set)
        snprintf(what, sizeof what, " (%s)", component_names[comp]);
    /* a motion made here goes to the cache, for the rows of a batch after it */
    rb_record_opts none;
    rb_record_opts_init(&none);
    rb_status st;
    if (!job->cached && !job->generated)
        generate_one(job);
    *series = job->series;
    memset(&job->series, 0, sizeof job->series);
    if (job->cached)
        st = rb_synth_describe(t, series, info);
    else {
        st = job->st;
        *info = job->info;
        if (st == RB_OK && job->keyed && generate_on)
            rb_record_cache_put(c->cache, job->key, &none, 0, 0, series);
    }
    if (st == RB_ERR_LIMIT) {
        const rb_motion_summary *m = &info->summary;
        rb_cctx_error_at(c, RB_ERR_INVALID, at->file, at->line, at->col, k, "motion %u%s "
                         "of seed %llu did not meet both the spectrum (the laboratory's "
                         "rules at every offset within [%g, %g]%s, "
                         "a peak of %.3g g) and the table's envelope (%s, %g m/s) in %u "
                         "passes: the closest had a margin of %.3f, ratios %.3f to %.3f, "
                         "a peak of %.3g g, PGD %.3g m and PGV %.3g m/s; try another seed "
                         "or a larger table", index + 1, what, cm->seed, t->band_lower,
                         t->band_upper, t->kind == RB_TARGET_AC156 ? ", the rigid end to "
                         "50 Hz" : "", RB_SYNTH_PEAK_MARGIN * t->min_peak_mps2 / RB_G0,
                         cm->table_displacement_m > 0
                             ? rb_qty_str(c->units, RB_Q_SMALL_LENGTH,
                                          cm->table_displacement_m, 4).s : "no limit",
                         cm->table_velocity_mps, info->iterations, m->accept.margin,
                         m->accept.min_ratio, m->accept.max_ratio, m->pga_mps2 / RB_G0,
                         m->pgd_m, m->pgv_mps);
        rb_series_free(series);
        return 0;
    }
    if (st != RB_OK) {
        if (st == RB_ERR_NOMEM)
            c->nomem = 1;
        else
            rb_cctx_error_at(c, st, at->file, at->line, at->col, k, "cannot generate "
                             "the motion (%s)", rb_status_str(st));
        return 0;
    }
    return 1;
}

/* An AC156 motion's source and name (comp: "" or " V") */
static int describe_motion(rb_cctx *c, const rb_cmotion *cm, const rb_target *t,
                           unsigned index, const char *comp, rb_case_motion *out)
{
    char desc[200];
    if (t->kind == RB_TARGET_IEEE693)
        snprintf(desc, sizeof desc, "synthetic: IEEE 693 %s%s, damping %g %%, seed %llu, "
                 "motion %u", rb_enum_str(rb_ieee693_level_names, (int)t->level),
                 t->vertical ? " vertical" : "", 100.0 * t->damping, cm->seed, index + 1);
    else if (t->vertical)
        snprintf(desc, sizeof desc, "synthetic: AC156 vertical S_DS %s, seed %llu, "
                 "motion %u", rb_qty_str(c->units, RB_Q_ACCEL, t->sds_mps2, 6).s,
                 cm->seed, index + 1);
    else
        snprintf(desc, sizeof desc, "synthetic: AC156 (%s) S_DS %s, z/h %g, seed "
                 "%llu, motion %u", rb_enum_str(rb_ac156_edition_names, (int)t->edition),
                 rb_qty_str(c->units, RB_Q_ACCEL, t->sds_mps2, 6).s, t->z_over_h,
                 cm->seed, index + 1);
    out->source = rb_case_strdup(c, desc);
    const char *base = cm->name ? cm->name
                                : rb_enum_str(rb_target_type_names, (int)t->kind);
    if (cm->count > 1)
        snprintf(desc, sizeof desc, "%.150s-%u%s", base, index + 1, comp);
    else
        snprintf(desc, sizeof desc, "%.150s%s", base, comp);
    out->name = rb_case_strdup(c, desc);
    return out->source && out->name;
}

/* Motion `index` of a suite from its jobs (one, or a set's three). */
static int build_one(rb_cctx *c, const rb_cmotion *cm, const rb_case_target *ct,
                     unsigned index, suite_job *jobs, rb_case_motion *out)
{
    const rb_target *t = &ct->target;
    int set = cm->components == RB_SYNTH_TRIAXIAL;
    out->type = RB_CASE_MOTION_SYNTHETIC;
    out->motion = cm->motion;
    out->target = t;
    out->rules = &ct->rules;
    out->synth_index = index;
    out->synth_seed = cm->seed;
    if (!take_job(c, cm, index, RB_SYNTH_H1, set, &jobs[0], &out->series, &out->synth))
        return 0;
    out->motion.series = &out->series;
    out->motion.scale = 1.0;
    if (!cm->has_duration)
        out->motion.duration_s = (double)(out->series.n - 1) * out->series.dt_s;
    if (t->kind == RB_TARGET_TABLE) {
        char desc[200];
        snprintf(desc, sizeof desc, "synthetic: table %.120s, seed %llu, motion %u",
                 ct->file, cm->seed, index + 1);
        out->source = rb_case_strdup(c, desc);
        const char *base = cm->name ? cm->name : "table";
        if (cm->count > 1)
            snprintf(desc, sizeof desc, "%.150s-%u", base, index + 1);
        else
            snprintf(desc, sizeof desc, "%.150s", base);
        out->name = rb_case_strdup(c, desc);
        if (!out->source || !out->name)
            return 0;
    } else if (!describe_motion(c, cm, t, index, "", out)) {
        return 0;
    }
    if (!set)
        return 1;
    out->has_set = 1;
    if (!take_job(c, cm, index, RB_SYNTH_H2, 1, &jobs[1], &out->h2, &out->h2_synth))
        return 0;
    rb_case_motion *v = calloc(1, sizeof *v);
    if (!v) {
        c->nomem = 1;
        return 0;
    }
    out->vertical = v;
    v->type = RB_CASE_MOTION_SYNTHETIC;
    rb_motion_init(&v->motion);
    v->motion.kind = RB_MOTION_SAMPLED;
    v->target = &ct->vertical;
    v->rules = &ct->vertical_rules;
    v->synth_index = index;
    v->synth_seed = cm->seed;
    if (!take_job(c, cm, index, RB_SYNTH_V, 1, &jobs[2], &v->series, &v->synth)
        || !describe_motion(c, cm, &ct->vertical, index, " V", v))
        return 0;
    v->motion.series = &v->series;
    v->motion.scale = 1.0;
    v->motion.duration_s = 0; /* the motion it belongs to sets the run */
    out->motion.vertical = &v->motion;
    /* the set's independence (AC156 5.2.2.7.3), as laboratories check it;
     * independent streams still correlate by chance (the largest of some
     * 12000 lags' correlations runs 0.1 to 0.3): the later component of a
     * pair found dependent is drawn again from another stream */
    rb_series *comp[3] = {&out->series, &out->h2, &v->series};
    rb_synth_info *infos[3] = {&out->synth, &out->h2_synth, &v->synth};
    static const int pairs[3][2] = {{0, 1}, {0, 2}, {1, 2}};
    unsigned retry[3] = {0, 0, 0};
    /* samples of zero (rb_case_set_generate) say nothing of independence,
     * and measuring it is the suite's cost: 1 000 sets of three pairs took
     * the case fuzzer past its time limit */
    for (int p = 0; p < 3 && !generate_on; p++)
        out->independence[p] = (rb_synth_pair){.independent = 1};
    for (int p = 0; p < 3 && generate_on; p++) {
        rb_status st = rb_synth_independence(comp[pairs[p][0]], comp[pairs[p][1]],
                                             &out->independence[p]);
        int later = pairs[p][1];
        if (st == RB_OK && !out->independence[p].independent
            && retry[later] < SYNTH_SET_RETRIES) {
            suite_job again;
            memset(&again, 0, sizeof again);
            job_init(cm, ct, index, (rb_synth_component)later, ++retry[later], &again);
            rb_series_free(comp[later]);
            if (!take_job(c, cm, index, (rb_synth_component)later, 1, &again, comp[later],
                          infos[later]))
                return 0;
            p = -1;       /* judge every pair again */
            continue;
        }
        if (st == RB_ERR_NOMEM) {
            c->nomem = 1;
            return 0;
        }
        if (st != RB_OK || !out->independence[p].independent) {
            char k[RB_CASE_KEY_MAX];
            const rb_ynode *at = cm->map;
            rb_case_keypath(k, cm->key, "components");
            rb_cctx_error_at(c, RB_ERR_INVALID, at->file, at->line, at->col, k,
                             "motion %u of seed %llu: %s and %s are not statistically "
                             "independent (correlation %.3f, at most %g; coherence %.3f, "
                             "at most %g); try another seed", index + 1, cm->seed,
                             component_names[pairs[p][0]], component_names[pairs[p][1]],
                             out->independence[p].correlation, RB_SYNTH_MAX_CORRELATION,
                             out->independence[p].coherence, RB_SYNTH_MAX_COHERENCE);
            return 0;
        }
    }
    /* z'' must stay above -g, as for a given vertical (case_validate.c) */
    double least = rb_motion_least(&v->motion, out->motion.duration_s);
    if (!(least > -RB_G0)) {
        char k[RB_CASE_KEY_MAX];
        const rb_ynode *at = cm->map;
        rb_case_keypath(k, cm->key, "components");
        rb_cctx_error_at(c, RB_ERR_INVALID, at->file, at->line, at->col, k, "motion %u's "
                         "vertical reaches %.3g g downward, at or beyond gravity: the "
                         "cabinet would leave the floor in free flight, which the model "
                         "does not follow; give 'horizontal'", index + 1, -least / RB_G0);
        return 0;
    }
    return 1;
}

/* The node of the key the generator's option check blames. */
static const rb_ynode *option_node(const rb_cmotion *cm, const char *key)
{
    const rb_ynode *v = NULL;
    if (strcmp(key, "dt") == 0)
        v = cm->synth_dt_node ? cm->synth_dt_node : cm->table_node;
    else if (strcmp(key, "duration") == 0)
        v = cm->synth_total_node;
    else if (strcmp(key, "strong") == 0)
        v = cm->synth_strong_node ? cm->synth_strong_node : cm->synth_total_node;
    else if (strcmp(key, "spectrum") == 0)
        v = cm->table_node;
    return v ? v : cm->map;
}

int rb_case_check_suite(rb_cctx *c, const rb_cmotion *cm, const rb_case_target *ct,
                        size_t count)
{
    char k[RB_CASE_KEY_MAX], why[300];
    const char *key;
    suite_job job;
    job_init(cm, ct, 0, RB_SYNTH_H1, 0, &job);
    if (!rb_synth_opts_check(&job.o, &key, why, sizeof why)) {
        const rb_ynode *at = option_node(cm, key);
        if (at == cm->table_node && at)
            key = "spectrum.file";
        if (at == cm->map || !key[0])
            snprintf(k, sizeof k, "%s", cm->key);
        else
            rb_case_keypath(k, cm->key, key);
        rb_cctx_error_at(c, RB_ERR_INVALID, at->file, at->line, at->col, k, "%s", why);
        return 0;
    }
    size_t n = (size_t)llround(cm->total_s / cm->synth_dt_s) + 1;
    for (size_t i = 0; i < count; i++) {
        if (n > RB_CASE_MAX_SAMPLES - c->n_samples) {
            const rb_ynode *at = cm->map;
            rb_cctx_error_at(c, RB_ERR_LIMIT, at->file, at->line, at->col, cm->key, "the "
                             "motions of one case may hold %u samples in all (the limit): "
                             "this one needs %zu and the motions before it hold %zu",
                             RB_CASE_MAX_SAMPLES, n, c->n_samples);
            return 0;
        }
        c->n_samples += n;
    }
    return 1;
}

double rb_case_suite_duration(const rb_cmotion *cm)
{
    if (cm->has_duration)
        return cm->motion.duration_s;
    size_t n = (size_t)llround(cm->total_s / cm->synth_dt_s) + 1;
    return (double)(n - 1) * cm->synth_dt_s;
}

int rb_case_build_suite(rb_cctx *c, const rb_cmotion *cm, const rb_case_target *ct,
                        rb_case_motion *out, size_t count)
{
    size_t per = cm->components == RB_SYNTH_TRIAXIAL ? 3 : 1, all = count * per;
    suite_job *jobs = calloc(all, sizeof *jobs);
    if (!jobs) {
        c->nomem = 1;
        return 0;
    }
    rb_record_opts none;
    rb_record_opts_init(&none);
    size_t i;
    /* the cases of a batch that share a suite generate it once */
    for (i = 0; i < all; i++) {
        job_init(cm, ct, (unsigned)(i / per), (rb_synth_component)(i % per), 0, &jobs[i]);
        jobs[i].cached = jobs[i].keyed
                         && rb_record_cache_get(c->cache, jobs[i].key, &none, 0, 0,
                                                &jobs[i].series);
    }
    /* a suite's motions take most of a check's time; each is its own
     * random stream, so they do not depend on one another or on the order
     * they are made in */
    suite_jobs s = {jobs, 0, 0, PTHREAD_MUTEX_INITIALIZER};
    for (i = 0; i < all; i++)
        s.to_generate += !jobs[i].cached;
    rb_pool_map(all, 0, generate_job, &s, NULL);
    int ok = 1;
    for (i = 0; i < count && ok && !c->nomem; i++)
        ok = build_one(c, cm, ct, (unsigned)i, &jobs[i * per], &out[i]);
    for (i = 0; i < all; i++)
        rb_series_free(&jobs[i].series);
    free(jobs);
    return ok;
}
