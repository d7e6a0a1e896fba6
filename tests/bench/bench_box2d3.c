/*
 * The canonical scenes (bench_scenes.h) on Box2D v3 (Erin Catto's C library,
 * source from ../shared/peers, built by tests/bench/bench.mk into
 * build/peers; never part of the project): its public API only.
 * cc -O2 -I$(BOX2D3)/include bench_box2d3.c libbox2d.a -lm -pthread
 * -DBENCH_BOX2D3_BUILD='"sse2"' (or "avx2": the name the library was built
 * for, printed in the engine's name).
 *
 * Settings: Box2D v3's defaults (b2DefaultWorldDef, b2DefaultBodyDef,
 * b2DefaultShapeDef, printed by describe()) are kept: 4 sub-steps per step
 * (b2World_Step's usual count), its soft contacts (contact hertz 30, damping
 * ratio 10, push-out speed 3 m/s), restitution threshold 1 m/s, continuous
 * collision against static bodies, maximum linear speed 400 m/s, single
 * precision, one thread (workerCount 1; --workers N gives N to v3's own
 * scheduler, for the two-worker comparison). Changed: sleeping off
 * (worldDef.enableSleep = false) in the variant box2d3-BUILD, so that every
 * body is stepped every step, as in the other programs; box2d3-BUILD-sleeping
 * (pile only) keeps its default, sleeping on. --iterations is ignored: v3's
 * sub-steps are not solver iterations. Friction is mixed by sqrt(f1 f2) and
 * restitution by max, as in our engine, so shapes get the scene's values.
 * Polygons have radius 0 (no skin): the shapes are the scene's polygons.
 * Mass: density = scene mass / polygon area. Angles are read as
 * atan2(s, c) of the body's rotation (b2Rot_GetAngle is an approximation).
 *
 * Penetration: v3's manifolds are computed at the start of a step (before
 * its solve) and keep speculative points up to 0.02 m apart, so they are not
 * read as they are: for every contact a dynamic body holds after the step
 * whose manifold has points, the two shapes are collided again at the
 * bodies' current transforms (b2CollidePolygons for polygons of radius 0,
 * and the collide function of each pair with a circle or a capsule) and the
 * penetration is the largest -separation of that manifold (0 when apart).
 *
 * Springs: b2DistanceJoint between the two centres as a spring of rest
 * length 1 m (spring_rest), with hertz = sqrt(k / m) / (2 pi) and damping
 * ratio c / (2 sqrt(k m)), m the reduced mass of the two bodies (the mass
 * v3's joint sees along the line of centres), so that the spring's force is
 * k (length - rest) + c (rate of change of length); v3 solves it as a soft
 * constraint inside its sub-steps.
 *
 * Joints: b2RevoluteJoint from b2DefaultRevoluteJointDef (its joint
 * softness, printed by describe(), kept), the
 * local frames at the scene's world point, body B's frame turned so that
 * the angle and its limits count from the pose the joint is made in; a
 * joint to the world is made to a static body at the origin. Groups: a
 * negative filter.groupIndex (b2Shape_SetFilter).
 */

#include "box2d/box2d.h"
#include "box2d/math_functions.h"

#include "bench_scenes.h"

#ifndef BENCH_BOX2D3_BUILD
#define BENCH_BOX2D3_BUILD "sse2"
#endif

#define B3_SUBSTEPS 4
#define B3_SPRING_REST 1.0
#define B3_MAX_PAIRS 4

typedef struct {
    int body1, body2;
    double G;
} b3_pair_t;

/* worldDef.workerCount: above 1, v3 runs its own scheduler's threads. */
static int b3_workers = 1;

typedef struct {
    b2WorldId world;
    b2BodyId *bodies;
    b2ShapeId *shapes; /* each body's one shape */
    double *mass;      /* the scene's mass; 0 for static bodies */
    int count, capacity;
    b3_pair_t pairs[B3_MAX_PAIRS];
    int pair_count;
    b2ContactData *contacts; /* scratch for the penetration queries */
    int contact_capacity;
    b2BodyId ground; /* a static body at the origin for joints to the world; made when needed */
    int has_ground;
} b3_world_t;

