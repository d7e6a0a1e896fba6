#ifndef BODY_H
#define BODY_H

/*
 * A rigid body: a convex polygon with a mass, a pose (the centroid's position
 * and a rotation angle), a linear and an angular velocity, and the forces and
 * impulses accumulated since its last tick.
 *
 * Units: metres, kilograms, seconds, radians (counter-clockwise positive).
 *
 * The shape is kept relative to the centroid in the body's own frame, so a
 * move rewrites no vertex; world vertices are computed when first asked for
 * after a move.
 *
 * Mass INFINITY makes a body immovable by forces and impulses (a static wall,
 * or a kinematic paddle when it is given a velocity): its inverse mass and
 * inverse moment of inertia are zero.
 *
 * Programmer errors stop the program with a message on stderr that names the
 * function and the problem: a NULL body or shape, a shape that polygon_check
 * refuses (fewer than 3 vertices, non-convex, zero area, NaN), a mass that is
 * NaN, zero or negative, a mass, moment of inertia or centroid that a double
 * cannot carry through a step (below), a non-finite position, velocity,
 * angle, force or impulse, a non-finite query point, a dt that is not finite
 * and > 0, a body_tick whose result is not finite. A clockwise shape is
 * accepted and reversed to counter-clockwise (documented normalisation).
 *
 * Every step divides by the mass and the moment of inertia, so both and their
 * inverses must be finite: a subnormal mass (below about 2.2e-308 kg, where
 * 1 / m overflows) is refused, and so is a finite mass whose moment of
 * inertia on the shape is not finite or has no finite inverse (1e307 kg on a
 * 200 m square; give a body that must not move mass INFINITY instead).
 */

#include <stdbool.h>
#include <stdint.h>
#include "aabb.h"
#include "color.h"
#include "list.h"
#include "polygon.h"
#include "vector.h"
#include "export.h"

JOSTLE_API_BEGIN

typedef struct body body_t;

/*
 * A body of the given shape (a list of heap vector_t *, world coordinates,
 * either winding), mass (kg, > 0, INFINITY allowed) and colour. The body takes
 * ownership of `shape`: it copies the vertices and frees the list at once with
 * list_free, so give the list a freer (free) for its vertices. The caller must
 * not use `shape` afterwards. A clockwise shape is stored reversed, so
 * body_get_shape then lists the vertices in the opposite order. The body
 * starts at rest, rotation 0, with its centroid at the shape's area centroid.
 * Its moment of inertia is that of a uniform polygon of that mass; elasticity
 * 0, friction 0.6. A refused shape or mass aborts with a message naming the
 * function called, e.g. "engine error in body_init: bad shape: polygon is not
 * strictly convex", "engine error in body_init: mass is NaN" or "engine error
 * in body_init: mass 1e-310 kg is too small: its inverse is not finite"; so
 * does a moment of inertia (of the shape with that mass) that is not finite
 * or whose inverse is not, and a shape so large that its centroid is not.
 */
body_t *body_init(list_t *shape, double mass, rgb_color_t color);

/* As body_init, with an info pointer the caller can read back. When
 * info_freer is not NULL, body_free calls it on info. */
body_t *body_init_with_info(list_t *shape, double mass, rgb_color_t color, void *info,
                            free_func_t info_freer);

/* As body_init_with_info, for a shape already in the body's own frame: the
 * vertices are taken relative to the centroid and kept exactly as given
 * (body_init subtracts the area centroid it computes, which rounds), so a
 * body rebuilt from another's body_get_local_polygon, mass and pose is the
 * same to the bit. The area centroid of the vertices must lie within a
 * thousandth of the shape's radius of the origin ("bad shape: its centroid
 * (...) is not at the origin"). The body starts at the origin. */
body_t *body_init_centred(list_t *shape, double mass, rgb_color_t color, void *info,
                          free_func_t info_freer);

/*
 * Round bodies. A circle (centre, radius) or a capsule (the centres p1, p2
 * of its two end circles and their radius: a rounded box), of uniform
 * density and the given mass (kg, > 0, INFINITY allowed), at rest, rotation
 * 0, its centroid at the circle's centre or the midpoint of p1 and p2. Area,
 * centroid and moment of inertia are exact: a disc's m r^2 / 2; a capsule's
 * its rectangle's plus its two half-discs' about the centroid (parallel-axis
 * theorem). Contacts, find_collision, body_get_bounds and
 * body_contains_point use the exact round shape.
 *
 * The seed's polygon functions see a round body's outline: a convex polygon
 * with its vertices on the boundary (32 for a circle, 17 on each end of a
 * capsule, the first of a circle at angle 0 from the centre), which
 * body_get_shape returns (a new list, as for a polygon), body_get_polygon
 * and body_get_local_polygon view. The scene's queries (query.h) and the
 * search for the moment of an impact within a step use the exact shape.
 *
 * A radius that is not finite or not > 0, a non-finite centre or end, and
 * the mass errors of body_init stop the program: "engine error in
 * body_init_circle: radius must be finite and > 0 (got 0)". Capsule ends
 * that are equal make a circle; ends closer than 1e-9 of the radius but
 * not equal are refused ("ends ... are closer than ..."), as is a shape
 * whose area or moment of inertia does not fit a double.
 */
