/* Only the seed declarations: a mass on a spring above an infinite-mass
 * anchor, and two blocks in an elastic physics collision. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "body.h"
#include "collision.h"
#include "forces.h"
#include "list.h"
#include "scene.h"
#include "vector.h"

static list_t *square(double x, double y, double half) {
    list_t *shape = list_init(4, free);
    double corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (size_t i = 0; i < 4; i++) {
        vector_t *v = malloc(sizeof(vector_t));
        *v = (vector_t){x + half * corners[i][0], y + half * corners[i][1]};
        list_add(shape, v);
    }
    return shape;
}

int main(void) {
    scene_t *scene = scene_init();
    rgb_color_t red = {1, 0, 0};
    body_t *anchor = body_init(square(0, 0, 0.1), INFINITY, red);
    body_t *bob = body_init(square(0, -2, 0.1), 2.0, red);
    scene_add_body(scene, anchor);
    scene_add_body(scene, bob);
    create_spring(scene, 8.0, anchor, bob); /* omega = sqrt(k / m) = 2 rad/s */

    body_t *left = body_init(square(10, 0, 0.5), 1.0, red);
    body_t *right = body_init(square(12, 0, 0.5), 1.0, red);
    body_set_velocity(left, (vector_t){1, 0});
    scene_add_body(scene, left);
    scene_add_body(scene, right);
    create_physics_collision(scene, left, right, 1.0);

    double dt = 1e-3;
    for (int i = 0; i < 3000; i++) scene_tick(scene, dt);
    double t = 3000 * dt, expected = -2.0 * cos(2.0 * t);
    printf("spring: y = %.4f m, A cos(wt) = %.4f m\n", body_get_centroid(bob).y, expected);
    printf("collision: left %.3f m/s, right %.3f m/s\n", body_get_velocity(left).x,
           body_get_velocity(right).x);
    collision_info_t info = find_collision(left, right);
    printf("still touching: %s\n", info.collided ? "yes" : "no");
    bool ok = fabs(body_get_centroid(bob).y - expected) < 1e-2 &&
              fabs(body_get_velocity(left).x) < 1e-12 &&
              fabs(body_get_velocity(right).x - 1.0) < 1e-12;
    scene_free(scene);
    return ok ? 0 : 1;
}
