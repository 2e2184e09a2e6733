/* rockbolt's value of each row of the thesis table.
 *
 * A row names a case of cases/thesis/, a motion of it and a quantity. The
 * quantity is an evaluator name with an optional argument after ':' and an
 * optional "@-1" that reverses the motion's polarity. Cases are loaded once
 * and every solver run, search and sweep is kept, because many rows read
 * the same run (Table 6.3's 0.4 A* column is Table 6.2's g_r = 0.01 one). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rockbolt/rockbolt.h"
#include "vd.h"

#define PI 3.14159265358979323846
/* The critical-excitation search (Table 3.1) only needs the first
 * half-cycles: above K0 the first one already amplifies the initial angle.
 * The longest half-cycle of the table (theta/alpha = 0.5) is about 0.7 s. */
#define VD_CRITICAL_SEARCH_S 5.0
/* Resolution of that search in K = a / (g alpha): a tenth of the last digit
 * the table prints. */
#define VD_CRITICAL_RESOLUTION 1e-6

typedef struct {
    char *name;
    rb_case c;
    int ok;
    char err[VD_ERR];
} vd_case_slot;

/* One cached number or word, keyed by case, motion and quantity. */
typedef struct {
    char *key;
    int numeric;
    double value;
    char word[32];
    char err[VD_ERR];    /* "" when the value is good */
} vd_cached;

/* One cached solver run. */
typedef struct {
    char *key;
    rb_status st;
    rb_result r;
    char err[VD_ERR];
} vd_run_slot;

/* One cached design-factor search or gap search, keyed by case and motion. */
typedef struct {
    char *key;
    rb_status st;
    char err[VD_ERR];
    rb_design_factor_result f;
    int gap_found;
    double gap_ratio, gap_yield_final_max;
} vd_search_slot;

struct vd_ctx {
    char root[512];
    vd_search_slot *searches;
    size_t n_searches;
    int n_threads;
    vd_case_slot *cases;
    size_t n_cases;
    vd_run_slot *runs;
    size_t n_runs;
    vd_cached *vals;
    size_t n_vals;
    long solver_runs;
};

static char *vd_strdup(const char *s)
{
    size_t n = strlen(s) + 1;
    char *d = malloc(n);
    if (d)
        memcpy(d, s, n);
    return d;
}

/* Grow *arr (of *n elements of size sz) by one zeroed element; NULL on
 * failure. */
static void *grow(void *arr_ptr, size_t *n, size_t sz)
{
    void **arr = arr_ptr;
    char *p = realloc(*arr, (*n + 1) * sz);
    if (!p)
        return NULL;
    *arr = p;
    memset(p + *n * sz, 0, sz);
    return p + (*n)++ * sz;
}

vd_ctx *vd_ctx_new(const char *root, int n_threads)
{
    vd_ctx *c = calloc(1, sizeof *c);
    if (!c)
        return NULL;
    snprintf(c->root, sizeof c->root, "%s", root);
    c->n_threads = n_threads;
    return c;
}

void vd_ctx_free(vd_ctx *c)
{
    if (!c)
        return;
    for (size_t i = 0; i < c->n_cases; i++) {
        free(c->cases[i].name);
        rb_case_free(&c->cases[i].c);
    }
    for (size_t i = 0; i < c->n_runs; i++) {
        free(c->runs[i].key);
        rb_result_free(&c->runs[i].r);
    }
    for (size_t i = 0; i < c->n_vals; i++)
        free(c->vals[i].key);
    for (size_t i = 0; i < c->n_searches; i++)
        free(c->searches[i].key);
    free(c->searches);
    free(c->cases);
    free(c->runs);
    free(c->vals);
    free(c);
}

long vd_ctx_runs(const vd_ctx *c)
{
    return c->solver_runs;
}

