/* Figures: the reference cabinet solved through the library with a time
 * history (0.6 A*, 4 Hz: it yields, breaks a row and overturns), drawn as
 * SVG; a hand-made sweep; the HTML page. Checks the structure a reader and
 * a parser rely on: one <path> per series, the event markers, escaped
 * text, no "nan" or "inf" anywhere, decimation of long histories, errors
 * for what cannot be drawn. */
#include <ctype.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "harness.h"
#include "report_fixture.h"
#include "../../src/plot/plot_internal.h"
#include "rockbolt/rockbolt.h"
#include "rockbolt/plot.h"

static report_fixture fx;

static size_t count(const char *s, const char *needle)
{
    size_t n = 0, k = strlen(needle);
    while ((s = strstr(s, needle)) != NULL) {
        n++;
        s += k;
    }
    return n;
}

/* "nan" or "inf" in any case, as printf would write a non-finite double. */
static int has_nonfinite(const char *s)
{
    for (; *s; s++) {
        char a = (char)tolower((unsigned char)s[0]);
        if (!s[1] || !s[2])
            break;
        if ((a == 'n' && tolower((unsigned char)s[1]) == 'a'
             && tolower((unsigned char)s[2]) == 'n')
            || (a == 'i' && tolower((unsigned char)s[1]) == 'n'
                && tolower((unsigned char)s[2]) == 'f'))
            return 1;
    }
    return 0;
}

/* Coordinate pairs in the d of the path with data-series="name". */
static size_t path_points(const char *svg, const char *name, size_t *subpaths)
{
    char key[64];
    const char *p, *d, *end;
    size_t n = 0;
    snprintf(key, sizeof key, "data-series=\"%s\"", name);
    p = strstr(svg, key);
    *subpaths = 0;
    if (!p || !(d = strstr(p, " d=\"")) || !(end = strchr(d + 4, '"')))
        return 0;
    for (p = d + 4; p < end; p++) {
        n += *p == ',';
        *subpaths += *p == 'M';
    }
    return n;
}

static rb_status solve(double a_over_astar, double duration, double dt)
{
    rb_derived d;
    rb_solve_opts o;
    rb_result_free(&fx.res);
    rb_model_derive(&fx.kase.model, &d, NULL);
    fx.cm.motion.amplitude_mps2 = a_over_astar * d.a_star_mps2;
    fx.cm.motion.duration_s = duration;
    rb_solve_opts_init(&o);
    o.history_dt_s = dt;
    rb_status st = rb_solve_run(&fx.kase.model, &fx.cm.motion, &o, &fx.res, NULL);
    rb_judge(&fx.kase.criteria, &fx.res, &fx.rm.verdict);
    rb_report_conclude(&fx.rep);
    return st;
}

static void setup(void)
{
    report_fixture_init(&fx, "pump & <motor> \"A\"", "harmonic <4 Hz> & 'more'", "harmonic");
    rb_report_conclude(&fx.rep);
}

