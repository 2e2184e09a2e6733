/* The name table of rb_synth_components (rockbolt/synth.h). */
#include "rockbolt/synth.h"

const rb_enum_name rb_synth_components_names[] = {
    {"horizontal", RB_SYNTH_HORIZONTAL}, {"triaxial", RB_SYNTH_TRIAXIAL}, {NULL, 0}};
