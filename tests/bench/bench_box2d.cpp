/*
 * The canonical scenes (bench_scenes.h) on Box2D 2.4.1 (Debian libbox2d-dev):
 * c++ -O2 bench_box2d.cpp -lbox2d.
 *
 * Settings: Box2D's defaults are kept: 8 velocity and 3 position iterations
 * per step, warm starting, continuous collision (time of impact of dynamic
 * bodies against static ones), sleeping, linear slop 0.005 m, polygon skin
 * radius 0.01 m, restitution threshold 1 m/s, at most 2 m of translation per
 * step, single precision (float). Friction is mixed by sqrt(f1 f2) and
 * restitution by max, as in our engine, so shapes get the scene's values
 * directly. Mass: fixture density = scene mass / polygon area.
 *
 * Variants (describe() prints what each changes):
 *   box2d           all defaults, sleeping on, every scene;
 *   box2d-nosleep   its defaults with sleeping off (SetAllowSleeping(false)),
 *                   every scene: the comparison at Box2D's own settings, as
 *                   our engine's benchmark variant runs without sleeping (in
 *                   orbit the heavy body moves at 0.01 m/s, under Box2D's
 *                   sleep tolerance, and loses its velocity every time it
 *                   falls asleep);
 *   box2d-matched   sleeping off and 4 position iterations (default 3), our
 *                   engine's count; the velocity iterations are 8 in both.
 *                   Box2D's linear slop (0.005 m) and polygon skin (0.01 m)
 *                   are compile-time constants and stay;
 *   box2d-discrete  continuous collision off (SetContinuousPhysics(false)),
 *                   pile only: b2World::SolveTOI rescans the whole contact
 *                   list for every time-of-impact event, which dominates a
 *                   large pile (83% of the time at N = 10000 under perf).
 *
 * Joints: b2RevoluteJoint (b2RevoluteJointDef::Initialize at the scene's
 * world point, to a static body at the origin for the world); groups: a
 * negative groupIndex.
 *
 * Penetration: on the scene's polygons, without Box2D's skins. The
 * separations of b2WorldManifold (the contact's manifold at the bodies'
 * transforms after the step) are between the polygons grown by their skins
 * (b2_polygonRadius each), where bodies rest about b2_linearSlop deep, so
 * the penetration of the polygons themselves is -(separation + rA + rB),
 * rA and rB the two shapes' radii: a box resting on the floor reads 0 (its
 * polygon rests 0.015 m above it).
 */

#include <box2d/box2d.h>
#include <vector>

#ifndef BENCH_BOX2D_PACKAGE
#define BENCH_BOX2D_PACKAGE "unknown"
#endif
#include "bench_scenes.h"

