/*
 * Joint blocks (scene_file_parse.h): `joint TYPE A B { ... }`, a joint of
 * jostle/joint.h between the bodies the file makes A-th and B-th (A may be
 * `world`), each line one field of its definition; read exactly, checked
 * with the file's line and column, made after the bodies.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "scene_file_parse.h"

#define FIELD(name, kind) {#name, kind, offsetof(joint_def_t, name)}

const sf_joint_field_t SF_JOINT_FIELDS[] = {
    FIELD(anchor1, SF_FIELD_VECTOR),
    FIELD(anchor2, SF_FIELD_VECTOR),
    FIELD(axis, SF_FIELD_VECTOR),
    FIELD(reference_angle, SF_FIELD_NUMBER),
    FIELD(length, SF_FIELD_NUMBER),
    FIELD(min_length, SF_FIELD_NUMBER),
    FIELD(max_length, SF_FIELD_NUMBER),
    FIELD(frequency, SF_FIELD_NUMBER),
    FIELD(damping_ratio, SF_FIELD_NUMBER),
    {"limit", SF_FIELD_FLAG, offsetof(joint_def_t, enable_limit)},
    FIELD(lower_angle, SF_FIELD_NUMBER),
    FIELD(upper_angle, SF_FIELD_NUMBER),
    FIELD(lower_translation, SF_FIELD_NUMBER),
    FIELD(upper_translation, SF_FIELD_NUMBER),
    {"motor", SF_FIELD_FLAG, offsetof(joint_def_t, enable_motor)},
    FIELD(motor_speed, SF_FIELD_NUMBER),
    FIELD(max_motor_torque, SF_FIELD_NUMBER),
    FIELD(max_motor_force, SF_FIELD_NUMBER),
    FIELD(target, SF_FIELD_VECTOR),
    FIELD(max_force, SF_FIELD_NUMBER),
    FIELD(linear_offset, SF_FIELD_VECTOR),
    FIELD(angular_offset, SF_FIELD_NUMBER),
    FIELD(max_torque, SF_FIELD_NUMBER),
    FIELD(correction_factor, SF_FIELD_NUMBER),
    {"collide_connected", SF_FIELD_FLAG, offsetof(joint_def_t, collide_connected)},
};
const size_t SF_JOINT_FIELD_COUNT = sizeof SF_JOINT_FIELDS / sizeof SF_JOINT_FIELDS[0];

static bool read_type(parser_t *p, joint_type_t *type) {
    for (int t = 0; t < JOINT_TYPE_COUNT; t++) {
        if (sf_token_is(&p->token, joint_type_name((joint_type_t)t))) {
            *type = (joint_type_t)t;
            next(p);
            return true;
        }
    }
    return sf_expected(p, "a joint type (revolute, distance, mouse, weld, prismatic, wheel, "
                          "motor)");
}

/* A field may be given once in a block; the message names the block, as
 * a joint's fields are not statements of the file. */
static bool first_in_block(parser_t *p, sf_where_t *seen, const char *field, sf_where_t here) {
    if (seen->line != 0) {
        return sf_fail(p->lexer, here,
                       "expected one %s line per joint block, found a second (the first at "
                       "line %zu)",
                       field, seen->line);
    }
    *seen = here;
    return true;
}

/* `impulses PX PY ANGLE AXIAL SPRING MOTOR LOWER UPPER STEP`: the
 * joint's state (joint_state_t), read exactly. */
static bool read_state(parser_t *p, joint_state_t *state) {
    quantity_t value = STATE_VALUE, step = DURATION;
    value.what = "an impulse";
    step.what = "the length of the step the impulses are of (s)";
    return sf_read_vector(p, &value, &state->point_impulse) &&
           sf_read_quantity(p, &value, &state->angle_impulse) &&
           sf_read_quantity(p, &value, &state->axial_impulse) &&
           sf_read_quantity(p, &value, &state->spring_impulse) &&
           sf_read_quantity(p, &value, &state->motor_impulse) &&
           sf_read_quantity(p, &value, &state->lower_impulse) &&
           sf_read_quantity(p, &value, &state->upper_impulse) &&
           sf_read_quantity(p, &step, &state->step_length);
}

