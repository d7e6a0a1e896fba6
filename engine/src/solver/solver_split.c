#include "solver/solver_split.h"
#include "base/workers.h"
#include "solver/velocity_solve.h"

/* A colour with fewer batches than this is swept by the calling thread
 * alone: waking the others would cost more than it saves. */
static const size_t SPLIT_MIN_BATCHES = 16;

typedef enum {
    SWEEP_WARM,
    SWEEP_ITERATE,
    SWEEP_RELAX,
    SWEEP_CORRECT
} sweep_t;

typedef struct {
    solver_wide_t *wide;
    sweep_t sweep;
    solver_velocity_t *rows;
    solver_displacement_t *displacements;
    int first_group, end_group; /* the groups swept (solver_wide.h) */
} colour_sweep_t;

static void sweep_range(const colour_sweep_t *s, size_t begin, size_t end) {
    switch (s->sweep) {
    case SWEEP_WARM:
        solver_wide_warm_start_range(s->wide, s->rows, begin, end);
        break;
    case SWEEP_ITERATE:
        solver_wide_iterate_range(s->wide, s->rows, begin, end);
        break;
    case SWEEP_RELAX:
        solver_wide_relax_range(s->wide, s->rows, begin, end);
        break;
    case SWEEP_CORRECT:
        solver_wide_correct_range(s->wide, s->displacements, begin, end);
        break;
    }
}

/* Chunk [begin, end) of a call over the batches of the groups swept takes
 * that share of each group: a group lists its contacts in the order of
 * their bodies, which is near the order of the body rows, so a thread that
 * takes the same chunks of every call (workers.h) finds most rows where it
 * left them. Cut through the whole range instead, one thread swept one
 * kind of batch over the whole scene and the other the other kind, and
 * each row crossed between the cores at each colour: two workers' sweeps
 * took 1.9 times one worker's CPU time (pile(10000)). */
static void sweep_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    const colour_sweep_t *s = context;
    const uint32_t *group_batch = s->wide->group_batch;
    size_t total = group_batch[s->end_group] - group_batch[s->first_group];
    (void)chunk;
    for (int g = s->first_group; g < s->end_group; g++) {
        size_t size = group_batch[g + 1] - group_batch[g];
        sweep_range(s, group_batch[g] + begin * size / total, group_batch[g] + end * size / total);
    }
}

static void sweep_groups(colour_sweep_t *s, int first_group, int end_group) {
    const solver_wide_t *wide = s->wide;
    size_t begin = wide->group_batch[first_group], end = wide->group_batch[end_group];
    if (end - begin < SPLIT_MIN_BATCHES) {
        sweep_range(s, begin, end);
        return;
    }
    s->first_group = first_group;
    s->end_group = end_group;
    workers_for(wide->workers, end - begin, sweep_chunk, s);
}

static void sweep_colour(colour_sweep_t *s, int colour) {
    sweep_groups(s, colour * SOLVER_WIDE_KINDS, (colour + 1) * SOLVER_WIDE_KINDS);
}

static void sweep_forward(colour_sweep_t *s) {
    for (int c = 0; c < COLORING_MAX_COLORS; c++) sweep_colour(s, c);
}

static void sweep_backward(colour_sweep_t *s) {
    for (int c = COLORING_MAX_COLORS; c-- > 0;) sweep_colour(s, c);
}

static void sweep_colours(colour_sweep_t *s, bool backward) {
    if (backward) {
        sweep_backward(s);
        return;
    }
    sweep_forward(s);
}

/* Preparing and storing over the workers: chunks of the visits
 * (solver_wide.h), each batch writing only its own lanes and contacts;
 * what each chunk of preparing found is joined after. */
typedef struct {
    solver_wide_t *wide;
    solver_contact_t *contacts;
    const solver_anchor_t *anchors;
    const solver_bodies_t *bodies;
    const solver_settings_t *settings;
    prepared_t found[WORKERS_MAX_CHUNKS];
} visit_split_t;

static void join(prepared_t *found, prepared_t more) {
    found->impact |= more.impact;
    found->elastic |= more.elastic;
    found->raised |= more.raised;
}

static void prepare_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    visit_split_t *p = context;
    p->found[chunk] =
        solver_wide_prepare(p->wide, p->contacts, p->anchors, p->bodies, p->settings, begin, end);
}

prepared_t solver_split_prepare(solver_wide_t *wide, solver_contact_t *contacts,
                                const solver_anchor_t *anchors, size_t count,
                                const solver_bodies_t *bodies, const solver_settings_t *settings) {
    solver_wide_arrange(wide, contacts, count, bodies->velocities, bodies->body_count);
    prepared_t found = {false, false, false};
    for (size_t k = 0; k < wide->loose_count; k++) {
        uint32_t i = wide->loose[k];
        found.impact |= solver_prepare_contact(&contacts[i], &anchors[i], bodies, settings,
                                               &found.raised);
        found.elastic |= contacts[i].restitution > 0.0;
    }
    /* Without workers, or with few batches, one chunk on this thread. */
    visit_split_t split = {wide, contacts, anchors, bodies, settings, {{false, false, false}}};
    workers_for(wide->workers, wide->batch_count, prepare_chunk, &split);
    for (size_t k = 0; k < workers_chunks(wide->workers, wide->batch_count); k++) {
        join(&found, split.found[k]);
    }
    return found;
}

static void store_chunk(void *context, size_t chunk, size_t begin, size_t end) {
    const visit_split_t *p = context;
    (void)chunk;
    solver_wide_store_range(p->wide, p->contacts, begin, end);
}

void solver_split_store(const solver_wide_t *wide, solver_contact_t *contacts) {
    /* Only read. */
    visit_split_t split = {.wide = (solver_wide_t *)wide, .contacts = contacts};
    workers_for(wide->workers, wide->batch_count, store_chunk, &split);
}

void solver_split_warm_start(solver_wide_t *wide, solver_velocity_t *rows) {
    if (wide->workers == NULL) {
        solver_wide_warm_start(wide, rows);
        return;
    }
    colour_sweep_t s = {.wide = wide, .sweep = SWEEP_WARM, .rows = rows};
    sweep_forward(&s);
}

void solver_split_iterate(solver_wide_t *wide, solver_velocity_t *rows, bool backward) {
    if (wide->workers == NULL) {
        solver_wide_iterate(wide, rows, backward);
        return;
    }
    colour_sweep_t s = {.wide = wide, .sweep = SWEEP_ITERATE, .rows = rows};
    sweep_colours(&s, backward);
}

void solver_split_relax(solver_wide_t *wide, solver_velocity_t *rows, bool backward) {
    if (wide->workers == NULL) {
        solver_wide_relax(wide, rows, backward);
        return;
    }
    colour_sweep_t s = {.wide = wide, .sweep = SWEEP_RELAX, .rows = rows};
    sweep_colours(&s, backward);
}

void solver_split_correct_positions(solver_wide_t *wide, solver_displacement_t *displacements,
                                    bool backward) {
    if (wide->workers == NULL) {
        solver_wide_correct_positions(wide, displacements, backward);
        return;
    }
    colour_sweep_t s = {.wide = wide, .sweep = SWEEP_CORRECT, .displacements = displacements};
    sweep_colours(&s, backward);
}
