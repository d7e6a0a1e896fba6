/*
 * Contact blocks (scene_file_parse.h): `contact A B { ... }`, the world's
 * contact memory of one pair (scene_state.h), read back exactly so that a
 * saved scene continues as it would have.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "scene_file_parse.h"

/* `point ID X Y SEPARATION NORMAL TANGENT RESTITUTION RESTITUTION_TANGENT` */
static bool read_memory_point(parser_t *p, scene_memory_point_t *point) {
    quantity_t coordinate = STATE_VALUE, separation = STATE_VALUE;
    coordinate.what = "a coordinate of the point (m)";
    separation.what = "the separation (m)";
    quantity_t impulses[4] = {STATE_VALUE, STATE_VALUE, STATE_VALUE, STATE_VALUE};
    impulses[0].what = "the normal impulse (N s)";
    impulses[1].what = "the tangent impulse (N s)";
    impulses[2].what = "the collision pass's normal impulse (N s)";
    impulses[3].what = "the collision pass's tangent impulse (N s)";
    return sf_read_bits(p, "the point's feature id", &point->id) &&
           sf_read_vector(p, &coordinate, &point->point) &&
           sf_read_quantity(p, &separation, &point->separation) &&
           sf_read_quantity(p, &impulses[0], &point->normal_impulse) &&
           sf_read_quantity(p, &impulses[1], &point->tangent_impulse) &&
           sf_read_quantity(p, &impulses[2], &point->restitution_impulse) &&
           sf_read_quantity(p, &impulses[3], &point->restitution_tangent_impulse);
}

/* `previous ID NORMAL TANGENT` */
static bool read_previous_point(parser_t *p, scene_memory_previous_t *point) {
    quantity_t normal = STATE_VALUE, tangent = STATE_VALUE;
    normal.what = "the normal impulse of the step before (N s)";
    tangent.what = "the tangent impulse of the step before (N s)";
    return sf_read_bits(p, "the previous point's feature id", &point->id) &&
           sf_read_quantity(p, &normal, &point->normal_impulse) &&
           sf_read_quantity(p, &tangent, &point->tangent_impulse);
}

/* `face a|b NX NY X Y [lead L] [edge]`; no lead: INFINITY */
static bool read_face(parser_t *p, scene_contact_memory_t *m) {
    if (!sf_token_is(&p->token, "a") && !sf_token_is(&p->token, "b")) {
        return sf_expected(p, "a or b (the body holding the reference face)");
    }
    m->flip = sf_token_is(&p->token, "b");
    next(p);
    quantity_t point = STATE_VALUE;
    point.what = "a coordinate of the face's point (m)";
    if (!sf_read_vector(p, &UNIT_COMPONENT, &m->face_normal) ||
        !sf_read_vector(p, &point, &m->face_point))
        return false;
    if (sf_token_is(&p->token, "lead")) {
        next(p);
        quantity_t lead = STATE_VALUE;
        lead.what = "the reference face's lead (m)";
        if (!sf_read_quantity(p, &lead, &m->face_lead)) return false;
    }
    m->edge_ends = sf_token_is(&p->token, "edge");
    if (m->edge_ends) next(p);
    return true;
}