/* One line: a field's name and its value (seen[SF_JOINT_FIELD_COUNT] is
 * the impulses line's). */
static bool parse_joint_line(parser_t *p, sf_joint_t *joint, sf_where_t *seen) {
    sf_where_t here = p->token.where;
    if (sf_token_is(&p->token, "impulses")) {
        next(p);
        joint->has_state = true;
        return first_in_block(p, &seen[SF_JOINT_FIELD_COUNT], "impulses", here) &&
               read_state(p, &joint->state);
    }
    for (size_t i = 0; i < SF_JOINT_FIELD_COUNT; i++) {
        const sf_joint_field_t *field = &SF_JOINT_FIELDS[i];
        if (!sf_token_is(&p->token, field->name)) continue;
        next(p);
        if (!first_in_block(p, &seen[i], field->name, here)) return false;
        char *at = (char *)&joint->def + field->offset;
        quantity_t value = STATE_VALUE;
        value.what = field->name;
        if (field->kind == SF_FIELD_VECTOR) return sf_read_vector(p, &value, (vector_t *)at);
        if (field->kind == SF_FIELD_NUMBER) return sf_read_quantity(p, &value, (double *)at);
        if (!sf_token_is(&p->token, "on") && !sf_token_is(&p->token, "off")) {
            return sf_expected(p, "on or off");
        }
        *(bool *)at = sf_token_is(&p->token, "on");
        next(p);
        return true;
    }
    return sf_expected(p, "a joint line (anchor1, anchor2, axis, reference_angle, length, "
                          "min_length, max_length, frequency, damping_ratio, limit, lower_angle, "
                          "upper_angle, lower_translation, upper_translation, motor, "
                          "motor_speed, max_motor_torque, max_motor_force, target, max_force, "
                          "linear_offset, angular_offset, max_torque, correction_factor, "
                          "collide_connected, impulses) or '}'");
}

bool sf_parse_joint(parser_t *p, sf_where_t here) {
    sf_doc_t *doc = p->doc;
    sf_reserve((void **)&doc->joints, &doc->joint_capacity, doc->joint_count + 1,
               sizeof(sf_joint_t));
    sf_joint_t *joint = &doc->joints[doc->joint_count++];
    *joint = (sf_joint_t){.where = here};
    joint_type_t type = JOINT_REVOLUTE;
    if (!read_type(p, &type)) return false;
    joint->def = joint_def_default(type);
    const uint64_t last = SCENE_FILE_MAX_BODIES - 1;
    uint64_t a = 0, b = 0;
    if (sf_token_is(&p->token, "world")) {
        joint->body1 = SF_WORLD;
        next(p);
    } else if (sf_read_count(p, "the number of the joint's first body, or world", 0, last, &a)) {
        joint->body1 = (size_t)a;
    } else {
        return false;
    }
    if (!sf_read_count(p, "the number of the joint's second body", 0, last, &b)) return false;
    joint->body2 = (size_t)b;
    while (p->token.kind == TOKEN_NEWLINE) next(p);
    if (p->token.kind != TOKEN_OPEN) return sf_expected(p, "'{' to open the joint");
    next(p);
    sf_where_t seen[sizeof SF_JOINT_FIELDS / sizeof SF_JOINT_FIELDS[0] + 1] = {{0, 0}};
    for (;;) {
        while (at_separator(p)) next(p);
        if (p->token.kind == TOKEN_CLOSE) break;
        if (p->token.kind != TOKEN_WORD) {
            char expectation[96];
            snprintf(expectation, sizeof expectation,
                     "a joint line or '}' to close the block opened at line %zu", here.line);
            return sf_expected(p, expectation);
        }
        if (!parse_joint_line(p, joint, seen)) return false;
        if (!at_separator(p) && p->token.kind != TOKEN_CLOSE) {
            return sf_expected(p, "the end of the line (a new line, ';' or '}')");
        }
    }
    next(p);
    return true;
}

