#include "draw/render.h"
#include <SDL2_gfxPrimitives.h>
#include <math.h>
#include <stdlib.h>
#include "draw/batch.h"
#include "draw/draw.h"
#include "draw/edge_markers.h"
#include "draw/focus.h"
#include "tools/tools.h"
#include "tools/joint_tool.h"
#include "draw/joint_draw.h"
#include "draw/raster.h"
#include "draw/round_outline.h"

#define MAX_VERTICES BATCH_MAX_POLYGON
#define IMPULSE_MAX_PIXELS 200.0
#define THROW_PIXELS 4.0 /* a throw's arrow, pixels per m/s */

static palette_rgb_t rgb_of(rgb_color_t c) {
    return (palette_rgb_t){(unsigned char)lround(fmin(1.0, fmax(0.0, c.r)) * 255.0),
                           (unsigned char)lround(fmin(1.0, fmax(0.0, c.g)) * 255.0),
                           (unsigned char)lround(fmin(1.0, fmax(0.0, c.b)) * 255.0)};
}

static palette_rgb_t lighter(palette_rgb_t c, double amount) {
    return (palette_rgb_t){(unsigned char)(c.r + (255 - c.r) * amount),
                           (unsigned char)(c.g + (255 - c.g) * amount),
                           (unsigned char)(c.b + (255 - c.b) * amount)};
}

static void draw_grid(SDL_Renderer *renderer, const camera_t *camera) {
    double step = 1.0;
    while (camera_length_to_pixels(camera, step) < 12.0) step *= 5.0;
    vector_t low = camera_to_world(camera, (vector_t){0, camera->height});
    vector_t high = camera_to_world(camera, (vector_t){camera->width, 0});
    SDL_SetRenderDrawBlendMode(renderer, SDL_BLENDMODE_NONE);
    SDL_SetRenderDrawColor(renderer, PALETTE_GRID.r, PALETTE_GRID.g, PALETTE_GRID.b, 255);
    for (double x = floor(low.x / step) * step; x <= high.x; x += step) {
        int px = (int)lround(camera_to_pixel(camera, (vector_t){x, 0}).x);
        SDL_RenderDrawLine(renderer, px, 0, px, camera->height - 1);
    }
    for (double y = floor(low.y / step) * step; y <= high.y; y += step) {
        int py = (int)lround(camera_to_pixel(camera, (vector_t){0, y}).y);
        SDL_RenderDrawLine(renderer, 0, py, camera->width - 1, py);
    }
}

/* Kept across frames so that once warm a frame allocates nothing. */
static batch_t body_batch, arrow_batch, impulse_batch, throw_batch;

void render_free(void) {
    batch_free(&body_batch);
    batch_free(&arrow_batch);
    batch_free(&impulse_batch);
    batch_free(&throw_batch);
    edge_markers_free();
    raster_free();
}

/* A body's outline in pixels (room for BATCH_MAX_POLYGON): a polygon's own
 * vertices; a circle's or capsule's true boundary (round_outline). For a
 * round body, also the radius line that shows its rotation: from the centre
 * of a circle, or of a capsule's second end, to the rim along the body's
 * angle (a capsule's: along its core). Returns the vertex count. */
static int body_pixels(const camera_t *camera, body_t *body, vector_t *pixels,
                       vector_t line[2]) {
    body_shape_kind_t kind = body_get_shape_kind(body);
    if (kind == BODY_SHAPE_POLYGON) {
        polygon_t polygon = body_get_polygon(body);
        int n = polygon.count < BATCH_MAX_POLYGON ? (int)polygon.count : BATCH_MAX_POLYGON;
        for (int k = 0; k < n; k++) pixels[k] = camera_to_pixel(camera, polygon.vertices[k]);
        return n;
    }
    vector_t p1, p2;
    body_get_core(body, &p1, &p2);
    double r = camera_length_to_pixels(camera, body_get_round_radius(body));
    vector_t c1 = camera_to_pixel(camera, p1), c2 = camera_to_pixel(camera, p2);
    double angle = body_get_rotation(body);
    if (kind == BODY_SHAPE_CAPSULE) angle = atan2(p2.y - p1.y, p2.x - p1.x);
    line[0] = c2;
    line[1] = round_rim_point(c2, r, angle);
    return round_outline(c1, c2, r, pixels);
}

