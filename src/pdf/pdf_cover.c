/* The parts every calculation package has, whatever the command: the
 * cover block and the statement of what the tool does not check. */
#include <stdio.h>
#include "pdf_internal.h"
#include "rockbolt/version.h"

/* A cover line, blank when not given, so that a reviewer can write it in. */
static void field(rb_strbuf *b, const char *name, const char *value)
{
    rb_strbuf_printf(b, "| %s | %s\n", name, value ? value : "");
}

void rb_pdf_cover_markup(rb_strbuf *b, const rb_pdf_cover *cv)
{
    const rb_case_project *p = cv->project && cv->project->given ? cv->project : NULL;
    rb_strbuf_printf(b, "= %s\n", cv->title);
    rb_strbuf_puts(b, "|= calculation | \n");
    field(b, "project", p ? p->project : NULL);
    field(b, "client", p ? p->client : NULL);
    field(b, "job number", p ? p->job_number : NULL);
    field(b, "engineer", p ? p->engineer : NULL);
    field(b, "checker", p ? p->checker : NULL);
    field(b, "date", p ? p->date : NULL);
    field(b, "revision", p ? p->revision : NULL);
    if (cv->case_name) {
        field(b, "case", cv->case_name);
        field(b, "case file", cv->case_path);
        field(b, "units", cv->units == RB_UNITS_US ? "US customary" : "SI");
    }
    rb_strbuf_printf(b, "| calculated with | rockbolt %s\n", RB_VERSION_STRING);
    if (cv->verdict)
        field(b, "result", cv->verdict);
    rb_strbuf_puts(b, "\n");
}

/* What a reviewer must not read into a PASS (docs/pdf.md keeps the same
 * list): the model's reach, and what it leaves to the engineer. */
void rb_pdf_limits_markup(rb_strbuf *b)
{
    rb_strbuf_puts(b,
        "# What this calculation does not check\n"
        "- The equipment itself: its frame, its internal components and their "
        "attachments, the base plate and its welds, and whether the equipment "
        "functions after the motion (certification by shake-table test, ASCE 7 "
        "13.2.2 and ICC-ES AC156, is not checked).\n"
        "- The floor and the structure: the floor motion is taken as given, the "
        "floor as rigid; the slab beyond the anchors' failure modes of ACI 318-19 "
        "Chapter 17 (its flexure, punching, the building's response) is not checked.\n"
        "- Vertical floor acceleration, the two horizontal directions at once, and "
        "torsion: the model is planar, rocking in the plane of the motion.\n"
        "- Sliding of an anchored cabinet is reported, not judged: the anchors are "
        "taken to carry the horizontal reaction.\n"
        "- Installation: hole drilling and cleaning, torque, cover and edge distances "
        "as built, corrosion, fatigue, and the qualification of post-installed "
        "anchors beyond the values of their evaluation report given in the case.\n"
        "- Attached conduit, piping and ducts, and pounding against neighbouring "
        "equipment or walls.\n"
        "- The inputs: every number above comes from the case file, which the "
        "engineer of record must check. A run with a validity warning has left what "
        "the model describes; its numbers are estimates.\n");
}
