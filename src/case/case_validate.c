/* The last stage of loading a case: physics checks, A*, and records.
 *
 * Cross-field checks (the bolt on the plate, the gap against the angle the
 * cabinet can rock through, Housner's restitution) are rb_model_derive's;
 * its diag names a model field, which is mapped back to the YAML key and
 * value node that set it. The gap check is also made here first, because
 * with the gap given as a ratio the engineer needs the angles to see why.
 * Once the model is valid, amplitudes given in A* are multiplied out and
 * the records are read, passed through the building filter, windowed and
 * scaled so that their peak equals the target: the series is scaled in
 * place and motion.scale stays 1. */
#include <math.h>
#include <stdio.h>
#include <sys/stat.h>
#include <stdlib.h>
#include <string.h>
#include "case_internal.h"
#include "rockbolt/datadir.h"

#define RB_DEG (180.0 / 3.14159265358979323846)

static const rb_cfield *field_of(const rb_cctx *c, const char *field)
{
    for (size_t i = 0; i < c->n_fields; i++)
        if (strcmp(c->fields[i].field, field) == 0)
            return &c->fields[i];
    return NULL;
}

/* theta0 >= alpha: the plate would tip past its overturning angle before
 * the bolts could hold it. */
static int check_gap_angle(rb_cctx *c, const rb_model *m)
{
    const rb_cfield *f = field_of(c, "gap");
    double l = m->lever_arm_m, g = m->gap_m;
    if (!f || m->bolt_model == RB_BOLT_NONE || !(l > 0))
        return 1;
    double alpha = atan2(m->half_width_m, m->cm_height_m);
    double theta0 = g < 2 * l ? 2 * asin(g / (2 * l)) : (double)INFINITY;
    if (theta0 < alpha)
        return 1;
    rb_cctx_error(c, f->node, f->key, "the gap (%s, %g of the lever arm) "
                  "lets the plate rotate %.3g deg before the bolts hold it, "
                  "past the overturning angle alpha = %.3g deg",
                  rb_qty_str(c->units, RB_Q_SMALL_LENGTH, g, 6).s, g / l, theta0 * RB_DEG,
                  alpha * RB_DEG);
    return 0;
}

/* Run rb_model_derive and report its complaint against the case. */
static int check_model(rb_cctx *c, rb_case *cs, const rb_ynode *root,
                          rb_derived *d)
{
    rb_diag diag;
    memset(&diag, 0, sizeof diag);
    if (c->model_errors > 0 || !check_gap_angle(c, &cs->model))
        return 0;
    if (rb_model_derive(&cs->model, d, &diag) == RB_OK)
        return 1;
    const rb_cfield *f = field_of(c, diag.key);
    if (f)
        rb_cctx_error(c, f->node, f->key, "%s", diag.msg);
    else
        rb_cctx_error(c, root, "equipment", "%s: %s", diag.key, diag.msg);
    return 0;
}

/* A floor acceleration at most 1000 g, once A* is multiplied out. */
static int check_accel(rb_cctx *c, const rb_cmotion *cm, const rb_ynode *v,
                          const char *key, double a)
{
    char k[RB_CASE_KEY_MAX];
    const double g = 9.80665;
    if (a <= RB_CASE_MAX_ACCEL_G * g)
        return 1;
    rb_case_keypath(k, cm->key, key);
    rb_cctx_error(c, v, k, "must be at most %g g (got '%s', %g g)",
                  RB_CASE_MAX_ACCEL_G, v->text, a / g);
    return 0;
}

/* Resolve an amplitude that may be in A*; 0 after an error. */
static int resolve_accel(rb_cctx *c, const rb_cmotion *cm, const rb_ynode *v,
                            const char *key, rb_quantity q, const rb_derived *d,
                            int have_model, double *out)
{
    char k[RB_CASE_KEY_MAX];
    if (!q.relative_a_star) {
        *out = q.value;
        return check_accel(c, cm, v, key, *out);
    }
    if (!have_model)
        return 0;   /* the model's own errors say why */
    if (!(d->a_star_mps2 > 0)) {
        rb_case_keypath(k, cm->key, key);
        rb_cctx_error(c, v, k, "A* is the acceleration that yields a bolt row "
                      "and is not defined without anchorage; give '%s' in g "
                      "or m/s^2", key);
        return 0;
    }
    *out = q.value * d->a_star_mps2;
    return check_accel(c, cm, v, key, *out);
}