static void test_history_figure(void)
{
    static const char *const series[RB_PLOT_HISTORY_SERIES] = {
        "accel", "theta", "u", "bolt_left", "bolt_right", "shear_frame",
        "shear_total", "energy_left", "energy_right"
    };
    char *svg = NULL;
    rb_diag d;
    size_t i, sub, n_rows;
    rb_diag_clear(&d);
    CHECK(solve(0.6, 8.0, 0.005) == RB_OK);
    CHECK(fx.res.history && fx.res.history->n > 100);
    CHECK(fx.res.overturned && (fx.res.broken[0] || fx.res.broken[1]));
    if (!fx.res.history)
        return;
    n_rows = fx.res.history->n;
    CHECK(rb_plot_history_svg(&fx.rep, 0, &svg, &d) == RB_OK);
    CHECK(svg != NULL);
    if (!svg)
        return;
    CHECK(strncmp(svg, "<svg xmlns=\"http://www.w3.org/2000/svg\"", 39) == 0);
    CHECK(count(svg, "</svg>") == 1);
    CHECK(count(svg, "<path") == RB_PLOT_HISTORY_SERIES);
    for (i = 0; i < RB_PLOT_HISTORY_SERIES; i++) {
        char key[64];
        snprintf(key, sizeof key, "data-series=\"%s\"", series[i]);
        CHECK(count(svg, key) == 1);
    }
    /* markers: every event the result has, and no other */
    CHECK(count(svg, "class=\"marker yield\"") == (size_t)(fx.res.yielded[0] + fx.res.yielded[1]));
    CHECK(count(svg, "class=\"marker break\"") == (size_t)(fx.res.broken[0] + fx.res.broken[1]));
    CHECK(count(svg, "class=\"marker overturn\"") == 1);
    CHECK(strstr(svg, ">overturn ") != NULL);
    /* the stages it went through are shaded, and all five named */
    CHECK(count(svg, "class=\"stage s1\"") > 0);
    CHECK(count(svg, "class=\"stage s2\"") > 0);
    CHECK(count(svg, "class=\"stage s4\"") > 0);
    CHECK(count(svg, "class=\"stage s5\"") > 0);
    CHECK(count(svg, "class=\"stage-key s") == 5);
    /* normalised panels and units */
    CHECK(strstr(svg, "bolt force / Fy (-)") != NULL);
    CHECK(strstr(svg, "energy / capacity (-)") != NULL);
    CHECK(strstr(svg, ">time (s)<") != NULL);
    /* text escaped; the raw name never appears */
    CHECK(strstr(svg, "pump &amp; &lt;motor&gt; &quot;A&quot;") != NULL);
    CHECK(strstr(svg, "harmonic &lt;4 Hz&gt; &amp; &#39;more&#39;") != NULL);
    CHECK(strstr(svg, "<motor>") == NULL);
    CHECK(!has_nonfinite(svg));
    /* short enough to keep every point: one subpath of n points */
    CHECK(n_rows <= 2 * 868);
    CHECK(path_points(svg, "theta", &sub) == n_rows && sub == 1);
    free(svg);

    /* a NaN sample breaks the line instead of reaching the file */
    fx.res.history->theta[n_rows / 2] = NAN;
    fx.res.history->u[n_rows / 3] = HUGE_VAL;
    CHECK(rb_plot_history_svg(&fx.rep, 0, &svg, &d) == RB_OK);
    CHECK(svg && !has_nonfinite(svg));
    CHECK(svg && path_points(svg, "theta", &sub) == n_rows - 1 && sub == 2);
    CHECK(svg && path_points(svg, "u", &sub) == n_rows - 1 && sub == 2);
    CHECK(svg && count(svg, "<path") == RB_PLOT_HISTORY_SERIES);
    free(svg);

    /* no bolts to divide by: engineering units instead */
    fx.res.fy_row_n = 0;
    fx.res.capacity_j = 0;
    CHECK(rb_plot_history_svg(&fx.rep, 0, &svg, &d) == RB_OK);
    CHECK(svg && strstr(svg, "bolt force (kN)") != NULL);
    CHECK(svg && strstr(svg, "absorbed energy (J)") != NULL);
    CHECK(svg && !has_nonfinite(svg));
    free(svg);
    /* in the case's output units */
    fx.kase.output_units = RB_UNITS_US;
    CHECK(rb_plot_history_svg(&fx.rep, 0, &svg, &d) == RB_OK);
    CHECK(svg && strstr(svg, "bolt force (kip)") != NULL);
    CHECK(svg && strstr(svg, "absorbed energy (ft-lbf)") != NULL);
    CHECK(svg && strstr(svg, "base shear / W (-)") != NULL);
    free(svg);
    fx.kase.output_units = RB_UNITS_SI;
}

/* Hysteresis: force against elongation per row, moment against rotation,
 * in the case's output units. */
