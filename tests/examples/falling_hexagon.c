#include <stdio.h>
#include <jostle/jostle.h>

int main(void) {
    scene_t *scene = scene_init();
    scene_set_gravity(scene, (vector_t){0, -10});          /* m/s^2 */
    scene_set_contacts_enabled(scene, true);              /* bodies collide */
    list_t *floor = polygon_make_box((vector_t){0, -0.5}, 10, 0.5);
    scene_add_body(scene, body_init(floor, INFINITY, (rgb_color_t){0.3, 0.3, 0.3}));
    list_t *hexagon = polygon_make_regular(6, 0.5, (vector_t){0, 5}, 0);
    body_t *body = body_init(hexagon, 1.0, (rgb_color_t){0.9, 0.4, 0.1});
    body_set_elasticity(body, 0.5);
    scene_add_body(scene, body);
    for (int i = 0; i < 300; i++) scene_tick(scene, 1.0 / 60);
    printf("after 5 s the hexagon rests at y = %.3f m\n", body_get_centroid(body).y);
    scene_free(scene);
    return 0;
}
