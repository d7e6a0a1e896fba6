/*
 * The canonical scenes (bench_scenes.h) on Chipmunk2D 7 (Debian
 * libchipmunk-dev): cc -O2 bench_chipmunk.c -lchipmunk -lm.
 *
 * Variants (describe() prints each one's settings beside Chipmunk's
 * defaults, read from a fresh cpSpace):
 *   chipmunk-default  Chipmunk's defaults: 10 solver iterations, collision
 *                     slop 0.1 m, collision bias (1 - 0.1)^60, collision
 *                     persistence 3 steps, damping 1, sleeping off (sleep
 *                     time threshold INFINITY), the bounding-box-tree
 *                     spatial index, the single-threaded cpSpace (not
 *                     cpHastySpace);
 *   chipmunk          matched to our engine where Chipmunk has the same
 *                     setting: 8 solver iterations (our velocity
 *                     iterations; default 10) and collision slop 0.001 m
 *                     (the overlap our solver leaves alone; default 0.1 m);
 *                     the rest as chipmunk-default (sleeping off in both).
 * In both, Chipmunk multiplies the two shapes' coefficients (friction
 * u = ua ub, elasticity e = ea eb), so every shape gets friction sqrt(mu)
 * for a pair friction of mu, and static shapes get elasticity 1 so that the
 * dynamic body's elasticity is the pair's (bounce: floor 1.0, box 0.8).
 * --iterations N sets both variants' iterations.
 * Bodies get the scene's mass and cpMomentForPoly's moment; static boxes are
 * static bodies of their own at the box's centre.
 * Joints: cpPivotJoint at the scene's world point (the space's static body
 * for the world) and, for limits, cpRotaryLimitJoint; groups: the shapes'
 * filter group.
 * Penetration: -distance of the points of cpArbiterGetContactPointSet over
 * the arbiters of the dynamic bodies after the step (Chipmunk moves bodies,
 * then collides, then solves, so these are the current positions'; its
 * polygons have radius 0, so the distances are the scene's geometry).
 */

#include <chipmunk/chipmunk.h>
#include <unistd.h>
#include "bench_scenes.h"

typedef struct {
    int body1, body2;
    double G;
} cp_pair_t;

typedef struct {
    cpSpace *space;
    cpBody **bodies;
    int count, capacity;
    cp_pair_t pairs[4];
    int pair_count;
    cpConstraint **constraints;
    int constraint_count, constraint_capacity;
} cp_world_t;

/* A new cpSpace. The first one a debug build of Chipmunk makes prints a
 * banner on stdout ("... (Debug Enabled)"); it is caught here so that the
 * output stays key=value lines, and reported as a setting. */
static int cp_debug_build = -1;

static cpSpace *cp_space_new_quiet(void) {
    if (cp_debug_build >= 0) return cpSpaceNew();
    int fds[2];
    fflush(stdout);
    int saved = dup(STDOUT_FILENO);
    if (saved < 0 || pipe(fds) != 0) {
        cp_debug_build = 0;
        return cpSpaceNew();
    }
    dup2(fds[1], STDOUT_FILENO);
    cpSpace *space = cpSpaceNew();
    fflush(stdout);
    dup2(saved, STDOUT_FILENO);
    close(saved);
    close(fds[1]);
    char banner[512];
    ssize_t n = read(fds[0], banner, sizeof banner - 1);
    close(fds[0]);
    banner[n > 0 ? n : 0] = '\0';
    cp_debug_build = strstr(banner, "Debug Enabled") != NULL;
    return space;
}

/* The matched variant's settings: our engine's velocity iterations and the
 * overlap its solver leaves alone (engine/src/solver/solver.c, SOLVER_LINEAR_SLOP). */
#define CP_MATCHED_ITERATIONS 8
#define CP_MATCHED_SLOP 0.001