static void test_hysteresis(void)
{
    char *svg = NULL;
    rb_diag d;
    rb_diag_clear(&d);
    CHECK(solve(0.6, 2.0, 0.005) == RB_OK);
    CHECK(rb_plot_hysteresis_svg(&fx.rep, 0, &svg, &d) == RB_OK);
    CHECK(svg && count(svg, "<path") == 3);
    CHECK(svg && count(svg, "data-series=\"force_left\"") == 1);
    CHECK(svg && count(svg, "data-series=\"force_right\"") == 1);
    CHECK(svg && count(svg, "data-series=\"moment\"") == 1);
    CHECK(svg && strstr(svg, "bolt row force (kN)") != NULL);
    CHECK(svg && strstr(svg, "elongation (mm)") != NULL);
    CHECK(svg && strstr(svg, "(kN-m)") != NULL);
    CHECK(svg && strstr(svg, "pump &amp; &lt;motor&gt;") != NULL);
    CHECK(svg && !has_nonfinite(svg));
    free(svg);
    fx.kase.output_units = RB_UNITS_US;
    CHECK(rb_plot_hysteresis_svg(&fx.rep, 0, &svg, &d) == RB_OK);
    CHECK(svg && strstr(svg, "bolt row force (kip)") != NULL);
    CHECK(svg && strstr(svg, "elongation (in)") != NULL);
    CHECK(svg && strstr(svg, "(kip-in)") != NULL);
    free(svg);
    fx.kase.output_units = RB_UNITS_SI;
    svg = (char *)1;
    CHECK(rb_plot_hysteresis_svg(&fx.rep, 1, &svg, &d) == RB_ERR_INVALID);
    CHECK(svg == NULL);
}

/* Axes follow the data: a response of 0.25 Fy fills its panel (ticks of
 * 0.1, not 0.5 up to 1.5), and the panel says the yield lines are off it. */
static void test_history_scaling(void)
{
    char *svg = NULL;
    rb_diag d;
    size_t i;
    rb_diag_clear(&d);
    CHECK(solve(0.6, 2.0, 0.005) == RB_OK);
    if (!fx.res.history)
        return;
    CHECK(rb_plot_history_svg(&fx.rep, 0, &svg, &d) == RB_OK);
    CHECK(svg && strstr(svg, "off this scale") == NULL);
    CHECK(svg && strstr(svg, ">-1.5<") != NULL);   /* the +-1.1 yield range */
    /* the title names the case and the motion, and what the motion is */
    CHECK(svg && strstr(svg, "(harmonic, 4 Hz)</text>") != NULL);
    free(svg);
    for (i = 0; i < fx.res.history->n; i++) {
        fx.res.history->bolt_force_left[i] *= 0.25;
        fx.res.history->bolt_force_right[i] *= 0.25;
        fx.res.history->energy_left[i] *= 0.1;
        fx.res.history->energy_right[i] *= 0.1;
    }
    CHECK(rb_plot_history_svg(&fx.rep, 0, &svg, &d) == RB_OK);
    CHECK(svg && strstr(svg, "yield at \xc2\xb1" "1 Fy: off this scale") != NULL);
    CHECK(svg && strstr(svg, "break at 1: off this scale") != NULL);
    CHECK(svg && strstr(svg, ">-1.5<") == NULL);
    CHECK(svg && strstr(svg, ">-0.2<") != NULL);
    CHECK(svg && strstr(svg, ">0.2<") != NULL);
    CHECK(svg && !has_nonfinite(svg));
    free(svg);
}

static void test_decimation(void)
{
    char *svg = NULL;
    rb_diag d;
    size_t sub, pts;
    rb_diag_clear(&d);
    CHECK(solve(0.2, 30.0, 0.001) == RB_OK);
    CHECK(fx.res.history && fx.res.history->n > 20000);
    CHECK(rb_plot_history_svg(&fx.rep, 0, &svg, &d) == RB_OK);
    if (!svg)
        return;
    /* two extremes per pixel column of the 868-unit wide panels */
    pts = path_points(svg, "accel", &sub);
    printf("decimation: %zu rows -> %zu points, %zu bytes\n", fx.res.history->n, pts,
           strlen(svg));
    CHECK(pts > 868 && pts <= 2 * 868 + 2);
    CHECK(strlen(svg) < 400000);
    /* the extremes survive: the samples of the largest and smallest floor
     * acceleration are drawn (panels start at x = 100, 868 wide) */
    {
        const rb_history *h = fx.res.history;
        size_t i, imax = 0, imin = 0;
        char at[32];
        const char *path = strstr(svg, "data-series=\"accel\"");
        const char *end = path ? strstr(path, "/>") : NULL;
        for (i = 1; i < h->n; i++) {
            imax = h->accel[i] > h->accel[imax] ? i : imax;
            imin = h->accel[i] < h->accel[imin] ? i : imin;
        }
        CHECK(path && end);
        snprintf(at, sizeof at, "%.1f,", 100 + 868 * (h->t[imax] - h->t[0])
                 / (h->t[h->n - 1] - h->t[0]));
        CHECK(path && (path = strstr(path, at)) != NULL && path < end);
        path = strstr(svg, "data-series=\"accel\"");
        snprintf(at, sizeof at, "%.1f,", 100 + 868 * (h->t[imin] - h->t[0])
                 / (h->t[h->n - 1] - h->t[0]));
        CHECK(path && (path = strstr(path, at)) != NULL && path < end);
    }
    CHECK(!has_nonfinite(svg));
    free(svg);
}