/* A one-and-a-half-pixel line from a to b as a thin quad (nothing when
 * shorter than a pixel). */
static void batch_line(batch_t *batch, vector_t a, vector_t b, palette_rgb_t color) {
    vector_t d = vec_subtract(b, a);
    double length = vec_get_length(d);
    if (!(length >= 1.0)) return;
    vector_t side = vec_multiply(0.75 / length, vec_perpendicular(d));
    vector_t quad[4] = {vec_add(a, side), vec_add(b, side), vec_subtract(b, side),
                        vec_subtract(a, side)};
    batch_polygon(batch, quad, 4, color, 255);
}

/* A chain: each segment a band 6 pixels deep on its solid side (the right
 * of its direction), filled and outlined, so that the side bodies rest on
 * shows. */
static void batch_chain(batch_t *batch, const camera_t *camera, body_t *chain,
                        palette_rgb_t fill, palette_rgb_t outline) {
    double depth = 6.0 / camera_length_to_pixels(camera, 1.0);
    for (size_t k = 0; k < body_get_segment_count(chain); k++) {
        vector_t p1, p2;
        body_get_segment(chain, k, &p1, &p2);
        vector_t e = vec_normalize(vec_subtract(p2, p1));
        vector_t back = {e.y * depth, -e.x * depth};
        vector_t quad[4] = {camera_to_pixel(camera, p1), camera_to_pixel(camera, vec_add(p1, back)),
                            camera_to_pixel(camera, vec_add(p2, back)),
                            camera_to_pixel(camera, p2)};
        if (!batch_polygon_visible(quad, 4, camera->width, camera->height)) continue;
        batch_outlined(batch, quad, 4, fill, fill);
        batch_line(batch, quad[0], quad[3], outline);
    }
}

/* Every body in view, fill and outline, in one batch: each body's outline
 * is read and taken to pixels once. */
static void draw_bodies(SDL_Renderer *renderer, SDL_Surface *canvas, app_t *app,
                        body_t *hovered) {
    scene_t *scene = app->sandbox.scene;
    const camera_t *camera = &app->camera;
    vector_t pixels[BATCH_MAX_POLYGON];
    bool dim_sleeping = app->overlays[OVERLAY_SLEEPING];
    batch_clear(&body_batch);
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        if (body_is_removed(body)) continue;
        if (body_get_shape_kind(body) == BODY_SHAPE_CHAIN) {
            palette_rgb_t fill = rgb_of(body_get_color(body));
            palette_rgb_t outline = body == hovered ? PALETTE_GRAB : lighter(fill, 0.45);
            batch_chain(&body_batch, camera, body, fill, outline);
            continue;
        }
        vector_t line[2] = {VEC_ZERO, VEC_ZERO};
        int n = body_pixels(camera, body, pixels, line);
        if (!batch_polygon_visible(pixels, n, camera->width, camera->height)) continue;
        palette_rgb_t fill = rgb_of(body_get_color(body));
        if (dim_sleeping && body_is_sleeping(body)) fill = palette_sleeping(fill);
        palette_rgb_t outline = body == hovered              ? PALETTE_GRAB
                                : body == app->sandbox.inspected ? PALETTE_ACCENT
                                                                 : lighter(fill, 0.45);
        batch_outlined(&body_batch, pixels, n, fill, outline);
        batch_line(&body_batch, line[0], line[1], outline);
    }
    raster_begin(renderer, canvas);
    raster_batch(&body_batch);
}

/* The scene file's springs: a zigzag between the centroids they join,
 * over the bodies. */
