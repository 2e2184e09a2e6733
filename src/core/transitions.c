/* Stage transitions of the restrained-rocking model (Fig. 5.3.b).
 *
 * Each stage watches a few guard functions; a transition is the root of one
 * of them, applied as an instantaneous map of the state: floor impact with
 * restitution (5.17, U' unchanged per 5.20), bolt-head impact (5.14c),
 * release (5.9a), yield, unloading (5.14d), rupture (sec. 5.3). Guards are
 * written so that their sign agrees with the direction the next stage moves
 * in (the uplift guard is the stage-2 moment equation at theta = 0, the bolt
 * force is the stage-4 moment equation), so a transition never lands the
 * state on the wrong side of the boundary it just crossed. */
#include <float.h>
#include <math.h>
#include "bolt.h"
#include "solver.h"

static const int guard_dir[G_COUNT] = {
    [G_UP_POS] = 1, [G_UP_NEG] = 1, [G_FLOOR] = -1, [G_CONTACT] = 1,
    [G_OVERTURN] = 1, [G_SLACK] = -1, [G_YIELD] = 1, [G_UNLOAD] = -1,
    [G_BREAK] = 1, [G_SWITCH] = 0,
};

/* A guard nudged off its boundary (rb_guard_nudge) that reads exactly 0
 * again has not moved at all: the state is still where the last transition
 * put it (theta one rounding step inside the contact angle right after a
 * release, say). Reading that as a crossing would map the state back and
 * forth between two stages without time advancing: a rounding-level
 * chatter of release and bolt impact that only the work bound stopped. */
int rb_guard_crossed(int guard, double a, double b)
{
    switch (guard_dir[guard]) {
    case 1: return a < 0 && (b > 0 || (b == 0 && a != -DBL_MIN));
    case -1: return a > 0 && (b < 0 || (b == 0 && a != DBL_MIN));
    default: return (a < 0 && b >= 0) || (a > 0 && b <= 0);
    }
}

int rb_guard_direction(int guard)
{
    return guard_dir[guard];
}

int rb_guard_stays(int guard, double ga, double reach_a, double gb, double reach_b)
{
    switch (guard_dir[guard]) {
    case 1: return ga + reach_a < 0 && gb + reach_b < 0;
    case -1: return ga - reach_a > 0 && gb - reach_b > 0;
    default: return 0;
    }
}

/* Most turns of the force on the floor are far below uplift (a sixth of
 * the time of a run that never lifts went to finding them). Over a check
 * interval, an eighth of the fastest period, the rate is monotone about
 * its zero (as for the peaks in track.c), so from either end the guard
 * moves by at most dt times that end's rate; the bound takes twice that,
 * from both ends. */
int rb_force_turn_stays(unsigned mask, double dt, double rate_a, double rate_b,
                        const double *ga, const double *gb)
{
    for (unsigned m = mask; m;) {
        int k = rb_guard_next(&m);
        if (!rb_guard_stays(k, ga[k], 2 * dt * rate_a, gb[k], 2 * dt * rate_b))
            return 0;
    }
    return 1;
}

/* A guard that starts a step exactly on its boundary (theta = 0 right after
 * a floor impact or an uplift, the chord = gap right after a release) is
 * counted as just inside its inactive side; otherwise a short excursion that
 * leaves and re-crosses the boundary inside one check interval (a small hop
 * after an impact) would read 0 -> negative and be missed. */
void rb_guard_nudge(double *g)
{
    for (int k = 0; k < G_COUNT; k++)
        if (g[k] == 0 && guard_dir[k] != 0)
            g[k] = guard_dir[k] > 0 ? -DBL_MIN : DBL_MIN;
}

/* The floor is taken to be met a hair below theta = 0. Right after an
 * uplift at the very threshold (uplift moment and restoring moment equal
 * to rounding) theta'' is ~1e-12 and the step's values of theta are
 * rounding noise of either sign; reading -1e-30 rad as a return to the
 * floor sent the plate to rest, whence it lifted again at once, without
 * time advancing. The hair is a thousandth of the rest amplitude: a fall
 * through it gains less than the rest criterion's energy, so it cannot
 * feed a bounce that never comes to rest, and it moves a real impact by
 * about 1e-3 rest_theta / theta'. */