/* What joint_create would refuse in the definition, as a message; NULL
 * when it takes it. */
static const char *refusal(const joint_def_t *d, char *message, size_t size) {
    if (d->frequency < 0.0 || d->damping_ratio < 0.0 || d->max_motor_torque < 0.0 ||
        d->max_motor_force < 0.0 || d->max_force < 0.0 || d->max_torque < 0.0) {
        return "expected frequency, damping_ratio and the maximum forces and torques >= 0";
    }
    if (d->correction_factor < 0.0 || d->correction_factor > 1.0) {
        snprintf(message, size, "expected correction_factor in [0, 1], found %g",
                 d->correction_factor);
        return message;
    }
    if (d->type == JOINT_DISTANCE &&
        (d->length <= 0.0 || d->max_length <= 0.0 || d->min_length < 0.0 ||
         d->min_length > d->max_length)) {
        snprintf(message, size,
                 "expected length and max_length > 0 and 0 <= min_length <= max_length, found "
                 "%g, %g and %g",
                 d->length, d->max_length, d->min_length);
        return message;
    }
    if (d->type == JOINT_REVOLUTE && d->lower_angle > d->upper_angle) {
        snprintf(message, size, "expected lower_angle <= upper_angle, found %g > %g",
                 d->lower_angle, d->upper_angle);
        return message;
    }
    bool line = d->type == JOINT_PRISMATIC || d->type == JOINT_WHEEL;
    if (line && d->lower_translation > d->upper_translation) {
        snprintf(message, size, "expected lower_translation <= upper_translation, found %g > %g",
                 d->lower_translation, d->upper_translation);
        return message;
    }
    if (line && d->axis.x == 0.0 && d->axis.y == 0.0) return "expected a non-zero axis";
    return NULL;
}

bool sf_check_joints(const sf_doc_t *doc, sf_lexer_t *lexer) {
    for (size_t i = 0; i < doc->joint_count; i++) {
        const sf_joint_t *j = &doc->joints[i];
        if (!doc->settings.contacts) {
            return sf_fail(lexer, j->where, "expected contacts on for a joint, found contacts off");
        }
        size_t last = j->body1 != SF_WORLD && j->body1 > j->body2 ? j->body1 : j->body2;
        if (last >= doc->total_bodies) {
            return sf_fail(lexer, j->where,
                           "expected bodies numbered from 0 to %zu (the file makes %zu), found %zu",
                           doc->total_bodies == 0 ? 0 : doc->total_bodies - 1, doc->total_bodies,
                           last);
        }
        if (j->body1 == j->body2) {
            return sf_fail(lexer, j->where, "expected two different bodies, found %zu twice",
                           j->body2);
        }
        char message[200];
        const char *why = refusal(&j->def, message, sizeof message);
        if (why != NULL) return sf_fail(lexer, j->where, "%s", why);
    }
    return true;
}

static bool moves(body_t *body) {
    return body != NULL && (!isinf(body_get_mass(body)) || !isinf(body_get_inertia(body)));
}

bool sf_make_joints(scene_file_t *file, sf_lexer_t *lexer) {
    const sf_doc_t *doc = &file->doc;
    for (size_t i = 0; i < doc->joint_count; i++) {
        const sf_joint_t *j = &doc->joints[i];
        joint_def_t def = j->def;
        def.body1 = j->body1 == SF_WORLD ? NULL : file->records[j->body1]->body;
        def.body2 = file->records[j->body2]->body;
        if (!moves(def.body1) && !moves(def.body2)) {
            return sf_fail(lexer, j->where,
                           "expected a body that moves at one end, found two static ones (the "
                           "world is static)");
        }
        joint_t *joint = joint_create(file->scene, &def);
        if (j->has_state) joint_set_state(joint, j->state);
    }
    return true;
}
