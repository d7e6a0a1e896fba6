#ifndef FORCES_H
#define FORCES_H

/*
 * Force creators for the common forces and collisions. Each create_* function
 * registers a force creator with the scene that depends on the bodies it
 * names, so it is dropped when one of them is removed.
 */

#include <stdbool.h>
#include "body.h"
#include "list.h"
#include "scene.h"
#include "vector.h"
#include "export.h"

JOSTLE_API_BEGIN

/* Newtonian gravity between the centroids of two bodies: each is pulled
 * toward the other with G m1 m2 / r^2 (N). G >= 0 in N m^2 / kg^2. The force
 * is left out while the centroids are closer than a small distance
 * (1e-9 m) to avoid dividing by zero, and whenever a mass is INFINITY (the
 * pull on the other body would be infinite). Huge finite masses are fine as
 * long as the force itself is finite; when it is not, scene_tick stops,
 * naming the pair (scene.h). */
void create_newtonian_gravity(scene_t *scene, double G, body_t *body1, body_t *body2);

/* A Hooke spring of constant k (N/m, >= 0) and rest length 0 between the
 * centroids of two distinct bodies (a spring from a body to itself is
 * refused): each body is pulled toward the other with k |x2 - x1|. With
 * m the reduced mass m1 m2 / (m1 + m2) (the finite one against INFINITY) and
 * omega = sqrt(k / m), the seed and explicit Euler integrators multiply its
 * energy at every step by 1 + (omega dt)^2 / 2 (more once omega dt > 4) and
 * 1 + (omega dt)^2; symplectic Euler keeps it bounded for
 * dt < 2 sqrt(m / k); implicit Euler at every dt, dividing its energy by
 * 1 + (omega dt)^2 every step. A force that is no longer finite stops
 * scene_tick, naming the spring and that limit. */
void create_spring(scene_t *scene, double k, body_t *body1, body_t *body2);

/* A Hooke spring of constant k (N/m, >= 0) and rest length L (m, finite and
 * >= 0) between the centroids of two distinct bodies: with d the distance
 * between them and u the unit vector from body1 toward body2, body1 is
 * pulled along u with k (d - L) (pushed back while d < L) and body2 the
 * opposite way; its energy is k (d - L)^2 / 2. The force is left out while
 * the centroids coincide (no direction to push along). Along the spring it
 * is as stiff as create_spring's, so the integrators' limits above hold with
 * the same omega; implicit Euler takes it at the end of the step too, its
 * stiffness across the spring, k (1 - L / d), left out while d < L (the
 * spring pushes there, and that part stays explicit). L = 0 is
 * create_spring's force to rounding. */
void create_spring_with_length(scene_t *scene, double k, double rest_length, body_t *body1,
                               body_t *body2);

/* Linear drag -gamma v (gamma in kg/s, >= 0) on body's centroid. Every
 * integrator but implicit Euler updates the velocity explicitly, v' = v (1 -
 * gamma dt / m), which oscillates and grows unless dt < 2 m / gamma; a force
 * that is no longer finite stops scene_tick, naming the drag and that
 * limit. Implicit Euler divides it by 1 + gamma dt / m, stable at every dt. */
void create_drag(scene_t *scene, double gamma, body_t *body);

/* Called when two bodies start colliding: the bodies in the order they were
 * registered, the collision axis (unit, from body1 toward body2), the aux the
 * collision was created with, and its force constant. */
typedef void (*collision_handler_t)(body_t *body1, body_t *body2, vector_t axis, void *aux,
                                    double force_const);

/*
 * Registers a collision between two distinct bodies. handler (not NULL) is
 * called once when they start colliding, in stage 1 of scene_tick, and not
 * again until they have parted. aux stays owned by the caller (the scene
 * never frees it). What colliding means depends on the pair:
 *
 * - World contacts off, or the pair kept out of them (its collision filters,
 *   or both masses INFINITY: scene_set_contacts_enabled), the seed's rule: at
 *   every tick, if the bodies overlap (find_collision; touching counts) and
 *   did not at the previous tick, the handler runs with find_collision's
 *   axis. They have parted when find_collision finds no overlap. Bodies that
 *   already overlap when the collision is created collide at the first tick.
 *
 * - A pair that world contacts resolve: the solver stops fast bodies at the
 *   surface, so they need never overlap. The handler runs when the world's
 *   contact of the pair starts touching (contact_t.touching: a point at or
 *   below zero separation, or an impulse of the solver), with that contact's
 *   axis turned to point from body1 toward body2. The world finds its
 *   contacts in stage 2, after the force creators, so the handler runs in
 *   stage 1 of the tick after the step in which the pair first touched: one
 *   step late, the world having already stopped or bounced them (the
 *   velocities the handler sees are those after the impact). The pair has
 *   parted, and may fire again, once its polygons are further apart than a
 *   tenth of the smaller body's radius (the largest distance from its
 *   centroid to a vertex) at the reads of two ticks in a row. So a landing
 *   is one meeting: bodies moving on together hover within rounding of
 *   zero separation, and a polygon that lands on a corner and tips onto a
 *   face lifts off less than that (dropped from up to twelve radii); a
 *   bounce, or a pair pulled apart and pushed together again, is a new
 *   one. While either body sleeps the pair keeps its state. A pair already
 *   touching when the collision is created collides at the first tick
 *   whose previous step found it touching (the second tick of a new
 *   scene).
 */