static void draw_springs(SDL_Renderer *renderer, app_t *app) {
    scene_file_t *file = app->sandbox.file;
    palette_rgb_t c = PALETTE_SPRING;
    size_t count = scene_file_force_count(file);
    for (size_t i = 0; i < count; i++) {
        scene_file_force_t force = scene_file_get_force(file, i);
        if (force.kind != SCENE_FILE_SPRING || force.body2 == NULL) continue;
        vector_t a = camera_to_pixel(&app->camera, body_get_centroid(force.body1));
        vector_t b = camera_to_pixel(&app->camera, body_get_centroid(force.body2));
        vector_t d = vec_subtract(b, a);
        double length = vec_get_length(d);
        if (!(length < 1e5)) continue; /* not finite, or far beyond the view */
        if (length < 16.0) {
            aalineRGBA(renderer, draw_coord(a.x), draw_coord(a.y), draw_coord(b.x),
                       draw_coord(b.y), c.r, c.g, c.b, 255);
            continue;
        }
        /* Straight ends, ten zigs between, 4 px to either side. */
        vector_t along = vec_multiply(1.0 / length, d), side = vec_perpendicular(along);
        const int zigs = 10;
        double end = 4.0, span = length - 2.0 * end;
        vector_t previous = a;
        for (int k = 0; k <= zigs + 1; k++) {
            vector_t next;
            if (k == zigs + 1) {
                next = b;
            } else {
                double t = end + span * (k + 0.5) / (zigs + 1);
                double offset = k == 0 ? 0.0 : (k % 2 == 0 ? 4.0 : -4.0);
                next = vec_add(vec_add(a, vec_multiply(t, along)), vec_multiply(offset, side));
            }
            aalineRGBA(renderer, draw_coord(previous.x), draw_coord(previous.y),
                       draw_coord(next.x), draw_coord(next.y), c.r, c.g, c.b, 255);
            previous = next;
        }
    }
}

/* While a throw is dragged: the velocity it will leave with, as an arrow
 * from the shape (THROW_PIXELS a m/s) in the velocity overlay's colour,
 * with its speed written at the head. */
static void draw_throw(SDL_Renderer *renderer, vector_t from, vector_t velocity) {
    double speed = vec_get_length(velocity);
    vector_t head = {from.x + THROW_PIXELS * velocity.x, from.y - THROW_PIXELS * velocity.y};
    SDL_RenderFlush(renderer);
    batch_clear(&throw_batch);
    batch_arrow(&throw_batch, from, head, PALETTE_VELOCITY, 255, 2);
    raster_batch(&throw_batch);
    draw_text(renderer, draw_coord(head.x + 6), draw_coord(head.y - 4), PALETTE_VELOCITY,
              "%.1f m/s", speed);
}

/* The next shape's outline in pixels with its centroid at `at` (room for
 * MAX_VERTICES): a round one's true boundary, a polygon's vertices. */
static int preview_pixels(const app_t *app, vector_t at, vector_t *pixels) {
    const camera_t *camera = &app->camera;
    vector_t p1, p2;
    double radius;
    if (sandbox_shape_core(app->shape, &p1, &p2, &radius)) {
        return round_outline(camera_to_pixel(camera, vec_add(at, p1)),
                             camera_to_pixel(camera, vec_add(at, p2)),
                             camera_length_to_pixels(camera, radius), pixels);
    }
    size_t n = list_size(app->next_vertices);
    if (n > MAX_VERTICES) n = MAX_VERTICES;
    vector_t centroid = polygon_centroid(app->next_vertices);
    for (size_t i = 0; i < n; i++) {
        vector_t v = *(vector_t *)list_get(app->next_vertices, i);
        pixels[i] = camera_to_pixel(camera, vec_add(at, vec_subtract(v, centroid)));
    }
    return (int)n;
}

/* The shape the next click drops, translucent, where it would go (moved
 * clear of the floor and walls); a red outline where a drop is refused.
 * None in a game. */