static void b3_describe(FILE *out) {
    b2Version v = b2GetVersion();
    b2WorldDef def = b2DefaultWorldDef();
    b2BodyDef body = b2DefaultBodyDef();
    b2RevoluteJointDef joint = b2DefaultRevoluteJointDef();
    fprintf(out,
            "# box2d3-%s: Box2D v3 %d.%d.%d (source 617d32ab, %s build, %s precision); defaults "
            "kept: %d sub-steps, contact hertz %g, damping ratio %g, push-out speed %g m/s, "
            "restitution threshold %g m/s, continuous %s, maximum linear speed %g m/s, "
            "workers %d, body sleep threshold %g m/s, polygon radius 0, joint softness %g Hz "
            "damping ratio %g; set: sleeping off "
            "(default %s; box2d3-%s-sleeping keeps it on, pile only); penetration: shapes "
            "collided again at the final transforms (no speculative margin, no skin)\n",
            BENCH_BOX2D3_BUILD, v.major, v.minor, v.revision, BENCH_BOX2D3_BUILD,
            b2IsDoublePrecision() ? "double" : "single", B3_SUBSTEPS, (double)def.contactHertz,
            (double)def.contactDampingRatio, (double)def.contactSpeed,
            (double)def.restitutionThreshold, def.enableContinuous ? "on" : "off",
            (double)def.maximumLinearSpeed, b3_workers,
            (double)body.sleepThreshold, (double)joint.base.constraintHertz,
            (double)joint.base.constraintDampingRatio, def.enableSleep ? "on" : "off",
            BENCH_BOX2D3_BUILD);
}

static void b3_describe_none(FILE *out) {
    (void)out;
}

static void *b3_world_new_common(double gy, int capacity, int sleeping) {
    b3_world_t *w = (b3_world_t *)calloc(1, sizeof(b3_world_t));
    b2WorldDef def = b2DefaultWorldDef();
    def.gravity = (b2Vec2){0.0f, (float)gy};
    def.enableSleep = sleeping != 0;
    def.workerCount = b3_workers;
    w->world = b2CreateWorld(&def);
    w->capacity = capacity > 0 ? capacity : 4;
    w->bodies = (b2BodyId *)malloc(sizeof(b2BodyId) * (size_t)w->capacity);
    w->shapes = (b2ShapeId *)malloc(sizeof(b2ShapeId) * (size_t)w->capacity);
    w->mass = (double *)malloc(sizeof(double) * (size_t)w->capacity);
    return w;
}

static void *b3_world_new(double gy, int contacts, int capacity) {
    (void)contacts; /* non-colliding bodies get maskBits 0 */
    return b3_world_new_common(gy, capacity, 0);
}

static void *b3_world_new_sleeping(double gy, int contacts, int capacity) {
    (void)contacts;
    return b3_world_new_common(gy, capacity, 1);
}

static void b3_world_free(void *world) {
    b3_world_t *w = (b3_world_t *)world;
    b2DestroyWorld(w->world);
    free(w->bodies);
    free(w->shapes);
    free(w->mass);
    free(w->contacts);
    free(w);
}

static int b3_add(b3_world_t *w, b2BodyId body, b2ShapeId shape, double mass) {
    if (w->count == w->capacity) {
        w->capacity *= 2;
        w->bodies = (b2BodyId *)realloc(w->bodies, sizeof(b2BodyId) * (size_t)w->capacity);
        w->shapes = (b2ShapeId *)realloc(w->shapes, sizeof(b2ShapeId) * (size_t)w->capacity);
        w->mass = (double *)realloc(w->mass, sizeof(double) * (size_t)w->capacity);
    }
    w->bodies[w->count] = body;
    w->shapes[w->count] = shape;
    w->mass[w->count] = mass;
    return w->count++;
}

/* The exact rotation (b2MakeRot approximates cos and sin). */
static b2Rot b3_rot(double angle) {
    b2Rot q = {(float)cos(angle), (float)sin(angle)};
    return q;
}

