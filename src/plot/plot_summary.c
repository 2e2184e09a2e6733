/* The summary tables at the head of the HTML page: the verdict, each
 * motion's verdict and checks, its results, and the anchorage it was
 * judged on, in the case's output units. What a calculation package
 * prints on its first page; the figures and the full text follow. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "plot_internal.h"
#include "report/report_internal.h"
#include "rockbolt/names.h"

static void cell_text(rb_strbuf *b, const char *tag, const char *cls, const char *s)
{
    if (cls)
        rb_strbuf_printf(b, "<%s class=\"%s\">", tag, cls);
    else
        rb_strbuf_printf(b, "<%s>", tag);
    rb_plot_escape(b, s ? s : "");
    rb_strbuf_printf(b, "</%s>", tag);
}

/* v with 3 decimals, or "-" when there is no number */
static void fixed3(double v, char *buf, size_t n)
{
    if (isfinite(v))
        snprintf(buf, n, "%.3f", v);
    else
        snprintf(buf, n, "-");
}

static void cell_num(rb_strbuf *b, double v)
{
    char buf[64];
    fixed3(v, buf, sizeof buf);
    rb_strbuf_printf(b, "<td class=\"num\">%s</td>", buf);
}

static void cell_pair(rb_strbuf *b, double l, double r)
{
    char a[32], c[32];
    fixed3(l, a, sizeof a);
    fixed3(r, c, sizeof c);
    rb_strbuf_printf(b, "<td class=\"num\">%s / %s</td>", a, c);
}

static void cell_sig(rb_strbuf *b, double v)
{
    rb_strbuf_printf(b, "<td class=\"num\">%.4g</td>", v);
}

static double ratio(double a, double b)
{
    return b > 0 ? a / b : (double)NAN;
}

static const char *motion_name(const rb_report_motion *m, size_t i, char *buf, size_t n)
{
    if (m->motion && m->motion->name)
        return m->motion->name;
    snprintf(buf, n, "motion %zu", i + 1);
    return buf;
}

static void verdicts(rb_strbuf *b, const rb_report *rep)
{
    char name[32];
    rb_strbuf_puts(b, "<div class=\"scroll\"><table class=\"checks\">\n<caption>Verdict of "
                      "each motion</caption>\n<tr><th>motion</th><th>verdict</th>"
                      "<th>criteria</th>");
    for (int k = 0; k < RB_N_CHECKS; k++)
        cell_text(b, "th", NULL, rb_check_name((rb_check)k));
    rb_strbuf_puts(b, "<th>what governed</th></tr>\n");
    for (size_t i = 0; i < rep->n_motions; i++) {
        const rb_report_motion *m = &rep->motions[i];
        const rb_verdict *v = &m->verdict;
        rb_strbuf_puts(b, "<tr>");
        cell_text(b, "td", NULL, motion_name(m, i, name, sizeof name));
        cell_text(b, "td", v->pass ? "pass" : "fail", v->pass ? "PASS" : "FAIL");
        cell_text(b, "td", v->criteria_pass ? "pass" : "fail",
                  v->criteria_pass ? "met" : "not met");
        for (int k = 0; k < RB_N_CHECKS; k++)
            cell_text(b, "td", v->check[k] == RB_CHECK_WARNING ? "warn" : NULL,
                      rb_check_status_str(v->check[k]));
        cell_text(b, "td", "reason", v->reason);
        rb_strbuf_puts(b, "</tr>\n");
    }
    rb_strbuf_puts(b, "</table></div>\n");
}

static void results(rb_strbuf *b, const rb_report *rep, const rb_out_units *u)
{
    char name[32];
    rb_strbuf_printf(b, "<div class=\"scroll\"><table class=\"results\">\n<caption>Peaks of "
                        "each motion</caption>\n<tr><th>motion</th><th>peak floor (g)</th>"
                        "<th>&#952; / &#945;</th><th>U / U<sub>static</sub></th>"
                        "<th>frame shear / W</th><th>bolt force / Fy, left / right</th>"
                        "<th>largest bolt force (%s)</th><th>usage, left / right</th>"
                        "</tr>\n", u->force);
    for (size_t i = 0; i < rep->n_motions; i++) {
        const rb_report_motion *m = &rep->motions[i];
        const rb_result *r = m->result;
        rb_strbuf_puts(b, "<tr>");
        cell_text(b, "td", NULL, motion_name(m, i, name, sizeof name));
        if (!r) {
            rb_strbuf_puts(b, "<td colspan=\"7\">no result</td></tr>\n");
            continue;
        }
        cell_num(b, r->peak_floor_mps2 / rep->derived.g);
        cell_num(b, r->max_theta_over_alpha);
        cell_num(b, r->max_u_over_ustatic);
        cell_num(b, ratio(r->max_shear_elastic_n, r->weight_n));
        cell_pair(b, ratio(r->max_bolt_force_n[RB_LEFT], r->fy_row_n),
                  ratio(r->max_bolt_force_n[RB_RIGHT], r->fy_row_n));
        cell_sig(b, fmax(r->max_bolt_force_n[RB_LEFT], r->max_bolt_force_n[RB_RIGHT])
                        / u->force_f);
        cell_pair(b, r->usage[RB_LEFT], r->usage[RB_RIGHT]);
        rb_strbuf_puts(b, "</tr>\n");
    }
    rb_strbuf_puts(b, "</table></div>\n");
}