/* The loaded case, or NULL with the loader's first message in err. */
static const rb_case *get_case(vd_ctx *c, const char *name, char *err, size_t n)
{
    for (size_t i = 0; i < c->n_cases; i++)
        if (strcmp(c->cases[i].name, name) == 0) {
            if (!c->cases[i].ok)
                snprintf(err, n, "%s", c->cases[i].err);
            return c->cases[i].ok ? &c->cases[i].c : NULL;
        }
    vd_case_slot *s = grow(&c->cases, &c->n_cases, sizeof *s);
    if (!s || !(s->name = vd_strdup(name))) {
        if (s)
            c->n_cases--;
        snprintf(err, n, "out of memory");
        return NULL;
    }
    char path[1024];
    snprintf(path, sizeof path, "%s/cases/thesis/%s", c->root, name);
    rb_diag_list dl = {0};
    rb_status st = rb_case_load(path, &s->c, &dl);
    s->ok = st == RB_OK;
    if (!s->ok) {
        if (dl.n)
            snprintf(s->err, sizeof s->err, "%s:%d:%d: %s: %s", dl.items[0].file,
                     dl.items[0].line, dl.items[0].col, dl.items[0].key,
                     dl.items[0].msg);
        else
            snprintf(s->err, sizeof s->err, "%s: %s", path, rb_status_str(st));
        snprintf(err, n, "%s", s->err);
    }
    rb_diag_list_free(&dl);
    return s->ok ? &s->c : NULL;
}

static const rb_case_motion *get_motion(const rb_case *k, int motion, char *err, size_t n)
{
    if (motion < 1 || (size_t)motion > k->n_motions) {
        snprintf(err, n, "case has %zu motions, row asks for motion %d",
                 k->n_motions, motion);
        return NULL;
    }
    return &k->motions[motion - 1];
}

static vd_run_slot *find_run(vd_ctx *c, const char *key)
{
    for (size_t i = 0; i < c->n_runs; i++)
        if (strcmp(c->runs[i].key, key) == 0)
            return &c->runs[i];
    return NULL;
}

static vd_run_slot *new_run(vd_ctx *c, const char *key)
{
    vd_run_slot *s = grow(&c->runs, &c->n_runs, sizeof *s);
    if (s && !(s->key = vd_strdup(key))) {
        c->n_runs--;
        s = NULL;
    }
    return s;
}

/* Solve case kase, motion 'motion', polarity reversed when flip. */
static const rb_result *get_run(vd_ctx *c, const char *kase, int motion, int flip,
                                char *err, size_t n)
{
    char key[600];
    snprintf(key, sizeof key, "%s#%d%s", kase, motion, flip ? "@-1" : "");
    vd_run_slot *s = find_run(c, key);
    if (!s) {
        const rb_case *k = get_case(c, kase, err, n);
        if (!k)
            return NULL;
        const rb_case_motion *m = get_motion(k, motion, err, n);
        if (!m)
            return NULL;
        if (!(s = new_run(c, key))) {
            snprintf(err, n, "out of memory");
            return NULL;
        }
        rb_motion mo = m->motion;
        if (flip)
            mo.polarity = -mo.polarity;
        rb_diag d;
        rb_diag_clear(&d);
        s->st = rb_solve_run(&k->model, &mo, &k->solve, &s->r, &d);
        c->solver_runs++;
        if (s->st != RB_OK)
            snprintf(s->err, sizeof s->err, "%s: %s", rb_status_str(s->st), d.msg);
    }
    if (s->st != RB_OK) {
        snprintf(err, n, "%s", s->err);
        return NULL;
    }
    return &s->r;
}

/* The critical rectangular excitation of chapter 3, a sign(theta'), with
 * the amplitude of the case's motion, from rest at theta = v1 alpha. */
static rb_status critical_run(vd_ctx *c, const rb_case *k, double K, double v1,
                              double duration_s, rb_result *r, rb_diag *d)
{
    rb_derived dv;
    rb_status st = rb_model_derive(&k->model, &dv, d);
    if (st != RB_OK)
        return st;
    rb_motion mo;
    rb_motion_init(&mo);
    mo.kind = RB_MOTION_CRITICAL;
    mo.amplitude_mps2 = K * dv.g * dv.alpha;
    mo.duration_s = duration_s;
    rb_solve_opts o = k->solve;
    o.theta_init_rad = v1 * dv.alpha;
    c->solver_runs++;
    return rb_solve_run(&k->model, &mo, &o, r, d);
}

/* K = a / (g alpha) of a closed-form motion of case k. */
static double motion_k(const rb_case *k, const rb_motion *m)
{
    rb_derived dv;
    if (rb_model_derive(&k->model, &dv, NULL) != RB_OK)
        return NAN;
    return m->amplitude_mps2 / (dv.g * dv.alpha);
}