static int b3_add_static_box(void *world, double cx, double cy, double hx, double hy,
                             double friction, double elasticity) {
    b3_world_t *w = (b3_world_t *)world;
    b2BodyDef def = b2DefaultBodyDef();
    def.type = b2_staticBody;
    def.position = (b2Pos){(float)cx, (float)cy};
    b2BodyId body = b2CreateBody(w->world, &def);
    b2ShapeDef shape = b2DefaultShapeDef();
    shape.material.friction = (float)friction;
    shape.material.restitution = (float)elasticity;
    b2Polygon box = b2MakeBox((float)hx, (float)hy);
    return b3_add(w, body, b2CreatePolygonShape(body, &shape, &box), 0.0);
}

static b2Polygon b3_polygon(const bench_shape_t *shape) {
    if (shape->sides == 0) return b2MakeBox((float)shape->hx, (float)shape->hy);
    b2Vec2 points[B2_MAX_POLYGON_VERTICES];
    int n = bench_shape_vertex_count(shape);
    for (int i = 0; i < n; i++) {
        double x, y;
        bench_shape_vertex(shape, i, &x, &y);
        points[i] = (b2Vec2){(float)x, (float)y};
    }
    b2Hull hull = b2ComputeHull(points, n);
    if (hull.count != n) {
        fprintf(stderr, "bench_box2d3: b2ComputeHull kept %d of %d vertices\n", hull.count, n);
        abort();
    }
    return b2MakePolygon(&hull, 0.0f);
}

static int b3_add_body(void *world, const bench_shape_t *shape, double x, double y, double angle,
                       double mass, double friction, double elasticity, int collides) {
    b3_world_t *w = (b3_world_t *)world;
    b2BodyDef def = b2DefaultBodyDef();
    def.type = b2_dynamicBody;
    def.position = (b2Pos){(float)x, (float)y};
    def.rotation = b3_rot(angle);
    b2BodyId body = b2CreateBody(w->world, &def);
    b2ShapeDef sdef = b2DefaultShapeDef();
    sdef.density = (float)(mass / bench_shape_area(shape));
    sdef.material.friction = (float)friction;
    sdef.material.restitution = (float)elasticity;
    if (!collides) sdef.filter.maskBits = 0;
    if (shape->sides == BENCH_CIRCLE) {
        b2Circle circle = {{0.0f, 0.0f}, (float)shape->radius};
        return b3_add(w, body, b2CreateCircleShape(body, &sdef, &circle), mass);
    }
    if (shape->sides == BENCH_CAPSULE) {
        b2Capsule capsule = {{(float)-shape->hx, 0.0f}, {(float)shape->hx, 0.0f},
                             (float)shape->radius};
        return b3_add(w, body, b2CreateCapsuleShape(body, &sdef, &capsule), mass);
    }
    b2Polygon polygon = b3_polygon(shape);
    return b3_add(w, body, b2CreatePolygonShape(body, &sdef, &polygon), mass);
}

static void b3_set_velocity(void *world, int body, double vx, double vy) {
    b3_world_t *w = (b3_world_t *)world;
    b2Body_SetLinearVelocity(w->bodies[body], (b2Vec2){(float)vx, (float)vy});
}

static void b3_set_angular_velocity(void *world, int body, double omega) {
    b3_world_t *w = (b3_world_t *)world;
    b2Body_SetAngularVelocity(w->bodies[body], (float)omega);
}

/* Newtonian gravity: a force on each body at the start of every step (v3
 * keeps it over the step's sub-steps and clears it after). */
static void b3_add_gravity_pair(void *world, int body1, int body2, double G) {
    b3_world_t *w = (b3_world_t *)world;
    if (w->pair_count == B3_MAX_PAIRS) {
        fprintf(stderr, "bench_box2d3: more than %d gravity pairs\n", B3_MAX_PAIRS);
        abort();
    }
    w->pairs[w->pair_count].body1 = body1;
    w->pairs[w->pair_count].body2 = body2;
    w->pairs[w->pair_count].G = G;
    w->pair_count++;
}

static int b3_awake_bodies(void *world) {
    b3_world_t *w = (b3_world_t *)world;
    int awake = 0;
    for (int i = 0; i < w->count; i++) awake += w->mass[i] > 0.0 && b2Body_IsAwake(w->bodies[i]);
    return awake;
}

