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
 * on the line between them. Cores overlapping: the face of either core
 * that separates the other's vertices most is the reference, as for
 * polygons. Each point's separation is its distance from the reference
 * face (or vertex) less the radii, exact; the point lies midway between
 * the surfaces. Points are kept while their separation is at most margin
 * (speculative contacts), with ids naming their features. The normal
 * points from a toward b.
 *
 * The same contract as manifold_collide: *separation receives the shapes'
 * separation (their distance when apart, minus the overlap along the
 * normal otherwise); world polygons must be up to date.
 */

#include "dynamics/body_private.h"
#include "collision/manifold_types.h"

manifold_t round_manifold_collide(const body_t *a, const body_t *b, double margin,
                                  manifold_features_t *features, double *separation);

#endif // #ifndef ROUND_MANIFOLD_H