static void row_num(rb_strbuf *b, const char *what, double v, const char *unit)
{
    char buf[64];
    snprintf(buf, sizeof buf, "%.4g", v);
    rb_strbuf_puts(b, "<tr>");
    cell_text(b, "th", NULL, what);
    rb_strbuf_printf(b, "<td class=\"num\">%s</td>", buf);
    cell_text(b, "td", NULL, unit);
    rb_strbuf_puts(b, "</tr>\n");
}

static void anchorage(rb_strbuf *b, const rb_report *rep, const rb_out_units *u)
{
    const rb_model *m = &rep->kase->model;
    const rb_derived *d = &rep->derived;
    rb_strbuf_puts(b, "<div class=\"scroll\"><table class=\"model\">\n<caption>Cabinet "
                      "and anchorage</caption>\n<tr><th>bolt model</th>");
    cell_text(b, "td", NULL, rb_enum_str(rb_bolt_model_names, (int)m->bolt_model));
    rb_strbuf_puts(b, "<td></td></tr>\n");
    row_num(b, "mass", m->mass_kg / u->mass_f, u->mass);
    row_num(b, "centre of mass above the plate, h", m->cm_height_m / u->length_f, u->length);
    row_num(b, "half width of the plate, b", m->half_width_m / u->length_f, u->length);
    if (m->bolt_model != RB_BOLT_NONE) {
        row_num(b, "bolts per row", m->bolts_per_row, "");
        row_num(b, "pivot to bolt row, l", m->lever_arm_m / u->length_f, u->length);
        row_num(b, "gap", m->gap_m / u->small_length_f, u->small_length);
        row_num(b, "yield force of a row, Fy", d->fy_row_n / u->force_f, u->force);
        row_num(b, "A*", d->a_star_mps2 / d->g, "g");
    }
    rb_strbuf_puts(b, "</table></div>\n");
}

/* The concrete check (a case with concrete:): each mode's strengths, then
 * each motion's demand at its largest 17.8 utilization. */
static void concrete(rb_strbuf *b, const rb_report *rep, const rb_out_units *u)
{
    const rb_anchor_strength *s = &rep->kase->anchor;
    char name[32];
    rb_strbuf_printf(b, "<div class=\"scroll\"><table class=\"concrete\">\n<caption>"
                        "Anchorage in concrete, ACI 318-19 Chapter 17 (%s)</caption>\n"
                        "<tr><th>mode</th><th>clause</th><th>nominal (%s)</th><th>&#966;"
                        "</th><th>seismic</th><th>design (%s)</th></tr>\n",
                     s->ductile ? "ductile" : "not ductile", u->force, u->force);
    for (int k = 0; k < RB_ANCHOR_N_MODES; k++) {
        const rb_anchor_mode_strength *m = &s->mode[k];
        rb_strbuf_puts(b, "<tr>");
        cell_text(b, "td", (k == (int)s->tension_mode || k == (int)s->shear_mode)
                  ? "governs" : NULL, rb_enum_str(rb_anchor_mode_names, k));
        cell_text(b, "td", NULL, rb_anchor_clause((rb_anchor_mode)k));
        if (m->applies) {
            cell_sig(b, m->nominal_n / u->force_f);
            cell_num(b, m->phi);
            cell_num(b, m->seismic);
            cell_sig(b, m->design_n / u->force_f);
        } else {
            rb_strbuf_puts(b, "<td colspan=\"4\">does not apply</td>");
        }
        rb_strbuf_puts(b, "</tr>\n");
    }
    rb_strbuf_puts(b, "</table></div>\n");
    rb_strbuf_printf(b, "<div class=\"scroll\"><table class=\"demand\">\n<caption>Demand "
                        "on the anchorage (17.8, tension and shear at the same instant)"
                        "</caption>\n<tr><th>motion</th><th>utilization</th><th>t (s)</th>"
                        "<th>tension (%s)</th><th>shear (%s)</th><th>governs</th></tr>\n",
                     u->force, u->force);
    for (size_t i = 0; i < rep->n_motions; i++) {
        const rb_report_motion *m = &rep->motions[i];
        const rb_result *r = m->result;
        if (!r || !r->anchor_checked)
            continue;
        rb_strbuf_puts(b, "<tr>");
        cell_text(b, "td", NULL, motion_name(m, i, name, sizeof name));
        cell_num(b, r->anchor_max_ratio);
        cell_num(b, r->anchor_max_s);
        cell_sig(b, r->anchor_tension_n / u->force_f);
        cell_sig(b, r->anchor_shear_n / u->force_f);
        cell_text(b, "td", NULL,
                  rb_enum_str(rb_anchor_mode_names,
                              (int)rb_anchor_governing_mode(s, r->anchor_tension_n,
                                                            r->anchor_shear_n)));
        rb_strbuf_puts(b, "</tr>\n");
    }
    rb_strbuf_puts(b, "</table></div>\n");
}