static void cp_describe(FILE *out) {
    cpSpace *space = cp_space_new_quiet();
    fprintf(out,
            "# chipmunk-default: Chipmunk2D %s (library %s), cpFloat %s, at its defaults: "
            "iterations %d, collision slop %g m, collision bias %g, collision persistence %u, "
            "damping %g, sleep time threshold %g (sleeping off), BB-tree spatial index, single "
            "thread; coefficients are multiplied, so shape friction sqrt(mu) and static "
            "elasticity 1\n",
            cpVersionString,
            cp_debug_build ? "built with debug checks: 'Debug Enabled'" : "release build",
            sizeof(cpFloat) == sizeof(double) ? "double" : "float", cpSpaceGetIterations(space),
            (double)cpSpaceGetCollisionSlop(space), (double)cpSpaceGetCollisionBias(space),
            (unsigned)cpSpaceGetCollisionPersistence(space), (double)cpSpaceGetDamping(space),
            (double)cpSpaceGetSleepTimeThreshold(space));
    fprintf(out,
            "# chipmunk: matched to our engine, differs from chipmunk-default in: iterations %d "
            "(default %d), collision slop %g m (default %g); penetration: contact point "
            "distances at the final positions (radius-0 polygons)\n",
            CP_MATCHED_ITERATIONS, cpSpaceGetIterations(space), CP_MATCHED_SLOP,
            (double)cpSpaceGetCollisionSlop(space));
    if (bench_iterations > 0) {
        fprintf(out, "# chipmunk, chipmunk-default: --iterations %d\n", bench_iterations);
    }
    cpSpaceFree(space);
}

static void *cp_world_new_common(double gy, int capacity, int matched) {
    cp_world_t *w = (cp_world_t *)calloc(1, sizeof(cp_world_t));
    w->space = cp_space_new_quiet();
    cpSpaceSetGravity(w->space, cpv(0.0, gy));
    if (matched) {
        cpSpaceSetCollisionSlop(w->space, CP_MATCHED_SLOP);
        cpSpaceSetIterations(w->space, CP_MATCHED_ITERATIONS);
    }
    if (bench_iterations > 0) cpSpaceSetIterations(w->space, bench_iterations);
    w->capacity = capacity > 0 ? capacity : 4;
    w->bodies = (cpBody **)malloc(sizeof(cpBody *) * (size_t)w->capacity);
    return w;
}

/* contacts: non-colliding bodies get CP_SHAPE_FILTER_NONE instead. */
static void *cp_world_new(double gy, int contacts, int capacity) {
    (void)contacts;
    return cp_world_new_common(gy, capacity, 1);
}

static void *cp_world_new_default(double gy, int contacts, int capacity) {
    (void)contacts;
    return cp_world_new_common(gy, capacity, 0);
}

static void cp_describe_none(FILE *out) {
    (void)out;
}

static void cp_free_shape(cpBody *body, cpShape *shape, void *data) {
    (void)body;
    cpSpace *space = (cpSpace *)data;
    cpSpaceRemoveShape(space, shape);
    cpShapeFree(shape);
}

static void cp_world_free(void *world) {
    cp_world_t *w = (cp_world_t *)world;
    for (int i = 0; i < w->constraint_count; i++) {
        cpSpaceRemoveConstraint(w->space, w->constraints[i]);
        cpConstraintFree(w->constraints[i]);
    }
    free(w->constraints);
    for (int i = 0; i < w->count; i++) {
        cpBodyEachShape(w->bodies[i], cp_free_shape, w->space);
        cpSpaceRemoveBody(w->space, w->bodies[i]);
        cpBodyFree(w->bodies[i]);
    }
    cpSpaceFree(w->space);
    free(w->bodies);
    free(w);
}

static int cp_add(cp_world_t *w, cpBody *body) {
    if (w->count == w->capacity) {
        w->capacity *= 2;
        w->bodies = (cpBody **)realloc(w->bodies, sizeof(cpBody *) * (size_t)w->capacity);
    }
    w->bodies[w->count] = body;
    return w->count++;
}