static void draw_preview(SDL_Renderer *renderer, app_t *app) {
    /* A player wants the field, not a shape hanging at the cursor. */
    if (app->sandbox.game != NULL || app->tool != TOOL_DROP) return;
    if (!app->mouse_inside || app->next_vertices == NULL) return;
    if (app->drag != DRAG_NONE && app->drag != DRAG_THROW) return;
    if (!app_in_view(app, app->mouse)) return;
    vector_t at;
    bool refused = sandbox_place(&app->sandbox, app->next_vertices,
                                 camera_to_world(&app->camera, app->mouse), &at) != NULL;
    vector_t pixels[MAX_VERTICES];
    int n = preview_pixels(app, at, pixels);
    Sint16 xs[MAX_VERTICES], ys[MAX_VERTICES];
    for (int i = 0; i < n; i++) {
        xs[i] = draw_coord(pixels[i].x);
        ys[i] = draw_coord(pixels[i].y);
    }
    if (refused) {
        polygonRGBA(renderer, xs, ys, (int)n, PALETTE_WARNING.r, PALETTE_WARNING.g,
                    PALETTE_WARNING.b, 220);
        return;
    }
    palette_rgb_t c = PALETTE_BODIES[app->sandbox.next_color % PALETTE_BODY_COUNT];
    Uint8 alpha = app->drag == DRAG_THROW ? 150 : 70;
    filledPolygonRGBA(renderer, xs, ys, (int)n, c.r, c.g, c.b, alpha);
    polygonRGBA(renderer, xs, ys, (int)n, c.r, c.g, c.b, 200);
    if (app->drag == DRAG_THROW) {
        draw_throw(renderer, camera_to_pixel(&app->camera, at), app_throw_velocity(app));
    }
}

/* The explosion tool's reach round the cursor, and the last blast's ring
 * growing from its centre to its radius as it fades. */
static void draw_blast(SDL_Renderer *renderer, app_t *app) {
    palette_rgb_t c = PALETTE_BLAST;
    vector_t cursor = app->mouse;
    if (app->tool == TOOL_EXPLODE && app->mouse_inside && app_in_view(app, cursor)) {
        Sint16 r = draw_coord(TOOLS_BLAST_RADIUS_PIXELS);
        aacircleRGBA(renderer, draw_coord(cursor.x), draw_coord(cursor.y), r, c.r, c.g, c.b, 160);
        aacircleRGBA(renderer, draw_coord(cursor.x), draw_coord(cursor.y), 3, c.r, c.g, c.b, 255);
    }
    if (!app->blast.shown) return;
    double t = app->blast.age / TOOLS_BLAST_SECONDS;
    vector_t at = camera_to_pixel(&app->camera, app->blast.centre);
    double radius = camera_length_to_pixels(&app->camera, app->blast.radius) * (0.3 + 0.7 * t);
    Uint8 alpha = (Uint8)lround(255.0 * fmax(0.0, 1.0 - t));
    for (int k = 0; k < 3; k++) {
        aacircleRGBA(renderer, draw_coord(at.x), draw_coord(at.y), draw_coord(radius - k), c.r,
                     c.g, c.b, alpha);
    }
}

/* A body's outline, thick, in colour c: what the box tool found. */
static void outline_body(SDL_Renderer *renderer, const camera_t *camera, body_t *body,
                         palette_rgb_t c) {
    polygon_t polygon = body_get_polygon(body);
    size_t n = polygon.count;
    /* An open chain's points do not close. */
    size_t edges = body_get_shape_kind(body) == BODY_SHAPE_CHAIN ? body_get_segment_count(body) : n;
    for (size_t k = 0; k < edges; k++) {
        vector_t a = camera_to_pixel(camera, polygon.vertices[k]);
        vector_t b = camera_to_pixel(camera, polygon.vertices[(k + 1) % n]);
        thickLineRGBA(renderer, draw_coord(a.x), draw_coord(a.y), draw_coord(b.x),
                      draw_coord(b.y), 3, c.r, c.g, c.b, 255);
    }
}

/* The ray tool's ray: to its first hit in the accent colour, a dot at the
 * point, the normal as a short arrow, the fraction beside it; beyond the
 * hit, dim. The box tool's box, and every body overlapping it outlined. */