static void test_history_errors(void)
{
    char *svg = (char *)1;
    rb_diag d;
    rb_history *h = fx.res.history;
    rb_diag_clear(&d);
    CHECK(rb_plot_history_svg(&fx.rep, 1, &svg, &d) == RB_ERR_INVALID);
    CHECK(svg == NULL && strstr(d.msg, "no such motion") != NULL);
    fx.res.history = NULL;
    svg = (char *)1;
    CHECK(rb_plot_history_svg(&fx.rep, 0, &svg, &d) == RB_ERR_INVALID);
    CHECK(svg == NULL && strstr(d.msg, "no time history") != NULL);
    /* the report page skips it: text only */
    CHECK(rb_plot_report_html(&fx.rep, "report", &svg, &d) == RB_OK);
    CHECK(svg && count(svg, "<svg") == 0 && strstr(svg, "<pre class=\"report\">report</pre>"));
    free(svg);
    fx.res.history = h;
}

static void test_sweep(void)
{
    rb_sweep_point pts[6];
    rb_sweep s;
    char *svg = NULL;
    rb_diag d;
    size_t i, sub;
    rb_diag_clear(&d);
    memset(pts, 0, sizeof pts);
    memset(&s, 0, sizeof s);
    for (i = 0; i < 6; i++) {
        pts[i].x = 0.5 + 0.2 * (double)i;
        pts[i].max_u_over_ustatic = 2 + (double)i;
        pts[i].max_force_over_fy[RB_LEFT] = 0.3 + 0.1 * (double)i;
        pts[i].max_force_over_fy[RB_RIGHT] = 0.2 + 0.15 * (double)i;
        pts[i].status = RB_OK;
        pts[i].meets = 1;
    }
    pts[3].yielded[RB_RIGHT] = 1;       /* o on the deflection and right curves */
    pts[4].yielded[RB_LEFT] = 1;
    pts[4].broken[RB_LEFT] = 1;         /* x on the deflection and left curves */
    pts[5].status = RB_ERR_STEP_TOO_SMALL;
    pts[5].max_u_over_ustatic = NAN;    /* must not be drawn */
    s.kind = RB_SWEEP_FREQUENCY;
    s.a_star_mps2 = 114.77;
    s.fixed_base_hz = 5;
    s.amplitude_astar = 0.3;
    s.points = pts;
    s.n_points = 6;
    CHECK(rb_plot_sweep_svg(&s, "gap <0.01> & more", &svg, &d) == RB_OK);
    if (!svg)
        return;
    CHECK(count(svg, "<path") == 3);
    CHECK(count(svg, "class=\"mark-yield\"") == 2);
    CHECK(count(svg, "class=\"mark-fail\"") == 2);
    CHECK(path_points(svg, "u_over_ustatic", &sub) == 5 && sub == 1);
    CHECK(strstr(svg, "gap &lt;0.01&gt; &amp; more") != NULL);
    CHECK(strstr(svg, "f / f0") != NULL);
    CHECK(count(svg, "class=\"g-tick\"") == 0);  /* no level axis in g */
    CHECK(strstr(svg, "1 of 6 points have no result") != NULL);
    CHECK(!has_nonfinite(svg));
    free(svg);

    s.kind = RB_SWEEP_AMPLITUDE;
    pts[5].status = RB_OK;
    pts[5].max_u_over_ustatic = 1;
    pts[5].overturned = 1;              /* x on all three curves */
    CHECK(rb_plot_sweep_svg(&s, NULL, &svg, &d) == RB_OK);
    CHECK(svg && strstr(svg, "a / A*") != NULL);
    /* the levels in g as well: 1 A* = 114.77 / 9.80665 g */
    CHECK(svg && count(svg, "class=\"g-tick\"") >= 3);
    CHECK(svg && strstr(svg, "class=\"g-tick\"") && strstr(svg, ">11.7</text>") != NULL);
    CHECK(svg && strstr(svg, ">a (g)<") != NULL);
    CHECK(svg && strstr(svg, "Amplitude response") != NULL);
    CHECK(svg && count(svg, "class=\"mark-fail\"") == 5);
    CHECK(svg && strstr(svg, "have no result") == NULL);
    free(svg);

    s.n_points = 0;
    svg = (char *)1;
    CHECK(rb_plot_sweep_svg(&s, NULL, &svg, &d) == RB_ERR_INVALID);
    CHECK(svg == NULL);
}