static int cp_add_static_box(void *world, double cx, double cy, double hx, double hy,
                             double friction, double elasticity) {
    cp_world_t *w = (cp_world_t *)world;
    cpBody *body = cpSpaceAddBody(w->space, cpBodyNewStatic());
    cpBodySetPosition(body, cpv(cx, cy));
    cpShape *shape = cpSpaceAddShape(w->space, cpBoxShapeNew(body, 2.0 * hx, 2.0 * hy, 0.0));
    cpShapeSetFriction(shape, friction);
    cpShapeSetElasticity(shape, elasticity);
    return cp_add(w, body);
}

/* A circle, or a capsule as Chipmunk's rounded segment; the exact moment
 * of either (cpMomentForSegment leaves out the caps' share). */
static int cp_add_round(cp_world_t *w, const bench_shape_t *shape, double x, double y,
                        double angle, double mass, double friction, double elasticity,
                        int collides) {
    cpBody *body =
        cpSpaceAddBody(w->space, cpBodyNew(mass, bench_shape_inertia(shape, mass)));
    cpBodySetPosition(body, cpv(x, y));
    cpBodySetAngle(body, angle);
    cpShape *s = shape->sides == BENCH_CIRCLE
                     ? cpCircleShapeNew(body, shape->radius, cpvzero)
                     : cpSegmentShapeNew(body, cpv(-shape->hx, 0.0), cpv(shape->hx, 0.0),
                                         shape->radius);
    cpSpaceAddShape(w->space, s);
    cpShapeSetFriction(s, friction);
    cpShapeSetElasticity(s, elasticity);
    if (!collides) cpShapeSetFilter(s, CP_SHAPE_FILTER_NONE);
    return cp_add(w, body);
}

static int cp_add_body(void *world, const bench_shape_t *shape, double x, double y, double angle,
                       double mass, double friction, double elasticity, int collides) {
    cp_world_t *w = (cp_world_t *)world;
    if (shape->sides < 0) return cp_add_round(w, shape, x, y, angle, mass, friction, elasticity, collides);
    cpVect verts[16];
    int n = bench_shape_vertex_count(shape);
    for (int i = 0; i < n; i++) {
        double vx, vy;
        bench_shape_vertex(shape, i, &vx, &vy);
        verts[i] = cpv(vx, vy);
    }
    cpFloat moment = cpMomentForPoly(mass, n, verts, cpvzero, 0.0);
    cpBody *body = cpSpaceAddBody(w->space, cpBodyNew(mass, moment));
    cpBodySetPosition(body, cpv(x, y));
    cpBodySetAngle(body, angle);
    cpShape *s = cpSpaceAddShape(w->space, cpPolyShapeNew(body, n, verts, cpTransformIdentity, 0.0));
    cpShapeSetFriction(s, friction);
    cpShapeSetElasticity(s, elasticity);
    if (!collides) cpShapeSetFilter(s, CP_SHAPE_FILTER_NONE);
    return cp_add(w, body);
}

static void cp_set_velocity(void *world, int body, double vx, double vy) {
    cp_world_t *w = (cp_world_t *)world;
    cpBodySetVelocity(w->bodies[body], cpv(vx, vy));
}

/* Chipmunk moves positions first and integrates velocities after the
 * collision pass, so a force set before cpSpaceStep would act at the old
 * positions (forward Euler). Its own way for a position-dependent force (the
 * Planet demo's gravity) is a velocity update function: the force is then
 * computed at the positions of this step, like every other engine here
 * (semi-implicit Euler). */