/* The record's path: relative to the directory of the file that named it,
 * or "shipped:NAME" in the data directory (rockbolt/datadir.h). */
/* Report an unreadable record at its `file:` value, with the reader's own
 * diagnostic (which names the line of the record when it has one). */
static void record_fail(rb_cctx *c, const rb_cmotion *cm, const char *key,
                           const char *path, rb_status st, const rb_diag *rd)
{
    const rb_ynode *v = cm->file_node;
    rb_status as = st == RB_ERR_NOMEM ? st : RB_ERR_IO;
    if (rd->line > 0)
        rb_cctx_error_at(c, as, v->file, v->line, v->col, key, "cannot read "
                         "record '%s' (line %d: %s)", path, rd->line, rd->msg);
    else
        rb_cctx_error_at(c, as, v->file, v->line, v->col, key, "cannot read "
                         "record '%s' (%s)", path,
                         rd->msg[0] ? rd->msg : rb_status_str(st));
}

/* Read, filter, window and scale one record into out->series. */
static int load_record(rb_cctx *c, const rb_cmotion *cm, rb_case_motion *out,
                          double peak_mps2)
{
    char k[RB_CASE_KEY_MAX];
    rb_diag rd;
    memset(&rd, 0, sizeof rd);
    rb_case_keypath(k, cm->key, "file");
    out->source = rb_case_input_path(cm->file_node);
    if (!out->source) {
        c->nomem = 1;
        return 0;
    }
    /* The records of a case share one sample budget (see case_internal.h). */
    rb_record_opts ro = cm->ropts;
    size_t budget = RB_CASE_MAX_SAMPLES - c->n_samples;
    int shared = budget < RB_CASE_MAX_SAMPLES;
    if (ro.max_points == 0 || ro.max_points > budget)
        ro.max_points = budget;
    /* Without a cache of the caller's, the case keeps its own while it
     * loads, when it has motions to share records: each record is read
     * once per set of options. */
    if (!c->cache && !c->own_records && c->n_motions > 1)
        c->own_records = rb_record_cache_new(0);
    rb_record_cache *cache = c->cache ? c->cache : c->own_records;
    /* a cached series is already filtered by the same building */
    int cached = rb_record_cache_get(cache, out->source, &cm->ropts,
                                     cm->building_freq_hz, cm->building_damping,
                                     &out->series);
    rb_status st;
    struct stat sb;
    int regular = !cached && stat(out->source, &sb) == 0 && S_ISREG(sb.st_mode);
    /* a file over the limit alone gets the reader's own message */
    if (regular && (unsigned long long)sb.st_size <= RB_CASE_MAX_RECORD_BYTES
        && c->record_bytes + (unsigned long long)sb.st_size > RB_CASE_MAX_RECORD_BYTES) {
        rb_cctx_error_at(c, RB_ERR_LIMIT, cm->file_node->file, cm->file_node->line,
                         cm->file_node->col, k, "cannot read record '%s' (%lld bytes): "
                         "the records of one case may take %llu MiB in all (the limit; "
                         "a record named again with the same options is read once), "
                         "and the motions before this one read %llu MiB", out->source,
                         (long long)sb.st_size, RB_CASE_MAX_RECORD_BYTES >> 20,
                         c->record_bytes >> 20);
        return 0;
    }
    if (cached) {
        st = out->series.n <= budget ? RB_OK : RB_ERR_LIMIT;
    } else {
        st = budget ? rb_record_read(out->source, &ro, &out->series, &rd) : RB_ERR_LIMIT;
        /* what the file held when looked at; the reader stops one that
         * grows past its own limit */
        if (budget && regular)
            c->record_bytes += (unsigned long long)sb.st_size;
    }
    if (st == RB_ERR_LIMIT && shared) {
        rb_series_free(&out->series);
        rb_cctx_error_at(c, RB_ERR_LIMIT, cm->file_node->file, cm->file_node->line,
                         cm->file_node->col, k, "cannot read record '%s': the "
                         "records of one case may hold %u samples in all (the "
                         "limit), and the motions before this one hold %zu",
                         out->source, RB_CASE_MAX_SAMPLES, c->n_samples);
        return 0;
    }
    if (st != RB_OK) {
        record_fail(c, cm, k, out->source, st, &rd);
        return 0;
    }
    c->n_samples += out->series.n;
    /* the file's own sample interval (AT2 DT=, COSMOS, two columns): an
     * absurd one would make an endless run or an endless filter */
    if (!(out->series.dt_s >= RB_CASE_MIN_DT_S && out->series.dt_s <= RB_CASE_MAX_DT_S)) {
        rb_cctx_error_at(c, RB_ERR_LIMIT, cm->file_node->file, cm->file_node->line,
                         cm->file_node->col, k, "record '%s' has a sample interval "
                         "of %g s: expected %g ms to %g s", out->source,
                         out->series.dt_s, RB_CASE_MIN_DT_S * 1e3, RB_CASE_MAX_DT_S);
        return 0;
    }
    if (cm->building_freq_hz > 0) {
        out->building_freq_hz = cm->building_freq_hz;
        out->building_damping = cm->building_damping;
        st = cached ? RB_OK : rb_series_building_filter(&out->series, cm->building_freq_hz,
                                                        cm->building_damping);
        if (st != RB_OK) {
            rb_case_keypath(k, cm->key, "building");
            rb_cctx_error(c, cm->map, k, "the building filter failed (%s)",
                          rb_status_str(st));
            return 0;
        }
    }
    if (!cached)
        rb_record_cache_put(cache, out->source, &cm->ropts, cm->building_freq_hz,
                            cm->building_damping, &out->series);
    if (cm->has_window) {
        double len = out->series.t0_s + (double)(out->series.n - 1) * out->series.dt_s;
        st = cm->window[0] < len ? rb_series_window(&out->series, cm->window[0],
                                                    cm->window[1])
                                 : RB_ERR_INVALID;
        if (st == RB_OK && out->series.n < 2) {
            rb_case_keypath(k, cm->key, "window");
            rb_cctx_error(c, cm->map, k, "the window [%g s, %g s] holds %zu sample%s "
                          "of the record, whose samples are %g s apart: it needs "
                          "at least two", cm->window[0], cm->window[1],
                          out->series.n, out->series.n == 1 ? "" : "s",
                          out->series.dt_s);
            return 0;
        }
        if (st != RB_OK) {
            rb_case_keypath(k, cm->key, "window");
            rb_cctx_error(c, cm->map, k, "the window [%g s, %g s] does not fit "
                          "the record, which lasts %g s", cm->window[0],
                          cm->window[1], len);
            return 0;
        }
    }
    if (cm->peak_node) {
        double p = rb_series_peak(&out->series);
        if (!(p > 0) || !isfinite(p)) {
            rb_case_keypath(k, cm->key, "peak");
            rb_cctx_error(c, cm->peak_node, k, "cannot scale the record to a "
                          "peak: its samples are all zero");
            return 0;
        }
        if (p < RB_CASE_MIN_RECORD_PEAK) {
            rb_case_keypath(k, cm->key, "peak");
            rb_cctx_error(c, cm->peak_node, k, "cannot scale the record to a "
                          "peak: its largest sample is %s, below %s "
                          "(noise, or the wrong units)",
                          rb_qty_str(c->units, RB_Q_ACCEL, p, 6).s,
                          rb_qty_str(c->units, RB_Q_ACCEL, RB_CASE_MIN_RECORD_PEAK, 6).s);
            return 0;
        }
        rb_series_scale(&out->series, peak_mps2 / p);
        out->target_peak_mps2 = peak_mps2;
    }
    return 1;
}