static int set_num(vd_cached *v, double x)
{
    v->numeric = 1;
    v->value = x;
    return 1;
}

static int set_word(vd_cached *v, const char *w)
{
    v->numeric = 0;
    snprintf(v->word, sizeof v->word, "%s", w);
    return 1;
}

/* Quantities read off one solver run. Returns 0 if name is not one. */
static int eval_run_quantity(const char *name, const char *arg, const rb_result *r,
                             const rb_case *k, vd_cached *v)
{
    double w = r->weight_n;
    double v0 = k->model.mass_kg * r->peak_floor_mps2;
    double f_peak = fmax(r->max_bolt_force_n[RB_LEFT], r->max_bolt_force_n[RB_RIGHT]);
    if (strcmp(name, "u_over_ustatic") == 0)
        return set_num(v, r->max_u_over_ustatic);
    if (strcmp(name, "u_over_ustatic_nka") == 0)
        /* the mode's own static response N* a / K* = 4 a / (pi w^2) is
         * 32 / pi^3 times pi^2 a / (8 w^2) */
        return set_num(v, r->max_u_over_ustatic * PI * PI * PI / 32.0);
    if (strcmp(name, "shear_elastic_over_w") == 0)
        return set_num(v, r->max_shear_elastic_n / w);
    if (strcmp(name, "shear_total_over_w") == 0)
        return set_num(v, r->max_shear_total_n / w);
    if (strcmp(name, "shear_elastic_over_v0") == 0)
        return set_num(v, r->max_shear_elastic_n / v0);
    if (strcmp(name, "shear_total_over_v0") == 0)
        return set_num(v, r->max_shear_total_n / v0);
    if (strcmp(name, "force_over_fy") == 0) {
        /* arg: the thesis's Fy as a fraction of the case's (0.1 for the
         * runs with bolts ten times stronger) */
        double frac = arg ? atof(arg) : 1.0;
        return set_num(v, f_peak / (frac * r->fy_row_n));
    }
    if (strcmp(name, "final_gap_left") == 0 || strcmp(name, "final_gap_right") == 0) {
        int side = strcmp(name, "final_gap_left") == 0 ? RB_LEFT : RB_RIGHT;
        return set_num(v, r->final_gap_m[side] / k->model.lever_arm_m);
    }
    if (strcmp(name, "usage_left") == 0)
        return set_num(v, r->usage[RB_LEFT]);
    if (strcmp(name, "usage_right") == 0)
        return set_num(v, r->usage[RB_RIGHT]);
    if (strcmp(name, "theta_over_alpha") == 0)
        return set_num(v, r->max_theta_over_alpha);
    if (strcmp(name, "failure") == 0)
        return set_word(v, r->usage[0] >= 1 || r->usage[1] >= 1 || r->broken[0]
                        || r->broken[1] || r->overturned ? "yes" : "no");
    if (strcmp(name, "overturned") == 0)
        return set_word(v, r->overturned ? "overturns" : "rocks");
    if (strcmp(name, "overturn_s") == 0)
        return set_num(v, r->overturned ? r->overturn_s : HUGE_VAL);
    if (strcmp(name, "broken_row") == 0)
        return set_word(v, r->broken[0] && r->broken[1] ? "both"
                        : r->broken[0] ? "left" : r->broken[1] ? "right" : "none");
    if (strcmp(name, "break_s") == 0)
        return set_num(v, fmin(r->broken[0] ? r->break_s[0] : HUGE_VAL,
                               r->broken[1] ? r->break_s[1] : HUGE_VAL));
    if (strcmp(name, "first_yield_row") == 0) {
        if (!r->yielded[0] && !r->yielded[1])
            return set_word(v, "none");
        if (r->yielded[0] && (!r->yielded[1] || r->first_yield_s[0] < r->first_yield_s[1]))
            return set_word(v, "left");
        return set_word(v, "right");
    }
    if (strcmp(name, "yielded_rows") == 0)
        return set_word(v, r->yielded[0] && r->yielded[1] ? "both"
                        : r->yielded[0] ? "left" : r->yielded[1] ? "right" : "none");
    return 0;
}

/* Table 2.2: the overturning threshold of the case's pulse, by the design
 * factor search (free-standing: levels in units of g tan(alpha), the
 * criterion fails on overturning), as K = a / (g alpha). */