/* The design (`rockbolt design`): each motion's design factors and
 * recommended gap, in the words of the text report, then the code-static
 * check; the design page's summary as the PDF package has it. */
static void design(rb_strbuf *b, const rb_report *rep, const rb_out_units *u)
{
    const rb_case_design *d = rep->design;
    char name[32], text[640];
    rb_strbuf_puts(b, "<div class=\"scroll\"><table class=\"design\">\n<caption>Design "
                      "factor of each motion: A* over the largest floor peak the design "
                      "withstands</caption>\n<tr><th>motion</th>");
    for (int k = 0; k < RB_N_CRITERIA; k++) {
        rb_strbuf_puts(b, "<th>");
        rb_plot_escape(b, rb_criterion_titles[k]);
        rb_strbuf_puts(b, "</th>");
    }
    rb_strbuf_puts(b, "<th>recommended gap</th></tr>\n");
    for (size_t i = 0; i < rep->n_motions && i < d->n_motions; i++) {
        const rb_motion_design *md = &d->motions[i];
        rb_strbuf_puts(b, "<tr>");
        cell_text(b, "td", NULL, motion_name(&rep->motions[i], i, name, sizeof name));
        for (int k = 0; k < RB_N_CRITERIA; k++) {
            rb_design_factor_describe(&md->factor[k], u, rep->derived.g, text, sizeof text);
            cell_text(b, "td", NULL, text);
        }
        if (md->has_gap)
            rb_gap_describe(&md->gap, u, text, sizeof text);
        cell_text(b, "td", NULL, md->has_gap ? text : "no bolts");
        rb_strbuf_puts(b, "</tr>\n");
    }
    rb_strbuf_puts(b, "</table></div>\n");
    rb_strbuf_puts(b, "<p class=\"criterion\">The recommended gap is bounded by the ");
    rb_plot_escape(b, rb_enum_str(rb_criterion_names, (int)d->gap_criteria.kind));
    rb_strbuf_printf(b, " criterion; the design factor without breaking by usage limit "
                        "%.2f.</p>\n", d->factor_criteria[RB_CRIT_NO_BREAK].usage_limit);
    if (!d->has_code)
        return;
    const rb_code_result *k = &d->code;
    rb_strbuf_printf(b, "<div class=\"scroll\"><table class=\"code\">\n<caption>"
                        "Code-static check, %s</caption>\n",
                     rep->kase->code.edition == RB_ASCE7_16 ? "ASCE 7-16" : "ASCE 7-22");
    row_num(b, "horizontal seismic design force F_p", k->fp_n / u->force_f, u->force);
    row_num(b, "F_p / W_p", k->fp_over_wp, "");
    rb_strbuf_puts(b, "<tr><th>bound</th>");
    cell_text(b, "td", NULL, rb_report_code_bound_str(k->bound));
    rb_strbuf_puts(b, "<td></td></tr>\n");
    row_num(b, "H_f", k->hf, "");
    row_num(b, "R_mu", k->rmu, "");
    row_num(b, "anchor design force", k->fp_anchor_n / u->force_f, u->force);
    row_num(b, "as a floor acceleration", k->accel_astar, "A*");
    row_num(b, "bolt row tension T", k->tension_n / u->force_f, u->force);
    row_num(b, "phi N_sa of a row", k->phi_nsa_n / u->force_f, u->force);
    rb_strbuf_puts(b, "<tr><th>T / phi N_sa</th>");
    cell_num(b, k->ratio);
    int ok = rb_report_code_steel_pass(k);
    cell_text(b, "td", ok ? "pass" : "fail", ok ? "PASS" : "FAIL");
    rb_strbuf_puts(b, "</tr>\n");
    if (k->has_concrete) {
        rb_strbuf_puts(b, "<tr>");
        cell_text(b, "th", NULL, rb_aci17_interaction_clause(k->concrete_clause));
        cell_num(b, k->concrete_utilization);
        ok = rb_report_code_concrete_pass(k);
        cell_text(b, "td", ok ? "pass" : "fail", ok ? "PASS" : "FAIL");
        rb_strbuf_puts(b, "</tr>\n");
    }
    rb_strbuf_puts(b, "</table></div>\n");
}

void rb_plot_summary_tables(rb_strbuf *b, const rb_report *rep)
{
    if (!rep || !rep->kase)
        return;
    const rb_out_units *u = rb_out_units_of(rep->kase->output_units);
    rb_strbuf_printf(b, "<section class=\"summary\">\n<p class=\"verdict %s\">",
                     rep->pass ? "pass" : "fail");
    rb_plot_escape(b, rep->headline);
    rb_strbuf_puts(b, "</p>\n<p class=\"reason\">");
    rb_plot_escape(b, rep->reason);
    rb_strbuf_puts(b, "</p>\n");
    verdicts(b, rep);
    results(b, rep, u);
    anchorage(b, rep, u);
    if (rep->kase->has_concrete)
        concrete(b, rep, u);
    if (rep->design)
        design(b, rep, u);
    rb_strbuf_puts(b, "</section>\n");
}