static void b3_step(void *world, double dt) {
    b3_world_t *w = (b3_world_t *)world;
    for (int i = 0; i < w->pair_count; i++) {
        b2BodyId a = w->bodies[w->pairs[i].body1], b = w->bodies[w->pairs[i].body2];
        b2Pos pa = b2Body_GetWorldCenter(a), pb = b2Body_GetWorldCenter(b);
        double dx = (double)pb.x - pa.x, dy = (double)pb.y - pa.y;
        double r2 = dx * dx + dy * dy, r = sqrt(r2);
        if (r < 1e-9) continue;
        double f = w->pairs[i].G * w->mass[w->pairs[i].body1] * w->mass[w->pairs[i].body2] / r2 / r;
        b2Body_ApplyForceToCenter(a, (b2Vec2){(float)(f * dx), (float)(f * dy)}, true);
        b2Body_ApplyForceToCenter(b, (b2Vec2){(float)(-f * dx), (float)(-f * dy)}, true);
    }
    b2World_Step(w->world, (float)dt, B3_SUBSTEPS);
}

static void b3_get_state(void *world, int body, bench_state_t *out) {
    b3_world_t *w = (b3_world_t *)world;
    b2BodyId b = w->bodies[body];
    b2Pos p = b2Body_GetWorldCenter(b);
    b2Rot q = b2Body_GetRotation(b);
    b2Vec2 v = b2Body_GetLinearVelocity(b);
    out->x = p.x;
    out->y = p.y;
    out->angle = atan2((double)q.s, (double)q.c);
    out->vx = v.x;
    out->vy = v.y;
    out->omega = b2Body_GetAngularVelocity(b);
}

/* Box2D's order of shape types in a contact: the higher one is shape A. */
static int b3_rank(b2ShapeType type) {
    return type == b2_circleShape ? 0 : type == b2_capsuleShape ? 1 : 2;
}

/* The manifold of two shapes (circles, capsules, polygons) at their bodies'
 * current transforms, a of the higher type (b3_rank). */
static b2LocalManifold b3_collide(b2ShapeId a, b2ShapeId b) {
    b2Transform xf = b2InvMulTransforms(b2Body_GetTransform(b2Shape_GetBody(a)),
                                        b2Body_GetTransform(b2Shape_GetBody(b)));
    b2ShapeType ta = b2Shape_GetType(a), tb = b2Shape_GetType(b);
    if (ta == b2_circleShape) {
        b2Circle ca = b2Shape_GetCircle(a), cb = b2Shape_GetCircle(b);
        return b2CollideCircles(&ca, &cb, xf);
    }
    if (ta == b2_capsuleShape) {
        b2Capsule ca = b2Shape_GetCapsule(a);
        if (tb == b2_circleShape) {
            b2Circle cb = b2Shape_GetCircle(b);
            return b2CollideCapsuleAndCircle(&ca, &cb, xf);
        }
        b2Capsule cb = b2Shape_GetCapsule(b);
        return b2CollideCapsules(&ca, &cb, xf);
    }
    b2Polygon pa = b2Shape_GetPolygon(a);
    if (tb == b2_circleShape) {
        b2Circle cb = b2Shape_GetCircle(b);
        return b2CollidePolygonAndCircle(&pa, &cb, xf);
    }
    if (tb == b2_capsuleShape) {
        b2Capsule cb = b2Shape_GetCapsule(b);
        return b2CollidePolygonAndCapsule(&pa, &cb, xf);
    }
    b2Polygon pb = b2Shape_GetPolygon(b);
    return b2CollidePolygons(&pa, &pb, xf);
}

/* The deepest penetration of two shapes at their bodies' current
 * transforms (0 when they do not overlap). */
static double b3_shape_penetration(b2ShapeId a, b2ShapeId b) {
    if (b3_rank(b2Shape_GetType(a)) < b3_rank(b2Shape_GetType(b))) {
        b2ShapeId t = a;
        a = b;
        b = t;
    }
    b2LocalManifold m = b3_collide(a, b);
    double pen = 0.0;
    for (int i = 0; i < m.pointCount; i++) {
        if (-m.points[i].separation > pen) pen = -m.points[i].separation;
    }
    return pen;
}