static void eval_pulse_threshold(vd_ctx *c, const rb_case *k, const rb_motion *m,
                                 vd_cached *v)
{
    rb_design_factor_result f;
    rb_diag d;
    rb_diag_clear(&d);
    rb_status st = rb_design_factor(&k->model, m, &k->solve, &k->criteria, &k->design,
                                    c->n_threads, NULL, &f, &d);
    if (st != RB_OK) {
        snprintf(v->err, sizeof v->err, "design factor: %s: %s", rb_status_str(st), d.msg);
        return;
    }
    c->solver_runs += f.runs;
    if (f.no_failure) {
        snprintf(v->err, sizeof v->err, "no overturning up to the scan end");
        return;
    }
    rb_motion lo = *m;
    lo.amplitude_mps2 = 0.5 * (f.level_mps2 + f.fail_mps2);
    set_num(v, motion_k(k, &lo));
}

/* Table 3.1: K0, the critical amplitude for steady rocking at v1, by
 * bisection on whether the first half-cycles amplify the initial angle. */
static void eval_critical_k0(vd_ctx *c, const rb_case *k, double v1, vd_cached *v)
{
    double lo = 0.05, hi = 1.0;   /* K < 1: the block does not lift by itself */
    while (hi - lo > VD_CRITICAL_RESOLUTION) {
        double mid = 0.5 * (lo + hi);
        rb_result r;
        rb_diag d;
        rb_diag_clear(&d);
        rb_status st = critical_run(c, k, mid, v1, VD_CRITICAL_SEARCH_S, &r, &d);
        int grows = r.overturned || r.max_theta_over_alpha > v1 * (1 + 1e-7);
        rb_result_free(&r);
        if (st != RB_OK) {
            snprintf(v->err, sizeof v->err, "K = %.6f: %s: %s", mid, rb_status_str(st),
                     d.msg);
            return;
        }
        if (grows)
            hi = mid;
        else
            lo = mid;
    }
    set_num(v, 0.5 * (lo + hi));
}

/* Table 3.1: outcome of one cell, the case's motion amplitude as the
 * critical excitation from v1. */
static void eval_critical_cell(vd_ctx *c, const rb_case *k, const rb_motion *m,
                               double v1, int classify, vd_cached *v)
{
    rb_result r;
    rb_diag d;
    rb_diag_clear(&d);
    rb_status st = critical_run(c, k, motion_k(k, m), v1, m->duration_s, &r, &d);
    if (st != RB_OK)
        snprintf(v->err, sizeof v->err, "%s: %s", rb_status_str(st), d.msg);
    else if (classify)
        /* "oscillatory" when the rotation changes sign more than once before
         * the end: two floor impacts or more */
        set_word(v, r.floor_impacts >= 2 ? "O" : "N");
    else
        set_word(v, r.overturned ? "overturns" : "decays");
    rb_result_free(&r);
}

/* Table 6.1: the worst behaviour of the bolts over frequency sweep i. */
static void eval_sweep_behaviour(vd_ctx *c, const rb_case *k, int i, vd_cached *v)
{
    if (i < 1 || (size_t)i > k->n_sweeps) {
        snprintf(v->err, sizeof v->err, "case has %zu sweeps, row asks for %d",
                 k->n_sweeps, i);
        return;
    }
    rb_sweep s;
    rb_diag d;
    rb_diag_clear(&d);
    rb_status st = rb_sweep_frequency(&k->model, &k->solve, NULL, &k->sweeps[i - 1],
                                      c->n_threads, &s, &d);
    if (st != RB_OK) {
        snprintf(v->err, sizeof v->err, "sweep: %s: %s", rb_status_str(st), d.msg);
        return;
    }
    c->solver_runs += (long)s.n_points;
    int brk = 0, yld = 0, bad = 0;
    for (size_t p = 0; p < s.n_points; p++) {
        const rb_sweep_point *pt = &s.points[p];
        bad |= pt->status != RB_OK;
        brk |= pt->broken[0] || pt->broken[1] || pt->overturned;
        yld |= pt->yielded[0] || pt->yielded[1];
    }
    if (bad)
        snprintf(v->err, sizeof v->err, "a sweep point has no result");
    else
        set_word(v, brk ? "Break" : yld ? "Yield" : "No yield");
    rb_sweep_free(&s);
}

/* The cached search of kind 'd' (design factor) or 'g' (gap) for case
 * kase, motion m; NULL with err filled on failure. */
