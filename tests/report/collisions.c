/* 1D collisions (docs/accuracy.md, section 4): two boxes meet head-on
 * under each scheme; the velocities after against the exact ones. */
#include <math.h>
#include "report.h"

typedef struct {
    const char *name;
    double m1, m2, v1, v2, e;
} collision_case_t;

static const collision_case_t COLLISIONS[] = {
    {"elastic, masses 1 and 3", 1.0, 3.0, 2.0, -1.0, 1.0},
    {"inelastic, masses 1 and 3", 1.0, 3.0, 2.0, -1.0, 0.0},
    {"e = 0.5, masses 2 and 2", 2.0, 2.0, 3.0, 0.0, 0.5},
    {"e = 1.5 (gains energy), masses 1 and 1", 1.0, 1.0, 2.0, -2.0, 1.5},
    {"e = 0.8 against infinite mass", 1.0, INFINITY, 5.0, 0.0, 0.8},
};

/* v1' and v2' of a head-on collision with restitution e. */
static void collision_exact(const collision_case_t *c, double *v1, double *v2) {
    if (isinf(c->m2)) {
        *v1 = c->v2 - c->e * (c->v1 - c->v2);
        *v2 = c->v2;
        return;
    }
    double total = c->m1 + c->m2, p = c->m1 * c->v1 + c->m2 * c->v2;
    *v1 = (p - c->m2 * c->e * (c->v1 - c->v2)) / total;
    *v2 = (p + c->m1 * c->e * (c->v1 - c->v2)) / total;
}

/* Two unit boxes 2 m apart, run until well after they meet. world: world
 * contacts (restitution from elasticity); else create_physics_collision. */
static void collision_run(const collision_case_t *c, integrator_t integrator, bool world,
                          double *error, double *momentum_error) {
    const rgb_color_t grey = {0.5f, 0.5f, 0.5f};
    scene_t *scene = scene_init();
    scene_set_integrator(scene, integrator);
    body_t *a = body_init(polygon_make_box((vector_t){-1.0, 0.0}, 0.5, 0.5), c->m1, grey);
    body_t *b = body_init(polygon_make_box((vector_t){1.0, 0.0}, 0.5, 0.5), c->m2, grey);
    scene_add_body(scene, a);
    scene_add_body(scene, b);
    body_set_velocity(a, (vector_t){c->v1, 0.0});
    body_set_velocity(b, (vector_t){c->v2, 0.0});
    if (world) {
        scene_set_contacts_enabled(scene, true);
        body_set_elasticity(a, c->e);
        body_set_elasticity(b, c->e);
        body_set_friction(a, 0.0);
        body_set_friction(b, 0.0);
    } else {
        create_physics_collision(scene, a, b, c->e);
    }
    for (int i = 0; i < 120; i++) scene_tick(scene, 1.0 / 60.0);
    double v1, v2;
    collision_exact(c, &v1, &v2);
    double va = body_get_velocity(a).x, vb = body_get_velocity(b).x;
    double scale = fabs(c->v1) + fabs(c->v2);
    *error = fmax(fabs(va - v1), fabs(vb - v2)) / scale;
    if (isinf(c->m2)) {
        *momentum_error = fabs(vb - c->v2) / scale; /* the wall must not move */
    } else {
        double p0 = c->m1 * c->v1 + c->m2 * c->v2;
        *momentum_error = fabs(c->m1 * va + c->m2 * vb - p0) / (c->m1 * fabs(c->v1) +
                                                                c->m2 * fabs(c->v2));
    }
    scene_free(scene);
}

void report_write_collisions(FILE *md, const report_options_t *options) {
    FILE *csv = report_open(options->out_dir, "collisions.csv");
    fprintf(csv, "case,pipeline,integrator,velocity_error,momentum_error\n");
    if (md != NULL) {
        fprintf(md, "\n### 1D collisions\n\n");
        fprintf(md, "Two unit boxes meet head-on at 60 Hz; the velocities after are compared "
                    "with v1' = (p - m2 e (v1 - v2)) / (m1 + m2), v2' = (p + m1 e (v1 - v2)) / "
                    "(m1 + m2) (against an infinite mass: v1' = -e v1, the wall still). Errors "
                    "relative to |v1| + |v2|, the largest over the integrators; CSV: "
                    "[report/collisions.csv](report/collisions.csv).\n\n");
        fprintf(md, "| case | seed pair collision: velocity error | momentum error | world "
                    "contacts: velocity error | momentum error |\n|---|---|---|---|---|\n");
    }
    for (size_t k = 0; k < sizeof COLLISIONS / sizeof COLLISIONS[0]; k++) {
        double worst[2][2] = {{0, 0}, {0, 0}};
        for (int world = 0; world < 2; world++) {
            for (int i = 0; i < INTEGRATOR_COUNT; i++) {
                double error, momentum;
                collision_run(&COLLISIONS[k], (integrator_t)i, world, &error, &momentum);
                fprintf(csv, "%s,%s,%s,%.3e,%.3e\n", COLLISIONS[k].name,
                        world ? "world" : "seed", integrator_get_name((integrator_t)i), error,
                        momentum);
                worst[world][0] = fmax(worst[world][0], error);
                worst[world][1] = fmax(worst[world][1], momentum);
            }
        }
        if (md == NULL) continue;
        fprintf(md, "| %s | %.2g | %.2g | %.2g | %.2g |\n", COLLISIONS[k].name, worst[0][0],
                worst[0][1], worst[1][0], worst[1][1]);
    }
    fclose(csv);
}
