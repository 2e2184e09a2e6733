/* Equations of motion of the five stages (thesis sec. 5.4).
 *
 * Everything here is written for rocking about the left edge (mirrored angle
 * th >= 0, right bolt row loaded) in the variables U (top displacement
 * relative to the plate, positive in the tipping direction) and th; the
 * caller's side s maps the physical state by U -> sU, th -> s th, x'' -> s x''.
 *
 * Stage 2 and 5 (eqs. 5.5, 5.6, 5.15) form the 2x2 system
 *   [M*  F*] [U'' ]   [Q_U - C* U' - centrifugal          ]
 *   [F*  J ] [th''] = [Q_th - bolt moment - gyroscopic     ]
 * Formulations differ only in Q_U, Q_th, J and the velocity terms:
 *   large:      Q_U = N*(x'' cos th + g sin th) - K* U, centrifugal N* b th'^2,
 *               Q_th = M R x'' cos(a - th) - W R sin(a - th), J = I_o (as printed);
 *   small:      cos -> 1, sin th -> th, sin(a - th) -> a - th (5.21-5.24, eq. 2.6);
 *   consistent: the lever b of the deformed frame is b - U phi, kept to the
 *               same order in both equations, which makes the pair the
 *               Lagrange equations of the assumed-mode kinematics and closes
 *               the energy balance exactly. The printed equations keep the
 *               U-equation's share of these terms but not the moment
 *               equation's; their difference is the "coupling" work. */
#include <math.h>
#include "bolt.h"


double rb_dyn_contact_angle(const rb_sys *S, double g)
{
    return S->form == RB_FORM_SMALL ? g / S->l : 2 * asin(g / (2 * S->l));
}

/* cos and sin of a rotation; stage 1 (th = 0) skips the library call. */
static void cos_sin(double th, double *c, double *sn)
{
    if (th == 0) {
        *c = 1;
        *sn = 0;
        return;
    }
    *c = cos(th);
    *sn = sin(th);
}

double rb_dyn_chord(const rb_sys *S, double th)
{
    return S->form == RB_FORM_SMALL ? S->l * th : 2 * S->l * sin(th / 2);
}

double rb_dyn_lever(const rb_sys *S, double th)
{
    return S->form == RB_FORM_SMALL ? S->l : S->l * cos(th / 2);
}

/* Generalized loads of the mirrored 2-DOF system at angle th, under the
 * apparent gravity ge = g + z'' (g itself without a vertical). H_U and
 * H_th are the partial derivatives of the height function H whose g H is
 * the potential of rb_dyn_potential: the gravity loads are -ge of them
 * (the large and small U-equations' N* ge sin th aside, which is the
 * printed equations' coupling), and the vertical floor's power is
 * -z'' (H_U U' + H_th th'). */
typedef struct {
    double QU, Qth, J, cent, gyro, in_U, in_th, cpl_U, H_U, H_th;
    double c, sn; /* cos th, sin th */
} rb_loads;

static void loads(const rb_sys *S, double x, double ge, double U, double Ud, double th,
                  double thd, rb_loads *L)
{
    const rb_derived *d = &S->d;
    double g = ge, M = S->M, b = S->b, h = S->h;
    /* d->W to the bit without a vertical */
    double W = ge == d->g ? d->W : M * ge;
    double c, sn;
    rb_eval_memo *memo = S->memo;
    if (!memo)
        cos_sin(th, &c, &sn);
    else {
        if (memo->th != th) {
            cos_sin(th, &memo->c, &memo->sn);
            memo->th = th;
        }
        c = memo->c;
        sn = memo->sn;
    }
    L->c = c;
    L->sn = sn;
    L->H_U = 0;
    switch (S->form) {
    case RB_FORM_SMALL:
        L->in_U = d->Nstar;
        L->in_th = M * d->R;
        L->QU = d->Nstar * (x + g * th) - d->Kstar * U;
        L->Qth = M * d->R * x - W * d->R * (d->alpha - th);
        L->J = d->Io;
        L->cent = d->Nstar * b * thd * thd;
        L->gyro = 0;
        L->cpl_U = d->Nstar * (g * th - b * thd * thd);
        L->H_th = M * d->R * (d->alpha - th);
        return;
    case RB_FORM_CONSISTENT: {
        double Mb = M * b - d->Nstar * U;
        L->in_U = d->Nstar * c;
        L->in_th = Mb * sn + M * h * c;
        L->QU = d->Nstar * (x * c + g * sn) - d->Kstar * U;
        L->Qth = x * L->in_th - g * (Mb * c - M * h * sn);
        L->J = d->Io - 2 * b * d->Nstar * U + d->Mstar * U * U;
        L->cent = (d->Nstar * b - d->Mstar * U) * thd * thd;
        L->gyro = (2 * d->Mstar * U - 2 * b * d->Nstar) * Ud * thd;
        L->cpl_U = 0;
        L->H_U = -d->Nstar * sn;
        L->H_th = Mb * c - M * h * sn;
        return;
    }
    case RB_FORM_LARGE:
        break;
    }
    /* R cos(alpha - th) and R sin(alpha - th) by the angle-difference
     * formulas (R cos alpha = h, R sin alpha = b): one sincos per call */
    L->in_U = d->Nstar * c;
    L->in_th = M * (h * c + b * sn);
    L->QU = d->Nstar * (x * c + g * sn) - d->Kstar * U;
    L->Qth = x * L->in_th - W * (b * c - h * sn);
    L->J = d->Io;
    L->cent = d->Nstar * b * thd * thd;
    L->gyro = 0;
    L->cpl_U = d->Nstar * (g * sn - b * thd * thd);
    L->H_th = M * (b * c - h * sn);
}

