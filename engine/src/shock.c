#include "shock.h"
#include <math.h>
#include <string.h>
#include "memory.h"

static const uint32_t UNREACHED = UINT32_MAX;

void shock_free(shock_t *shock) {
    memory_free(shock->level);
    memory_free(shock->first);
    memory_free(shock->neighbours);
    memory_free(shock->queue);
    memory_free(shock->loaded);
    memset(shock, 0, sizeof *shock);
}

static bool carries_load(const solver_contact_t *c) {
    for (int i = 0; i < c->point_count; i++) {
        if (c->points[i].normal_impulse > 0.0) return true;
    }
    return false;
}

/* Lists the load-bearing contacts in shock->loaded and groups them by body
 * (counting sort); returns how many there are. */
static size_t link_bodies(shock_t *shock, const solver_contact_t *contacts, size_t count,
                          size_t body_count) {
    uint32_t *first = shock->first;
    memset(first, 0, (body_count + 1) * sizeof(uint32_t));
    size_t loaded = 0;
    for (size_t i = 0; i < count; i++) {
        if (!carries_load(&contacts[i])) continue;
        shock->loaded[loaded++] = (uint32_t)i;
        first[contacts[i].a + 1]++;
        first[contacts[i].b + 1]++;
    }
    for (size_t k = 0; k < body_count; k++) first[k + 1] += first[k];
    memory_reserve((void **)&shock->neighbours, &shock->neighbour_capacity, first[body_count],
                   sizeof(shock_link_t));
    /* queue doubles as the fill cursor until the levels need it */
    uint32_t *next = shock->queue;
    memcpy(next, first, body_count * sizeof(uint32_t));
    for (size_t j = 0; j < loaded; j++) {
        const solver_contact_t *c = &contacts[shock->loaded[j]];
        shock->neighbours[next[c->a]++] = (shock_link_t){shock->loaded[j], c->b};
        shock->neighbours[next[c->b]++] = (shock_link_t){shock->loaded[j], c->a};
    }
    return loaded;
}

/* Breadth first from every static body: shock->queue lists the reached
 * bodies by level; returns how many there are. */
static size_t assign_levels(shock_t *shock, const solver_velocity_t *velocities,
                            size_t body_count) {
    uint32_t *level = shock->level, *queue = shock->queue;
    size_t head = 0, tail = 0;
    for (size_t k = 0; k < body_count; k++) {
        level[k] = solver_row_is_static(&velocities[k]) ? 0 : UNREACHED;
        if (level[k] == 0) queue[tail++] = (uint32_t)k;
    }
    while (head < tail) {
        uint32_t body = queue[head++];
        for (uint32_t j = shock->first[body]; j < shock->first[body + 1]; j++) {
            uint32_t other = shock->neighbours[j].other;
            if (level[other] != UNREACHED) continue;
            level[other] = level[body] + 1;
            queue[tail++] = other;
        }
    }
    return tail;
}

/* The impulses along the normal that stop the upper body's approach at the
 * contact's points, the lower body held still: the same LCP as the
 * iterations' block solve, from zero. sign is +1 when the upper body is b. */
static void stop_upper(const solver_contact_t *c, solver_velocity_t *upper,
                       const solver_velocity_t *lower, double sign) {
    double m = upper->inverse_mass, ii = upper->inverse_inertia;
    double rn[2] = {0.0, 0.0}, gap[2] = {0.0, 0.0};
    for (int i = 0; i < c->point_count; i++) {
        const solver_point_t *p = &c->points[i];
        rn[i] = sign > 0.0 ? p->rn_b : p->rn_a;
        double lower_rn = sign > 0.0 ? p->rn_a : p->rn_b;
        /* relative normal velocity of b over a, less the target */
        double up = vec_dot(c->normal, upper->v) + upper->w * rn[i];
        double low = vec_dot(c->normal, lower->v) + lower->w * lower_rn;
        gap[i] = sign * (up - low) - p->target;
    }
    if (gap[0] >= 0.0 && (c->point_count == 1 || gap[1] >= 0.0)) return;
    double x[2] = {0.0, 0.0};
    double k11 = m + ii * rn[0] * rn[0];
    if (c->point_count == 1) {
        if (gap[0] < 0.0 && k11 > 0.0) x[0] = -gap[0] / k11;
    } else {
        double k22 = m + ii * rn[1] * rn[1], k12 = m + ii * rn[0] * rn[1];
        double det = k11 * k22 - k12 * k12;
        double x1 = det > 1e-12 * k11 * k22 ? (k12 * gap[1] - k22 * gap[0]) / det : -1.0;
        double x2 = det > 1e-12 * k11 * k22 ? (k12 * gap[0] - k11 * gap[1]) / det : -1.0;
        if (x1 >= 0.0 && x2 >= 0.0) {
            x[0] = x1, x[1] = x2;
        } else if (gap[0] < 0.0 && k11 > 0.0 && gap[1] - k12 * gap[0] / k11 >= 0.0) {
            x[0] = -gap[0] / k11;
        } else if (gap[1] < 0.0 && k22 > 0.0 && gap[0] - k12 * gap[1] / k22 >= 0.0) {
            x[1] = -gap[1] / k22;
        }
    }
    double total = x[0] + x[1];
    upper->v = vec_add(upper->v, vec_multiply(sign * m * total, c->normal));
    upper->w += sign * ii * (x[0] * rn[0] + x[1] * rn[1]);
}

