/*
 * This engine's bench_ops_t variants (the public API only), shared by the
 * benchmark program (bench_engine.c) and the stability suite
 * (tests/stability/stability.c), so that both run the scenes of
 * bench_scenes.h through the same code. Include after bench_scenes.h's
 * includes are available; link build/libjostle.a.
 *
 * Settings: world contacts on (scene_set_contacts_enabled), the default
 * solver iterations (scene_set_solver_iterations is not called: 8 velocity,
 * 4 position) and integrator (seed, or bench_integrator when set), gravity
 * by scene_set_gravity. Bodies: polygon_make_box / polygon_make_regular with
 * the scene's mass (density 1: mass = area), static bodies mass INFINITY;
 * body_set_friction and body_set_elasticity with the scene's values (the
 * engine mixes friction by geometric mean and elasticity by max, so a static
 * floor gets elasticity 0 and the bouncing box 0.8). Springs: create_spring
 * (rest length 0, so spring_rest is 0) and, for damping on a spring to a
 * static body, create_drag on the moving body (the same force: the anchor
 * does not move).
 * Penetration: the step record of the last scene_tick, max over
 * CONTACT_WORLD entries' points of -separation (0 when none overlaps). The
 * record is made by the narrowphase of that tick, i.e. before its solve and
 * integration (the positions one step earlier than the other engines' ones).
 *
 * Joints: joint_def_revolute at the scene's world point, reference angle
 * the bodies' relative angle then, its limits when asked; a group is the
 * collision filter's group (body_set_collision_filter).
 *
 * Variants: "ours" (world contacts, every scene), "ours-seed" (cradle
 * only, as the scene asks for seed-style elastic collisions; no joints, as
 * they need world contacts): contacts off
 * and create_physics_collision(scene, a, b, e) for every pair of bodies,
 * with e the larger of the two elasticities (1 in cradle); "ours-symplectic"
 * (orbit only): INTEGRATOR_SYMPLECTIC_EULER instead of the default seed
 * integrator, whose velocity update uses only the force at the start of the
 * step and is not symplectic; "ours-sleeping" (pile only): sleeping on.
 */
#ifndef BENCH_OURS_H
#define BENCH_OURS_H

#include "jostle/jostle.h"
#include "bench_scenes.h"

/* The integrator of every scene made after it is set (an integrator_t);
 * -1 keeps the scene's default (seed), and ours-symplectic its own. */
static int bench_integrator = -1;
/* The workers of every scene made after it is set (scene_set_workers). */
static size_t bench_workers = 1;

#ifndef BENCH_ENGINE_VERSION
#define BENCH_ENGINE_VERSION "unknown"
#endif

typedef struct {
    scene_t *scene;
    body_t **bodies;
    double *angle0; /* rotation built into the polygon (regular polygons) */
    int count, capacity;
    int seed; /* ours-seed: pairwise seed collisions instead of world contacts */
    int symplectic; /* ours-symplectic: INTEGRATOR_SYMPLECTIC_EULER */
} ours_world_t;

static const rgb_color_t grey = {0.5, 0.5, 0.5};

static void ours_describe(FILE *out) {
    fprintf(out,
            "# ours: this engine (build/libjostle.a, %s); world contacts on, the default solver "
            "iterations (scene.h), seed integrator, friction mixed by geometric "
            "mean, elasticity by max; penetration from the step record (before the last "
            "solve); ours-seed (cradle): contacts off, create_physics_collision for every pair; "
            "ours-symplectic (orbit): "
            "INTEGRATOR_SYMPLECTIC_EULER\n",
            BENCH_ENGINE_VERSION);
}

static void ours_describe_none(FILE *out) {
    (void)out;
}

