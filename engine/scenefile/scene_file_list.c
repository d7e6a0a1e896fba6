/*
 * Listing the forces a file made (scene_file_force_count, _get_force): the
 * springs and drags as made, and the pairs of each newton and collide,
 * worked out from the live records as they are read rather than stored (a
 * statement over N bodies has N (N - 1) / 2 of them and one engine force
 * creator). In file order: statement by statement, a statement's springs
 * and drags in the order made, its pairs in the order of its rule.
 */
#include <stdlib.h>
#include "scene_file_private.h"

static bool is_instance_statement(sf_statement_kind_t kind) {
    return kind == STATEMENT_SPRING || kind == STATEMENT_DRAG;
}

/* Enters the cursor's statement: its first instance (they are kept in
 * statement order), or the sides of a newton or collide from the live
 * records. */
static void enter(scene_file_t *file, sf_cursor_t *c) {
    const sf_statement_t *s = &file->doc.statements[c->statement];
    c->j = 0;
    if (is_instance_statement(s->kind)) {
        while (c->i < file->instance_count && file->instances[c->i].statement < c->statement) {
            c->i++;
        }
        return;
    }
    c->instance = c->i;
    c->i = 0;
    size_t room = file->record_count + 1;
    sf_reserve((void **)&file->side1, &file->side1_capacity, room, sizeof(sf_record_t *));
    sf_reserve((void **)&file->side2, &file->side2_capacity, room, sizeof(sf_record_t *));
    if (s->kind == STATEMENT_NEWTON) {
        c->n = c->m = sf_members(file, s->refs, s->ref_count, file->side1);
        for (size_t k = 0; k < c->n; k++) file->side2[k] = file->side1[k];
    } else if (s->kind == STATEMENT_PHYSICS || s->kind == STATEMENT_DESTRUCTIVE) {
        c->n = sf_members(file, &s->refs[0], 1, file->side1);
        c->m = sf_members(file, &s->refs[1], 1, file->side2);
    }
}

/* Whether the cursor's place is a force of its statement. */
static bool is_force(const scene_file_t *file, const sf_cursor_t *c) {
    const sf_statement_t *s = &file->doc.statements[c->statement];
    if (is_instance_statement(s->kind)) return true; /* in_statement said so */
    if (s->kind == STATEMENT_NEWTON) return c->j > c->i;
    const sf_record_t *a = file->side1[c->i], *b = file->side2[c->j];
    if (a == b) return false;
    /* A pair of two bodies on both sides is taken once, the earlier first. */
    return !(sf_in_ref(file, &s->refs[1], a) && sf_in_ref(file, &s->refs[0], b) &&
             a->index > b->index);
}

/* Whether the cursor's statement has places left at or after it. */
static bool in_statement(const scene_file_t *file, const sf_cursor_t *c) {
    const sf_statement_t *s = &file->doc.statements[c->statement];
    if (is_instance_statement(s->kind)) {
        return c->i < file->instance_count && file->instances[c->i].statement == c->statement;
    }
    return c->i < c->n && c->m > 0;
}

static void step_place(const scene_file_t *file, sf_cursor_t *c) {
    const sf_statement_t *s = &file->doc.statements[c->statement];
    if (is_instance_statement(s->kind)) {
        c->i++;
    } else if (++c->j >= c->m) {
        c->i++;
        c->j = 0;
    }
}

/* Moves the cursor to the first force at or after its place. */
static void settle(scene_file_t *file, sf_cursor_t *c) {
    while (c->statement < file->doc.statement_count) {
        while (in_statement(file, c)) {
            if (is_force(file, c)) return;
            step_place(file, c);
        }
        /* On to the next statement; the instances go on where these ended. */
        if (!is_instance_statement(file->doc.statements[c->statement].kind)) c->i = c->instance;
        c->statement++;
        if (c->statement < file->doc.statement_count) enter(file, c);
    }
}

static void rewind_cursor(scene_file_t *file) {
    file->cursor = (sf_cursor_t){.valid = true};
    if (file->doc.statement_count == 0) return;
    enter(file, &file->cursor);
    settle(file, &file->cursor);
}

size_t scene_file_force_count(scene_file_t *file) {
    sf_drop_orphan_forces(file);
    sf_record_t **scratch = malloc((2 * file->record_count + 1) * sizeof *scratch);
    if (scratch == NULL) abort();
    size_t count = 0;
    for (size_t s = 0; s < file->doc.statement_count; s++) {
        count += sf_statement_pairs(file, s, scratch);
    }
    free(scratch);
    file->listed = count;
    file->listing_fresh = true;
    file->cursor.valid = false;
    return count;
}

scene_file_force_t scene_file_get_force(scene_file_t *file, size_t index) {
    static const scene_file_force_kind_t KINDS[] = {
        [STATEMENT_SPRING] = SCENE_FILE_SPRING,
        [STATEMENT_NEWTON] = SCENE_FILE_NEWTON,
        [STATEMENT_DRAG] = SCENE_FILE_DRAG,
        [STATEMENT_PHYSICS] = SCENE_FILE_PHYSICS_COLLISION,
        [STATEMENT_DESTRUCTIVE] = SCENE_FILE_DESTRUCTIVE_COLLISION,
    };
    if (!file->listing_fresh) scene_file_force_count(file);
    if (index >= file->listed) return (scene_file_force_t){0};
    sf_cursor_t *c = &file->cursor;
    /* Read in order, each force is one step on; any other index starts
     * over. */
    if (!c->valid || c->index > index) rewind_cursor(file);
    while (c->index < index) {
        step_place(file, c);
        settle(file, c);
        c->index++;
    }
    const sf_statement_t *s = &file->doc.statements[c->statement];
    scene_file_force_t force = {.kind = KINDS[s->kind], .constant = s->constant,
                                .rest_length = s->rest_length};
    if (is_instance_statement(s->kind)) {
        const sf_instance_t *instance = &file->instances[c->i];
        force.body1 = instance->body1->body;
        force.body2 = instance->body2 != NULL ? instance->body2->body : NULL;
    } else {
        force.body1 = file->side1[c->i]->body;
        force.body2 = file->side2[c->j]->body;
    }
    return force;
}