#define RB_FLOOR_SLACK 1e-3

static int row_intact(const rb_solver *sv, int side)
{
    return sv->sys.bolt->rows && !sv->disc.broken[rb_row_of_side(side)];
}

unsigned rb_guard_mask(const rb_solver *sv)
{
    const rb_disc *D = &sv->disc;
    unsigned m = 0;
    int critical = sv->sys.motion->kind == RB_MOTION_CRITICAL;
    switch (D->stage) {
    case RB_STAGE_FIXED:
        return 1u << G_UP_POS | 1u << G_UP_NEG;
    case RB_STAGE_UPLIFT:
        m = 1u << G_FLOOR | 1u << G_OVERTURN;
        if (row_intact(sv, D->side))
            m |= 1u << G_CONTACT;
        break;
    case RB_STAGE_HELD:
        m = 1u << G_SLACK;
        if (sv->sys.bolt->yields)
            m |= 1u << G_YIELD;
        break;
    case RB_STAGE_YIELD:
        m = 1u << G_UNLOAD | 1u << G_OVERTURN;
        if (!sv->opts.stretch_past_failure)
            m |= 1u << G_BREAK;
        break;
    default:
        break;
    }
    if (critical)
        m |= 1u << G_SWITCH;
    return m;
}

double rb_absorbed_at(const rb_solver *sv, int row, const double *y)
{
    const rb_disc *D = &sv->disc;
    if (D->stage != RB_STAGE_YIELD || rb_row_of_side(D->side) != row)
        return D->absorbed[row];
    double th = D->side * y[RB_Y_TH];
    return D->absorbed_entry + sv->sys.d.fy_row_n * (rb_dyn_chord(&sv->sys, th) - D->chord_entry);
}

double rb_absorbed_now(const rb_solver *sv, int row)
{
    return rb_absorbed_at(sv, row, sv->y);
}

/* A row's force as a guard, from an evaluation of the equations. */
static double bolt_guard(const rb_solver *sv, int guard, const rb_aux *a)
{
    return guard == G_YIELD ? a->bolt_force - sv->sys.d.fy_row_n : a->bolt_force;
}

double rb_guard_one(const rb_solver *sv, int guard, double t, const double *y)
{
    const rb_sys *S = &sv->sys;
    const rb_disc *D = &sv->disc;
    double th = D->side * y[RB_Y_TH];
    switch (guard) {
    case G_UP_POS: return rb_dyn_uplift_guard(S, t, y, 1);
    case G_UP_NEG: return rb_dyn_uplift_guard(S, t, y, -1);
    case G_FLOOR: return th + RB_FLOOR_SLACK * sv->rest_theta;
    case G_CONTACT: return th - D->contact[rb_row_of_side(D->side)];
    case G_OVERTURN: return th - S->d.alpha;
    case G_UNLOAD: return D->side * y[RB_Y_THD];
    case G_SWITCH: return y[RB_Y_THD];
    case G_BREAK:
        return rb_absorbed_at(sv, rb_row_of_side(D->side), y) - S->d.capacity_j;
    case G_SLACK:
    case G_YIELD: {
        rb_aux a;
        /* a force law's tension grows with the chord, a function of the
         * angle alone: the row goes slack at the contact angle and
         * reaches Fy at yield_at, and its guards are those angles
         * (rb_guard_angle), found on theta's series like stage 2's */
        if (!S->bolt->rigid_stop)
            return th - (guard == G_SLACK ? D->contact : D->yield_at)[rb_row_of_side(D->side)];
        rb_dyn_rhs(S, D, t, y, NULL, &a);
        return bolt_guard(sv, guard, &a);
    }
    default:
        return 0;
    }
}

