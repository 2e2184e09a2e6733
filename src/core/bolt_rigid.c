/* The thesis's rows (ch. 5-6) and no rows at all. A rigid stop needs no
 * force law: transitions.c holds the plate still in stage 4 and the moment
 * equation gives the tension (eq. 5.13). */
#include "bolt.h"

/* free-standing: no rows; "rigid" only so that nothing asks for a law */
const rb_bolt_ops rb_bolt_none = {.rows = 0, .yields = 0, .rigid_stop = 1};

/* rigid until Fy, then yields at Fy (the default, ch. 6) */
const rb_bolt_ops rb_bolt_rigid_plastic = {.rows = 1, .yields = 1, .rigid_stop = 1};

/* rigid and never yields (the ch. 5 runs) */
const rb_bolt_ops rb_bolt_nonyielding = {.rows = 1, .yields = 0, .rigid_stop = 1};
