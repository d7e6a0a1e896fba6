/*
 * Body and template blocks (scene_file_parse.h): each property read once,
 * then the shape checked as the engine will see it, the mass derived and
 * checked, the defaults and the limits applied, and the name recorded.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "scene_file_parse.h"

static const double DEFAULT_FRICTION = 0.6; /* the engine's default (body.h) */
static const double DEFAULT_DENSITY = 1.0;  /* kg/m^2 */
static const rgb_color_t STATIC_COLOR = {0.5, 0.5, 0.5};
static const rgb_color_t MOVING_COLOR = {0.85, 0.55, 0.25};
/* The engine's outline of a round body (body.h), counted against the limits
 * on vertices since the engine keeps it. */
enum { CIRCLE_OUTLINE = 32, CAPSULE_OUTLINE = 34 };
static const double SHORTEST_CAPSULE = 1e-9; /* share of the radius (body.h) */

/* ---- Bodies --------------------------------------------------------------- */

/* Where each property of the block was given (line 0: not given), so that a
 * second one is refused naming the first. */
typedef struct {
    sf_where_t shape, mass, elasticity, friction, color, position, angle, velocity, spin, tag,
        filter, repeat, asleep, sleep_timer;
} seen_t;

static bool once(parser_t *p, sf_where_t *seen, const char *what, sf_where_t here) {
    if (seen->line != 0) {
        return sf_fail(p->lexer, here,
                       "expected one %s per body, found a second (the first at line %zu)", what,
                       seen->line);
    }
    *seen = here;
    return true;
}

/* Vertex coordinates up to the end of the property, at least `least` of
 * them. A list may go on over several lines: a line that starts with a
 * number continues it. */
static bool read_vertices(parser_t *p, sf_shape_t *shape, size_t least) {
    size_t capacity = 0;
    for (;;) {
        if (p->token.kind == TOKEN_NEWLINE) {
            /* Look past the line ends without taking them, unless a number
             * follows. */
            sf_lexer_t saved_lexer = *p->lexer;
            sf_token_t saved_token = p->token;
            while (p->token.kind == TOKEN_NEWLINE) next(p);
            double ignored;
            if (sf_read_number(&p->token, false, &ignored) == SF_NUMBER_SYNTAX) {
                *p->lexer = saved_lexer;
                p->token = saved_token;
                break;
            }
        }
        if (p->token.kind != TOKEN_WORD ||
            sf_read_number(&p->token, false, &(double){0}) == SF_NUMBER_SYNTAX) {
            break;
        }
        if (shape->count == SCENE_FILE_MAX_VERTICES) {
            char expectation[128];
            snprintf(expectation, sizeof expectation, "at most %d vertices",
                     SCENE_FILE_MAX_VERTICES);
            return sf_expected(p, expectation);
        }
        vector_t v;
        char what[64];
        snprintf(what, sizeof what, "the x of vertex %zu (m)", shape->count + 1);
        quantity_t x = COORDINATE, y = COORDINATE;
        x.what = what;
        if (!sf_read_quantity(p, &x, &v.x)) return false;
        snprintf(what, sizeof what, "the y of vertex %zu (m)", shape->count + 1);
        y.what = what;
        if (!sf_read_quantity(p, &y, &v.y)) return false;
        sf_reserve((void **)&shape->written, &capacity, shape->count + 1, sizeof(vector_t));
        shape->written[shape->count++] = v;
    }
    if (shape->count < least) {
        char expectation[128];
        snprintf(expectation, sizeof expectation, "at least %zu %s (x y pairs), %zu so far", least,
                 least == 3 && shape->kind == SHAPE_VERTICES ? "vertices" : "points",
                 shape->count);
        return sf_expected(p, expectation);
    }
    return true;
}

