#include "tools/explosion.h"
#include <math.h>

size_t explosion_apply(scene_t *scene, vector_t centre, double radius, double speed) {
    if (!vec_is_finite(centre) || !(radius > 0.0) || !(speed > 0.0)) return 0;
    size_t pushed = 0;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        double mass = body_get_mass(body);
        if (body_is_removed(body) || isinf(mass)) continue;
        vector_t away = vec_subtract(body_get_centroid(body), centre);
        double distance = vec_get_length(away);
        if (distance >= radius) continue;
        vector_t direction = distance > 1e-9 ? vec_multiply(1.0 / distance, away)
                                             : (vector_t){0.0, 1.0};
        double dv = speed * (1.0 - distance / radius);
        body_add_impulse(body, vec_multiply(mass * dv, direction));
        pushed++;
    }
    return pushed;
}