static void cp_gravity_velocity(cpBody *body, cpVect gravity, cpFloat damping, cpFloat dt) {
    cp_world_t *w = (cp_world_t *)cpBodyGetUserData(body);
    cpVect force = cpvzero;
    for (int i = 0; i < w->pair_count; i++) {
        cpBody *a = w->bodies[w->pairs[i].body1], *b = w->bodies[w->pairs[i].body2];
        if (body != a && body != b) continue;
        cpBody *other = body == a ? b : a;
        cpVect d = cpvsub(cpBodyGetPosition(other), cpBodyGetPosition(body));
        double r2 = cpvlengthsq(d), r = sqrt(r2);
        if (r < 1e-9) continue;
        double f = w->pairs[i].G * cpBodyGetMass(a) * cpBodyGetMass(b) / r2;
        force = cpvadd(force, cpvmult(d, f / r));
    }
    cpBodySetForce(body, force);
    cpBodyUpdateVelocity(body, gravity, damping, dt);
}

static void cp_add_gravity_pair(void *world, int body1, int body2, double G) {
    cp_world_t *w = (cp_world_t *)world;
    if (w->pair_count < 4) {
        w->pairs[w->pair_count].body1 = body1;
        w->pairs[w->pair_count].body2 = body2;
        w->pairs[w->pair_count].G = G;
        w->pair_count++;
        cpBody *bodies[2] = {w->bodies[body1], w->bodies[body2]};
        for (int i = 0; i < 2; i++) {
            cpBodySetUserData(bodies[i], w);
            cpBodySetVelocityUpdateFunc(bodies[i], cp_gravity_velocity);
        }
    }
}

static void cp_step(void *world, double dt) {
    cpSpaceStep(((cp_world_t *)world)->space, dt);
}

static void cp_get_state(void *world, int body, bench_state_t *out) {
    cp_world_t *w = (cp_world_t *)world;
    cpBody *b = w->bodies[body];
    cpVect p = cpBodyGetPosition(b), v = cpBodyGetVelocity(b);
    out->x = p.x;
    out->y = p.y;
    out->angle = cpBodyGetAngle(b);
    out->vx = v.x;
    out->vy = v.y;
    out->omega = cpBodyGetAngularVelocity(b);
}

typedef struct {
    cpBody *other; /* NULL: any */
    double penetration;
} cp_pen_query_t;

static void cp_arbiter_pen(cpBody *body, cpArbiter *arb, void *data) {
    (void)body;
    cp_pen_query_t *q = (cp_pen_query_t *)data;
    CP_ARBITER_GET_BODIES(arb, a, b);
    if (q->other != NULL && a != q->other && b != q->other) return;
    cpContactPointSet set = cpArbiterGetContactPointSet(arb);
    for (int i = 0; i < set.count; i++) {
        double pen = -set.points[i].distance;
        if (pen > q->penetration) q->penetration = pen;
    }
}

static double cp_max_penetration(void *world) {
    cp_world_t *w = (cp_world_t *)world;
    cp_pen_query_t q = {NULL, 0.0};
    for (int i = 0; i < w->count; i++) {
        if (cpBodyGetType(w->bodies[i]) == CP_BODY_TYPE_DYNAMIC)
            cpBodyEachArbiter(w->bodies[i], cp_arbiter_pen, &q);
    }
    return q.penetration;
}

static double cp_pair_penetration(void *world, int body1, int body2) {
    cp_world_t *w = (cp_world_t *)world;
    cpBody *a = w->bodies[body1], *b = w->bodies[body2];
    if (cpBodyGetType(a) != CP_BODY_TYPE_DYNAMIC) {
        cpBody *t = a;
        a = b;
        b = t;
    }
    cp_pen_query_t q = {b, 0.0};
    cpBodyEachArbiter(a, cp_arbiter_pen, &q);
    return q.penetration;
}

/* cpDampedSpring: the spring force from the positions at the start of
 * the step's velocity update (Chipmunk moves the bodies first), its
 * damping solved with the velocity iterations (an exponential decay of the
 * relative velocity along the spring). */