/* `capsule X1 Y1 X2 Y2 R`: two different end centres and the radius. */
static bool read_capsule(parser_t *p, sf_shape_t *shape) {
    static const char *const names[4] = {"the x of the first end (m)", "the y of the first end (m)",
                                         "the x of the second end (m)",
                                         "the y of the second end (m)"};
    double *values[4] = {&shape->ends[0].x, &shape->ends[0].y, &shape->ends[1].x,
                         &shape->ends[1].y};
    for (size_t i = 0; i < 4; i++) {
        quantity_t q = COORDINATE;
        q.what = names[i];
        if (!sf_read_quantity(p, &q, values[i])) return false;
    }
    sf_where_t radius_where = p->token.where;
    if (!sf_read_quantity(p, &RADIUS, &shape->radius)) return false;
    double length = vec_get_length(vec_subtract(shape->ends[1], shape->ends[0]));
    if (!(length >= SHORTEST_CAPSULE * shape->radius)) {
        /* The engine makes equal ends a circle and refuses ends nearly
         * equal; a file says circle for a circle. */
        return sf_fail(p->lexer, radius_where,
                       "expected capsule ends at least %g of the radius apart (circle R for a "
                       "circle), found them %g m apart with radius %g m",
                       SHORTEST_CAPSULE, length, shape->radius);
    }
    return true;
}

static bool parse_shape(parser_t *p, const char *keyword, sf_body_t *body, seen_t *seen,
                        sf_where_t here) {
    if (!once(p, &seen->shape, "shape (regular, box, vertices, circle, capsule, chain or loop)",
              here))
        return false;
    sf_shape_t *shape = &body->shape;
    shape->where = here;
    if (strcmp(keyword, "circle") == 0) {
        shape->kind = SHAPE_CIRCLE;
        shape->count = CIRCLE_OUTLINE;
        return sf_read_quantity(p, &RADIUS, &shape->radius);
    }
    if (strcmp(keyword, "capsule") == 0) {
        shape->kind = SHAPE_CAPSULE;
        shape->count = CAPSULE_OUTLINE;
        return read_capsule(p, shape);
    }
    if (strcmp(keyword, "regular") == 0) {
        uint64_t sides = 0;
        shape->kind = SHAPE_REGULAR;
        if (!sf_read_count(p, "the number of sides", 3, SCENE_FILE_MAX_VERTICES, &sides))
            return false;
        shape->sides = (size_t)sides;
        shape->count = shape->sides;
        return sf_read_quantity(p, &RADIUS, &shape->radius);
    }
    if (strcmp(keyword, "box") == 0) {
        shape->kind = SHAPE_BOX;
        shape->count = 4;
        quantity_t width = SIZE, height = SIZE;
        width.what = "the width (m)";
        height.what = "the height (m)";
        return sf_read_quantity(p, &width, &shape->width) &&
               sf_read_quantity(p, &height, &shape->height);
    }
    if (strcmp(keyword, "chain") == 0 || strcmp(keyword, "loop") == 0) {
        shape->kind = keyword[0] == 'c' ? SHAPE_CHAIN : SHAPE_LOOP;
        return read_vertices(p, shape, shape->kind == SHAPE_CHAIN ? 2 : 3);
    }
    shape->kind = SHAPE_VERTICES;
    return read_vertices(p, shape, 3);
}