static void draw_probe(SDL_Renderer *renderer, app_t *app) {
    if (!app->probe.shown) return;
    const camera_t *camera = &app->camera;
    vector_t from = camera_to_pixel(camera, app->probe.from);
    vector_t to = camera_to_pixel(camera, app->probe.to);
    palette_rgb_t a = PALETTE_ACCENT, dim = PALETTE_TEXT_DIM;
    if (app->probe.tool == TOOL_BOX) {
        static body_t *found[TOOLS_BOX_MAX];
        size_t n = tools_box_bodies(app, found, TOOLS_BOX_MAX);
        for (size_t i = 0; i < n && i < TOOLS_BOX_MAX; i++) outline_body(renderer, camera, found[i], a);
        rectangleRGBA(renderer, draw_coord(fmin(from.x, to.x)), draw_coord(fmin(from.y, to.y)),
                      draw_coord(fmax(from.x, to.x)), draw_coord(fmax(from.y, to.y)), a.r, a.g,
                      a.b, 255);
        draw_text(renderer, draw_coord(fmax(from.x, to.x) + 4), draw_coord(fmin(from.y, to.y)),
                  PALETTE_ACCENT, "%zu", n);
        return;
    }
    ray_hit_t hit;
    if (!tools_ray_hit(app, &hit)) {
        aalineRGBA(renderer, draw_coord(from.x), draw_coord(from.y), draw_coord(to.x),
                   draw_coord(to.y), a.r, a.g, a.b, 255);
        return;
    }
    vector_t at = camera_to_pixel(camera, hit.point);
    aalineRGBA(renderer, draw_coord(at.x), draw_coord(at.y), draw_coord(to.x), draw_coord(to.y),
               dim.r, dim.g, dim.b, 160);
    thickLineRGBA(renderer, draw_coord(from.x), draw_coord(from.y), draw_coord(at.x),
                  draw_coord(at.y), 2, a.r, a.g, a.b, 255);
    filledCircleRGBA(renderer, draw_coord(at.x), draw_coord(at.y), 4, a.r, a.g, a.b, 255);
    vector_t tip = {at.x + 40.0 * hit.normal.x, at.y - 40.0 * hit.normal.y};
    palette_rgb_t n = PALETTE_POINT;
    thickLineRGBA(renderer, draw_coord(at.x), draw_coord(at.y), draw_coord(tip.x),
                  draw_coord(tip.y), 2, n.r, n.g, n.b, 255);
    filledCircleRGBA(renderer, draw_coord(tip.x), draw_coord(tip.y), 3, n.r, n.g, n.b, 255);
    draw_text(renderer, draw_coord(at.x + 8), draw_coord(at.y + 6), PALETTE_ACCENT, "%.3f",
              hit.fraction);
}

/* The grab as a spring, in a scene without world contacts (a mouse joint
 * is drawn with the joints). */
static void draw_grab(SDL_Renderer *renderer, app_t *app) {
    if (app->sandbox.grab.body == NULL || app->sandbox.grab.joint != NULL) return;
    vector_t from = camera_to_pixel(&app->camera, sandbox_grab_point(&app->sandbox));
    vector_t to = camera_to_pixel(&app->camera, app->sandbox.grab.target);
    aalineRGBA(renderer, draw_coord(from.x), draw_coord(from.y), draw_coord(to.x),
               draw_coord(to.y), PALETTE_GRAB.r, PALETTE_GRAB.g, PALETTE_GRAB.b, 220);
    filledCircleRGBA(renderer, draw_coord(from.x), draw_coord(from.y), 3, PALETTE_GRAB.r,
                     PALETTE_GRAB.g, PALETTE_GRAB.b, 255);
    circleRGBA(renderer, draw_coord(to.x), draw_coord(to.y), 5, PALETTE_GRAB.r, PALETTE_GRAB.g,
               PALETTE_GRAB.b, 255);
}

/* The joint tool's first end, and a line from it to the cursor while
 * the second is chosen. */
static void draw_joint_pick(SDL_Renderer *renderer, app_t *app) {
    vector_t from;
    if (!joint_tool_pick(app, &from)) return;
    vector_t a = camera_to_pixel(&app->camera, from), b = app->mouse;
    palette_rgb_t c = PALETTE_ACCENT;
    filledCircleRGBA(renderer, draw_coord(a.x), draw_coord(a.y), 4, c.r, c.g, c.b, 255);
    if (!app->mouse_inside || !app_in_view(app, b)) return;
    aalineRGBA(renderer, draw_coord(a.x), draw_coord(a.y), draw_coord(b.x), draw_coord(b.y), c.r,
               c.g, c.b, 200);
}