static void test_html(void)
{
    const char *svgs[2] = { "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\"></svg>",
                            "<svg xmlns=\"http://www.w3.org/2000/svg\"><text>x</text></svg>" };
    const char *bad[1] = { "<script>alert(1)</script>" };
    char *html = NULL;
    rb_diag d;
    rb_diag_clear(&d);
    CHECK(rb_plot_html_page(NULL, "a<b> & \"c\"", "x < y && z\n\tw\x01\xff\xc2\x85"
                            "\xe2\x80\xae\xef\xbf\xbe", svgs, 2, &html, &d) == RB_OK);
    if (!html)
        return;
    CHECK(strncmp(html, "<!DOCTYPE html>\n<html xmlns=\"http://www.w3.org/1999/xhtml\"", 58) == 0);
    CHECK(strstr(html, "<title>a&lt;b&gt; &amp; &quot;c&quot;</title>") != NULL);
    /* a control character, a byte that is not UTF-8, a C1 control (NEL),
     * an RLO and U+FFFE are shown as the shared escaping shows them */
    CHECK(strstr(html, "<pre class=\"report\">x &lt; y &amp;&amp; z\n\tw\\x01\\xff\\u0085"
                 "\\u202e\\ufffe</pre>") != NULL);
    CHECK(count(html, "<svg") == 2);
    CHECK(strstr(html, "<?xml") == NULL);
    /* nothing from outside the page */
    CHECK(strstr(html, "src=") == NULL && strstr(html, "href=") == NULL
          && strstr(html, "url(") == NULL && strstr(html, "<script") == NULL);
    free(html);
    html = (char *)1;
    CHECK(rb_plot_html_page(NULL, "t", NULL, bad, 1, &html, &d) == RB_ERR_INVALID);
    CHECK(html == NULL && strstr(d.msg, "figure 1") != NULL);

    /* the whole check: one figure per motion with a history */
    CHECK(rb_plot_report_html(&fx.rep, "FAIL: text & <report>", &html, &d) == RB_OK);
    CHECK(html && count(html, "<svg") == 1);
    CHECK(html && count(html, "<path") == RB_PLOT_HISTORY_SERIES);
    CHECK(html && strstr(html, "FAIL: text &amp; &lt;report&gt;") != NULL);
    /* the page's title is the report's headline and the case */
    char title[160];
    snprintf(title, sizeof title, "<title>%s: pump &amp; &lt;motor&gt;", fx.rep.headline);
    CHECK(html && strstr(html, title) != NULL);
    CHECK(html && !has_nonfinite(html));
    free(html);
}

static void test_axis(void)
{
    rb_axis ax;
    char lab[32];
    rb_axis_nice(&ax, 0, 4.68, 5, 1);
    CHECK(ax.lo == 0 && ax.hi == 5 && ax.step == 1 && ax.n_ticks == 6);
    rb_axis_nice(&ax, -1.1, 1.1, 5, 1);
    CHECK_NEAR(ax.lo, -1.5, 1e-12);
    CHECK_NEAR(ax.hi, 1.5, 1e-12);
    CHECK(ax.n_ticks == 7 && ax.decimals == 1);
    rb_axis_label(&ax, ax.ticks[3], lab, sizeof lab);
    CHECK(strcmp(lab, "0.0") == 0);           /* not "-0.0" */
    rb_axis_nice(&ax, 0, 39.99, 10, 0);       /* the time axis stays as given */
    CHECK(ax.lo == 0 && ax.hi == 39.99 && ax.step == 5 && ax.n_ticks == 8);
    rb_axis_nice(&ax, 3, 3, 5, 1);            /* a flat series still has an axis */
    CHECK(ax.hi > ax.lo && ax.n_ticks >= 2);
    rb_axis_nice(&ax, NAN, HUGE_VAL, 5, 1);
    CHECK(isfinite(ax.lo) && isfinite(ax.hi) && ax.hi > ax.lo);
}

