/*
 * Forces and collision rules (scene_file_parse.h): spring, newton, drag and
 * collide, with the bodies and groups they name (resolved later, by
 * scene_file_build.c).
 */
#include <string.h>
#include "scene_file_parse.h"

static bool read_ref(parser_t *p, const char *what, sf_statement_t *statement, bool allow_all) {
    sf_reserve((void **)&statement->refs, &statement->ref_capacity, statement->ref_count + 1,
               sizeof(sf_ref_t));
    sf_ref_t *ref = &statement->refs[statement->ref_count];
    *ref = (sf_ref_t){.where = p->token.where};
    if (allow_all && sf_token_is(&p->token, "all")) {
        ref->kind = REF_ALL;
        strcpy(ref->name.text, "all");
        next(p);
    } else if (!sf_read_name(p, what, &ref->name, NULL)) {
        return false;
    }
    statement->ref_count++;
    return true;
}

bool sf_parse_statement(parser_t *p, const char *keyword, sf_where_t here) {
    sf_doc_t *doc = p->doc;
    sf_reserve((void **)&doc->statements, &doc->statement_capacity, doc->statement_count + 1,
               sizeof(sf_statement_t));
    sf_statement_t *s = &doc->statements[doc->statement_count++];
    *s = (sf_statement_t){.where = here};
    if (strcmp(keyword, "spring") == 0) {
        s->kind = STATEMENT_SPRING;
        if (!sf_read_quantity(p, &SPRING_K, &s->constant) ||
            !read_ref(p, "the spring's first body", s, false) ||
            !read_ref(p, "the spring's second body", s, false))
            return false;
        if (!sf_token_is(&p->token, "length")) return true;
        next(p);
        s->has_rest_length = true;
        return sf_read_quantity(p, &REST_LENGTH, &s->rest_length);
    }
    if (strcmp(keyword, "newton") == 0 || strcmp(keyword, "drag") == 0) {
        bool newton = keyword[0] == 'n';
        s->kind = newton ? STATEMENT_NEWTON : STATEMENT_DRAG;
        if (!sf_read_quantity(p, newton ? &NEWTON_G : &DRAG_GAMMA, &s->constant)) return false;
        const char *what = newton ? "all or the bodies and groups that attract each other"
                                  : "all or the bodies and groups it acts on";
        if (!read_ref(p, what, s, true)) return false;
        if (s->refs[0].kind == REF_ALL) return true;
        while (p->token.kind == TOKEN_WORD) {
            if (!read_ref(p, "a body or group name", s, false)) return false;
        }
        return true;
    }
    /* collide A B physics E | destructive */
    if (!read_ref(p, "the first body, group or all", s, true) ||
        !read_ref(p, "the second body, group or all", s, true))
        return false;
    if (sf_token_is(&p->token, "physics")) {
        s->kind = STATEMENT_PHYSICS;
        next(p);
        return sf_read_quantity(p, &ELASTICITY, &s->constant);
    }
    if (sf_token_is(&p->token, "destructive")) {
        s->kind = STATEMENT_DESTRUCTIVE;
        next(p);
        return true;
    }
    return sf_expected(p, "the kind of collision (physics ELASTICITY, or destructive)");
}