static void draw_bounds(SDL_Renderer *renderer, app_t *app) {
    scene_t *scene = app->sandbox.scene;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        if (body_is_removed(body)) continue;
        aabb_t box = body_get_bounds(body);
        vector_t a = camera_to_pixel(&app->camera, box.min);
        vector_t b = camera_to_pixel(&app->camera, box.max);
        rectangleRGBA(renderer, draw_coord(a.x), draw_coord(b.y), draw_coord(b.x),
                      draw_coord(a.y), PALETTE_BOUNDS.r, PALETTE_BOUNDS.g, PALETTE_BOUNDS.b, 255);
    }
}

static void draw_velocities(app_t *app) {
    scene_t *scene = app->sandbox.scene;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        if (body_is_removed(body) || sandbox_is_static(body)) continue;
        vector_t c = body_get_centroid(body);
        vector_t tip = vec_add(c, vec_multiply(RENDER_VELOCITY_SCALE, body_get_velocity(body)));
        batch_arrow(&arrow_batch, camera_to_pixel(&app->camera, c),
                    camera_to_pixel(&app->camera, tip), PALETTE_VELOCITY, 255, 1);
    }
}

static void draw_centroids(SDL_Renderer *renderer, app_t *app) {
    scene_t *scene = app->sandbox.scene;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        if (body_is_removed(body) || sandbox_is_static(body)) continue;
        vector_t p = camera_to_pixel(&app->camera, body_get_centroid(body));
        Sint16 x = draw_coord(p.x), y = draw_coord(p.y);
        filledCircleRGBA(renderer, x, y, 3, PALETTE_CENTROID.r, PALETTE_CENTROID.g,
                         PALETTE_CENTROID.b, 255);
        circleRGBA(renderer, x, y, 3, 0, 0, 0, 255);
    }
}

/* Where a contact's arrow sits: the middle of its points, or between the
 * centroids when it has none. */
static vector_t contact_anchor(const contact_t *contact) {
    if (contact->point_count >= 2) {
        return vec_multiply(0.5, vec_add(contact->points[0], contact->points[1]));
    }
    if (contact->point_count == 1) return contact->points[0];
    return vec_multiply(0.5, vec_add(body_get_centroid(contact->body1),
                                     body_get_centroid(contact->body2)));
}

/* Half the smaller side of the body's bounding box (pixels). */
static double body_extent(const camera_t *camera, body_t *body) {
    aabb_t box = body_get_bounds(body);
    return 0.5 * camera_length_to_pixels(camera, fmin(box.max.x - box.min.x, box.max.y - box.min.y));
}

/* The cursor over the view, in pixels; false when it is elsewhere. */
static bool cursor_in_view(const app_t *app, vector_t *cursor) {
    *cursor = app->mouse;
    return app->mouse_inside && app_in_view(app, app->mouse);
}

/* The strength of a contact's impact this step: its normal impulses. */
static double contact_weight(const contact_t *contact) {
    size_t n = contact->point_count > 2 ? 2 : contact->point_count;
    double sum = n == 0 ? contact->normal_impulse[0] : 0.0;
    for (size_t k = 0; k < n; k++) sum += contact->normal_impulse[k];
    return isfinite(sum) ? sum : 0.0;
}

/* An arrow along the collision axis of the touching contacts nearest the
 * cursor and of the step's strongest impacts (draw/focus.h). */