namespace {

struct GravityPair {
    int body1, body2;
    double G;
};

/* box2d-matched's position iterations: our engine's default. */
const int B2_MATCHED_POSITION_ITERATIONS = 4;

struct B2World {
    b2World world;
    std::vector<b2Body *> bodies;
    std::vector<GravityPair> pairs;
    int position_iterations = 3;
    b2Body *ground = nullptr; /* the world's end of joints, made when needed */
    explicit B2World(double gy) : world(b2Vec2(0.0f, (float)gy)) {}
};

void b2_describe(FILE *out) {
    fprintf(out,
            "# box2d: Box2D b2_version %d.%d.%d (package %s; 2.4.1 still says 2.4.0), float, at "
            "its defaults: 8 velocity / 3 position iterations, warm starting, continuous "
            "collision, sleeping on, linear slop %g m, polygon radius %g m, restitution "
            "threshold 1 m/s, max translation %g m/step; penetration: manifold separations "
            "at the final transforms plus both polygon radii (skins removed)\n"
            "# box2d-nosleep: differs from box2d in: sleeping off\n"
            "# box2d-matched: differs from box2d in: sleeping off, position iterations %d "
            "(default 3)\n"
            "# box2d-discrete: differs from box2d in: continuous collision off (pile)\n",
            b2_version.major, b2_version.minor, b2_version.revision, BENCH_BOX2D_PACKAGE,
            (double)b2_linearSlop, (double)b2_polygonRadius, (double)b2_maxTranslation,
            B2_MATCHED_POSITION_ITERATIONS);
    if (bench_iterations > 0) {
        fprintf(out, "# box2d*: --iterations %d (velocity iterations)\n", bench_iterations);
    }
}

void b2_describe_none(FILE *out) {
    (void)out;
}

void *b2_world_new_common(double gy, int capacity, bool sleep, bool continuous,
                          int position_iterations = 3) {
    B2World *w = new B2World(gy);
    w->world.SetAllowSleeping(sleep);
    w->world.SetContinuousPhysics(continuous);
    w->position_iterations = position_iterations;
    w->bodies.reserve((size_t)(capacity > 0 ? capacity : 4));
    return w;
}

void *b2_world_new(double gy, int contacts, int capacity) {
    (void)contacts; /* non-colliding bodies get maskBits 0 */
    return b2_world_new_common(gy, capacity, true, true);
}

void *b2_world_new_nosleep(double gy, int contacts, int capacity) {
    (void)contacts;
    return b2_world_new_common(gy, capacity, false, true);
}

void *b2_world_new_matched(double gy, int contacts, int capacity) {
    (void)contacts;
    return b2_world_new_common(gy, capacity, false, true, B2_MATCHED_POSITION_ITERATIONS);
}

void *b2_world_new_discrete(double gy, int contacts, int capacity) {
    (void)contacts;
    return b2_world_new_common(gy, capacity, true, false);
}

void b2_world_free(void *world) {
    delete static_cast<B2World *>(world);
}

int b2_add(B2World *w, b2Body *body) {
    w->bodies.push_back(body);
    return (int)w->bodies.size() - 1;
}

int b2_add_static_box(void *world, double cx, double cy, double hx, double hy, double friction,
                      double elasticity) {
    B2World *w = static_cast<B2World *>(world);
    b2BodyDef def;
    def.type = b2_staticBody;
    def.position.Set((float)cx, (float)cy);
    b2Body *body = w->world.CreateBody(&def);
    b2PolygonShape box;
    box.SetAsBox((float)hx, (float)hy);
    b2FixtureDef fixture;
    fixture.shape = &box;
    fixture.friction = (float)friction;
    fixture.restitution = (float)elasticity;
    body->CreateFixture(&fixture);
    return b2_add(w, body);
}

int b2_add_body(void *world, const bench_shape_t *shape, double x, double y, double angle,
                double mass, double friction, double elasticity, int collides) {
    B2World *w = static_cast<B2World *>(world);
    b2BodyDef def;
    def.type = b2_dynamicBody;
    def.position.Set((float)x, (float)y);
    def.angle = (float)angle;
    b2Body *body = w->world.CreateBody(&def);
    if (shape->sides == BENCH_CAPSULE) {
        fprintf(stderr, "bench_box2d: Box2D 2.4 has no capsule shape\n");
        exit(2);
    }
    b2CircleShape circle;
    b2PolygonShape polygon;
    if (shape->sides == BENCH_CIRCLE) {
        circle.m_radius = (float)shape->radius;
    } else {
        b2Vec2 verts[b2_maxPolygonVertices];
        int n = bench_shape_vertex_count(shape);
        for (int i = 0; i < n; i++) {
            double vx, vy;
            bench_shape_vertex(shape, i, &vx, &vy);
            verts[i].Set((float)vx, (float)vy);
        }
        polygon.Set(verts, n);
    }
    b2FixtureDef fixture;
    fixture.shape = shape->sides == BENCH_CIRCLE ? static_cast<b2Shape *>(&circle)
                                                 : static_cast<b2Shape *>(&polygon);
    fixture.density = (float)(mass / bench_shape_area(shape));
    fixture.friction = (float)friction;
    fixture.restitution = (float)elasticity;
    if (!collides) fixture.filter.maskBits = 0;
    body->CreateFixture(&fixture);
    return b2_add(w, body);
}

void b2_set_velocity(void *world, int body, double vx, double vy) {
    B2World *w = static_cast<B2World *>(world);
    w->bodies[(size_t)body]->SetLinearVelocity(b2Vec2((float)vx, (float)vy));
}

void b2_add_gravity_pair(void *world, int body1, int body2, double G) {
    B2World *w = static_cast<B2World *>(world);
    GravityPair pair = {body1, body2, G};
    w->pairs.push_back(pair);
}

void b2_step(void *world, double dt) {
    B2World *w = static_cast<B2World *>(world);
    for (const GravityPair &pair : w->pairs) {
        b2Body *a = w->bodies[(size_t)pair.body1], *b = w->bodies[(size_t)pair.body2];
        b2Vec2 d = b->GetWorldCenter() - a->GetWorldCenter();
        double r2 = (double)d.x * d.x + (double)d.y * d.y, r = sqrt(r2);
        if (r < 1e-9) continue;
        double f = pair.G * a->GetMass() * b->GetMass() / r2 / r;
        b2Vec2 force((float)(f * d.x), (float)(f * d.y));
        a->ApplyForceToCenter(force, true);
        b->ApplyForceToCenter(-force, true);
    }
    w->world.Step((float)dt, bench_iterations > 0 ? bench_iterations : 8, w->position_iterations);
}

void b2_get_state(void *world, int body, bench_state_t *out) {
    B2World *w = static_cast<B2World *>(world);
    b2Body *b = w->bodies[(size_t)body];
    b2Vec2 p = b->GetWorldCenter(), v = b->GetLinearVelocity();
    out->x = p.x;
    out->y = p.y;
    out->angle = b->GetAngle();
    out->vx = v.x;
    out->vy = v.y;
    out->omega = b->GetAngularVelocity();
}

double b2_contact_penetration(b2Contact *c) {
    double pen = 0.0;
    if (!c->IsTouching()) return 0.0;
    b2WorldManifold wm;
    c->GetWorldManifold(&wm);
    /* A polygon's radius is its skin, which its separation leaves out; a
     * circle's is its size, already in it. */
    b2Shape *sa = c->GetFixtureA()->GetShape(), *sb = c->GetFixtureB()->GetShape();
    double skins = (sa->GetType() == b2Shape::e_polygon ? (double)sa->m_radius : 0.0) +
                   (sb->GetType() == b2Shape::e_polygon ? (double)sb->m_radius : 0.0);
    for (int i = 0; i < c->GetManifold()->pointCount; i++) {
        double depth = -((double)wm.separations[i] + skins);
        if (depth > pen) pen = depth;
    }
    return pen;
}

double b2_max_penetration(void *world) {
    B2World *w = static_cast<B2World *>(world);
    double pen = 0.0;
    for (b2Contact *c = w->world.GetContactList(); c; c = c->GetNext()) {
        double p = b2_contact_penetration(c);
        if (p > pen) pen = p;
    }
    return pen;
}

double b2_pair_penetration(void *world, int body1, int body2) {
    B2World *w = static_cast<B2World *>(world);
    b2Body *a = w->bodies[(size_t)body1], *b = w->bodies[(size_t)body2];
    double pen = 0.0;
    for (b2Contact *c = w->world.GetContactList(); c; c = c->GetNext()) {
        b2Body *ba = c->GetFixtureA()->GetBody(), *bb = c->GetFixtureB()->GetBody();
        if ((ba == a && bb == b) || (ba == b && bb == a)) {
            double p = b2_contact_penetration(c);
            if (p > pen) pen = p;
        }
    }
    return pen;
}

/* b2DistanceJoint as a spring: rest length `rest`, no limits (minimum 0,
 * which Box2D raises to b2_linearSlop; maximum FLT_MAX), stiffness k and
 * damping c: a soft constraint solved with the velocity iterations. */
void b2_add_spring(void *world, int body1, int body2, double k, double damping, double rest) {
    B2World *w = static_cast<B2World *>(world);
    b2Body *a = w->bodies[(size_t)body1], *b = w->bodies[(size_t)body2];
    b2DistanceJointDef def;
    def.Initialize(a, b, a->GetWorldCenter(), b->GetWorldCenter());
    def.length = (float)rest;
    def.minLength = 0.0f;
    def.maxLength = FLT_MAX;
    def.stiffness = (float)k;
    def.damping = (float)damping;
    def.collideConnected = false;
    w->world.CreateJoint(&def);
}

void b2_set_angular_velocity(void *world, int body, double omega) {
    B2World *w = static_cast<B2World *>(world);
    w->bodies[(size_t)body]->SetAngularVelocity((float)omega);
}

/* b2RevoluteJointDef::Initialize at the world point (reference angle the
 * bodies' relative angle now), a static body at the origin standing for
 * the world, the limits when asked. */
void b2_add_revolute(void *world, int body1, int body2, double x, double y, int limit,
                     double lower, double upper) {
    B2World *w = static_cast<B2World *>(world);
    if (body1 < 0 && w->ground == nullptr) {
        b2BodyDef def;
        w->ground = w->world.CreateBody(&def);
    }
    b2Body *a = body1 >= 0 ? w->bodies[(size_t)body1] : w->ground;
    b2RevoluteJointDef def;
    def.Initialize(a, w->bodies[(size_t)body2], b2Vec2((float)x, (float)y));
    def.enableLimit = limit != 0;
    def.lowerAngle = (float)lower;
    def.upperAngle = (float)upper;
    w->world.CreateJoint(&def);
}

/* A negative groupIndex: never collide within the group. */
void b2_set_group(void *world, int body, int group) {
    B2World *w = static_cast<B2World *>(world);
    for (b2Fixture *f = w->bodies[(size_t)body]->GetFixtureList(); f; f = f->GetNext()) {
        b2Filter filter = f->GetFilterData();
        filter.groupIndex = (int16)-group;
        f->SetFilterData(filter);
    }
}

const bench_ops_t box2d_ops = {
    "box2d",         NULL,          0,
    0,               b2_describe,   b2_world_new,
    b2_world_free,   b2_add_static_box, b2_add_body,
    b2_set_velocity, b2_add_gravity_pair, b2_step,
    b2_get_state,    b2_max_penetration, b2_pair_penetration,
    b2_add_spring,   b2_set_angular_velocity, 1.0, NULL,
    b2_add_revolute, b2_set_group, NULL,
};

const bench_ops_t box2d_nosleep_ops = {
    "box2d-nosleep",   NULL, 0,
    0,                 b2_describe_none,              b2_world_new_nosleep,
    b2_world_free,     b2_add_static_box,             b2_add_body,
    b2_set_velocity,   b2_add_gravity_pair,           b2_step,
    b2_get_state,      b2_max_penetration,            b2_pair_penetration,
    b2_add_spring,     b2_set_angular_velocity,       1.0, NULL,
    b2_add_revolute, b2_set_group, NULL,
};

const bench_ops_t box2d_matched_ops = {
    "box2d-matched",   NULL,                          0,
    0,                 b2_describe_none,              b2_world_new_matched,
    b2_world_free,     b2_add_static_box,             b2_add_body,
    b2_set_velocity,   b2_add_gravity_pair,           b2_step,
    b2_get_state,      b2_max_penetration,            b2_pair_penetration,
    b2_add_spring,     b2_set_angular_velocity,       1.0, NULL,
    b2_add_revolute, b2_set_group, NULL,
};

const bench_ops_t box2d_discrete_ops = {
    "box2d-discrete", "pile",            0,
    0,                b2_describe_none,  b2_world_new_discrete,
    b2_world_free,    b2_add_static_box, b2_add_body,
    b2_set_velocity,  b2_add_gravity_pair, b2_step,
    b2_get_state,     b2_max_penetration, b2_pair_penetration,
    b2_add_spring,    b2_set_angular_velocity, 1.0, NULL,
    b2_add_revolute, b2_set_group, NULL,
};

} // namespace

int main(int argc, char **argv) {
    const bench_ops_t *ops[4] = {&box2d_ops, &box2d_nosleep_ops, &box2d_matched_ops,
                                 &box2d_discrete_ops};
    return bench_main(argc, argv, ops, 4);
}