static const vd_search_slot *get_search(vd_ctx *c, char kind, const char *kase,
                                        int motion, const rb_case *k,
                                        const rb_motion *m, char *err, size_t n)
{
    char key[600];
    snprintf(key, sizeof key, "%c#%s#%d", kind, kase, motion);
    vd_search_slot *s = NULL;
    for (size_t i = 0; i < c->n_searches && !s; i++)
        if (strcmp(c->searches[i].key, key) == 0)
            s = &c->searches[i];
    if (!s) {
        if (!(s = grow(&c->searches, &c->n_searches, sizeof *s))
            || !(s->key = vd_strdup(key))) {
            if (s)
                c->n_searches--;
            snprintf(err, n, "out of memory");
            return NULL;
        }
        rb_diag d;
        rb_diag_clear(&d);
        if (kind == 'd') {
            s->st = rb_design_factor(&k->model, m, &k->solve, &k->criteria,
                                     &k->design, c->n_threads, NULL, &s->f, &d);
            c->solver_runs += s->st == RB_OK ? s->f.runs : 0;
        } else {
            rb_gap_result g;
            s->st = rb_gap_recommend(&k->model, m, &k->solve, &k->criteria, &k->design,
                                     c->n_threads, &g, &d);
            if (s->st == RB_OK) {
                c->solver_runs += g.runs;
                s->gap_found = g.found;
                s->gap_ratio = g.gap_ratio;
                s->gap_yield_final_max = g.yield_final_gap_ratio_max;
                rb_gap_result_free(&g);
            }
        }
        if (s->st != RB_OK)
            snprintf(s->err, sizeof s->err, "%s: %s: %s",
                     kind == 'd' ? "design factor" : "gap search",
                     rb_status_str(s->st), d.msg);
    }
    if (s->st != RB_OK) {
        snprintf(err, n, "%s", s->err);
        return NULL;
    }
    return s;
}

/* Section 6.6: design factor of the case, and the shear at the level found. */
static void eval_design(vd_ctx *c, const char *kase, int motion, const rb_case *k,
                        const rb_motion *m, const char *name, vd_cached *v)
{
    const vd_search_slot *s = get_search(c, 'd', kase, motion, k, m, v->err,
                                         sizeof v->err);
    if (!s)
        return;
    const rb_design_factor_result *f = &s->f;
    if (strcmp(name, "design_factor") == 0) {
        set_num(v, f->factor);
        return;
    }
    if (strcmp(name, "design_level") == 0) {
        set_num(v, f->level_astar);
        return;
    }
    /* design_shear_*: one run at the level found */
    rb_motion at = *m;
    if (at.kind == RB_MOTION_SAMPLED)
        at.scale = f->level_mps2 / rb_motion_peak(m) * m->scale;
    else
        at.amplitude_mps2 = f->level_mps2;
    rb_result r;
    rb_diag d;
    rb_diag_clear(&d);
    rb_status st = rb_solve_run(&k->model, &at, &k->solve, &r, &d);
    c->solver_runs++;
    if (st != RB_OK)
        snprintf(v->err, sizeof v->err, "%s: %s", rb_status_str(st), d.msg);
    else if (!eval_run_quantity(name + strlen("design_"), NULL, &r, k, v))
        snprintf(v->err, sizeof v->err, "unknown quantity '%s'", name);
    rb_result_free(&r);
}

/* Section 6.6: the recommended gap ratio, and the largest final gap of the
 * yielding run the thesis read its recommendation from. */
static void eval_gap(vd_ctx *c, const char *kase, int motion, const rb_case *k,
                     const rb_motion *m, const char *name, vd_cached *v)
{
    const vd_search_slot *s = get_search(c, 'g', kase, motion, k, m, v->err,
                                         sizeof v->err);
    if (!s)
        return;
    if (strcmp(name, "gap_yield_final_max") == 0)
        set_num(v, s->gap_yield_final_max);
    else if (s->gap_found)
        set_num(v, s->gap_ratio);
    else
        snprintf(v->err, sizeof v->err, "no gap in the grid keeps the bolts elastic");
}

/* Section 6.6 as the thesis did it: the case's motion shape at the levels
 * step, 2 step, ... up to top (in A*), the highest level below the first
 * that fails the criteria (0 when the first already fails). The thesis ran
 * its earthquake cases at 0.2, 0.3 and 0.4 A* only. */