/*
 * The upper body moved with the lower one as one rigid body (both points of
 * the contact touching and held, no sliding), when the impulses that takes, added to the
 * iterations' at each point, press (>= 0) and stay within the friction
 * cone. Returns false, changing nothing, when they would not: the contact
 * is then opening, tipping or sliding, and only its approach is stopped.
 */
static bool weld_upper(const solver_contact_t *c, solver_velocity_t *upper,
                       const solver_velocity_t *lower, double sign) {
    if (c->point_count != 2 || upper->inverse_mass <= 0.0 || upper->inverse_inertia <= 0.0) {
        return false;
    }
    const solver_point_t *p1 = &c->points[0], *p2 = &c->points[1];
    /* Only faces in touch: a gap the step may close is no support yet,
     * and welding across it left a landed box hovering (measured). */
    if (p1->separation > 0.0 || p2->separation > 0.0) return false;
    bool b_upper = sign > 0.0;
    double rn1 = b_upper ? p1->rn_b : p1->rn_a, rn2 = b_upper ? p2->rn_b : p2->rn_a;
    double rt1 = b_upper ? p1->rt_b : p1->rt_a, rt2 = b_upper ? p2->rt_b : p2->rt_a;
    if (fabs(rn1 - rn2) < 1e-9) return false;
    vector_t n = c->normal, t = vec_perpendicular(n);
    /* From the lower centroid to the upper one, through point 1's lever
     * arms (r = (r x t) n - (r x n) t in the contact frame). */
    double lower_rn1 = b_upper ? p1->rn_a : p1->rn_b, lower_rt1 = b_upper ? p1->rt_a : p1->rt_b;
    vector_t r_lower = vec_subtract(vec_multiply(lower_rt1, n), vec_multiply(lower_rn1, t));
    vector_t r_upper = vec_subtract(vec_multiply(rt1, n), vec_multiply(rn1, t));
    vector_t offset = vec_subtract(r_lower, r_upper);
    vector_t target_v = vec_add(lower->v, (vector_t){-lower->w * offset.y, lower->w * offset.x});
    vector_t impulse = vec_multiply(1.0 / upper->inverse_mass, vec_subtract(target_v, upper->v));
    double moment = (lower->w - upper->w) / upper->inverse_inertia;
    /* Per point: the tangential impulse shared equally, the normal ones
     * from the total and the moment. */
    double jn = sign * vec_dot(impulse, n), jt = sign * vec_dot(impulse, t);
    double turn = sign * moment - 0.5 * jt * (rt1 + rt2);
    double n1 = (turn - rn2 * jn) / (rn1 - rn2), n2 = jn - n1;
    double pressed1 = p1->normal_impulse + n1, pressed2 = p2->normal_impulse + n2;
    if (!(pressed1 >= 0.0 && pressed2 >= 0.0)) return false;
    if (fabs(p1->tangent_impulse + 0.5 * jt) > c->friction * pressed1) return false;
    if (fabs(p2->tangent_impulse + 0.5 * jt) > c->friction * pressed2) return false;
    upper->v = target_v;
    upper->w = lower->w;
    return true;
}

/* Body's contacts with the level below, each solved with the lower body
 * held still; welded when it is the only one (a column), since a body
 * held by two is pulled two ways. */
static void hold_up(const shock_t *shock, const solver_contact_t *contacts, uint32_t body,
                    solver_velocity_t *velocities) {
    const uint32_t *level = shock->level;
    const shock_link_t *links = shock->neighbours + shock->first[body];
    uint32_t count = shock->first[body + 1] - shock->first[body];
    int supports = 0;
    for (uint32_t j = 0; j < count; j++) supports += level[links[j].other] < level[body];
    for (uint32_t j = 0; j < count; j++) {
        uint32_t other = links[j].other;
        if (level[other] >= level[body]) continue;
        const solver_contact_t *c = &contacts[links[j].contact];
        double sign = c->b == body ? 1.0 : -1.0;
        if (supports != 1 || !weld_upper(c, &velocities[body], &velocities[other], sign)) {
            stop_upper(c, &velocities[body], &velocities[other], sign);
        }
    }
}

void shock_propagate(shock_t *shock, const solver_contact_t *contacts, size_t count,
                     solver_velocity_t *velocities, size_t body_count) {
    if (count == 0) return;
    memory_reserve((void **)&shock->level, &shock->level_capacity, body_count, sizeof(uint32_t));
    memory_reserve((void **)&shock->first, &shock->first_capacity, body_count + 1,
                   sizeof(uint32_t));
    memory_reserve((void **)&shock->queue, &shock->queue_capacity, body_count, sizeof(uint32_t));
    memory_reserve((void **)&shock->loaded, &shock->loaded_capacity, count, sizeof(uint32_t));
    if (link_bodies(shock, contacts, count, body_count) == 0) return;
    size_t reached = assign_levels(shock, velocities, body_count);
    for (size_t k = 0; k < reached; k++) {
        uint32_t body = shock->queue[k];
        if (shock->level[body] > 0) hold_up(shock, contacts, body, velocities);
    }
}
