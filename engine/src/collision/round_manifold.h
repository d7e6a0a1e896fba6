#ifndef ROUND_MANIFOLD_H
#define ROUND_MANIFOLD_H

/*
 * The contact manifold of a pair with a round body (a circle or capsule,
 * body.h) and a round body or polygon: each shape is a core (a point, a
 * segment or the polygon) grown by its radius (0 for a polygon), so two
 * shapes are as far apart as their cores less the radii.
 *
 * Cores apart: the nearest features of the two cores give the normal. An
 * edge's interior (a polygon face or a capsule's side) is a reference face
 * and the other core's edge most opposed to it, clipped to the face's side
 * planes, gives up to two points (a capsule lying on a face or a capsule);
 * two vertices (core ends, circle centres, polygon corners) give one point
 * on the line between them, unless both cores have edges and the face
 * that separates most clips the other to points as near (ends lying over
 * each other: two points). Cores overlapping: the face of either core
 * that separates the other's vertices most is the reference, as for
 * polygons. Each point's separation is its distance from the reference
 * face (or vertex) less the radii, exact; the point lies midway between
 * the surfaces. Points are kept while their separation is at most margin
 * (speculative contacts), with ids naming their features (a point cut
 * by clipping, the end it cuts off), or, between two segments (capsules,
 * a chain's run), their order along a's core, whichever face is the
 * reference. The normal points from a toward b.
 *
 * A chain's segment (BODY_SHAPE_SEGMENT) is a core of one face, its free
 * side's; segment_manifold.h applies its chain's rules on top.
 *
 * The same contract as manifold_collide: *separation receives the shapes'
 * separation (their distance when apart, minus the overlap along the
 * normal otherwise); world polygons must be up to date.
 */

#include "dynamics/body_private.h"
#include "collision/manifold_types.h"

manifold_t round_manifold_collide(const body_t *a, const body_t *b, double margin,
                                  manifold_features_t *features, double *separation);

/* The manifold of `other` on a straight face from v1 to v2 whose unit
 * normal points to where other lies: other's core point, or its edge most
 * opposed to the normal clipped to the face's side planes, each point's
 * separation its distance from the face's line less other's radius. The
 * normal points from the face toward other, or the other way when
 * face_is_b. */
manifold_t round_manifold_on_face(vector_t v1, vector_t v2, vector_t normal, const body_t *other,
                                  bool face_is_b, double margin);

#endif // #ifndef ROUND_MANIFOLD_H
