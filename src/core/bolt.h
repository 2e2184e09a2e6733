/* Internal: the bolt models behind one interface.
 *
 * A model says whether there are rows at all, whether a row can yield,
 * and how a row meets the plate. A rigid stop (the thesis's rows) holds
 * the plate still in stage 4, meets it with a plastic impact and takes
 * whatever the moment equation leaves (eq. 5.13); the transitions in
 * transitions.c do that for every rigid-stop model. A row that is not a
 * rigid stop is a force law: stage 4 rocks against its tension, and the
 * functions below say what the row does. A new model is a file that fills
 * an rb_bolt_ops, its value in rb_bolt_model (rockbolt/model.h), its name
 * in names.c and its line in bolt.c's table. */
#ifndef RB_BOLT_H
#define RB_BOLT_H

#include "dynamics.h"

struct rb_bolt_ops {
    int rows;         /* 0: free-standing, nothing holds the plate down */
    int yields;       /* a row can reach Fy and yield (stage 5) */
    int rigid_stop;   /* the row is a rigid stop (see above) */
    /* For rows that are not rigid stops (NULL otherwise), at the mirrored
     * angle th of the loaded row's side: */
    /* the row's tension in stage 4: a function of the chord's stretch
     * past the gap that grows with it, so that the row goes slack at the
     * contact angle and reaches Fy at yield_stretch (rb_disc's yield_at) */
    double (*tension)(const rb_sys *S, const rb_disc *D, double th);
    /* the elastic energy the row holds, in stages 2, 4 and 5 */
    double (*stored)(const rb_sys *S, const rb_disc *D, double th);
    /* the elastic stretch at Fy, which a row unloading from yield gives back */
    double (*yield_stretch)(const rb_sys *S);
    /* the fastest frequency the rows add to the response while taut (Hz) */
    double (*frequency_hz)(const rb_sys *S);
    /* A row whose tension is k (chord - gap) while taut: k (N/m). The
     * Taylor steps carry such a row as a series; a force law without it
     * is integrated by Dormand-Prince in stage 4. */
    double (*spring_npm)(const rb_sys *S);
};

/* The operations of a model; never NULL (an unknown value is rigid-plastic). */
const rb_bolt_ops *rb_bolt_ops_of(rb_bolt_model m);

/* The models (bolt_rigid.c, bolt_elastic.c). */
extern const rb_bolt_ops rb_bolt_none, rb_bolt_rigid_plastic, rb_bolt_nonyielding,
    rb_bolt_elastic_plastic;

#endif
