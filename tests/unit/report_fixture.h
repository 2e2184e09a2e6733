/* A report of one harmonic motion on the reference cabinet, for the tests
 * of the outputs built from a report (test_report, test_plot): the case,
 * its motion, the run's result and the report that points at them. Each
 * test then fills the result (by hand or by solving) and concludes it. */
#ifndef RB_TEST_REPORT_FIXTURE_H
#define RB_TEST_REPORT_FIXTURE_H

#include <string.h>
#include "harness.h"
#include "rockbolt/rockbolt.h"

typedef struct {
    rb_case kase;
    rb_case_motion cm;
    rb_result res;
    rb_report_motion rm;
    rb_report rep;
} report_fixture;

/* The case named name at cases/x.yaml, one 4 Hz harmonic motion named
 * motion from source (amplitude and duration left to the test), the
 * default solver options and criteria, the result zero. f must stay where
 * it is: the report points into it. */
static inline void report_fixture_init(report_fixture *f, char *name,
                                       char *motion, char *source)
{
    memset(f, 0, sizeof *f);
    rb_model_reference(&f->kase.model);
    rb_solve_opts_init(&f->kase.solve);
    rb_criteria_init(&f->kase.criteria);
    f->kase.path = "cases/x.yaml";
    f->kase.name = name;
    f->cm.name = motion;
    f->cm.source = source;
    rb_motion_init(&f->cm.motion);
    f->cm.motion.kind = RB_MOTION_HARMONIC;
    f->cm.motion.freq_hz = 4;
    f->kase.motions = &f->cm;
    f->kase.n_motions = 1;
    f->rm.motion = &f->cm;
    f->rm.result = &f->res;
    f->rep.kase = &f->kase;
    CHECK(rb_model_derive(&f->kase.model, &f->rep.derived, NULL) == RB_OK);
    f->rep.motions = &f->rm;
    f->rep.n_motions = 1;
}

#endif