static void eval_grid_level(vd_ctx *c, const rb_case *k, const rb_motion *m,
                            const char *arg, vd_cached *v)
{
    double step = atof(arg), top = 0, pass = 0;
    const char *colon = strchr(arg, ':');
    if (colon)
        top = atof(colon + 1);
    rb_derived dv;
    if (!(step > 0) || !(top >= step) || rb_model_derive(&k->model, &dv, NULL) != RB_OK) {
        snprintf(v->err, sizeof v->err, "design_grid_level needs 'step:top' in A* "
                 "and a valid model");
        return;
    }
    for (int i = 1; i * step <= top * (1 + 1e-12); i++) {
        double level = i * step * dv.a_star_mps2;
        rb_motion at = *m;
        if (at.kind == RB_MOTION_SAMPLED)
            at.scale = level / rb_motion_peak(m) * m->scale;
        else
            at.amplitude_mps2 = level;
        /* bolts stretch past their capacity and usage >= 1 fails, as in the
         * thesis's earthquake runs (sec. 6.3) */
        rb_solve_opts o = k->solve;
        o.stretch_past_failure = 1;
        rb_result r;
        rb_diag d;
        rb_diag_clear(&d);
        rb_status st = rb_solve_run(&k->model, &at, &o, &r, &d);
        c->solver_runs++;
        rb_verdict vd;
        if (st == RB_OK)
            rb_judge(&k->criteria, &r, &vd);
        int meets = st == RB_OK && vd.pass;
        rb_result_free(&r);
        if (st != RB_OK) {
            snprintf(v->err, sizeof v->err, "run at %.2f A*: %s: %s", i * step,
                     rb_status_str(st), d.msg);
            return;
        }
        if (!meets)
            break;
        pass = i * step;
    }
    set_num(v, pass);
}

/* Compute the value of (kase, motion, quantity) into v. */
static void compute(vd_ctx *c, const char *kase, int motion, const char *quantity,
                    vd_cached *v)
{
    char name[128], *arg = NULL;
    snprintf(name, sizeof name, "%s", quantity);
    char *at = strchr(name, '@');
    int flip = 0;
    if (at) {
        flip = strcmp(at, "@-1") == 0;
        if (!flip) {
            snprintf(v->err, sizeof v->err, "only '@-1' may follow a quantity");
            return;
        }
        *at = '\0';
    }
    if ((arg = strchr(name, ':')))
        *arg++ = '\0';
    const rb_case *k = get_case(c, kase, v->err, sizeof v->err);
    if (!k)
        return;
    const rb_case_motion *cm = get_motion(k, motion, v->err, sizeof v->err);
    if (!cm)
        return;
    if (strcmp(name, "pulse_threshold_k") == 0) {
        eval_pulse_threshold(c, k, &cm->motion, v);
    } else if (strcmp(name, "critical_k0") == 0 && arg) {
        eval_critical_k0(c, k, atof(arg), v);
    } else if ((strcmp(name, "critical_outcome") == 0
                || strcmp(name, "critical_class") == 0) && arg) {
        eval_critical_cell(c, k, &cm->motion, atof(arg),
                           strcmp(name, "critical_class") == 0, v);
    } else if (strcmp(name, "sweep_behaviour") == 0 && arg) {
        eval_sweep_behaviour(c, k, atoi(arg), v);
    } else if (strcmp(name, "design_grid_level") == 0 && arg) {
        eval_grid_level(c, k, &cm->motion, arg, v);
    } else if (strncmp(name, "design_", 7) == 0) {
        eval_design(c, kase, motion, k, &cm->motion, name, v);
    } else if (strcmp(name, "gap_recommended") == 0
               || strcmp(name, "gap_yield_final_max") == 0) {
        eval_gap(c, kase, motion, k, &cm->motion, name, v);
    } else if (strcmp(name, "u_ratio") == 0 && arg) {
        /* U of this run over U of motion 1 of case arg */
        const rb_result *a = get_run(c, kase, motion, flip, v->err, sizeof v->err);
        const rb_result *b = a ? get_run(c, arg, 1, 0, v->err, sizeof v->err) : NULL;
        if (b)
            set_num(v, a->max_u_m / b->max_u_m);
    } else {
        const rb_result *r = get_run(c, kase, motion, flip, v->err, sizeof v->err);
        if (r && !eval_run_quantity(name, arg, r, k, v))
            snprintf(v->err, sizeof v->err, "unknown quantity '%s'", quantity);
    }
}