body_t *body_init_circle(vector_t center, double radius, double mass, rgb_color_t color);
body_t *body_init_circle_with_info(vector_t center, double radius, double mass,
                                   rgb_color_t color, void *info, free_func_t info_freer);
body_t *body_init_capsule(vector_t p1, vector_t p2, double radius, double mass,
                          rgb_color_t color);
body_t *body_init_capsule_with_info(vector_t p1, vector_t p2, double radius, double mass,
                                    rgb_color_t color, void *info, free_func_t info_freer);

/*
 * Chains: static geometry made of line segments (a floor, a slope, a
 * terrain outline, a closed loop). points[0 .. count) (world coordinates,
 * copied) are joined in order by segments, and the last back to the first
 * when loop is true. A chain collides on one side only, the left of its
 * direction: a floor listed left to right is solid from above, a loop listed
 * counter-clockwise keeps bodies inside it and one listed clockwise keeps
 * them out. Joins are smooth: each segment knows the points before and after
 * it, so a body sliding or rolling over a join meets one surface and does
 * not catch on the corner where two segments meet, and the segments of a
 * straight run act as one long segment. The ends of an open chain are
 * rounded corners.
 *
 * A chain is static: mass, moment of inertia and the default material as a
 * body of mass INFINITY. Its frame is the world's as made (centroid (0, 0),
 * rotation 0); body_set_centroid and body_set_rotation move and turn that
 * frame and the segments with it. A nonzero velocity or angular velocity,
 * or a finite moment of inertia, stops the program: a chain does not move.
 *
 * The seed's polygon functions see its points, in order, relative to that
 * frame: body_get_shape returns them (a new list), body_get_polygon and
 * body_get_local_polygon view them, their normals those of the edges from
 * each point to the next (the last to the first). The points are not a
 * convex polygon: the polygon functions' areas and centroids mean nothing
 * for them. body_get_bounds is the box of the points; body_contains_point
 * is whether the point lies on a segment; find_collision, the contact
 * record and the queries use the segments.
 *
 * Refused, stopping the program: fewer than 2 points (3 for a loop), a
 * NULL list, a point that is not finite, two consecutive points that are
 * equal (a segment of zero length), a loop's last point equal to its first
 * ("engine error in body_init_chain: segment 3 from (1, 0) to (1, 0) has
 * zero length").
 */
body_t *body_init_chain(const vector_t *points, size_t count, bool loop, rgb_color_t color);
body_t *body_init_chain_with_info(const vector_t *points, size_t count, bool loop,
                                  rgb_color_t color, void *info, free_func_t info_freer);

/* What a body's shape is. */
typedef enum {
    BODY_SHAPE_POLYGON = 0,
    BODY_SHAPE_CIRCLE,
    BODY_SHAPE_CAPSULE,
    BODY_SHAPE_CHAIN,
} body_shape_kind_t;

/* A chain's segments: how many (0 for another body), and segment i's world
 * ends (from point i to point i + 1). */
size_t body_get_segment_count(body_t *body);
void body_get_segment(body_t *body, size_t index, vector_t *p1, vector_t *p2);
/* Whether a chain closes into a loop (false for another body). */
bool body_is_loop(body_t *body);

body_shape_kind_t body_get_shape_kind(body_t *body);

/* The radius of a circle or capsule (m); 0 for a polygon. */
double body_get_round_radius(body_t *body);

/* The world centres of a round body's core: a capsule's two end centres, a
 * circle's centre twice; a polygon's centroid twice. */
void body_get_core(body_t *body, vector_t *p1, vector_t *p2);

/* Frees the body, and its info with its info_freer when there is one. A
 * body that a scene owns, or that a force creator of a scene names, is
 * refused (the program stops): the scene frees it; body_remove it instead,
 * or free a named body that was never added after scene_free. */
void body_free(body_t *body);

/* A new list of new vector_t *: the current world vertices, counter-clockwise.
 * The caller frees it (list_free frees the vectors too). */
list_t *body_get_shape(body_t *body);

/* The current world polygon without copying (see polygon_t for how long the
 * view stays valid). */
polygon_t body_get_polygon(body_t *body);

/* The shape in the body's own frame (relative to its centroid, at angle 0),
 * counter-clockwise, without copying; it never changes and lives as long
 * as the body. */
polygon_t body_get_local_polygon(body_t *body);

vector_t body_get_centroid(body_t *body);
vector_t body_get_velocity(body_t *body);
double body_get_mass(body_t *body);
rgb_color_t body_get_color(body_t *body);
/* The rotation angle (radians) relative to the shape as given to body_init. */
double body_get_rotation(body_t *body);
void *body_get_info(body_t *body);