static bool parse_property(parser_t *p, sf_body_t *body, seen_t *seen) {
    sf_where_t here = p->token.where;
    char keyword[16] = "";
    if (p->token.length < sizeof keyword) memcpy(keyword, p->token.text, p->token.length);
    keyword[p->token.length < sizeof keyword ? p->token.length : 0] = '\0';
    if (strcmp(keyword, "regular") == 0 || strcmp(keyword, "box") == 0 ||
        strcmp(keyword, "vertices") == 0 || strcmp(keyword, "circle") == 0 ||
        strcmp(keyword, "capsule") == 0 || strcmp(keyword, "chain") == 0 ||
        strcmp(keyword, "loop") == 0) {
        next(p);
        return parse_shape(p, keyword, body, seen, here);
    }
    if (strcmp(keyword, "mass") == 0 || strcmp(keyword, "density") == 0 ||
        strcmp(keyword, "static") == 0) {
        if (!once(p, &seen->mass, "mass, density or static", here)) return false;
        next(p);
        if (keyword[0] == 's') {
            body->mass_kind = MASS_STATIC;
            return true;
        }
        body->mass_kind = keyword[0] == 'm' ? MASS_TOTAL : MASS_DENSITY;
        return sf_read_quantity(p, keyword[0] == 'm' ? &MASS : &DENSITY, &body->mass_value);
    }
    if (strcmp(keyword, "elasticity") == 0) {
        next(p);
        return once(p, &seen->elasticity, keyword, here) &&
               sf_read_quantity(p, &ELASTICITY, &body->elasticity);
    }
    if (strcmp(keyword, "friction") == 0) {
        next(p);
        return once(p, &seen->friction, keyword, here) &&
               sf_read_quantity(p, &FRICTION, &body->friction);
    }
    if (strcmp(keyword, "color") == 0) {
        next(p);
        body->has_color = true;
        quantity_t r = COLOR, g = COLOR, b = COLOR;
        r.what = "the red component of the colour";
        g.what = "the green component of the colour";
        b.what = "the blue component of the colour";
        return once(p, &seen->color, keyword, here) && sf_read_quantity(p, &r, &body->color.r) &&
               sf_read_quantity(p, &g, &body->color.g) && sf_read_quantity(p, &b, &body->color.b);
    }
    if (strcmp(keyword, "position") == 0) {
        next(p);
        body->has_position = true;
        return once(p, &seen->position, keyword, here) &&
               sf_read_vector(p, &COORDINATE, &body->position);
    }
    if (strcmp(keyword, "angle") == 0) {
        next(p);
        return once(p, &seen->angle, keyword, here) && sf_read_quantity(p, &ANGLE, &body->angle);
    }
    if (strcmp(keyword, "velocity") == 0) {
        next(p);
        return once(p, &seen->velocity, keyword, here) &&
               sf_read_vector(p, &VELOCITY, &body->velocity);
    }
    if (strcmp(keyword, "spin") == 0) {
        next(p);
        return once(p, &seen->spin, keyword, here) && sf_read_quantity(p, &SPIN, &body->spin);
    }
    if (strcmp(keyword, "tag") == 0) {
        next(p);
        return once(p, &seen->tag, keyword, here) && sf_read_name(p, "a tag", &body->tag, NULL);
    }
    if (strcmp(keyword, "group") == 0) {
        next(p);
        return sf_read_group_names(p, &body->groups, &body->group_count);
    }
    if (strcmp(keyword, "filter") == 0) {
        next(p);
        body->has_filter = true;
        return once(p, &seen->filter, keyword, here) &&
               sf_read_bits(p, "the filter's category bits", &body->category) &&
               sf_read_bits(p, "the filter's mask bits", &body->mask) &&
               sf_read_bits(p, "the filter's group", &body->filter_group);
    }
    if (strcmp(keyword, "centred") == 0) {
        next(p);
        if (body->shape.as_centred) {
            return sf_fail(p->lexer, here, "expected one centred per body, found a second");
        }
        body->shape.as_centred = true;
        return true;
    }
    if (strcmp(keyword, "asleep") == 0) {
        next(p);
        uint64_t island = 0;
        if (!once(p, &seen->asleep, keyword, here) ||
            !sf_read_count(p, "the island's number", 0, SCENE_FILE_MAX_BODIES, &island))
            return false;
        body->has_island = true;
        body->island = (size_t)island;
        if (p->doc->first_island.line == 0) p->doc->first_island = here;
        return true;
    }
    if (strcmp(keyword, "sleep_timer") == 0) {
        next(p);
        body->has_timer = true;
        body_sleep_timer_t *t = &body->timer;
        quantity_t slow = DURATION, window = DURATION, angle = STATE_VALUE;
        slow.what = "the time the body has been slow (s)";
        window.what = "the time since the anchor was taken (s)";
        angle.what = "the anchor's angle (rad)";
        return once(p, &seen->sleep_timer, keyword, here) &&
               sf_read_quantity(p, &slow, &t->slow_time) &&
               sf_read_quantity(p, &window, &t->window) &&
               sf_read_vector(p, &COORDINATE, &t->anchor) &&
               sf_read_quantity(p, &angle, &t->anchor_angle);
    }
    if (strcmp(keyword, "repeat") == 0) {
        next(p);
        uint64_t x = 0, y = 0;
        if (!once(p, &seen->repeat, keyword, here) ||
            !sf_read_count(p, "the number of copies along x", 1, SCENE_FILE_MAX_BODIES, &x) ||
            !sf_read_count(p, "the number of copies along y", 1, SCENE_FILE_MAX_BODIES, &y))
            return false;
        body->has_repeat = true;
        body->repeat_x = (size_t)x;
        body->repeat_y = (size_t)y;
        return sf_read_vector(p, &OFFSET, &body->repeat_step);
    }
    return sf_expected(p, "a body property (regular, box, vertices, circle, capsule, chain, loop, "
                          "mass, density, static, "
                          "elasticity, friction, color, position, angle, velocity, spin, tag, "
                          "group, filter, centred, asleep, sleep_timer, repeat) or '}'");
}