/* The vertical floor's power on the body, -z'' dH/dt: the input besides
 * the horizontal's, booked with it (rb_dyn_potential keeps the static g). */
static double vertical_power(const rb_sys *S, double ge, const rb_loads *L, double Ud,
                             double thd)
{
    return -(ge - S->d.g) * (L->H_U * Ud + L->H_th * thd);
}

/* Floor acceleration; the critical excitation takes its sign from theta',
 * and at rest from the side gravity will move the block towards. */
static double floor_accel(const rb_sys *S, double t, const double *y)
{
    double thd = y[RB_Y_THD] != 0 ? y[RB_Y_THD] : -y[RB_Y_TH];
    rb_eval_memo *memo = S->memo;
    if (!memo || S->motion->kind == RB_MOTION_CRITICAL)
        return rb_motion_accel(S->motion, t, thd);
    if (memo->t != t) {
        memo->x = rb_motion_accel(S->motion, t, thd);
        memo->t = t;
    }
    return memo->x;
}

int rb_dyn_rocking(const rb_sys *S, const rb_disc *D)
{
    return D->stage == RB_STAGE_UPLIFT || D->stage == RB_STAGE_YIELD
           || (D->stage == RB_STAGE_HELD && !S->bolt->rigid_stop);
}

/* Bolt moment about the pivot for a rocking stage, and the row tension. */
static double bolt_moment(const rb_sys *S, const rb_disc *D, double th, double *force)
{
    *force = 0;
    if (D->stage == RB_STAGE_YIELD)
        *force = S->d.fy_row_n;
    else if (D->stage == RB_STAGE_HELD && !S->bolt->rigid_stop)
        *force = S->bolt->tension(S, D, th);
    /* slack rows (all of stage 2) need no lever arm and its cosine */
    return *force != 0 ? *force * rb_dyn_lever(S, th) : 0;
}

static void solve_rocking(const rb_sys *S, const rb_disc *D, double x, const double *m,
                          rb_aux *a)
{
    const rb_derived *d = &S->d;
    rb_loads L;
    double U = m[0], Ud = m[1], th = m[2], thd = m[3];
    loads(S, x, a->gz, U, Ud, th, thd, &L);
    double Mb = bolt_moment(S, D, th, &a->bolt_force);
    a->cos_th = L.c;
    a->sin_th = L.sn;
    double Rth = L.Qth - Mb - L.gyro;
    if (S->model->rigid) {
        a->udd = 0;
        a->thdd = Rth / L.J;
    } else {
        double RU = L.QU - d->Cstar * Ud - L.cent;
        double det = d->Mstar * L.J - d->Fstar * d->Fstar;
        a->udd = (L.J * RU - d->Fstar * Rth) / det;
        a->thdd = (d->Mstar * Rth - d->Fstar * RU) / det;
    }
    a->p_input = x * (L.in_U * Ud + L.in_th * thd);
    if (S->motion->vertical)
        a->p_input += vertical_power(S, a->gz, &L, Ud, thd);
    a->p_coupling = L.cpl_U * Ud;
}

/* Stages 1 and 4 (rigid bolts): the plate is still, the frame is an SDOF
 * (5.3c, 5.11) and the bolt force follows from the moment equation (5.13). */