static void *ours_world_new_common(double gy, int contacts, int capacity, int seed,
                                   int symplectic, int sleeping) {
    ours_world_t *w = (ours_world_t *)calloc(1, sizeof(ours_world_t));
    w->scene = scene_init();
    scene_set_gravity(w->scene, (vector_t){0.0, gy});
    if (contacts && !seed) scene_set_contacts_enabled(w->scene, true);
    /* The speed comparisons run every body every step, as the peers do
     * with their sleeping off; ours-sleeping measures the settled pile. */
    scene_set_sleeping(w->scene, sleeping);
    w->seed = seed;
    w->symplectic = symplectic;
    if (symplectic) {
        scene_set_integrator(w->scene, INTEGRATOR_SYMPLECTIC_EULER);
    } else if (bench_integrator >= 0) {
        scene_set_integrator(w->scene, (integrator_t)bench_integrator);
    }
    if (bench_iterations > 0) scene_set_solver_iterations(w->scene, (size_t)bench_iterations, 4);
    if (bench_workers > 1) scene_set_workers(w->scene, bench_workers);
    if (bench_stages) scene_set_profiling(w->scene, true);
    w->capacity = capacity > 0 ? capacity : 4;
    w->bodies = (body_t **)malloc(sizeof(body_t *) * (size_t)w->capacity);
    w->angle0 = (double *)malloc(sizeof(double) * (size_t)w->capacity);
    return w;
}

static void *ours_world_new(double gy, int contacts, int capacity) {
    return ours_world_new_common(gy, contacts, capacity, 0, 0, 0);
}

static void *ours_world_new_sleeping(double gy, int contacts, int capacity) {
    return ours_world_new_common(gy, contacts, capacity, 0, 0, 1);
}

static void *ours_world_new_seed(double gy, int contacts, int capacity) {
    return ours_world_new_common(gy, contacts, capacity, 1, 0, 0);
}

static void *ours_world_new_symplectic(double gy, int contacts, int capacity) {
    return ours_world_new_common(gy, contacts, capacity, 0, 1, 0);
}

static void ours_world_free(void *world) {
    ours_world_t *w = (ours_world_t *)world;
    scene_free(w->scene);
    free(w->bodies);
    free(w->angle0);
    free(w);
}

static int ours_add(ours_world_t *w, body_t *body, double angle0) {
    if (w->count == w->capacity) {
        w->capacity *= 2;
        w->bodies = (body_t **)realloc(w->bodies, sizeof(body_t *) * (size_t)w->capacity);
        w->angle0 = (double *)realloc(w->angle0, sizeof(double) * (size_t)w->capacity);
    }
    if (w->seed) {
        for (int i = 0; i < w->count; i++) {
            double e = fmax(body_get_elasticity(w->bodies[i]), body_get_elasticity(body));
            create_physics_collision(w->scene, w->bodies[i], body, e);
        }
    }
    scene_add_body(w->scene, body);
    w->bodies[w->count] = body;
    w->angle0[w->count] = angle0;
    return w->count++;
}

static int ours_add_static_box(void *world, double cx, double cy, double hx, double hy,
                               double friction, double elasticity) {
    ours_world_t *w = (ours_world_t *)world;
    body_t *body = body_init(polygon_make_box((vector_t){cx, cy}, hx, hy), INFINITY, grey);
    body_set_friction(body, friction);
    body_set_elasticity(body, elasticity);
    return ours_add(w, body, 0.0);
}

static int ours_add_body(void *world, const bench_shape_t *shape, double x, double y,
                         double angle, double mass, double friction, double elasticity,
                         int collides) {
    ours_world_t *w = (ours_world_t *)world;
    body_t *body;
    double angle0 = 0.0;
    if (shape->sides == BENCH_CIRCLE) {
        body = body_init_circle((vector_t){x, y}, shape->radius, mass, grey);
        angle0 = angle;
    } else if (shape->sides == BENCH_CAPSULE) {
        /* its ends turned by angle about (x, y) */
        vector_t half = {shape->hx * cos(angle), shape->hx * sin(angle)};
        body = body_init_capsule((vector_t){x - half.x, y - half.y},
                                 (vector_t){x + half.x, y + half.y}, shape->radius, mass, grey);
        angle0 = angle;
    } else if (shape->sides == 0) {
        body = body_init(polygon_make_box((vector_t){x, y}, shape->hx, shape->hy), mass, grey);
        if (angle != 0.0) body_set_rotation(body, angle);
    } else {
        /* the first vertex at `angle`: the shape turned by angle about its centre */
        body = body_init(polygon_make_regular((size_t)shape->sides, shape->radius,
                                              (vector_t){x, y}, angle),
                         mass, grey);
        angle0 = angle;
    }
    body_set_friction(body, friction);
    body_set_elasticity(body, elasticity);
    if (!collides) body_set_collision_filter(body, 0, 0, 0);
    return ours_add(w, body, angle0);
}