int rb_guard_angle(const rb_solver *sv, int guard, double *level)
{
    const rb_disc *D = &sv->disc;
    double th;
    switch (guard) {
    case G_FLOOR: th = -RB_FLOOR_SLACK * sv->rest_theta; break;
    case G_CONTACT: th = D->contact[rb_row_of_side(D->side)]; break;
    case G_OVERTURN: th = sv->sys.d.alpha; break;
    case G_SLACK:
    case G_YIELD:
        if (sv->sys.bolt->rigid_stop)
            return 0;
        th = (guard == G_SLACK ? D->contact : D->yield_at)[rb_row_of_side(D->side)];
        break;
    default: return 0;
    }
    *level = D->side * th;
    return 1;
}

void rb_disc_yield_angles(const rb_sys *S, rb_disc *D)
{
    for (int row = 0; row < 2; row++) {
        D->yield_at[row] = 0;
        if (S->bolt->rigid_stop || !S->bolt->yields)
            continue;
        double chord = D->gap[row] + S->bolt->yield_stretch(S);
        /* a chord past the diameter is never reached */
        D->yield_at[row] = S->form != RB_FORM_SMALL && !(chord < 2 * S->l)
                               ? HUGE_VAL : rb_dyn_contact_angle(S, chord);
    }
}

void rb_guard_eval(const rb_solver *sv, double t, const double *y, double *g)
{
    rb_guard_eval_x(sv, t, y, NAN, NAN, g);
}

/* The guards at (t, y), with the floor x and ge given (x NAN: read
 * here), and where a is given, the evaluation of the equations there. */
static void guard_eval(const rb_solver *sv, double t, const double *y, double x, double ge,
                       const rb_aux *a, double *g)
{
    unsigned mask = rb_guard_mask(sv);
    for (int k = 0; k < G_COUNT; k++)
        g[k] = 0; /* inactive guards are never read as crossings, but are copied */
    /* the rigid bolt's force serves both of stage 4's guards */
    if ((mask & 1u << G_YIELD) && sv->sys.bolt->rigid_stop) {
        rb_aux b;
        if (!a) {
            rb_dyn_rhs(&sv->sys, &sv->disc, t, y, NULL, &b);
            a = &b;
        }
        g[G_SLACK] = bolt_guard(sv, G_SLACK, a);
        g[G_YIELD] = bolt_guard(sv, G_YIELD, a);
        mask &= ~(1u << G_SLACK | 1u << G_YIELD);
    }
    if (mask & 1u << G_UP_POS) {
        if (a)
            rb_dyn_uplift_guards_x(&sv->sys, a->x, a->gz, y, g + G_UP_POS);
        else if (isnan(x))
            rb_dyn_uplift_guards(&sv->sys, t, y, g + G_UP_POS);
        else
            rb_dyn_uplift_guards_x(&sv->sys, x, ge, y, g + G_UP_POS);
        mask &= ~(1u << G_UP_POS | 1u << G_UP_NEG);
    }
    for (unsigned m = mask; m;) {
        int k = rb_guard_next(&m);
        g[k] = rb_guard_one(sv, k, t, y);
    }
}

void rb_guard_eval_x(const rb_solver *sv, double t, const double *y, double x, double ge,
                     double *g)
{
    guard_eval(sv, t, y, x, ge, NULL, g);
}

void rb_guard_eval_aux(const rb_solver *sv, double t, const double *y, const rb_aux *a,
                       double *g)
{
    guard_eval(sv, t, y, NAN, NAN, a, g);
}

static void count_event(rb_solver *sv)
{
    sv->res->events++;
    sv->window_events++;
}

static void bolt_impact(rb_solver *sv);

/* With no gap on the side now loaded, the plate is held at once; a plate
 * still rotating hits the bolt head as it leaves the floor. */
static void enter_stage2_or_4(rb_solver *sv)
{
    rb_disc *D = &sv->disc;
    int row = rb_row_of_side(D->side);
    D->stage = RB_STAGE_UPLIFT;
    if (row_intact(sv, D->side) && D->gap[row] == 0) {
        if (sv->y[RB_Y_THD] != 0) {
            bolt_impact(sv);
            return;
        }
        D->stage = RB_STAGE_HELD;
        D->theta_hold = 0;
    }
}