/* Moves the body so that its centroid is at x (the shape moves with it). */
void body_set_centroid(body_t *body, vector_t x);
void body_set_velocity(body_t *body, vector_t v);
/* Sets the absolute rotation angle (radians), turning the shape about its
 * centroid. */
void body_set_rotation(body_t *body, double angle);
void body_set_color(body_t *body, rgb_color_t color);

/* Adds a force (N) through the centroid, acting until the next tick. */
void body_add_force(body_t *body, vector_t force);

/* Whether the scene's world contacts have put the body to sleep
 * (scene_set_sleeping): it rests and takes no part in steps until touched
 * by a moving body, or until a pose, velocity, inertia, filter, a different
 * friction or elasticity, a nonzero force, torque or impulse is set on it
 * or a body of its resting group is removed (it wakes at once), or until a
 * body it touches, a static one included, changes so (its box before or
 * after the change overlaps the sleeper's: it wakes at the start of the
 * next scene_tick), or gravity changes (scene_set_gravity). */
bool body_is_sleeping(body_t *body);

/* Adds an impulse (N s) through the centroid, applied at the next tick. */
void body_add_impulse(body_t *body, vector_t impulse);

/*
 * Advances the body by dt seconds (finite, > 0) with the seed scheme:
 * v' = v + (F / m) dt + J / m and x' = x + dt (v + v') / 2, and likewise for
 * the angle with torque, angular impulse and the moment of inertia; then the
 * accumulated force and impulse are cleared. A result that is not finite
 * stops the program, naming what overflowed and why, e.g. "engine error in
 * body_tick: position is not finite after integrating with dt = 10 s; likely
 * cause: dt is too large for its velocity (1e+308, 0) m/s: ...".
 */
void body_tick(body_t *body, double dt);

/* Clears the accumulated force, torque, impulse and angular impulse. */
void body_reset(body_t *body);

/* Marks the body for removal by its scene at the end of the next scene_tick
 * (idempotent). */
void body_remove(body_t *body);

bool body_is_removed(body_t *body);

/* Additions beyond the seed API: rotation. */

/* Angular velocity (rad/s, counter-clockwise positive). */
double body_get_angular_velocity(body_t *body);
void body_set_angular_velocity(body_t *body, double omega);

/* Moment of inertia about the centroid (kg m^2); INFINITY for static bodies. */
double body_get_inertia(body_t *body);
/* Overrides the moment of inertia (> 0, INFINITY keeps the body from
 * turning); one whose inverse is not finite (subnormal) is refused. */
void body_set_inertia(body_t *body, double inertia);

/* Adds a torque (N m) acting until the next tick. */
void body_add_torque(body_t *body, double torque);

/* Adds a force (N) acting at a world point: a force through the centroid plus
 * the torque (point - centroid) x force. */
void body_add_force_at(body_t *body, vector_t force, vector_t point);

/* Adds an impulse (N s) at a world point: linear impulse plus angular impulse
 * (point - centroid) x impulse, applied at the next tick. */
void body_add_impulse_at(body_t *body, vector_t impulse, vector_t point);

/* The velocity (m/s) of the material point of the body now at world point p
 * (finite): v + omega x (p - centroid). */
vector_t body_get_point_velocity(body_t *body, vector_t point);

/* Additions: contact material and filtering (used by world contacts). */

/* Elasticity (coefficient of restitution, >= 0) used by world contacts;
 * default 0. A pair combines by taking the larger of the two. */
double body_get_elasticity(body_t *body);
void body_set_elasticity(body_t *body, double elasticity);

/* Coulomb friction coefficient (>= 0) used by world contacts; default 0.6. A
 * pair combines by the geometric mean sqrt(mu1 mu2). */
double body_get_friction(body_t *body);
void body_set_friction(body_t *body, double friction);

/*
 * Which world contacts the body takes part in. Two bodies collide when
 * (a.category & b.mask) and (b.category & a.mask) are both non-zero and they
 * do not share a non-zero group. Default: category 1, mask all bits, group 0.
 */
void body_set_collision_filter(body_t *body, uint32_t category, uint32_t mask, uint32_t group);

/* The filter as set last (or the default); a NULL pointer skips its part. */
void body_get_collision_filter(body_t *body, uint32_t *category, uint32_t *mask,
                               uint32_t *group);

/* The world axis-aligned bounding box of the current polygon. */
aabb_t body_get_bounds(body_t *body);

/* Whether world point p (finite) lies inside the body's polygon or on its
 * boundary. */
bool body_contains_point(body_t *body, vector_t point);

/* Kinetic energy (J): translational plus rotational; 0 for infinite mass. */
double body_get_kinetic_energy(body_t *body);

JOSTLE_API_END

#endif // #ifndef BODY_H
