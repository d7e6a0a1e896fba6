#include "solver/joint_list.h"
#include "base/memory.h"

void joint_list_add(joint_list_t *list, joint_t *joint) {
    memory_reserve((void **)&list->joints, &list->capacity, list->count + 1, sizeof(joint_t *));
    list->joints[list->count++] = joint;
}

void joint_list_destroy(joint_list_t *list, joint_t *joint) {
    size_t kept = 0;
    for (size_t i = 0; i < list->count; i++) {
        if (list->joints[i] != joint) list->joints[kept++] = list->joints[i];
    }
    list->count = kept;
    memory_free(joint);
}

static bool has_removed_body(const joint_t *joint) {
    const body_t *body1 = joint->def.body1;
    return (body1 != NULL && body1->removed) || joint->def.body2->removed;
}

void joint_list_reap(joint_list_t *list) {
    size_t kept = 0;
    for (size_t i = 0; i < list->count; i++) {
        joint_t *joint = list->joints[i];
        if (has_removed_body(joint)) {
            memory_free(joint);
        } else {
            list->joints[kept++] = joint;
        }
    }
    list->count = kept;
}

void joint_list_free(joint_list_t *list) {
    for (size_t i = 0; i < list->count; i++) memory_free(list->joints[i]);
    memory_free(list->joints);
    *list = (joint_list_t){NULL, 0, 0};
}