static void solve_still(const rb_sys *S, const rb_disc *D, double x, const double *m,
                        rb_aux *a)
{
    const rb_derived *d = &S->d;
    rb_loads L;
    double U = m[0], Ud = m[1], th = m[2];
    loads(S, x, a->gz, U, Ud, th, 0, &L);
    a->cos_th = L.c;
    a->sin_th = L.sn;
    a->udd = S->model->rigid ? 0 : (L.QU - d->Cstar * Ud) / d->Mstar;
    a->thdd = 0;
    a->bolt_force = 0;
    if (D->stage == RB_STAGE_HELD)
        a->bolt_force = (L.Qth - d->Fstar * a->udd) / rb_dyn_lever(S, th);
    a->p_input = x * L.in_U * Ud;
    if (S->motion->vertical)
        a->p_input += vertical_power(S, a->gz, &L, Ud, 0);
    a->p_coupling = L.cpl_U * Ud;
}

static void mirror(const rb_disc *D, const double *y, double *m)
{
    double s = D->side < 0 ? -1.0 : 1.0;
    m[0] = s * y[RB_Y_U];
    m[1] = s * y[RB_Y_UD];
    m[2] = s * y[RB_Y_TH];
    m[3] = s * y[RB_Y_THD];
}

void rb_dyn_deriv(const rb_sys *S, const rb_disc *D, const double *y, const rb_aux *a,
                  double *dy)
{
    double s = D->side < 0 ? -1.0 : 1.0;
    int moving = rb_dyn_rocking(S, D);
    dy[RB_Y_U] = y[RB_Y_UD];
    dy[RB_Y_UD] = s * a->udd;
    dy[RB_Y_TH] = moving ? y[RB_Y_THD] : 0;
    dy[RB_Y_THD] = moving ? s * a->thdd : 0;
    dy[RB_Y_WDAMP] = S->d.Cstar * y[RB_Y_UD] * y[RB_Y_UD];
    dy[RB_Y_WIN] = a->p_input;
    dy[RB_Y_WCPL] = a->p_coupling;
}

void rb_dyn_rhs(const rb_sys *S, const rb_disc *D, double t, const double *y,
                double *dy, rb_aux *aux)
{
    double s = D->side < 0 ? -1.0 : 1.0, m[4];
    rb_aux a;
    mirror(D, y, m);
    a.x = floor_accel(S, t, y);
    a.gz = rb_motion_gravity(S->motion, S->d.g, t);
    if (D->stage == RB_STAGE_HELD && S->bolt->rigid_stop)
        m[2] = D->theta_hold;
    if (rb_dyn_rocking(S, D))
        solve_rocking(S, D, s * a.x, m, &a);
    else
        solve_still(S, D, s * a.x, m, &a);
    if (dy)
        rb_dyn_deriv(S, D, y, &a, dy);
    if (aux)
        *aux = a;
}

/* Written with the same operations as the stage-4 bolt force at
 * theta = 0 (solve_still), so that the two agree in sign to the last bit:
 * an uplift into a zero gap is never met by a bolt force of the other sign,
 * which would bounce the state between stages 1 and 4 for ever. */
static double uplift_guard_at(const rb_sys *S, double xp, double ge, const double *y,
                              int side)
{
    const rb_derived *d = &S->d;
    rb_disc D = {0};
    rb_loads L;
    double m[4];
    D.side = side;
    D.stage = RB_STAGE_FIXED;
    mirror(&D, y, m);
    double x = (side < 0 ? -1.0 : 1.0) * xp;
    loads(S, x, ge, m[0], m[1], 0, 0, &L);
    if (S->model->rigid)
        return L.Qth;
    double udd = (L.QU - d->Cstar * m[1]) / d->Mstar;
    return L.Qth - d->Fstar * udd;
}

double rb_dyn_uplift_guard(const rb_sys *S, double t, const double *y, int side)
{
    return uplift_guard_at(S, floor_accel(S, t, y), rb_motion_gravity(S->motion, S->d.g, t),
                           y, side);
}

/* one evaluation of the floor for both edges: through a building it is
 * an exponential and a sine and cosine */
void rb_dyn_uplift_guards(const rb_sys *S, double t, const double *y, double *g)
{
    rb_dyn_uplift_guards_x(S, floor_accel(S, t, y), rb_motion_gravity(S->motion, S->d.g, t),
                           y, g);
}