/* Over the contacts of body `index` with points; only those with `other`
 * unless other < 0. */
static double b3_body_penetration(b3_world_t *w, int index, int other) {
    b2BodyId body = w->bodies[index];
    int capacity = b2Body_GetContactCapacity(body);
    if (capacity > w->contact_capacity) {
        w->contact_capacity = 2 * capacity;
        w->contacts = (b2ContactData *)realloc(w->contacts,
                                               sizeof(b2ContactData) * (size_t)w->contact_capacity);
    }
    int count = b2Body_GetContactData(body, w->contacts, w->contact_capacity);
    double pen = 0.0;
    for (int i = 0; i < count; i++) {
        const b2ContactData *c = &w->contacts[i];
        if (c->manifold.pointCount == 0) continue;
        if (other >= 0) {
            b2BodyId ba = b2Shape_GetBody(c->shapeIdA), bb = b2Shape_GetBody(c->shapeIdB);
            b2BodyId o = w->bodies[other];
            if (!(B2_ID_EQUALS(ba, o) || B2_ID_EQUALS(bb, o))) continue;
        }
        double p = b3_shape_penetration(c->shapeIdA, c->shapeIdB);
        if (p > pen) pen = p;
    }
    return pen;
}

static double b3_max_penetration(void *world) {
    b3_world_t *w = (b3_world_t *)world;
    double pen = 0.0;
    for (int i = 0; i < w->count; i++) {
        if (w->mass[i] <= 0.0) continue;
        double p = b3_body_penetration(w, i, -1);
        if (p > pen) pen = p;
    }
    return pen;
}

static double b3_pair_penetration(void *world, int body1, int body2) {
    b3_world_t *w = (b3_world_t *)world;
    if (w->mass[body1] <= 0.0) {
        int t = body1;
        body1 = body2;
        body2 = t;
    }
    return b3_body_penetration(w, body1, body2);
}

static void b3_add_spring(void *world, int body1, int body2, double k, double damping,
                          double rest) {
    b3_world_t *w = (b3_world_t *)world;
    double m1 = w->mass[body1], m2 = w->mass[body2];
    double m = m1 <= 0.0 ? m2 : m2 <= 0.0 ? m1 : m1 * m2 / (m1 + m2);
    b2DistanceJointDef def = b2DefaultDistanceJointDef();
    def.base.bodyIdA = w->bodies[body1];
    def.base.bodyIdB = w->bodies[body2];
    def.base.collideConnected = false;
    def.length = (float)rest;
    def.enableSpring = true;
    def.hertz = (float)(sqrt(k / m) / (2.0 * M_PI));
    def.dampingRatio = (float)(damping / (2.0 * sqrt(k * m)));
    def.enableLimit = false;
    b2CreateDistanceJoint(w->world, &def);
}

/* The static body at the origin that stands for the world in joints. */
static b2BodyId b3_ground(b3_world_t *w) {
    if (!w->has_ground) {
        b2BodyDef def = b2DefaultBodyDef();
        w->ground = b2CreateBody(w->world, &def);
        w->has_ground = 1;
    }
    return w->ground;
}

/* b2RevoluteJointDef from b2DefaultRevoluteJointDef: each body's local
 * frame at the world point, body B's turned by A's angle less B's so that
 * the joint's angle (and its limits) count from the pose now. */
static void b3_add_revolute(void *world, int body1, int body2, double x, double y, int limit,
                            double lower, double upper) {
    b3_world_t *w = (b3_world_t *)world;
    b2BodyId a = body1 >= 0 ? w->bodies[body1] : b3_ground(w), b = w->bodies[body2];
    b2Pos point = {(float)x, (float)y};
    b2RevoluteJointDef def = b2DefaultRevoluteJointDef();
    def.base.bodyIdA = a;
    def.base.bodyIdB = b;
    def.base.localFrameA.p = b2Body_GetLocalPoint(a, point);
    def.base.localFrameB.p = b2Body_GetLocalPoint(b, point);
    def.base.localFrameB.q = b2InvMulRot(b2Body_GetRotation(b), b2Body_GetRotation(a));
    def.enableLimit = limit != 0;
    def.lowerAngle = (float)lower;
    def.upperAngle = (float)upper;
    b2CreateRevoluteJoint(w->world, &def);
}