static void draw_axes(app_t *app) {
    scene_t *scene = app->sandbox.scene;
    size_t count = scene_contact_count(scene), total = 0, shown = 0;
    vector_t cursor;
    bool has_cursor = cursor_in_view(app, &cursor);
    focus_top_t near, strong;
    focus_top_init(&near, FOCUS_NEAR);
    focus_top_init(&strong, FOCUS_STRONG);
    for (size_t i = 0; i < count; i++) {
        const contact_t *contact = scene_get_contact(scene, i);
        if (!vec_is_finite(contact->axis) || !contact->touching) continue;
        total++;
        focus_top_offer(&strong, i, contact_weight(contact));
        focus_near_offer(&near, i, camera_to_pixel(&app->camera, contact_anchor(contact)),
                         has_cursor, cursor);
    }
    focus_top_sort(&near);
    focus_top_sort(&strong);
    for (size_t i = 0; i < count; i++) {
        bool is_near = focus_top_has(&near, i), is_strong = focus_top_has(&strong, i);
        if (!is_near && !is_strong) continue;
        const contact_t *contact = scene_get_contact(scene, i);
        vector_t tail = camera_to_pixel(&app->camera, contact_anchor(contact));
        shown++;
        /* As long as the smaller body allows, so that neighbours' arrows stay apart. */
        double extent = fmin(body_extent(&app->camera, contact->body1),
                             body_extent(&app->camera, contact->body2));
        double length = fmin(48.0, fmax(10.0, 1.3 * extent));
        /* World y is up, pixel y is down. */
        vector_t dir = {contact->axis.x, -contact->axis.y};
        batch_arrow(&arrow_batch, tail, vec_add(tail, vec_multiply(length, dir)), PALETTE_AXIS,
                    255, 2);
    }
    app->overlay_shown[OVERLAY_AXES] = shown;
    app->overlay_total[OVERLAY_AXES] = total;
}

static void draw_points(SDL_Renderer *renderer, app_t *app) {
    scene_t *scene = app->sandbox.scene;
    for (size_t i = 0; i < scene_contact_count(scene); i++) {
        const contact_t *contact = scene_get_contact(scene, i);
        size_t n = contact->point_count > 2 ? 2 : contact->point_count;
        for (size_t k = 0; k < n; k++) {
            vector_t p = camera_to_pixel(&app->camera, contact->points[k]);
            Sint16 x = draw_coord(p.x), y = draw_coord(p.y);
            /* Filled where the bodies touch or push; hollow for a
             * speculative point (apart, about to touch). */
            if (contact->separation[k] <= 0.0 || contact->normal_impulse[k] > 0.0) {
                boxRGBA(renderer, x - 3, y - 3, x + 3, y + 3, PALETTE_POINT.r, PALETTE_POINT.g,
                        PALETTE_POINT.b, 255);
                rectangleRGBA(renderer, x - 3, y - 3, x + 3, y + 3, 0, 0, 0, 255);
            } else {
                rectangleRGBA(renderer, x - 3, y - 3, x + 3, y + 3, PALETTE_POINT.r,
                              PALETTE_POINT.g, PALETTE_POINT.b, 255);
            }
        }
    }
}

/* The impulses of the trail nearest the cursor, and its strongest (faded
 * with their age), as arrows that fade out (draw/focus.h). */
static void draw_impulses(app_t *app) {
    vector_t cursor;
    bool has_cursor = cursor_in_view(app, &cursor);
    size_t count = app->trail.count, shown = 0;
    focus_top_t near, strong;
    focus_top_init(&near, FOCUS_NEAR);
    focus_top_init(&strong, FOCUS_STRONG);
    for (size_t i = 0; i < count; i++) {
        const impulse_mark_t *mark = impulse_trail_get(&app->trail, i);
        double fade = 1.0 - mark->age / IMPULSE_TRAIL_SECONDS;
        if (fade <= 0.0) continue;
        focus_top_offer(&strong, i, fade * vec_get_length(mark->impulse));
        focus_near_offer(&near, i, camera_to_pixel(&app->camera, mark->point), has_cursor,
                         cursor);
    }
    focus_top_sort(&near);
    focus_top_sort(&strong);
    for (size_t i = 0; i < count; i++) {
        if (!focus_top_has(&near, i) && !focus_top_has(&strong, i)) continue;
        const impulse_mark_t *mark = impulse_trail_get(&app->trail, i);
        double fade = 1.0 - mark->age / IMPULSE_TRAIL_SECONDS;
        vector_t tail = camera_to_pixel(&app->camera, mark->point);
        vector_t head = camera_to_pixel(
            &app->camera, vec_add(mark->point, vec_multiply(app->impulse_scale, mark->impulse)));
        vector_t arrow = vec_subtract(head, tail);
        double length = vec_get_length(arrow);
        if (length < 3.0) continue;
        shown++;
        /* Linear in the impulse up to a cap, so a heavy impact stays on screen. */
        if (length > IMPULSE_MAX_PIXELS) {
            head = vec_add(tail, vec_multiply(IMPULSE_MAX_PIXELS / length, arrow));
        }
        batch_arrow(&impulse_batch, tail, head, PALETTE_IMPULSE, (Uint8)lround(255.0 * fade), 4);
    }
    app->overlay_shown[OVERLAY_IMPULSES] = shown;
    app->overlay_total[OVERLAY_IMPULSES] = count;
}

