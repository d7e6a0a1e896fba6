#include "core/frame_meter.h"

static void publish(frame_meter_t *m) {
    frame_times_t *t = &m->shown;
    double frames = (double)m->frames;
    t->fps = m->wall_s > 0.0 ? frames / m->wall_s : 0.0;
    t->frame_ms = 1000.0 * m->wall_s / frames;
    t->busy_ms = 1000.0 * m->busy_s / frames;
    t->render_ms = 1000.0 * m->render_s / frames;
    if (m->steps > 0) t->physics_ms = 1000.0 * m->physics_s / (double)m->steps;
}

void frame_meter_add(frame_meter_t *m, double wall_s, double busy_s, double physics_s,
                     int steps, double render_s) {
    m->wall_s += wall_s;
    m->busy_s += busy_s;
    m->physics_s += physics_s;
    m->render_s += render_s;
    m->steps += steps;
    m->frames++;
    if (m->wall_s < FRAME_METER_WINDOW) {
        if (!m->full) publish(m);
        return;
    }
    publish(m);
    m->full = true;
    m->wall_s = m->busy_s = m->physics_s = m->render_s = 0.0;
    m->frames = m->steps = 0;
}