static list_t *list_of(const vector_t *vertices, size_t count) {
    list_t *list = list_init(count, free);
    for (size_t i = 0; i < count; i++) {
        vector_t *v = malloc(sizeof *v);
        if (v == NULL) abort();
        *v = vertices[i];
        list_add(list, v);
    }
    return list;
}

/* The shape's vertices as the file describes them, before centring. */
static list_t *shape_list(const sf_shape_t *shape) {
    switch (shape->kind) {
    case SHAPE_REGULAR:
        /* A flat bottom edge: vertices at -90 degrees +- half a side. */
        return polygon_make_regular(shape->sides, shape->radius, VEC_ZERO,
                                    -M_PI / 2.0 - M_PI / (double)shape->sides);
    case SHAPE_BOX: return polygon_make_box(VEC_ZERO, shape->width / 2.0, shape->height / 2.0);
    default: return list_of(shape->written, shape->count);
    }
}

/* Whether the centroid of a centred list lies as near the origin as
 * body_init_centred asks: within a thousandth of the radius. */
static bool centred_enough(list_t *list, vector_t centroid) {
    double radius = 0.0;
    for (size_t i = 0; i < list_size(list); i++) {
        radius = fmax(radius, vec_get_length(*(vector_t *)list_get(list, i)));
    }
    return vec_get_length(centroid) <= 1e-3 * radius;
}

/* A capsule's (or, with length 0, a disc's) moment of inertia per kilogram
 * about its centroid: the rectangle's (L^2 + 4 r^2) / 12 and the two
 * half-discs' (r^2 / 2 about the end centre, less the shift of their
 * centroids 4 r / (3 pi), plus the shift to the capsule's centroid), each
 * weighted by its share of the area. */
static double round_moment_per_kg(double length, double r) {
    double rectangle = 2.0 * r * length, discs = M_PI * r * r;
    double off = 0.5 * length + 4.0 * r / (3.0 * M_PI);
    double disc_own = 0.5 * r * r - (4.0 * r / (3.0 * M_PI)) * (4.0 * r / (3.0 * M_PI));
    double rectangle_moment = (length * length + 4.0 * r * r) / 12.0;
    return (rectangle * rectangle_moment + discs * (disc_own + off * off)) / (rectangle + discs);
}

/* A circle or capsule: exact area and moment; the centroid where the engine
 * puts it (the centre, or the first end plus half the core). */
static void derive_round(sf_shape_t *shape) {
    double r = shape->radius;
    double length = 0.0;
    shape->centroid = VEC_ZERO;
    if (shape->kind == SHAPE_CAPSULE) {
        vector_t d = vec_subtract(shape->ends[1], shape->ends[0]);
        length = vec_get_length(d);
        shape->centroid = vec_add(shape->ends[0], vec_multiply(0.5, d));
    }
    shape->area = M_PI * r * r + 2.0 * r * length;
    shape->moment_per_kg = round_moment_per_kg(length, r);
}

/* A chain: its segments as body_init_chain checks them (no segment of zero
 * length, the loop's closing one included); its frame is the file's. */
static bool derive_chain(parser_t *p, sf_shape_t *shape) {
    size_t n = shape->count, segments = shape->kind == SHAPE_LOOP ? n : n - 1;
    for (size_t i = 0; i < segments; i++) {
        vector_t a = shape->written[i], b = shape->written[(i + 1) % n];
        if (a.x == b.x && a.y == b.y) {
            return sf_fail(p->lexer, shape->where,
                           "expected segments of some length, found point %zu (%g, %g) equal to "
                           "point %zu",
                           (i + 1) % n + 1, b.x, b.y, i + 1);
        }
    }
    shape->centroid = VEC_ZERO;
    shape->area = 0.0;
    shape->moment_per_kg = 0.0;
    return true;
}