/* Kinetic energy lost in an instantaneous map goes to the impact account. */
static void impact_loss(rb_solver *sv, double ke_before)
{
    sv->e_impact += ke_before - rb_dyn_kinetic(&sv->sys, &sv->disc, sv->y);
}

static void come_to_rest(rb_solver *sv)
{
    double ke = rb_dyn_kinetic(&sv->sys, &sv->disc, sv->y);
    sv->y[RB_Y_TH] = 0;
    sv->y[RB_Y_THD] = 0;
    sv->disc.stage = RB_STAGE_FIXED;
    sv->disc.side = 0;
    impact_loss(sv, ke);
}

/* Rocking that would rise less than rest_theta after this impact has died
 * out (the thesis's "number of high-frequency impacts" before stage 1): the
 * energy test keeps an endless series of ever smaller impacts finite. */
static void floor_impact(rb_solver *sv)
{
    const rb_sys *S = &sv->sys;
    rb_disc *D = &sv->disc;
    double ke = rb_dyn_kinetic(S, D, sv->y);
    sv->y[RB_Y_TH] = 0;
    sv->y[RB_Y_THD] *= S->d.delta;
    D->side = -D->side;
    sv->res->floor_impacts++;
    impact_loss(sv, ke);
    double thd = sv->y[RB_Y_THD];
    /* the weight the floor gives now: g + z'' under a vertical */
    double W = S->motion->vertical ? S->M * rb_motion_gravity(S->motion, S->d.g, sv->t)
                                   : S->d.W;
    double rise = 0.5 * S->d.Io * thd * thd / (W * S->b);
    if (rise < sv->rest_theta)
        come_to_rest(sv);
    else
        enter_stage2_or_4(sv);
}

/* What the rigid stop hides: a real row of stiffness k_row, met at the
 * chord's speed v by the body's effective mass at the row I_o / l^2,
 * would peak near v sqrt(k_row I_o / l^2) (an undamped elastic stop). */
static void note_impact_force(rb_solver *sv)
{
    const rb_sys *S = &sv->sys;
    double th = sv->disc.side * sv->y[RB_Y_TH], thd = sv->disc.side * sv->y[RB_Y_THD];
    double v = fabs(rb_dyn_lever(S, th) * thd);
    double force = v * sqrt(S->d.k_row_npm * S->d.Io / (S->l * S->l));
    if (force > sv->res->max_bolt_impact_n) {
        sv->res->max_bolt_impact_n = force;
        sv->res->max_bolt_impact_s = sv->t;
    }
}

static void bolt_impact(rb_solver *sv)
{
    const rb_sys *S = &sv->sys;
    rb_disc *D = &sv->disc;
    int row = rb_row_of_side(D->side);
    sv->res->bolt_impacts++;
    D->stage = RB_STAGE_HELD;
    if (!S->bolt->rigid_stop)
        return;
    double ke = rb_dyn_kinetic(S, D, sv->y);
    double th0 = D->contact[row];
    note_impact_force(sv);
    if (!S->model->rigid)
        sv->y[RB_Y_UD] += M_PI * S->h / 2 * sv->y[RB_Y_THD];
    sv->y[RB_Y_TH] = D->side * th0;
    sv->y[RB_Y_THD] = 0;
    D->theta_hold = th0;
    impact_loss(sv, ke);
}

static void release(rb_solver *sv)
{
    rb_disc *D = &sv->disc;
    int row = rb_row_of_side(D->side);
    if (sv->sys.bolt->rigid_stop) {
        sv->y[RB_Y_TH] = D->side * D->theta_hold;
        sv->y[RB_Y_THD] = 0;
    } else {
        /* a spring goes slack where the chord is the gap, which is the
         * contact angle; on it exactly, stage 2's contact guard starts at
         * 0 and is nudged, so that a dip and a new contact within one
         * check interval still reads as a crossing (a rounding step
         * past it read as already in contact, and the plate went on to
         * overturn through the row) */
        sv->y[RB_Y_TH] = D->side * D->contact[row];
    }
    if (D->gap[row] == 0)
        come_to_rest(sv);
    else
        D->stage = RB_STAGE_UPLIFT;
}

