/* The distance joint: a rod (rigid at its length when min and max lengths
 * are equal), or a spring toward its length and speculative limits at its
 * min and max lengths (a rope), along the line between the anchors. */
#include "solver/joint_types.h"

static bool is_rod(const joint_def_t *def) {
    return def->min_length == def->max_length;
}

static void prepare(joint_t *joint) {
    const joint_def_t *def = &joint->def;
    double length = vec_get_length(joint->delta);
    /* Anchors on top of each other: push along x rather than nowhere. */
    joint->axis = length > 0.0 ? vec_multiply(1.0 / length, joint->delta) : (vector_t){1.0, 0.0};
    joint->a1 = vec_cross(joint->r1, joint->axis);
    joint->a2 = vec_cross(joint->r2, joint->axis);
    joint->axial_mass = joint_inverse(joint->m1 + joint->m2 + joint->i1 * joint->a1 * joint->a1 +
                                      joint->i2 * joint->a2 * joint->a2);
    joint->translation = length; /* the distance at the start of the step */
    bool spring = !is_rod(def) && def->frequency > 0.0;
    joint->soft = joint_make_soft(spring ? def->frequency : 0.0, def->damping_ratio, joint->dt);
    if (!spring) joint->spring_impulse = 0.0;
    if (!is_rod(def)) joint->axial_impulse = 0.0;
    if (is_rod(def)) joint->lower_impulse = joint->upper_impulse = 0.0;
    double impulse = joint->axial_impulse + joint->spring_impulse + joint->lower_impulse -
                     joint->upper_impulse;
    joint_apply(joint, vec_multiply(impulse, joint->axis), impulse * joint->a1,
                impulse * joint->a2);
}

/* The rate at which the anchors part (m/s). */
static double parting(const joint_t *joint) {
    return vec_dot(joint->axis, joint_relative_velocity(joint));
}

static void push(joint_t *joint, double impulse) {
    joint_apply(joint, vec_multiply(impulse, joint->axis), impulse * joint->a1,
                impulse * joint->a2);
}

static void solve_velocity(joint_t *joint) {
    const joint_def_t *def = &joint->def;
    if (is_rod(def)) {
        double impulse = -joint->axial_mass * parting(joint);
        joint->axial_impulse += impulse;
        push(joint, impulse);
        return;
    }
    if (def->frequency > 0.0) {
        const joint_soft_t *soft = &joint->soft;
        double c = joint->translation - def->length;
        double impulse =
            -soft->mass_scale * joint->axial_mass * (parting(joint) + soft->bias_rate * c) -
            soft->impulse_scale * joint->spring_impulse;
        joint->spring_impulse += impulse;
        push(joint, impulse);
    }
    push(joint, joint_limit_impulse(joint->axial_mass, joint->translation - def->min_length,
                                    parting(joint), joint->dt, &joint->lower_impulse));
    push(joint, -joint_limit_impulse(joint->axial_mass, def->max_length - joint->translation,
                                     -parting(joint), joint->dt, &joint->upper_impulse));
}

static void solve_position(joint_t *joint) {
    const joint_def_t *def = &joint->def;
    vector_t r1, r2, delta;
    double angle;
    joint_current(joint, &r1, &r2, &delta, &angle);
    double length = vec_get_length(delta);
    vector_t u = length > 0.0 ? vec_multiply(1.0 / length, delta) : (vector_t){1.0, 0.0};
    double a1 = vec_cross(r1, u), a2 = vec_cross(r2, u);
    if (is_rod(def)) {
        double c = length - def->min_length;
        if (c > 0.0) {
            joint_correct_axial(joint, -c, vec_negate(u), -a1, -a2);
        } else {
            joint_correct_axial(joint, c, u, a1, a2);
        }
        return;
    }
    joint_correct_axial(joint, length - def->min_length, u, a1, a2);
    joint_correct_axial(joint, def->max_length - length, vec_negate(u), -a1, -a2);
}

/* The tree takes a rod: its row along the anchors' line. */
static int tree_rows(const joint_t *joint, joint_pose_t p1, joint_pose_t p2, double error[],
                     double j1[][3], double j2[][3]) {
    if (!is_rod(&joint->def)) return 0;
    vector_t r1, r2, d = joint_separation(joint, p1, p2, &r1, &r2);
    double length = vec_get_length(d);
    error[0] = length - joint->def.min_length;
    if (j1 != NULL) {
        vector_t u = length > 0.0 ? vec_multiply(1.0 / length, d) : (vector_t){1.0, 0.0};
        joint_tree_line(j1[0], j2[0], u, vec_cross(r1, u), vec_cross(r2, u));
    }
    return 1;
}

static void tree_add(joint_t *joint, const double impulse[]) {
    joint->axial_impulse += impulse[0];
}

const joint_kind_t JOINT_DISTANCE_KIND = {prepare,   solve_velocity, solve_position,
                                          NULL, tree_rows, NULL, tree_add};