/* Finish one motion into out; 0 after an error. */
static int build_motion(rb_cctx *c, const rb_cmotion *cm, rb_case_motion *out,
                           const rb_derived *d, int have_model)
{
    char desc[160];
    out->motion = cm->motion;
    double peak = 0;
    out->type = cm->motion.kind == RB_MOTION_HARMONIC ? RB_CASE_MOTION_HARMONIC
                : cm->motion.kind == RB_MOTION_PULSE ? RB_CASE_MOTION_PULSE
                : RB_CASE_MOTION_RECORD;
    if (cm->motion.kind != RB_MOTION_SAMPLED) {
        if (!resolve_accel(c, cm, cm->amplitude_node, "amplitude",
                              cm->amplitude, d, have_model,
                              &out->motion.amplitude_mps2))
            return 0;
        snprintf(desc, sizeof desc, "%s %s",
                 cm->motion.kind == RB_MOTION_HARMONIC ? "harmonic" : "pulse",
                 rb_qty_str(c->units, RB_Q_ACCEL, out->motion.amplitude_mps2, 6).s);
        out->source = rb_case_strdup(c, desc);
        out->name = rb_case_strdup(c, cm->name ? cm->name : cm->key);
        return out->source && out->name;
    }
    if (cm->peak_node && !resolve_accel(c, cm, cm->peak_node, "peak",
                                           cm->peak, d, have_model, &peak))
        return 0;
    if (!load_record(c, cm, out, peak))
        return 0;
    const char *base = strrchr(out->source, '/');
    out->name = rb_case_strdup(c, cm->name ? cm->name : (base ? base + 1 : out->source));
    out->motion.series = &out->series;
    out->motion.scale = 1.0;
    if (!cm->has_duration) {
        out->motion.duration_s = out->series.t0_s
                                 + (double)(out->series.n - 1) * out->series.dt_s;
        /* the run lasts as long as the (windowed) record */
        double t = out->motion.duration_s;
        const rb_ynode *v = cm->file_node;
        rb_case_keypath(desc, cm->key, cm->has_window ? "window" : "file");
        if (t > RB_CASE_MAX_RUN_S) {
            rb_cctx_error_at(c, RB_ERR_LIMIT, v->file, v->line, v->col, desc,
                             "the run would last %g s, the length of the %srecord, "
                             "over one simulated hour (%g s, the limit): give a "
                             "shorter window or a run_time", t,
                             cm->has_window ? "windowed " : "", RB_CASE_MAX_RUN_S);
            return 0;
        }
        if (!(t >= RB_CASE_MIN_TIME_S)) {
            rb_cctx_error_at(c, RB_ERR_INVALID, v->file, v->line, v->col, desc,
                             "the run would last %g s, the length of the %srecord: "
                             "it must last at least %g ms (give a run_time)", t,
                             cm->has_window ? "windowed " : "", RB_CASE_MIN_TIME_S * 1e3);
            return 0;
        }
    }
    return out->name != NULL;
}