void rb_dyn_uplift_guards_x(const rb_sys *S, double x, double ge, const double *y,
                            double *g)
{
    if (S->form != RB_FORM_LARGE) {
        g[0] = uplift_guard_at(S, x, ge, y, 1);
        g[1] = uplift_guard_at(S, x, ge, y, -1);
        return;
    }
    /* At theta = 0 the large formulation's loads are x M h - W b and
     * N* x - K* U, and the mirror negates x, U and U' exactly, so the
     * other edge's guard is made of the same products with their signs
     * turned: the same bits as uplift_guard_at for each side, at half the
     * cost (the floor stage reads both at every check point). */
    const rb_derived *d = &S->d;
    double p = x * (S->M * S->h), q = (ge == d->g ? d->W : S->M * ge) * S->b;
    if (S->model->rigid) {
        g[0] = p - q;
        g[1] = -p - q;
        return;
    }
    double udd = (d->Nstar * x - d->Kstar * y[RB_Y_U] - d->Cstar * y[RB_Y_UD]) / d->Mstar;
    g[0] = (p - q) - d->Fstar * udd;
    g[1] = (-p - q) + d->Fstar * udd;
}

double rb_dyn_kinetic(const rb_sys *S, const rb_disc *D, const double *y)
{
    const rb_derived *d = &S->d;
    double m[4], J = d->Io;
    mirror(D, y, m);
    if (S->form == RB_FORM_CONSISTENT)
        J = d->Io - 2 * S->b * d->Nstar * m[0] + d->Mstar * m[0] * m[0];
    return 0.5 * d->Mstar * m[1] * m[1] + d->Fstar * m[1] * m[3] + 0.5 * J * m[3] * m[3];
}

double rb_dyn_potential(const rb_sys *S, const rb_disc *D, const double *y)
{
    const rb_derived *d = &S->d;
    double m[4], V;
    mirror(D, y, m);
    double th = m[2];
    switch (S->form) {
    case RB_FORM_SMALL:
        V = d->W * d->R * (d->alpha * th - 0.5 * th * th);
        break;
    case RB_FORM_CONSISTENT:
        V = d->g * ((S->M * S->b - d->Nstar * m[0]) * sin(th) + S->M * S->h * cos(th))
            - d->g * S->M * S->h;
        break;
    case RB_FORM_LARGE:
    default:
        V = d->W * d->R * cos(d->alpha - th) - d->W * S->h;
        break;
    }
    if (S->bolt->stored && D->side != 0 && D->stage != RB_STAGE_FIXED)
        V += S->bolt->stored(S, D, th);
    return V;
}

double rb_dyn_strain(const rb_sys *S, const rb_disc *D, const double *y)
{
    (void)D;
    return 0.5 * S->d.Kstar * y[RB_Y_U] * y[RB_Y_U];
}

/* The same reactions as rb_dyn_reactions, summed over the frame's mass
 * points instead of through the mode's integrals N*, M h and M b: a point
 * at height y sits at p = b - U phi(y) along the base from the pivot, and
 * the floor and bolts give it m (x'' + X'') and m (g + z'' + Z''), z''
 * the floor's own vertical acceleration. Composite
 * Simpson over 2h in RB_REACTION_PANELS panels; only tests pay for it. */
#define RB_REACTION_PANELS 256
void rb_dyn_reactions_points(const rb_sys *S, const rb_disc *D, const double *y,
                             const rb_aux *a, double *horizontal, double *vertical)
{
    double s = D->side < 0 ? -1.0 : 1.0, m[4];
    mirror(D, y, m);
    double U = m[0], Ud = m[1], thd = m[3], Udd = a->udd, thdd = a->thdd;
    double c = a->cos_th, sn = a->sin_th, H = 2 * S->h, dy = H / RB_REACTION_PANELS;
    double sum_x = 0, sum_z = 0;
    for (int i = 0; i <= RB_REACTION_PANELS; i++) {
        double yy = i * dy;
        double w = (i == 0 || i == RB_REACTION_PANELS) ? 1 : (i % 2 ? 4 : 2);
        double phi = sin(M_PI * yy / (2 * H));
        double p = S->b - U * phi, pd = -Ud * phi, pdd = -Udd * phi;
        double Xdd = pdd * c - 2 * pd * sn * thd - p * (sn * thdd + c * thd * thd)
                     - yy * (c * thdd - sn * thd * thd);
        double Zdd = pdd * sn + 2 * pd * c * thd + p * (c * thdd - sn * thd * thd)
                     - yy * (sn * thdd + c * thd * thd);
        sum_x += w * Xdd;
        sum_z += w * Zdd;
    }
    double mass_per_height = S->M / H;
    sum_x *= mass_per_height * dy / 3;
    sum_z *= mass_per_height * dy / 3;
    *horizontal = -(S->M * a->x + s * sum_x);
    *vertical = (a->gz == S->d.g ? S->d.W : S->M * a->gz) + sum_z;
}
