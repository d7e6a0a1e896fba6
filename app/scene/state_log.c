#include "scene/state_log.h"
#include <inttypes.h>
#include <string.h>

static uint64_t hash_double(uint64_t h, double value) {
    uint64_t bits;
    memcpy(&bits, &value, sizeof bits);
    for (int i = 0; i < 8; i++) h = (h ^ ((bits >> (8 * i)) & 0xff)) * 1099511628211u;
    return h;
}

uint64_t state_log_hash(scene_t *scene) {
    uint64_t h = 14695981039346656037u;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        if (body_is_removed(body)) continue;
        vector_t at = body_get_centroid(body);
        h = hash_double(hash_double(hash_double(h, at.x), at.y), body_get_rotation(body));
    }
    return h;
}

void state_log_print(FILE *out, const sandbox_t *sandbox, unsigned long frame, bool bodies) {
    scene_t *scene = sandbox->scene;
    size_t count = 0;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        count += !body_is_removed(scene_get_body(scene, i));
    }
    fprintf(out, "state: frame %lu  bodies %zu  hash %016" PRIx64, frame, count,
            state_log_hash(scene));
    if (sandbox->game != NULL) {
        game_status_t status = game_status(sandbox->game);
        fprintf(out, "  score %d  lives %d  remaining %d", status.score, status.lives,
                status.remaining);
    }
    fputc('\n', out);
    for (size_t i = 0; bodies && i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        if (body_is_removed(body)) continue;
        vector_t at = body_get_centroid(body);
        fprintf(out, "body %zu  %.17g %.17g %.17g\n", i, at.x, at.y, body_get_rotation(body));
    }
    fflush(out);
}