/* Checks the shape as the engine will see it and derives what the body needs.
 * The engine gets the vertices relative to their centroid, so that is the
 * list polygon_check judges (centring rounds, so checking the written list
 * alone would not be enough). */
static bool derive_shape(parser_t *p, sf_shape_t *shape) {
    if (shape->kind == SHAPE_CIRCLE || shape->kind == SHAPE_CAPSULE) {
        derive_round(shape);
        return true;
    }
    if (shape->kind == SHAPE_CHAIN || shape->kind == SHAPE_LOOP) return derive_chain(p, shape);
    list_t *list = shape_list(shape);
    const char *problem = polygon_check(list);
    if (problem == NULL && shape->kind == SHAPE_VERTICES && !polygon_is_counterclockwise(list)) {
        /* Documented: a clockwise list is reversed, here rather than by the
         * engine, so that the description (and a saved file) is
         * counter-clockwise. */
        for (size_t i = 0; i < shape->count / 2; i++) {
            vector_t swap = shape->written[i];
            shape->written[i] = shape->written[shape->count - 1 - i];
            shape->written[shape->count - 1 - i] = swap;
        }
        list_free(list);
        list = shape_list(shape);
    }
    if (problem == NULL) {
        shape->centroid = polygon_centroid(list);
        if (!vec_is_finite(shape->centroid)) problem = "its centroid is not finite";
    }
    if (problem == NULL && shape->as_centred) {
        /* Taken as written, as body_init_centred takes them. */
        if (!centred_enough(list, shape->centroid)) {
            vector_t c = shape->centroid;
            list_free(list);
            return sf_fail(p->lexer, shape->where,
                           "expected vertices around their centroid (centred), found it at "
                           "(%g, %g), more than a thousandth of the radius from the origin",
                           c.x, c.y);
        }
        shape->centroid = VEC_ZERO;
    }
    if (problem == NULL && !shape->as_centred) {
        polygon_translate(list, vec_negate(shape->centroid));
        problem = polygon_check(list);
    }
    if (problem != NULL) {
        list_free(list);
        return sf_fail(p->lexer, shape->where,
                       "expected a usable shape (convex, distinct vertices, some area), found "
                       "one that is refused: %s",
                       problem);
    }
    shape->area = polygon_area(list);
    shape->moment_per_kg = polygon_moment_of_inertia(list, 1.0);
    shape->centred = malloc(shape->count * sizeof(vector_t));
    if (shape->centred == NULL) abort();
    for (size_t i = 0; i < shape->count; i++) shape->centred[i] = *(vector_t *)list_get(list, i);
    list_free(list);
    return true;
}

/* The mass from the block, checked as body_init will check it, with a wide
 * margin on the moment of inertia (our product and the engine's sum round
 * differently). */
static bool derive_mass(parser_t *p, sf_body_t *body, sf_where_t where) {
    if (body->mass_kind == MASS_STATIC) {
        body->mass = INFINITY;
        return true;
    }
    double mass =
        body->mass_kind == MASS_TOTAL ? body->mass_value : body->mass_value * body->shape.area;
    double moment = mass * body->shape.moment_per_kg;
    char given[160];
    if (body->mass_kind == MASS_TOTAL) {
        snprintf(given, sizeof given, "mass %g kg", mass);
    } else {
        snprintf(given, sizeof given, "density %g kg/m^2 on %g m^2, %g kg", body->mass_value,
                 body->shape.area, mass);
    }
    if (!(mass > 0.0) || !isfinite(mass) || !isfinite(1.0 / mass)) {
        return sf_fail(p->lexer, where, "expected a mass whose inverse is finite, found %s", given);
    }
    if (!(moment >= SF_MIN_MOMENT && moment <= SF_MAX_MOMENT)) {
        return sf_fail(p->lexer, where,
                       "expected a moment of inertia from %g to %g kg m^2, found %g kg m^2 "
                       "(%s on this shape)",
                       SF_MIN_MOMENT, SF_MAX_MOMENT, moment, given);
    }
    body->mass = mass;
    return true;
}