void create_collision(scene_t *scene, body_t *body1, body_t *body2,
                      collision_handler_t handler, void *aux, double force_const);

/* Both bodies are marked removed (body_remove) when they start colliding (as
 * create_collision); the scene frees them at the end of that same tick, with
 * every force creator that depends on either. With world contacts resolving
 * the pair, that is the end of the tick after the step in which they first
 * touched: for one step they bounce off each other (or stop) before they
 * disappear. */
void create_destructive_collision(scene_t *scene, body_t *body1, body_t *body2);

/*
 * The seed's collision response: an impulse along axis on body1 of
 * reduced_mass * (1 + elasticity) * (u_b - u_a), where u is each body's
 * velocity component along axis and the reduced mass is m_a m_b / (m_a + m_b)
 * (the other body's mass when one is INFINITY); body2 gets the opposite
 * impulse. The elasticity is force_const. aux is unused. An impulse that is
 * not finite stops the program, naming this function.
 *
 * u is the velocity with the impulses already added in this tick, so a
 * body that meets two others in one tick bounces off each in turn (applied
 * twice from its old velocity, the impulses added energy); a pair that is
 * no longer approaching along the axis (u_a - u_b <= 0) gets none.
 */
void physics_collision_handler(body_t *body1, body_t *body2, vector_t axis, void *aux,
                               double force_const);

/* A collision with physics_collision_handler: elasticity 0 sticks (common
 * velocity along the axis), 1 is elastic, above 1 adds energy. elasticity
 * >= 0. Meant for pairs that world contacts leave alone: on a pair they
 * resolve, the impulse comes a step after the world's response and acts on
 * the velocities it left (it turns a bounce back toward the other body). */
void create_physics_collision(scene_t *scene, body_t *body1, body_t *body2, double elasticity);

/*
 * All pairs of a group as one force creator. create_newtonian_gravity or
 * create_collision for every pair of N bodies makes N (N - 1) / 2 creators;
 * these make one, whose memory grows with N, and whose step costs, for
 * gravity, the N (N - 1) / 2 forces it must sum, and for collisions, the
 * members and the pairs near each other (a broadphase grid over their
 * bounding boxes, and the world's contacts), not every pair.
 *
 * The bodies must be in the scene already (scene_add_body): the program
 * stops naming the first that is not ("bodies2[3] is not in the scene").
 * The lists are only read (the caller frees them; a list made with a freer
 * would free the bodies). A group orders its members by when they joined
 * (the list's order, then the additions); a body listed twice joins once.
 * The group belongs to the scene and is valid until scene_free; a body
 * removed from the scene leaves it when reaped, and the group stays, even
 * empty.
 */

/* Newtonian gravity between every two members, exactly as
 * create_newtonian_gravity called for each pair (i, j), i < j, in member
 * order, i before j, would apply it. G >= 0. */
typedef struct gravity_group gravity_group_t;
gravity_group_t *create_newtonian_gravity_group(scene_t *scene, double G, list_t *bodies);

/* Adds a body of the scene after the other members (a member stays where it
 * is). */
void gravity_group_add(gravity_group_t *group, body_t *body);

/* create_collision(scene, b1, b2, handler, aux, force_const) for every b1
 * of bodies1 and b2 of bodies2, b1 != b2, each pair once: when b1 and b2
 * are each in both lists, the earlier member is body1. Each pair has the
 * state and rule of create_collision (when it fires, when it has parted,
 * the record); within a tick the pairs that fire are called in member
 * order of body1, then of body2. With physics_collision_handler it is
 * create_physics_collision for every pair (force_const the elasticity,
 * checked at the first call), with destructive_collision_handler
 * create_destructive_collision. */
typedef struct collision_group collision_group_t;
collision_group_t *create_collision_group(scene_t *scene, list_t *bodies1, list_t *bodies2,
                                          collision_handler_t handler, void *aux,
                                          double force_const);

/* Adds a body of the scene to the first set, the second or both (at least
 * one), after the other members; a member gains the sets and keeps its
 * place. */
void collision_group_add(collision_group_t *group, body_t *body, bool first, bool second);

/* create_destructive_collision's handler: marks both bodies removed. */
void destructive_collision_handler(body_t *body1, body_t *body2, vector_t axis, void *aux,
                                   double force_const);

JOSTLE_API_END

#endif // #ifndef FORCES_H