/* A negative group index: never collide within the group. */
static void b3_set_group(void *world, int body, int group) {
    b3_world_t *w = (b3_world_t *)world;
    b2Filter filter = b2Shape_GetFilter(w->shapes[body]);
    filter.groupIndex = -group;
    b2Shape_SetFilter(w->shapes[body], filter);
}

/* Its own profile of the last step (b2World_GetProfile, ms), as parts
 * that do not overlap: the solve's stages (b2Profile nests them in
 * constraints and solve), then what else the step timed. */
static int b3_stage_ms(void *world, const char **names, double *ms, int max) {
    b3_world_t *w = (b3_world_t *)world;
    b2Profile p = b2World_GetProfile(w->world);
    static const char *const parts[] = {"pairs",       "collide", "setup",      "prepare",
                                        "warm_start",  "solve",   "relax",      "integrate",
                                        "restitution", "store",   "transforms", "refit",
                                        "continuous",  "sleep",   "other"};
    double values[] = {p.pairs,        p.collide,
                       p.solverSetup,  p.prepareConstraints,
                       p.warmStart,    p.solveImpulses,
                       p.relaxImpulses, (double)p.integrateVelocities + p.integratePositions,
                       p.applyRestitution, p.storeImpulses,
                       p.transforms,   p.refit,
                       p.bullets,      (double)p.sleepIslands + p.splitIslands,
                       0.0};
    int count = (int)(sizeof parts / sizeof parts[0]);
    double listed = 0.0;
    for (int k = 0; k + 1 < count; k++) listed += values[k];
    values[count - 1] = p.step > listed ? p.step - listed : 0.0;
    if (count > max) count = max;
    for (int k = 0; k < count; k++) {
        names[k] = parts[k];
        ms[k] = values[k];
    }
    return count;
}

#define B3_OPS(name, only, describe, world_new, awake)                                                  \
    {name,                                                                                         \
     only,                                                                                         \
     0,                                                                                            \
     0,                                                                                            \
     describe,                                                                                     \
     world_new,                                                                                    \
     b3_world_free,                                                                                \
     b3_add_static_box,                                                                            \
     b3_add_body,                                                                                  \
     b3_set_velocity,                                                                              \
     b3_add_gravity_pair,                                                                          \
     b3_step,                                                                                      \
     b3_get_state,                                                                                 \
     b3_max_penetration,                                                                           \
     b3_pair_penetration,                                                                          \
     b3_add_spring,                                                                                \
     b3_set_angular_velocity,                                                                      \
     B3_SPRING_REST,                                                                               \
     awake,                                                                                        \
     b3_add_revolute,                                                                              \
     b3_set_group,                                                                                 \
     b3_stage_ms}

static const bench_ops_t box2d3_ops =
    B3_OPS("box2d3-" BENCH_BOX2D3_BUILD, NULL, b3_describe, b3_world_new, NULL);
static const bench_ops_t box2d3_sleeping_ops =
    B3_OPS("box2d3-" BENCH_BOX2D3_BUILD "-sleeping", "pile", b3_describe_none,
           b3_world_new_sleeping, b3_awake_bodies);

int main(int argc, char **argv) {
    const bench_ops_t *ops[2] = {&box2d3_ops, &box2d3_sleeping_ops};
    /* --workers is this program's own: taken out before bench_main. */
    int kept = 1;
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--workers") == 0 && i + 1 < argc) {
            char *end;
            long workers = strtol(argv[++i], &end, 10);
            if (*end != '\0' || workers < 1 || workers > 64) {
                fprintf(stderr, "%s: --workers takes 1 to 64, not %s\n", argv[0], argv[i]);
                return 2;
            }
            b3_workers = (int)workers;
            printf("# box2d3-%s: %d workers\n", BENCH_BOX2D3_BUILD, b3_workers);
        } else {
            argv[kept++] = argv[i];
        }
    }
    return bench_main(kept, argv, ops, 2);
}
