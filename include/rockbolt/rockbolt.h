/* rockbolt: seismic anchorage check of rocking equipment restrained by
 * bolts with a gap (El-Hosseny, McMaster University, 1985).
 *
 * One include for the whole public API, and the tool's version. The build
 * also passes the project version as RB_VERSION; a unit test checks that
 * the two agree. */
#ifndef ROCKBOLT_ROCKBOLT_H
#define ROCKBOLT_ROCKBOLT_H

#define RB_VERSION_MAJOR 0
#define RB_VERSION_MINOR 1
#define RB_VERSION_PATCH 0
#define RB_VERSION_STRING "0.1.0"

#include "rockbolt/status.h"
#include "rockbolt/model.h"
#include "rockbolt/motion.h"
#include "rockbolt/solve.h"
#include "rockbolt/criteria.h"
#include "rockbolt/record.h"
#include "rockbolt/units.h"
#include "rockbolt/case.h"
#include "rockbolt/report.h"
#include "rockbolt/design.h"

#endif