/* Adds a constraint to the space and keeps it for cp_world_free. */
static void cp_keep(cp_world_t *w, cpConstraint *constraint) {
    cpSpaceAddConstraint(w->space, constraint);
    if (w->constraint_count == w->constraint_capacity) {
        w->constraint_capacity = w->constraint_capacity ? 2 * w->constraint_capacity : 8;
        w->constraints = (cpConstraint **)realloc(
            w->constraints, sizeof(cpConstraint *) * (size_t)w->constraint_capacity);
    }
    w->constraints[w->constraint_count++] = constraint;
}

static void cp_add_spring(void *world, int body1, int body2, double k, double damping,
                          double rest) {
    cp_world_t *w = (cp_world_t *)world;
    cp_keep(w, cpDampedSpringNew(w->bodies[body1], w->bodies[body2], cpvzero, cpvzero, rest, k,
                                 damping));
}

/* cpPivotJoint at the world point (to the space's static body for the
 * world) and, with limits, a cpRotaryLimitJoint, whose bounds are on the
 * bodies' relative angle itself: the scene's limits moved by the relative
 * angle now. Neither lets the two bodies collide. */
static void cp_add_revolute(void *world, int body1, int body2, double x, double y, int limit,
                            double lower, double upper) {
    cp_world_t *w = (cp_world_t *)world;
    cpBody *a = body1 >= 0 ? w->bodies[body1] : cpSpaceGetStaticBody(w->space);
    cpBody *b = w->bodies[body2];
    cpConstraint *pivot = cpPivotJointNew(a, b, cpv(x, y));
    cpConstraintSetCollideBodies(pivot, cpFalse);
    cp_keep(w, pivot);
    if (limit) {
        double angle = cpBodyGetAngle(b) - cpBodyGetAngle(a);
        cpConstraint *rotary = cpRotaryLimitJointNew(a, b, angle + lower, angle + upper);
        cpConstraintSetCollideBodies(rotary, cpFalse);
        cp_keep(w, rotary);
    }
}

static void cp_group_shape(cpBody *body, cpShape *shape, void *data) {
    (void)body;
    cpShapeFilter filter = cpShapeGetFilter(shape);
    filter.group = (cpGroup)(size_t)data;
    cpShapeSetFilter(shape, filter);
}

/* The shapes' filter group: shapes of one non-zero group never collide. */
static void cp_set_group(void *world, int body, int group) {
    cp_world_t *w = (cp_world_t *)world;
    cpBodyEachShape(w->bodies[body], cp_group_shape, (void *)(size_t)group);
}

static void cp_set_angular_velocity(void *world, int body, double omega) {
    cp_world_t *w = (cp_world_t *)world;
    cpBodySetAngularVelocity(w->bodies[body], omega);
}

static const bench_ops_t chipmunk_ops = {
    "chipmunk",          NULL,           1, 1, cp_describe,
    cp_world_new,        cp_world_free,  cp_add_static_box,
    cp_add_body,         cp_set_velocity, cp_add_gravity_pair,
    cp_step,             cp_get_state,   cp_max_penetration,
    cp_pair_penetration, cp_add_spring,  cp_set_angular_velocity,
    1.0,                 NULL,
    cp_add_revolute,     cp_set_group,   NULL,
};

static const bench_ops_t chipmunk_default_ops = {
    "chipmunk-default",   NULL,           1, 1, cp_describe_none,
    cp_world_new_default, cp_world_free,  cp_add_static_box,
    cp_add_body,          cp_set_velocity, cp_add_gravity_pair,
    cp_step,              cp_get_state,   cp_max_penetration,
    cp_pair_penetration,  cp_add_spring,  cp_set_angular_velocity,
    1.0,                 NULL,
    cp_add_revolute,     cp_set_group,   NULL,
};

int main(int argc, char **argv) {
    const bench_ops_t *ops[2] = {&chipmunk_ops, &chipmunk_default_ops};
    return bench_main(argc, argv, ops, 2);
}