static void ours_set_velocity(void *world, int body, double vx, double vy) {
    ours_world_t *w = (ours_world_t *)world;
    body_set_velocity(w->bodies[body], (vector_t){vx, vy});
}

static void ours_add_gravity_pair(void *world, int body1, int body2, double G) {
    ours_world_t *w = (ours_world_t *)world;
    create_newtonian_gravity(w->scene, G, w->bodies[body1], w->bodies[body2]);
}

static void ours_step(void *world, double dt) {
    scene_tick(((ours_world_t *)world)->scene, dt);
}

static int ours_awake_bodies(void *world) {
    ours_world_t *w = (ours_world_t *)world;
    int awake = 0;
    for (int i = 0; i < w->count; i++) {
        awake += isfinite(body_get_mass(w->bodies[i])) && !body_is_sleeping(w->bodies[i]);
    }
    return awake;
}

static void ours_get_state(void *world, int body, bench_state_t *out) {
    ours_world_t *w = (ours_world_t *)world;
    body_t *b = w->bodies[body];
    vector_t x = body_get_centroid(b), v = body_get_velocity(b);
    out->x = x.x;
    out->y = x.y;
    out->angle = w->angle0[body] + body_get_rotation(b);
    out->vx = v.x;
    out->vy = v.y;
    out->omega = body_get_angular_velocity(b);
}

/* Max of -separation over the world contacts of the last tick, restricted to
 * the pair (a, b) unless a is NULL. */
static double ours_penetration(ours_world_t *w, body_t *a, body_t *b) {
    double pen = 0.0;
    size_t count = scene_contact_count(w->scene);
    for (size_t i = 0; i < count; i++) {
        const contact_t *c = scene_get_contact(w->scene, i);
        if (c->kind != CONTACT_WORLD) continue;
        if (a != NULL && !((c->body1 == a && c->body2 == b) || (c->body1 == b && c->body2 == a)))
            continue;
        for (size_t p = 0; p < c->point_count && p < 2; p++) {
            if (-c->separation[p] > pen) pen = -c->separation[p];
        }
    }
    return pen;
}

static double ours_max_penetration(void *world) {
    return ours_penetration((ours_world_t *)world, NULL, NULL);
}

static double ours_pair_penetration(void *world, int body1, int body2) {
    ours_world_t *w = (ours_world_t *)world;
    return ours_penetration(w, w->bodies[body1], w->bodies[body2]);
}

static void ours_add_spring(void *world, int body1, int body2, double k, double damping,
                            double rest) {
    ours_world_t *w = (ours_world_t *)world;
    body_t *a = w->bodies[body1], *b = w->bodies[body2];
    if (rest != 0.0) {
        fprintf(stderr, "bench_ours: create_spring has rest length 0 (asked %g)\n", rest);
        abort();
    }
    create_spring(w->scene, k, a, b);
    if (damping > 0.0) {
        if (isfinite(body_get_mass(a)) && isfinite(body_get_mass(b))) {
            fprintf(stderr, "bench_ours: damping needs one end static (create_drag)\n");
            abort();
        }
        create_drag(w->scene, damping, isfinite(body_get_mass(a)) ? a : b);
    }
}