/* The vertical of a motion (case_motion.c's read_vertical), built as a
 * motion of its own into out->vertical, which out->motion then carries;
 * 0 after an error. A floor that falls faster than gravity is refused
 * here, at the vertical, as the solver would refuse it without a place. */
static int build_vertical(rb_cctx *c, const rb_cmotion *cm, rb_case_motion *out,
                          const rb_derived *d, int have_model)
{
    const rb_cmotion *vm = cm->vertical;
    if (!vm)
        return 1;
    rb_case_motion *v = calloc(1, sizeof *v);
    if (!v) {
        c->nomem = 1;
        return 0;
    }
    out->vertical = v;
    if (!build_motion(c, vm, v, d, have_model))
        return 0;
    v->motion.duration_s = 0; /* the motion it belongs to sets the run */
    out->motion.vertical = &v->motion;
    double least = rb_motion_least(&v->motion, out->motion.duration_s);
    if (have_model && !(least > -d->g)) {
        rb_cctx_error(c, vm->map, vm->key, "the floor's downward acceleration reaches "
                      "%.4g m/s^2 (%.3g g), at or beyond gravity (%.4g m/s^2): the "
                      "cabinet would leave the floor in free flight, which the model "
                      "does not follow", -least, -least / RB_G0, d->g);
        return 0;
    }
    return 1;
}

/* The motions the case's entries make: one each, `count` for a synthetic
 * suite. 0 after an error (over RB_CASE_MAX_MOTIONS in all). */