static const vd_cached *get_value(vd_ctx *c, const vd_row *row)
{
    char key[600];
    snprintf(key, sizeof key, "%s#%d#%s", row->kase, row->motion, row->quantity);
    for (size_t i = 0; i < c->n_vals; i++)
        if (strcmp(c->vals[i].key, key) == 0)
            return &c->vals[i];
    vd_cached tmp;
    memset(&tmp, 0, sizeof tmp);
    compute(c, row->kase, row->motion, row->quantity, &tmp);
    vd_cached *v = grow(&c->vals, &c->n_vals, sizeof *v);
    if (!v)
        return NULL;
    *v = tmp;
    if (!(v->key = vd_strdup(key))) {
        c->n_vals--;
        return NULL;
    }
    return v;
}

/* Decimals that resolve a tenth of the tolerance (at least 2 significant
 * digits for words-free exact rows). */
static int decimals_for(double tol_abs)
{
    if (!(tol_abs > 0))
        return 4;
    int d = (int)ceil(-log10(tol_abs)) + 1;
    return d < 0 ? 0 : d > 7 ? 7 : d;
}

void vd_evaluate(vd_ctx *c, const vd_row *r, vd_outcome *out)
{
    memset(out, 0, sizeof *out);
    const vd_cached *v = get_value(c, r);
    if (!v) {
        out->verdict = VD_ERROR;
        snprintf(out->error, sizeof out->error, "out of memory");
        return;
    }
    if (v->err[0]) {
        /* a row known to differ may be one rockbolt cannot compute yet; its
         * note says why, and the message is shown with the verdict */
        out->verdict = r->differs_note ? VD_DIFFERS : VD_ERROR;
        snprintf(out->error, sizeof out->error, "%s", v->err);
        snprintf(out->word, sizeof out->word, "-");
        return;
    }
    out->numeric = v->numeric;
    out->value = v->value;
    int within;
    if (r->tol_kind == VD_TOL_EXACT) {
        if (v->numeric) {
            out->verdict = VD_ERROR;
            snprintf(out->error, sizeof out->error,
                     "quantity '%s' is a number; give a numeric tolerance", r->quantity);
            return;
        }
        snprintf(out->word, sizeof out->word, "%s", v->word);
        within = strcmp(v->word, r->thesis) == 0;
    } else {
        if (!v->numeric) {
            out->verdict = VD_ERROR;
            snprintf(out->error, sizeof out->error,
                     "quantity '%s' is a word; its tolerance must be 'exact'", r->quantity);
            return;
        }
        double t = strtod(r->thesis, NULL);
        double tol = r->tol_kind == VD_TOL_REL ? r->tol * fabs(t) : r->tol;
        double diff = v->value - t;
        /* a hair of slack so that a value printed on the boundary agrees */
        if (r->tol_kind == VD_TOL_RANGE) {
            within = v->value >= r->lo - 1e-12 * fabs(r->lo)
                     && v->value <= r->hi + 1e-12 * fabs(r->hi);
            tol = 0.01 * fabs(t);   /* print to a hundredth of the value */
        } else {
            within = isfinite(v->value) && fabs(diff) <= tol * (1 + 1e-12) + 1e-15;
        }
        int dec = decimals_for(tol);
        snprintf(out->word, sizeof out->word, "%.*f", dec, v->value);
        if (!isfinite(v->value))
            snprintf(out->word, sizeof out->word, "%s", v->value > 0 ? "none" : "n/a");
        if (!isfinite(diff))
            snprintf(out->diff, sizeof out->diff, "n/a");
        else if (r->tol_kind == VD_TOL_REL && t != 0)
            snprintf(out->diff, sizeof out->diff, "%+.*f (%+.1f %%)", dec, diff,
                     100.0 * diff / fabs(t));
        else
            snprintf(out->diff, sizeof out->diff, "%+.*f", dec, diff);
    }
    if (r->differs_note)
        out->verdict = within ? VD_AGREES_UNEXPECTED : VD_DIFFERS;
    else
        out->verdict = within ? VD_AGREES : VD_OUT;
}