static void ours_set_angular_velocity(void *world, int body, double omega) {
    ours_world_t *w = (ours_world_t *)world;
    body_set_angular_velocity(w->bodies[body], omega);
}

/* joint_def_revolute at the world point, its reference angle the bodies'
 * relative angle now, with the limits when asked. */
static void ours_add_revolute(void *world, int body1, int body2, double x, double y, int limit,
                              double lower, double upper) {
    ours_world_t *w = (ours_world_t *)world;
    body_t *b1 = body1 >= 0 ? w->bodies[body1] : NULL, *b2 = w->bodies[body2];
    joint_def_t def = joint_def_revolute(b1, b2, (vector_t){x, y});
    /* joint_def_revolute leaves it 0; the limits count from the pose now */
    def.reference_angle = body_get_rotation(b2) - (b1 != NULL ? body_get_rotation(b1) : 0.0);
    def.enable_limit = limit != 0;
    def.lower_angle = lower;
    def.upper_angle = upper;
    joint_create(w->scene, &def);
}

/* The body's filter with its group replaced. */
static void ours_set_group(void *world, int body, int group) {
    ours_world_t *w = (ours_world_t *)world;
    uint32_t category, mask;
    body_get_collision_filter(w->bodies[body], &category, &mask, NULL);
    body_set_collision_filter(w->bodies[body], category, mask, (uint32_t)group);
}

/* The scene's profile of the last step (--stages), in ms. */
static int ours_stage_ms(void *world, const char **names, double *ms, int max) {
    scene_profile_t profile = scene_get_profile(((ours_world_t *)world)->scene);
    int count = SCENE_STAGE_COUNT < max ? SCENE_STAGE_COUNT : max;
    for (int k = 0; k < count; k++) {
        names[k] = scene_stage_name((scene_stage_t)k);
        ms[k] = 1e3 * profile.seconds[k];
    }
    return count;
}

static const bench_ops_t ours_ops = {
    "ours",          NULL,           0, 0, ours_describe,
    ours_world_new,  ours_world_free, ours_add_static_box,
    ours_add_body,   ours_set_velocity, ours_add_gravity_pair,
    ours_step,       ours_get_state, ours_max_penetration,
    ours_pair_penetration, ours_add_spring, ours_set_angular_velocity, 0.0,
    NULL,                  ours_add_revolute, ours_set_group,     ours_stage_ms,
};

static const bench_ops_t ours_seed_ops = {
    "ours-seed",         "cradle",        0, 0, ours_describe_none,
    ours_world_new_seed, ours_world_free, ours_add_static_box,
    ours_add_body,       ours_set_velocity, ours_add_gravity_pair,
    ours_step,           ours_get_state,  ours_max_penetration,
    ours_pair_penetration, ours_add_spring, ours_set_angular_velocity, 0.0,
    NULL,                  NULL,              NULL,              NULL,
};

static const bench_ops_t ours_symplectic_ops = {
    "ours-symplectic",         "orbit",        0, 0, ours_describe_none,
    ours_world_new_symplectic, ours_world_free, ours_add_static_box,
    ours_add_body,             ours_set_velocity, ours_add_gravity_pair,
    ours_step,                 ours_get_state,  ours_max_penetration,
    ours_pair_penetration, ours_add_spring, ours_set_angular_velocity, 0.0,
    NULL,                  ours_add_revolute, ours_set_group,     NULL,
};

static const bench_ops_t ours_sleeping_ops = {
    "ours-sleeping",         "pile",         0, 0, ours_describe_none,
    ours_world_new_sleeping, ours_world_free, ours_add_static_box,
    ours_add_body,           ours_set_velocity, ours_add_gravity_pair,
    ours_step,               ours_get_state,  ours_max_penetration,
    ours_pair_penetration, ours_add_spring, ours_set_angular_velocity, 0.0,
    ours_awake_bodies,     ours_add_revolute, ours_set_group,     ours_stage_ms,
};

#endif // #ifndef BENCH_OURS_H