/* Records the block's name once its properties are known: a repeated body or
 * a template names a group; a single body takes a new name. */
static bool register_name(parser_t *p, sf_body_t *body, size_t index, sf_where_t name_where) {
    sf_doc_t *doc = p->doc;
    if (body->name.text[0] == '\0') return true;
    sf_name_entry_t *entry = sf_names_find(&doc->names, body->name.text);
    bool names_group = body->is_template || body->has_repeat;
    if (!names_group) {
        if (entry != NULL) {
            sf_where_t first = sf_entry_where(doc, entry);
            return sf_fail(p->lexer, name_where,
                           "expected a new name, found \"%s\", already the name of a %s (line %zu)",
                           body->name.text, entry->is_group ? "group" : "body", first.line);
        }
        sf_names_add(&doc->names, body->name.text, false, index);
        return true;
    }
    size_t group;
    if (!sf_find_or_make_group(p, &body->name, name_where, &group)) return false;
    if (body->is_template) {
        sf_group_t *g = &doc->groups[group];
        if (g->template_body != SIZE_MAX) {
            return sf_fail(p->lexer, name_where,
                           "expected a new template name, found \"%s\", already a template's "
                           "(line %zu)",
                           body->name.text, doc->bodies[g->template_body].where.line);
        }
        g->template_body = index;
    }
    body->own_group = group;
    return true;
}

/* A chain is static (body.h): no mass, density, velocity or spin; static
 * whether or not the block says so. */
static bool finish_chain(parser_t *p, sf_body_t *body, const seen_t *seen) {
    if (body->shape.kind != SHAPE_CHAIN && body->shape.kind != SHAPE_LOOP) return true;
    if (body->is_template) {
        return sf_fail(p->lexer, body->shape.where,
                       "expected no chain in a template (a game spawns moving copies), found one");
    }
    if (seen->mass.line != 0 && body->mass_kind != MASS_STATIC) {
        return sf_fail(p->lexer, seen->mass,
                       "expected a chain to be static (static, or no mass), found %s",
                       body->mass_kind == MASS_TOTAL ? "a mass" : "a density");
    }
    if (seen->velocity.line != 0 || seen->spin.line != 0) {
        return sf_fail(p->lexer, seen->velocity.line != 0 ? seen->velocity : seen->spin,
                       "expected a chain at rest (it is static), found a %s",
                       seen->velocity.line != 0 ? "velocity" : "spin");
    }
    body->mass_kind = MASS_STATIC;
    return true;
}