static void start_yield(rb_solver *sv)
{
    rb_disc *D = &sv->disc;
    int row = rb_row_of_side(D->side);
    if (sv->sys.bolt->rigid_stop) {
        sv->y[RB_Y_TH] = D->side * D->theta_hold;
        sv->y[RB_Y_THD] = 0;
    }
    D->stage = RB_STAGE_YIELD;
    D->chord_entry = rb_dyn_chord(&sv->sys, D->side * sv->y[RB_Y_TH]);
    D->absorbed_entry = D->absorbed[row];
    if (!sv->res->yielded[row]) {
        sv->res->yielded[row] = 1;
        sv->res->first_yield_s[row] = sv->t;
    }
}

static void stop_yield(rb_solver *sv)
{
    const rb_sys *S = &sv->sys;
    rb_disc *D = &sv->disc;
    int row = rb_row_of_side(D->side);
    double th = D->side * sv->y[RB_Y_TH];
    D->absorbed[row] = rb_absorbed_now(sv, row);
    sv->y[RB_Y_THD] = 0;
    D->gap[row] = rb_dyn_chord(S, th);
    D->contact[row] = th;
    if (!S->bolt->rigid_stop) {
        D->gap[row] -= S->bolt->yield_stretch(S);
        D->contact[row] = rb_dyn_contact_angle(S, D->gap[row]);
        rb_disc_yield_angles(S, D);
    }
    D->theta_hold = th;
    D->stage = RB_STAGE_HELD;
}

static void rupture(rb_solver *sv)
{
    rb_disc *D = &sv->disc;
    int row = rb_row_of_side(D->side);
    D->absorbed[row] = sv->sys.d.capacity_j;
    D->broken[row] = 1;
    sv->res->broken[row] = 1;
    sv->res->break_s[row] = sv->t;
    D->stage = RB_STAGE_UPLIFT;
}

void rb_transition(rb_solver *sv, int guard)
{
    rb_disc *D = &sv->disc;
    count_event(sv);
    switch (guard) {
    case G_UP_POS:
    case G_UP_NEG:
        D->side = guard == G_UP_POS ? 1 : -1;
        sv->res->uplifts++;
        enter_stage2_or_4(sv);
        break;
    case G_FLOOR: floor_impact(sv); break;
    case G_CONTACT: bolt_impact(sv); break;
    case G_SLACK: release(sv); break;
    case G_YIELD: start_yield(sv); break;
    case G_UNLOAD: stop_yield(sv); break;
    case G_BREAK: rupture(sv); break;
    case G_OVERTURN:
        sv->res->overturned = 1;
        sv->res->overturn_side = rb_row_of_side(D->side);
        sv->res->overturn_s = sv->t;
        sv->done = 1;
        break;
    case G_SWITCH:
        sv->y[RB_Y_THD] = 0;
        break;
    default:
        break;
    }
}

int rb_transition_immediate(rb_solver *sv, rb_aux *a)
{
    const rb_sys *S = &sv->sys;
    rb_disc *D = &sv->disc;
    rb_dyn_rhs(S, D, sv->t, sv->y, NULL, a);
    if (D->stage == RB_STAGE_FIXED) {
        double g[2];
        rb_dyn_uplift_guards_x(S, a->x, a->gz, sv->y, g);
        if (g[0] > 0 || g[1] > 0) {
            rb_transition(sv, g[0] > 0 ? G_UP_POS : G_UP_NEG);
            return 1;
        }
        return 0;
    }
    if (D->stage == RB_STAGE_HELD && S->bolt->rigid_stop) {
        if (a->bolt_force <= 0) {
            rb_transition(sv, G_SLACK);
            return 1;
        }
        if (S->bolt->yields && a->bolt_force >= S->d.fy_row_n) {
            rb_transition(sv, G_YIELD);
            return 1;
        }
    }
    return 0;
}