static size_t count_motions(rb_cctx *c, size_t *n_targets)
{
    size_t n = 0;
    *n_targets = 0;
    for (size_t i = 0; i < c->n_motions; i++) {
        const rb_cmotion *cm = &c->motions[i];
        size_t k = cm->synthetic ? (size_t)cm->count : 1;
        *n_targets += cm->synthetic || cm->judged;
        if (n + k > RB_CASE_MAX_MOTIONS) {
            const rb_ynode *v = cm->count_node ? cm->count_node : cm->map;
            rb_cctx_error_at(c, RB_ERR_LIMIT, v->file, v->line, v->col, cm->key,
                             "the case would have over %d motions (the limit) with "
                             "this entry's %zu", RB_CASE_MAX_MOTIONS, k);
            return 0;
        }
        n += k;
    }
    return n;
}

/* A sweep's key past a motion limit, at the key, or at the sweep when the
 * default is past it. */
static void sweep_limit(rb_cctx *c, const rb_ynode *map, size_t i, const char *key,
                        const char *what)
{
    char k[RB_CASE_KEY_MAX];
    rb_yentry *e = rb_ymap_find(map, key);
    const rb_ynode *v = e ? e->value : map;
    snprintf(k, sizeof k, "design.sweeps[%zu].%s", i + 1, key);
    rb_cctx_error(c, v, k, "%s%s", e ? "" : "by default: ", what);
}

/* Sweeps reach their motions only as a design runs: a `to: 1e300` made
 * every point past the 1000 Hz harmonic limit fail with "integrator step
 * too small", and printed 300-digit ratios. Held to the limits of the
 * motions they make, at the key, once the model is known. */
static void check_sweeps(rb_cctx *c, const rb_case *cs, const rb_derived *d)
{
    const double g = 9.80665, max_a = RB_CASE_MAX_ACCEL_G * g;
    char what[300];
    for (size_t i = 0; i < cs->n_sweeps && i < RB_CASE_MAX_SWEEPS; i++) {
        const rb_sweep_opts *sw = &cs->sweeps[i];
        const rb_ynode *map = c->sweep_maps[i];
        if (!map)
            continue;
        if (sw->kind == RB_SWEEP_FREQUENCY) {
            double f = cs->model.freq_hz;
            if (!cs->model.rigid && f > 0 && !(sw->to * f <= RB_CASE_MAX_MOTION_FREQ_HZ)) {
                snprintf(what, sizeof what, "the sweep would reach %g Hz (%g times "
                         "equipment.frequency, %g Hz): a harmonic may have at most %g Hz, "
                         "so 'to' may be at most %g", sw->to * f, sw->to, f,
                         RB_CASE_MAX_MOTION_FREQ_HZ, RB_CASE_MAX_MOTION_FREQ_HZ / f);
                sweep_limit(c, map, i, "to", what);
            }
            if (d->a_star_mps2 > 0 && !(sw->amplitude_astar * d->a_star_mps2 <= max_a)) {
                snprintf(what, sizeof what, "the sweep's harmonics would be %g g (%g A*): "
                         "an amplitude may be at most %g g", sw->amplitude_astar
                         * d->a_star_mps2 / g, sw->amplitude_astar, RB_CASE_MAX_ACCEL_G);
                sweep_limit(c, map, i, "amplitude", what);
            }
        } else if (d->a_star_mps2 > 0 && !(sw->to * d->a_star_mps2 <= max_a)) {
            snprintf(what, sizeof what, "the sweep would scale the motion to %g g (%g A*): "
                     "an amplitude may be at most %g g, so 'to' may be at most %g A*",
                     sw->to * d->a_star_mps2 / g, sw->to, RB_CASE_MAX_ACCEL_G,
                     max_a / d->a_star_mps2);
            sweep_limit(c, map, i, "to", what);
        }
    }
}

/* design.code.ase, where the case does not give it, is the anchorage's own
 * A_se by the concrete check's rule (rb_anchor_ase): the gross area would
 * overstate the steel by 26-38 % and pass a static check the anchors fail. */
static void resolve_code_ase(rb_cctx *c, rb_case *cs, const rb_ynode *root)
{
    if (!cs->has_code || cs->code.ase_m2 > 0 || cs->model.bolt_model == RB_BOLT_NONE)
        return;
    cs->code.ase_m2 = rb_anchor_ase(&cs->model, &cs->anchor_in, NULL, NULL, NULL);
    if (cs->code.ase_m2 > 0)
        return;
    rb_yentry *d = root ? rb_ymap_find(root, "design") : NULL;
    rb_yentry *k = d && d->value ? rb_ymap_find(d->value, "code") : NULL;
    rb_cctx_error(c, k ? k->value : root, "design.code.ase",
                  "the bolt's diameter is no UNC or ISO metric size, so its tensile "
                  "stress area cannot be worked out: give design.code.ase or "
                  "anchorage.tensile_area (A_se)");
}