/* Log axes: 1-2-5 ends and ticks around the data, positions by log10,
 * something drawable for any input. */
static void test_log_axis(void)
{
    rb_axis ax;
    char lab[32];
    rb_axis_log(&ax, 0.0318, 14.6);
    CHECK(ax.log && ax.lo == 0.02 && ax.hi == 20);
    CHECK(ax.n_ticks == 10 && ax.ticks[0] == 0.02 && ax.ticks[ax.n_ticks - 1] == 20);
    for (int i = 0; i < ax.n_ticks; i++) {
        double m = ax.ticks[i] / pow(10, floor(log10(ax.ticks[i]) + 1e-9));
        CHECK(fabs(m - 1) < 1e-9 || fabs(m - 2) < 1e-9 || fabs(m - 5) < 1e-9);
        CHECK(i == 0 || ax.ticks[i] > ax.ticks[i - 1]);
    }
    CHECK_NEAR(rb_axis_frac(&ax, 0.02), 0, 1e-12);
    CHECK_NEAR(rb_axis_frac(&ax, 20), 1, 1e-12);
    CHECK_NEAR(rb_axis_frac(&ax, sqrt(0.02 * 20)), 0.5, 1e-12);   /* the geometric mean */
    CHECK(!isfinite(rb_axis_frac(&ax, 0)));
    rb_axis_label(&ax, 0.05, lab, sizeof lab);
    CHECK(strcmp(lab, "0.05") == 0);
    rb_axis_label(&ax, 20, lab, sizeof lab);
    CHECK(strcmp(lab, "20") == 0);
    rb_axis_log(&ax, 2, 5);                   /* the ends are ticks already */
    CHECK(ax.lo == 2 && ax.hi == 5 && ax.n_ticks == 2);
    rb_axis_log(&ax, 1e-10, 1e10);            /* 20 decades: powers of 10 only */
    CHECK(ax.n_ticks >= 2 && ax.n_ticks <= RB_PLOT_MAX_TICKS);
    for (int i = 0; i < ax.n_ticks; i++)
        CHECK_NEAR(log10(ax.ticks[i]), round(log10(ax.ticks[i])), 1e-9);
    double bad[][2] = {{0, 0}, {-1, 3}, {NAN, HUGE_VAL}, {3, 3}, {1e-320, 1e308}};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        rb_axis_log(&ax, bad[i][0], bad[i][1]);
        CHECK(isfinite(ax.lo) && isfinite(ax.hi) && ax.lo > 0 && ax.hi > ax.lo);
        CHECK(ax.n_ticks >= 1 && ax.n_ticks <= RB_PLOT_MAX_TICKS);
    }
}

/* The x of the first circle drawn for a limit state. */
static double circle_x(const char *svg, const char *state)
{
    char key[64];
    snprintf(key, sizeof key, "data-limit-state=\"%s\"", state);
    const char *k = strstr(svg, key);
    const char *c = NULL;
    for (const char *p = svg; k && (p = strstr(p, "<circle cx=\"")) && p < k; p++)
        c = p;
    return c ? atof(c + strlen("<circle cx=\"")) : (double)NAN;
}

/* The fragility figure of a hand-made suite whose lift-off (0.035 g) is
 * four hundred times below its overturning (14 g): on the default log
 * axis both are spread over the panel, on a linear one lift-off is
 * squeezed against the axis. */
