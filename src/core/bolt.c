/* The table from a model's value to its operations (bolt.h). */
#include "bolt.h"

const rb_bolt_ops *rb_bolt_ops_of(rb_bolt_model m)
{
    switch (m) {
    case RB_BOLT_NONE: return &rb_bolt_none;
    case RB_BOLT_RIGID_PLASTIC: return &rb_bolt_rigid_plastic;
    case RB_BOLT_NONYIELDING: return &rb_bolt_nonyielding;
    case RB_BOLT_ELASTIC_PLASTIC: return &rb_bolt_elastic_plastic;
    }
    return &rb_bolt_rigid_plastic;
}