/* Where the axes and impulses are drawn in full: a faint ring round the
 * cursor, when some were left out elsewhere. */
static void draw_focus_ring(SDL_Renderer *renderer, app_t *app) {
    vector_t cursor;
    if (!cursor_in_view(app, &cursor) || app->drag != DRAG_NONE) return;
    bool left_out = false;
    for (int o = OVERLAY_AXES; o <= OVERLAY_IMPULSES; o++) {
        left_out = left_out || (app->overlays[o] && app->overlay_shown[o] < app->overlay_total[o]);
    }
    if (!left_out) return;
    palette_rgb_t c = PALETTE_FOCUS;
    aacircleRGBA(renderer, draw_coord(cursor.x), draw_coord(cursor.y), (Sint16)FOCUS_RADIUS, c.r,
                 c.g, c.b, 255);
}

double render_world(SDL_Renderer *renderer, SDL_Surface *canvas, app_t *app, body_t *hovered) {
    SDL_SetRenderDrawBlendMode(renderer, SDL_BLENDMODE_NONE);
    SDL_SetRenderDrawColor(renderer, PALETTE_BACKGROUND.r, PALETTE_BACKGROUND.g,
                           PALETTE_BACKGROUND.b, 255);
    SDL_RenderClear(renderer);
    draw_grid(renderer, &app->camera);
    draw_bodies(renderer, canvas, app, hovered);
    draw_springs(renderer, app);
    joint_draw_all(renderer, app, joint_tool_hovered(app));
    SDL_RenderFlush(renderer);
    Uint64 overlays_start = SDL_GetPerformanceCounter();
    if (app->overlays[OVERLAY_BOUNDS]) draw_bounds(renderer, app);
    /* The velocities and the axes: opaque arrows, over the bounds and
     * under the centroids, as they always were. */
    batch_clear(&arrow_batch);
    if (app->overlays[OVERLAY_VELOCITIES]) {
        draw_velocities(app);
        raster_begin(renderer, canvas);
        raster_batch(&arrow_batch);
        batch_clear(&arrow_batch);
    }
    if (app->overlays[OVERLAY_CENTROIDS]) draw_centroids(renderer, app);
    if (app->overlays[OVERLAY_AXES]) draw_axes(app);
    raster_begin(renderer, canvas);
    raster_batch(&arrow_batch);
    /* The impulses fade: translucent, so through SDL_RenderGeometry. */
    batch_clear(&impulse_batch);
    if (app->overlays[OVERLAY_IMPULSES]) draw_impulses(app);
    raster_begin(renderer, canvas);
    raster_batch(&impulse_batch);
    if (app->overlays[OVERLAY_POINTS]) draw_points(renderer, app);
    draw_focus_ring(renderer, app);
    SDL_RenderFlush(renderer);
    double overlays_s = (double)(SDL_GetPerformanceCounter() - overlays_start) /
                        (double)SDL_GetPerformanceFrequency();
    draw_grab(renderer, app);
    draw_joint_pick(renderer, app);
    draw_blast(renderer, app);
    draw_probe(renderer, app);
    draw_preview(renderer, app);
    edge_markers_draw(renderer, canvas, app);
    return overlays_s;
}