static void test_fragility_figure(void)
{
    static const double cap_g[4][RB_N_LIMITS] = {
        {3.0, 4.6, 13.0, 0.033, 4.1}, {3.2, 4.7, 14.0, 0.036, 4.3},
        {2.9, 4.8, 12.5, 0.034, 4.0}, {3.4, 4.5, 13.5, 0.037, 4.2}};
    rb_motion_fragility m[4];
    rb_case_fragility f;
    memset(&f, 0, sizeof f);
    f.motions = m;
    f.n_motions = 4;
    f.g_mps2 = 9.80665;
    f.a_star_mps2 = 11.7 * f.g_mps2;
    f.level_mps2 = 0.4 * f.a_star_mps2;
    f.present = (1u << RB_N_LIMITS) - 1;
    f.governing = RB_LIMIT_ANCHORAGE;
    for (int i = 0; i < 4; i++) {
        memset(&m[i], 0, sizeof m[i]);
        for (int k = 0; k < RB_N_LIMITS; k++)
            m[i].capacity_mps2[k] = cap_g[i][k] * f.g_mps2;
    }
    for (int k = 0; k < RB_N_LIMITS; k++) {
        double c[4];
        for (int i = 0; i < 4; i++)
            c[i] = m[i].capacity_mps2[k];
        CHECK(rb_fragility_mle(c, NULL, 4, &f.fit[k]) == RB_OK);
        f.fitted[k] = 1;
    }
    char *log_svg = NULL, *lin_svg = NULL;
    rb_diag d;
    CHECK(rb_plot_fragility_svg(&f, "suite", RB_PLOT_SCALE_LOG, &log_svg, &d) == RB_OK);
    CHECK(rb_plot_fragility_svg(&f, "suite", RB_PLOT_SCALE_LINEAR, &lin_svg, &d) == RB_OK);
    CHECK(log_svg && lin_svg);
    if (!log_svg || !lin_svg)
        goto done;
    CHECK(count(log_svg, "<path") == RB_N_LIMITS && count(lin_svg, "<path") == RB_N_LIMITS);
    /* the governing state is named in the legend and the subtitle */
    CHECK(strstr(log_svg, "anchorage (governs)") && strstr(log_svg, "governs: anchorage"));
    CHECK(!has_nonfinite(log_svg) && !has_nonfinite(lin_svg));
    CHECK(strstr(log_svg, "peak floor acceleration (g), log scale") != NULL);
    CHECK(strstr(lin_svg, "log scale") == NULL);
    CHECK(strstr(log_svg, ">0.02<") && strstr(log_svg, ">20<"));
    /* panel from x = 100 to 868: where the first lift-off and overturn
     * points land, as a fraction of it */
    double lo_log = (circle_x(log_svg, "lift-off") - 100) / 768;
    double ov_log = (circle_x(log_svg, "overturn") - 100) / 768;
    double lo_lin = (circle_x(lin_svg, "lift-off") - 100) / 768;
    CHECK(lo_log > 0.05 && ov_log < 0.97 && ov_log - lo_log > 0.6);
    CHECK(lo_lin >= 0 && lo_lin < 0.01);
    /* on the log axis equal ratios are equal distances */
    rb_axis ax;
    rb_axis_log(&ax, 0.02, 20);
    double want = rb_axis_frac(&ax, 0.033);
    CHECK_NEAR(lo_log, want, 0.01);
    /* a case without concrete: has no anchorage state: its zero
     * capacities neither stretch the log axis nor draw a curve */
    free(log_svg);
    log_svg = NULL;
    f.present &= ~(1u << RB_LIMIT_ANCHORAGE);
    f.fitted[RB_LIMIT_ANCHORAGE] = 0;
    f.governing = RB_LIMIT_FIRST_YIELD;
    for (int i = 0; i < 4; i++)
        m[i].capacity_mps2[RB_LIMIT_ANCHORAGE] = 0;
    CHECK(rb_plot_fragility_svg(&f, "suite", RB_PLOT_SCALE_LOG, &log_svg, &d) == RB_OK);
    CHECK(log_svg && count(log_svg, "<path") == RB_N_LIMITS - 1);
    CHECK(log_svg && !strstr(log_svg, "anchorage") && !has_nonfinite(log_svg)
          && strstr(log_svg, ">0.02<") && strstr(log_svg, ">20<"));
done:
    free(log_svg);
    free(lin_svg);
}

int main(void)
{
    setup();
    test_axis();
    test_log_axis();
    test_fragility_figure();
    test_history_figure();
    test_history_scaling();
    test_hysteresis();
    test_html();
    test_history_errors();
    test_decimation();
    test_sweep();
    rb_result_free(&fx.res);
    TEST_MAIN_END();
}