/* One line of a contact block. */
static bool parse_contact_line(parser_t *p, sf_contact_t *contact, sf_where_t *seen) {
    scene_contact_memory_t *m = &contact->memory;
    sf_where_t here = p->token.where;
    char keyword[16] = "";
    if (p->token.length < sizeof keyword) memcpy(keyword, p->token.text, p->token.length);
    keyword[p->token.length < sizeof keyword ? p->token.length : 0] = '\0';
    static const char *const LINES[] = {"normal", "point", "incident", "face", "pose",
                                        "previous", "segment"};
    bool known = false;
    for (size_t i = 0; i < sizeof LINES / sizeof LINES[0]; i++) {
        known = known || strcmp(keyword, LINES[i]) == 0;
    }
    if (!known) {
        return sf_expected(p, "a contact line (normal, point, face, incident, pose, previous, "
                              "segment) or '}'");
    }
    next(p);
    if (strcmp(keyword, "segment") == 0) {
        uint64_t segment = 0;
        if (!sf_first_time(p, &seen[3], "segment", here) ||
            !sf_read_count(p, "the chain's segment", 0, SCENE_FILE_MAX_VERTICES, &segment))
            return false;
        m->segment = (size_t)segment;
        return true;
    }
    if (strcmp(keyword, "previous") == 0) {
        if (m->previous_count == 2) {
            return sf_fail(p->lexer, here,
                           "expected at most two previous lines in a contact, found a third");
        }
        return read_previous_point(p, &m->previous[m->previous_count++]);
    }
    if (strcmp(keyword, "normal") == 0) {
        return sf_first_time(p, &seen[0], "normal", here) &&
               sf_read_vector(p, &UNIT_COMPONENT, &m->normal);
    }
    if (strcmp(keyword, "point") == 0 || strcmp(keyword, "incident") == 0) {
        bool incident = keyword[0] == 'i';
        int *count = incident ? &m->feature_count : &m->point_count;
        if (*count == 2) {
            return sf_fail(p->lexer, here,
                           "expected at most two %s lines in a contact, found a third", keyword);
        }
        if (!incident) return read_memory_point(p, &m->points[m->point_count++]);
        quantity_t coordinate = STATE_VALUE;
        coordinate.what = "a coordinate of the incident point (m)";
        int k = m->feature_count++;
        return sf_read_bits(p, "the incident point's feature id", &m->feature_ids[k]) &&
               sf_read_vector(p, &coordinate, &m->feature_points[k]);
    }
    if (strcmp(keyword, "face") == 0) {
        return sf_first_time(p, &seen[1], "face", here) && read_face(p, m);
    }
    /* pose */
    quantity_t coordinate = STATE_VALUE, angle = STATE_VALUE;
    coordinate.what = "a coordinate of the pose (m)";
    angle.what = "the pose's angle (rad)";
    return sf_first_time(p, &seen[2], "pose", here) && sf_read_vector(p, &coordinate, &m->pose) &&
           sf_read_quantity(p, &angle, &m->pose_angle);
}

/* `contact A B { ... }`: the world's memory of one pair. */
bool sf_parse_contact(parser_t *p, sf_where_t here) {
    sf_doc_t *doc = p->doc;
    sf_reserve((void **)&doc->contacts, &doc->contact_capacity, doc->contact_count + 1,
               sizeof(sf_contact_t));
    sf_contact_t *contact = &doc->contacts[doc->contact_count++];
    *contact = (sf_contact_t){.where = here};
    contact->memory.face_lead = INFINITY;
    uint64_t a = 0, b = 0;
    const uint64_t last = SCENE_FILE_MAX_BODIES - 1;
    if (!sf_read_count(p, "the number of the contact's first body", 0, last, &a) ||
        !sf_read_count(p, "the number of the contact's second body", 0, last, &b))
        return false;
    contact->body_a = (size_t)a;
    contact->body_b = (size_t)b;
    while (p->token.kind == TOKEN_NEWLINE) next(p);
    if (p->token.kind != TOKEN_OPEN) return sf_expected(p, "'{' to open the contact");
    next(p);
    sf_where_t seen[4] = {{0, 0}, {0, 0}, {0, 0}, {0, 0}};
    for (;;) {
        while (at_separator(p)) next(p);
        if (p->token.kind == TOKEN_CLOSE) break;
        if (p->token.kind != TOKEN_WORD) {
            char expectation[96];
            snprintf(expectation, sizeof expectation, "a contact line or '}' to close the block "
                     "opened at line %zu", here.line);
            return sf_expected(p, expectation);
        }
        if (!parse_contact_line(p, contact, seen)) return false;
        if (!at_separator(p) && p->token.kind != TOKEN_CLOSE) {
            return sf_expected(p, "the end of the line (a new line, ';' or '}')");
        }
    }
    next(p);
    return true;
}