/* After '}': the derived values, the defaults, the limits. */
static bool finish_body(parser_t *p, sf_body_t *body, const seen_t *seen, sf_where_t name_where,
                        sf_where_t close_where) {
    sf_doc_t *doc = p->doc;
    if (body->shape.kind == SHAPE_NONE) {
        return sf_fail(p->lexer, close_where,
                       "expected a shape (regular, box, vertices, circle, capsule, chain or loop) in the %s, "
                       "found '}' without "
                       "one",
                       body->is_template ? "template" : "body");
    }
    if (body->shape.as_centred && body->shape.kind != SHAPE_VERTICES) {
        return sf_fail(p->lexer, body->shape.where,
                       "expected centred with a vertices shape, found it with %s",
                       body->shape.kind == SHAPE_BOX       ? "a box"
                       : body->shape.kind == SHAPE_CIRCLE  ? "a circle"
                       : body->shape.kind == SHAPE_CAPSULE ? "a capsule"
                       : body->shape.kind == SHAPE_REGULAR ? "a regular polygon"
                                                           : "a chain");
    }
    if (!derive_shape(p, &body->shape)) return false;
    if (!finish_chain(p, body, seen)) return false;
    if (!derive_mass(p, body, seen->mass.line != 0 ? seen->mass : body->shape.where)) return false;
    if (!body->has_color)
        body->color = body->mass_kind == MASS_STATIC ? STATIC_COLOR : MOVING_COLOR;
    if (!body->has_position) body->position = body->shape.centroid;
    if (body->is_template && seen->repeat.line != 0) {
        return sf_fail(p->lexer, seen->repeat,
                       "expected no repeat in a template (a game spawns its copies), found one");
    }
    if (body->is_template && (body->has_island || body->has_timer)) {
        return sf_fail(p->lexer, body->has_island ? seen->asleep : seen->sleep_timer,
                       "expected no sleep state in a template (its copies start awake), found %s",
                       body->has_island ? "asleep" : "sleep_timer");
    }
    if (body->has_island && body->mass_kind == MASS_STATIC) {
        return sf_fail(p->lexer, seen->asleep,
                       "expected asleep on a body that can move, found it on a static body");
    }
    if (body->has_island && (body->velocity.x != 0.0 || body->velocity.y != 0.0 ||
                             body->spin != 0.0)) {
        return sf_fail(p->lexer, seen->asleep,
                       "expected a sleeping body at rest, found a velocity or spin on it");
    }
    size_t copies = body->repeat_x * body->repeat_y;
    if (body->has_repeat) {
        vector_t last =
            vec_add(body->position, (vector_t){(double)(body->repeat_x - 1) * body->repeat_step.x,
                                               (double)(body->repeat_y - 1) * body->repeat_step.y});
        if (!(fabs(last.x) <= SF_MAX_LENGTH && fabs(last.y) <= SF_MAX_LENGTH)) {
            return sf_fail(p->lexer, seen->repeat,
                           "expected copies within %g m of the origin, found the last at "
                           "(%g, %g)",
                           SF_MAX_LENGTH, last.x, last.y);
        }
    }
    if (!body->is_template) {
        if (copies > SCENE_FILE_MAX_BODIES - doc->total_bodies) {
            return sf_fail(p->lexer, body->where,
                           "expected at most %d bodies in a file, found %zu with this block",
                           SCENE_FILE_MAX_BODIES, doc->total_bodies + copies);
        }
        if (copies * body->shape.count > SCENE_FILE_MAX_TOTAL_VERTICES - doc->total_vertices) {
            return sf_fail(p->lexer, body->where,
                           "expected at most %d vertices over all bodies of a file, found %zu "
                           "with this block",
                           SCENE_FILE_MAX_TOTAL_VERTICES,
                           doc->total_vertices + copies * body->shape.count);
        }
        doc->total_bodies += copies;
        doc->total_vertices += copies * body->shape.count;
    }
    return register_name(p, body, doc->body_count - 1, name_where);
}

bool sf_parse_body(parser_t *p, bool is_template, sf_where_t here) {
    sf_doc_t *doc = p->doc;
    sf_reserve((void **)&doc->bodies, &doc->body_capacity, doc->body_count + 1, sizeof(sf_body_t));
    sf_body_t *body = &doc->bodies[doc->body_count++];
    *body = (sf_body_t){
        .where = here,
        .is_template = is_template,
        .mass_kind = MASS_DENSITY,
        .mass_value = DEFAULT_DENSITY,
        .friction = DEFAULT_FRICTION,
        .mask = UINT32_MAX,
        .category = 1,
        .repeat_x = 1,
        .repeat_y = 1,
        .own_group = SIZE_MAX,
    };
    sf_where_t name_where = here;
    if (p->token.kind == TOKEN_WORD || is_template) {
        if (!sf_read_new_name(p, is_template ? "the template's name" : "the body's name",
                              &body->name, &name_where))
            return false;
    }
    while (p->token.kind == TOKEN_NEWLINE) next(p);
    if (p->token.kind != TOKEN_OPEN) return sf_expected(p, "'{' to open the block");
    next(p);
    seen_t seen = {0};
    for (;;) {
        while (at_separator(p)) next(p);
        if (p->token.kind == TOKEN_CLOSE) break;
        if (p->token.kind == TOKEN_END) {
            char expectation[96];
            snprintf(expectation, sizeof expectation, "'}' to close the block opened at line %zu",
                     here.line);
            return sf_expected(p, expectation);
        }
        if (p->token.kind != TOKEN_WORD) {
            return sf_expected(p, "a body property or '}'");
        }
        if (!parse_property(p, body, &seen)) return false;
        if (!at_separator(p) && p->token.kind != TOKEN_CLOSE) {
            return sf_expected(p, "the end of the property (a new line, ';' or '}')");
        }
    }
    sf_where_t close_where = p->token.where;
    next(p);
    return finish_body(p, body, &seen, name_where, close_where);
}