void rb_case_resolve(rb_cctx *c, rb_case *cs, const rb_ynode *root)
{
    rb_derived d;
    memset(&d, 0, sizeof d);
    int have_model = check_model(c, cs, root, &d);
    if (have_model) {
        resolve_code_ase(c, cs, root);
        rb_case_resolve_concrete(c, cs);
        check_sweeps(c, cs, &d);
    }
    if (c->n_motions == 0)
        return;
    size_t n_targets, n = count_motions(c, &n_targets);
    if (n == 0)
        return;
    cs->motions = calloc(n, sizeof *cs->motions);
    cs->targets = n_targets ? calloc(n_targets, sizeof *cs->targets) : NULL;
    if (!cs->motions || (n_targets && !cs->targets)) {
        c->nomem = 1;
        return;
    }
    cs->n_motions = n;
    double rows = 0, dt = c->history_dt_s > 0 ? c->history_dt_s
                                               : RB_CASE_HISTORY_DT_DEFAULT_S;
    int over = 0;
    size_t at = 0;
    /* the targets of the suites to generate, by entry: they are generated
     * only once the whole case is known good (a suite takes seconds, and a
     * typo elsewhere must not wait for it) */
    rb_case_target **suite = calloc(c->n_motions, sizeof *suite);
    if (!suite) {
        c->nomem = 1;
        return;
    }
    for (size_t i = 0; i < c->n_motions && !c->nomem; i++) {
        const rb_cmotion *cm = &c->motions[i];
        size_t first = at;
        at += cm->synthetic ? (size_t)cm->count : 1;
        if (!cm->ok)
            continue;
        rb_case_target *ct = NULL;
        if (cm->synthetic || cm->judged) {
            ct = &cs->targets[cs->n_targets];
            if (!rb_case_make_target(c, cm, ct)) {
                free(ct->file);
                continue;
            }
            cs->n_targets++;
            if (!rb_case_accept_rules(c, cm, have_model ? &cs->model : NULL, ct))
                continue;
        }
        if (cm->synthetic) {
            if (!rb_case_check_suite(c, cm, ct, at - first))
                continue;
            suite[i] = ct;
        } else if (!build_motion(c, cm, &cs->motions[first], &d, have_model)
                   || !build_vertical(c, cm, &cs->motions[first], &d, have_model)) {
            continue;
        } else if (ct) {
            /* judged against its target, not matched to it */
            cs->motions[first].target = &ct->target;
            cs->motions[first].rules = &ct->rules;
        }
        for (size_t j = first; j < at; j++) {
            /* the history a run would record, asked for or not: whether a
             * case is refused must not depend on the outputs requested */
            double run_s = cm->synthetic ? rb_case_suite_duration(cm)
                                         : cs->motions[j].motion.duration_s;
            rows += floor(run_s / dt) + 2;
            if (rows > RB_CASE_MAX_HISTORY_ROWS && !over) {
                over = 1;
                const rb_ynode *v = c->history_dt_node ? c->history_dt_node : cm->map;
                rb_cctx_error_at(c, RB_ERR_LIMIT, v->file, v->line, v->col,
                                 c->history_dt_node ? "analysis.output_interval" : cm->key,
                                 "the time history would hold over %.0f rows (the limit)"
                                 " at %g s intervals by %s, which lasts %g s: give a "
                                 "longer output_interval or shorter runs",
                                 RB_CASE_MAX_HISTORY_ROWS, dt, cm->key, run_s);
            }
        }
    }
    at = 0;
    for (size_t i = 0; i < c->n_motions && c->n_errors == 0 && !c->nomem; i++) {
        const rb_cmotion *cm = &c->motions[i];
        size_t first = at;
        at += cm->synthetic ? (size_t)cm->count : 1;
        if (suite[i])
            rb_case_build_suite(c, cm, suite[i], &cs->motions[first], at - first);
    }
    free(suite);
}
