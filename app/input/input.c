#include "input/input.h"
#include <math.h>
#include "scene/integrator_choice.h"
#include "panels/ui.h"
#include "tools/tools.h"
#include "tools/joint_tool.h"

static const double ELASTICITY_STEP = 0.05;
static const double SIZE_FACTOR = 1.1;
static const double ZOOM_FACTOR = 1.15;
static const double PAN_PIXELS = 60.0;
static const double FRAME_MARGIN = 1.1;
static const double FRAME_MIN_SIZE = 6.0;

const input_control_t INPUT_CONTROLS[] = {
    {"Left click", "drop the shape at the cursor (not inside a body)"},
    {"Shift + left drag", "throw it with the drag's velocity"},
    {"Right drag on a body", "pull it to the cursor (a mouse joint)"},
    {"Right drag elsewhere, middle drag", "pan the view"},
    {"Ctrl + left click, D, Del, Backspace", "delete the joint or body under the cursor"},
    {"3 4 5 6 7 8", "regular polygon with 3 to 8 sides"},
    {"1 / 2", "circle / capsule"},
    {"B / P / Tab", "box / random convex polygon / next shape"},
    {"Mouse wheel", "shape size (over the slider: elasticity)"},
    {"Up / Down, slider", "elasticity of new bodies +/- 0.05"},
    {"E / Shift + E", "give that elasticity to the hovered body / every body"},
    {"A", "overlay: collision axes"},
    {"I", "overlay: impulses (fade over 0.5 s)"},
    {", / .", "impulse arrows shorter / longer"},
    {"T", "overlay: contact points"},
    {"V", "overlay: velocity vectors"},
    {"M", "overlay: centroids"},
    {"X", "overlay: bounding boxes"},
    {"Z / Shift + Z", "overlay: sleeping bodies dimmer / sleeping on, off"},
    {"O", "show every overlay (all shown: hide them all)"},
    {"Space, Enter", "pause / resume (in a game Enter only)"},
    {"S", "single step (pauses)"},
    {"[ / ]", "slow motion: time x0.1 to x1"},
    {"G", "gravity on / off"},
    {"N / Shift + N", "next / previous integrator (energy drift chart)"},
    {"C / R", "clear the bodies / reset the scene (read its file again)"},
    {"PageDown / PageUp", "next / previous sample"},
    {"Ctrl + S", "save the scene to a new ./saved-N.scene"},
    {"A .scene file dropped on the window", "open it"},
    {"Game: Left / Right, A / D", "move, drive (instead of panning, the A and D keys)"},
    {"Game: Space", "fire (instead of pausing: pause with Enter)"},
    {"Ctrl + wheel, + / -", "zoom about the cursor"},
    {"Left / Right, Ctrl + arrows", "pan the view (in a game Ctrl + Left / Right)"},
    {"J / U", "tool: ray cast / box query (drag)"},
    {"K / L", "tool: explosion / inspector (click)"},
    {"W; drag, Shift / Alt + drag", "tool: joint (click a body, then a point: pin); rope / rod / weld"},
    {"F2 F3 F4 F5", "side bar: PLAY, SAMPLES, SOLVER, TOOLS"},
    {"F", "frame every body"},
    {"0, Home", "the default view: the whole container or the file's view"},
    {"H, F1", "this help (a click closes it too)"},
    {"Esc, Q", "quit (Esc first closes the help)"},
};
const size_t INPUT_CONTROL_COUNT = sizeof(INPUT_CONTROLS) / sizeof(INPUT_CONTROLS[0]);

vector_t input_cursor_world(const app_t *app) {
    return camera_to_world(&app->camera, app->mouse);
}

body_t *input_hovered_body(app_t *app) {
    if (!app->mouse_inside || !app_in_view(app, app->mouse)) return NULL;
    if (app->drag == DRAG_GRAB) return app->sandbox.grab.body;
    return sandbox_body_at(&app->sandbox, input_cursor_world(app));
}

static void add_sample(app_t *app) {
    app->motion[app->motion_count % APP_MOTION_SAMPLES] =
        (motion_sample_t){app->now, camera_to_world(&app->camera, app->mouse)};
    app->motion_count++;
}

/* Drops the next shape at `at` (moved clear of the floor and walls), or
 * says on the status line why not: inside a static body, outside the
 * container (sandbox_place). */
static void drop_at(app_t *app, vector_t at, vector_t velocity) {
    vector_t placed;
    const char *refusal = sandbox_place(&app->sandbox, app->next_vertices, at, &placed);
    if (refusal != NULL) {
        app_warn(app, "cannot drop %s", refusal);
        return;
    }
    const char *problem = NULL;
    body_t *body = sandbox_drop_shape(&app->sandbox, app->shape,
                                      sandbox_copy_vertices(app->next_vertices), placed, velocity,
                                      app->elasticity, &problem);
    if (body == NULL) {
        app_status(app, "cannot drop: %s", problem);
        return;
    }
    if (app->shape.kind == SHAPE_RANDOM) app_new_shape(app);
}

static void set_shape(app_t *app, shape_kind_t kind, int sides) {
    app->shape.kind = kind;
    if (kind == SHAPE_REGULAR) app->shape.sides = sides;
    app_new_shape(app);
    app_status(app, "shape: %s", sandbox_shape_name(app->shape));
}

static void next_shape(app_t *app) {
    if (app->shape.kind == SHAPE_REGULAR && app->shape.sides < 8) {
        set_shape(app, SHAPE_REGULAR, app->shape.sides + 1);
    } else if (app->shape.kind == SHAPE_REGULAR) {
        set_shape(app, SHAPE_BOX, 0);
    } else if (app->shape.kind == SHAPE_BOX) {
        set_shape(app, SHAPE_RANDOM, 0);
    } else if (app->shape.kind == SHAPE_RANDOM) {
        set_shape(app, SHAPE_CIRCLE, 0);
    } else if (app->shape.kind == SHAPE_CIRCLE) {
        set_shape(app, SHAPE_CAPSULE, 0);
    } else {
        set_shape(app, SHAPE_REGULAR, 3);
    }
}

static void change_size(app_t *app, double factor) {
    double size = fmin(SHAPE_MAX_SIZE, fmax(SHAPE_MIN_SIZE, app->shape.size * factor));
    if (size == app->shape.size) return;
    app->shape.size = size;
    app_new_shape(app);
    app_status(app, "size %.2f m", app->shape.size);
}

static void change_elasticity(app_t *app, double delta) {
    app_set_elasticity(app, app->elasticity + delta);
    app_status(app, "elasticity of new bodies %.2f", app->elasticity);
}

/* Zooms about the cursor when it is over the view, else about the view's
 * middle. */
static void zoom(app_t *app, double factor) {
    vector_t anchor = {0.5 * app->camera.width, 0.5 * app->camera.height};
    if (app->mouse_inside && app_in_view(app, app->mouse)) anchor = app->mouse;
    camera_zoom_at(&app->camera, factor, anchor);
    app_status(app, "zoom x%.2f", camera_zoom(&app->camera));
}

/* What 0 shows: the default scene's container, a file's own view. */
static const char *home_view_name(const app_t *app) {
    return app->sandbox.is_default ? "the whole container" : "the scene's view";
}

/* Every body in view, with a margin; no closer than FRAME_MIN_SIZE across,
 * so that one body does not fill the screen. */
static void frame_all(app_t *app) {
    aabb_t box;
    if (!sandbox_bodies_bounds(&app->sandbox, &box)) {
        camera_reset(&app->camera);
        app_status(app, "no bodies: %s", home_view_name(app));
        return;
    }
    vector_t middle = vec_multiply(0.5, vec_add(box.min, box.max));
    vector_t half = vec_multiply(0.5, vec_subtract(box.max, box.min));
    half.x = fmax(half.x * FRAME_MARGIN + 0.5, 0.5 * FRAME_MIN_SIZE);
    half.y = fmax(half.y * FRAME_MARGIN + 0.5, 0.5 * FRAME_MIN_SIZE);
    camera_frame(&app->camera, vec_subtract(middle, half), vec_add(middle, half));
    size_t bodies = sandbox_totals(&app->sandbox).bodies;
    app_status(app, "framed %zu bod%s", bodies, bodies == 1 ? "y" : "ies");
}

static void set_body_elasticity(app_t *app, bool all) {
    if (all) {
        size_t changed = 0;
        for (size_t i = 0; i < scene_bodies(app->sandbox.scene); i++) {
            body_t *body = scene_get_body(app->sandbox.scene, i);
            if (sandbox_is_static(body) || body_is_removed(body)) continue;
            body_set_elasticity(body, app->elasticity);
            changed++;
        }
        app_status(app, "elasticity of all %zu bodies set to %.2f", changed, app->elasticity);
        return;
    }
    body_t *body = input_hovered_body(app);
    if (body == NULL) {
        app_status(app, "E: no body under the cursor");
        return;
    }
    body_set_elasticity(body, app->elasticity);
    app_status(app, "elasticity of this body set to %.2f", app->elasticity);
}

static void delete_hovered(app_t *app) {
    if (joint_tool_delete_hovered(app)) return;
    body_t *body = input_hovered_body(app);
    if (body == NULL) {
        app_status(app, "no body under the cursor to delete");
        return;
    }
    if (app->drag == DRAG_GRAB) app->drag = DRAG_NONE;
    sandbox_delete(&app->sandbox, body);
    app_status(app, "deleted a body");
}

static void clear_bodies(app_t *app) {
    size_t removed = sandbox_clear(&app->sandbox);
    if (app->drag == DRAG_GRAB) app->drag = DRAG_NONE;
    app_status(app, "cleared: %zu bod%s removed", removed, removed == 1 ? "y" : "ies");
}

/* Shift+Z: the engine's sleeping itself, on or off (off wakes every body). */
static void toggle_sleeping(app_t *app) {
    sandbox_set_sleeping(&app->sandbox, !app->sandbox.sleeping_on);
    app_status(app, app->sandbox.sleeping_on ? "sleeping on: bodies at rest 0.5 s sleep"
                                             : "sleeping off: every body awake");
}

static void change_time_scale(app_t *app, double delta) {
    double scale = round((app->time_scale + delta) * 10.0) / 10.0;
    app->time_scale = fmin(1.0, fmax(0.1, scale));
    app_status(app, "time x%.1f", app->time_scale);
}

/* A game's key, pressed or let go: Left / A, Right / D, Space (without
 * Ctrl, which keeps Left and Right for panning). False for other keys. */
static bool game_key(app_t *app, SDL_Keycode sym, bool down) {
    if (!app_game_mode(app) || (app->mods & KMOD_CTRL) != 0) {
        /* A key let go after Ctrl was pressed, or after the scene changed,
         * is let go all the same. */
        if (!down) {
            if (sym == SDLK_LEFT || sym == SDLK_a) app->keys.left = false;
            if (sym == SDLK_RIGHT || sym == SDLK_d) app->keys.right = false;
            if (sym == SDLK_SPACE) app->keys.fire = false;
        }
        return false;
    }
    bool *held, *tapped;
    switch (sym) {
    case SDLK_LEFT:
    case SDLK_a:
        held = &app->keys.left;
        tapped = &app->keys.left_tapped;
        break;
    case SDLK_RIGHT:
    case SDLK_d:
        held = &app->keys.right;
        tapped = &app->keys.right_tapped;
        break;
    case SDLK_SPACE:
        held = &app->keys.fire;
        tapped = &app->keys.fire_tapped;
        break;
    default:
        return false;
    }
    *held = down;
    if (down) *tapped = true;
    return true;
}

static void toggle_pause(app_t *app) {
    app->paused = !app->paused;
    if (app_game_mode(app)) app_status(app, app->paused ? "paused (Enter resumes)" : "running");
    else app_status(app, app->paused ? "paused" : "running");
}

static void on_key(app_t *app, const SDL_KeyboardEvent *key) {
    SDL_Keycode sym = key->keysym.sym;
    bool ctrl = (app->mods & KMOD_CTRL) != 0;
    bool shift = (app->mods & KMOD_SHIFT) != 0;
    bool repeat = key->repeat != 0;

    /* In a game its keys come first: Left, Right, A, D move, Space fires. */
    if (game_key(app, sym, true)) return;

    /* Keys that may repeat while held. */
    switch (sym) {
    case SDLK_UP:
        if (ctrl) camera_pan_pixels(&app->camera, 0, PAN_PIXELS);
        else change_elasticity(app, ELASTICITY_STEP);
        return;
    case SDLK_DOWN:
        if (ctrl) camera_pan_pixels(&app->camera, 0, -PAN_PIXELS);
        else change_elasticity(app, -ELASTICITY_STEP);
        return;
    case SDLK_LEFT: /* with or without Ctrl; in a game with Ctrl only */
        camera_pan_pixels(&app->camera, PAN_PIXELS, 0);
        return;
    case SDLK_RIGHT:
        camera_pan_pixels(&app->camera, -PAN_PIXELS, 0);
        return;
    case SDLK_PLUS:
    case SDLK_EQUALS:
    case SDLK_KP_PLUS:
        zoom(app, ZOOM_FACTOR);
        return;
    case SDLK_MINUS:
    case SDLK_KP_MINUS:
        zoom(app, 1.0 / ZOOM_FACTOR);
        return;
    case SDLK_s:
        if (ctrl) break; /* Ctrl+S saves, below */
        app->paused = true;
        app->step_once = true;
        app_status(app, "one step of %.4g s (paused)", app->sandbox.step);
        return;
    default:
        break;
    }
    if (repeat) return;

    switch (sym) {
    case SDLK_3: case SDLK_4: case SDLK_5: case SDLK_6: case SDLK_7: case SDLK_8:
        set_shape(app, SHAPE_REGULAR, 3 + (int)(sym - SDLK_3));
        break;
    case SDLK_b:
        set_shape(app, SHAPE_BOX, 0);
        break;
    case SDLK_p:
        set_shape(app, SHAPE_RANDOM, 0);
        break;
    case SDLK_1:
        set_shape(app, SHAPE_CIRCLE, 0);
        break;
    case SDLK_2:
        set_shape(app, SHAPE_CAPSULE, 0);
        break;
    case SDLK_TAB:
        next_shape(app);
        break;
    case SDLK_e:
        set_body_elasticity(app, shift);
        break;
    case SDLK_a:
        app_toggle_overlay(app, OVERLAY_AXES);
        break;
    case SDLK_i:
        app_toggle_overlay(app, OVERLAY_IMPULSES);
        break;
    case SDLK_t:
        app_toggle_overlay(app, OVERLAY_POINTS);
        break;
    case SDLK_v:
        app_toggle_overlay(app, OVERLAY_VELOCITIES);
        break;
    case SDLK_m:
        app_toggle_overlay(app, OVERLAY_CENTROIDS);
        break;
    case SDLK_x:
        app_toggle_overlay(app, OVERLAY_BOUNDS);
        break;
    case SDLK_COMMA:
    case SDLK_PERIOD:
        app->impulse_scale *= sym == SDLK_COMMA ? 1.0 / 1.5 : 1.5;
        app->impulse_scale = fmin(10.0, fmax(0.001, app->impulse_scale));
        app_status(app, "impulse arrows: %.3g m per N s", app->impulse_scale);
        break;
    case SDLK_o: {
        /* Show all, unless all are shown already (some are on at start). */
        bool all = true;
        for (int i = 0; i < OVERLAY_COUNT; i++) all = all && app->overlays[i];
        for (int i = 0; i < OVERLAY_COUNT; i++) app->overlays[i] = !all;
        app_status(app, "all overlays %s", all ? "off" : "on");
        break;
    }
    case SDLK_SPACE:
    case SDLK_RETURN:
    case SDLK_KP_ENTER:
        toggle_pause(app);
        break;
    case SDLK_s: /* with Ctrl: a plain S stepped above */
        app_save_scene(app);
        break;
    case SDLK_PAGEDOWN:
        app_cycle_scene(app, 1);
        break;
    case SDLK_PAGEUP:
        app_cycle_scene(app, -1);
        break;
    case SDLK_LEFTBRACKET:
        change_time_scale(app, -0.1);
        break;
    case SDLK_RIGHTBRACKET:
        change_time_scale(app, +0.1);
        break;
    case SDLK_g:
        app_set_gravity(app, !app->sandbox.gravity_on);
        break;
    case SDLK_n:
        app_set_integrator(app, integrator_choice_step(app->sandbox.integrator, shift ? -1 : 1));
        break;
    case SDLK_z:
        if (shift) toggle_sleeping(app);
        else app_toggle_overlay(app, OVERLAY_SLEEPING);
        break;
    case SDLK_c:
        clear_bodies(app);
        break;
    case SDLK_r:
        app_reset_scene(app);
        break;
    case SDLK_f:
        frame_all(app);
        break;
    case SDLK_d:
    case SDLK_DELETE:
    case SDLK_BACKSPACE:
        delete_hovered(app);
        break;
    case SDLK_0:
    case SDLK_HOME:
        camera_reset(&app->camera);
        app_status(app, "view: %s", home_view_name(app));
        break;
    case SDLK_h:
    case SDLK_F1:
        app->show_help = !app->show_help;
        break;
    case SDLK_F2:
    case SDLK_F3:
    case SDLK_F4:
    case SDLK_F5:
        app->page = (ui_page_t)(UI_PAGE_PLAY + (int)(sym - SDLK_F2));
        break;
    case SDLK_j:
        tools_choose(app, TOOL_RAY);
        break;
    case SDLK_u:
        tools_choose(app, TOOL_BOX);
        break;
    case SDLK_k:
        tools_choose(app, TOOL_EXPLODE);
        break;
    case SDLK_l:
        tools_choose(app, TOOL_INSPECT);
        break;
    case SDLK_w:
        tools_choose(app, TOOL_JOINT);
        break;
    case SDLK_ESCAPE:
        if (app->show_help) app->show_help = false;
        else app->quit = true;
        break;
    case SDLK_q:
        app->quit = true;
        break;
    default:
        break;
    }
}

static void on_button_down(app_t *app, const SDL_MouseButtonEvent *button) {
    app->mouse = (vector_t){button->x, button->y};
    app->mouse_inside = true;
    if (app->drag != DRAG_NONE) return;
    /* The help covers the view: a click there closes it and drops nothing. */
    if (app->show_help) {
        app->show_help = false;
        return;
    }
    /* The side bar's panels take their own clicks; nothing reaches the world. */
    if (!app_in_view(app, app->mouse)) {
        if (button->button == SDL_BUTTON_LEFT) app->drag = ui_press(app, app->mouse);
        return;
    }
    vector_t world = input_cursor_world(app);
    if (button->button == SDL_BUTTON_LEFT) {
        if (app->mods & KMOD_CTRL) {
            delete_hovered(app);
        } else if (app->tool != TOOL_DROP) {
            app->drag = tools_press(app, world);
        } else if (app->mods & KMOD_SHIFT) {
            app->drag = DRAG_THROW;
            add_sample(app);
        } else {
            drop_at(app, world, VEC_ZERO);
        }
    } else if (button->button == SDL_BUTTON_RIGHT) {
        body_t *body = sandbox_body_at(&app->sandbox, world);
        if (body != NULL) {
            sandbox_grab(&app->sandbox, body, world);
            app->drag = DRAG_GRAB;
        } else {
            app->drag = DRAG_PAN;
            app->drag_last = app->mouse;
        }
    } else if (button->button == SDL_BUTTON_MIDDLE) {
        app->drag = DRAG_PAN;
        app->drag_last = app->mouse;
    }
}

static void on_button_up(app_t *app, const SDL_MouseButtonEvent *button) {
    app->mouse = (vector_t){button->x, button->y};
    switch (app->drag) {
    case DRAG_THROW:
        if (button->button == SDL_BUTTON_LEFT) {
            add_sample(app);
            drop_at(app, input_cursor_world(app), app_throw_velocity(app));
            app->drag = DRAG_NONE;
        }
        break;
    case DRAG_SLIDER:
        if (button->button == SDL_BUTTON_LEFT) app->drag = DRAG_NONE;
        break;
    case DRAG_PROBE:
        if (button->button == SDL_BUTTON_LEFT) {
            tools_probe_release(app, input_cursor_world(app));
            app->drag = DRAG_NONE;
        }
        break;
    case DRAG_JOINT:
        if (button->button == SDL_BUTTON_LEFT) {
            app->drag = DRAG_NONE;
            joint_tool_release(app, input_cursor_world(app));
        }
        break;
    case DRAG_GRAB:
        if (button->button == SDL_BUTTON_RIGHT) {
            sandbox_release(&app->sandbox);
            /* The spring did work on the body: the drift starts again from
             * the energy it left. */
            energy_drift_rereference(&app->drift);
            app->drag = DRAG_NONE;
        }
        break;
    case DRAG_PAN:
        if (button->button == SDL_BUTTON_RIGHT || button->button == SDL_BUTTON_MIDDLE) {
            app->drag = DRAG_NONE;
        }
        break;
    case DRAG_NONE:
        break;
    }
}

static void on_motion(app_t *app, const SDL_MouseMotionEvent *motion) {
    app->mouse = (vector_t){motion->x, motion->y};
    app->mouse_inside = true;
    switch (app->drag) {
    case DRAG_THROW:
        add_sample(app);
        break;
    case DRAG_PROBE:
        tools_probe_move(app, input_cursor_world(app));
        break;
    case DRAG_JOINT:
        break;
    case DRAG_SLIDER:
        app_set_elasticity(app, ui_slider_value_at(app, app->mouse));
        app_status(app, "elasticity of new bodies %.2f", app->elasticity);
        break;
    case DRAG_GRAB:
        if (app->sandbox.grab.body == NULL) {
            app->drag = DRAG_NONE; /* the body was deleted or fell out */
        } else {
            sandbox_grab_move(&app->sandbox, input_cursor_world(app));
        }
        break;
    case DRAG_PAN:
        camera_pan_pixels(&app->camera, app->mouse.x - app->drag_last.x,
                          app->mouse.y - app->drag_last.y);
        app->drag_last = app->mouse;
        break;
    case DRAG_NONE:
        break;
    }
}

static void on_wheel(app_t *app, const SDL_MouseWheelEvent *wheel) {
    int notches = wheel->y;
    if (wheel->direction == SDL_MOUSEWHEEL_FLIPPED) notches = -notches;
    if (notches == 0) return;
    if (ui_slider_hit(app, app->mouse)) {
        change_elasticity(app, ELASTICITY_STEP * notches);
    } else if (app->mods & KMOD_CTRL) {
        zoom(app, pow(ZOOM_FACTOR, notches));
    } else {
        change_size(app, pow(SIZE_FACTOR, notches));
    }
}

void input_handle_event(app_t *app, const SDL_Event *event) {
    switch (event->type) {
    case SDL_QUIT:
        app->quit = true;
        break;
    case SDL_KEYDOWN:
        app->mods = event->key.keysym.mod;
        on_key(app, &event->key);
        break;
    case SDL_KEYUP:
        app->mods = event->key.keysym.mod;
        game_key(app, event->key.keysym.sym, false);
        break;
    case SDL_DROPFILE:
        /* A file dropped on the window: a scene to open. */
        if (event->drop.file != NULL) {
            app_open(app, event->drop.file);
            SDL_free(event->drop.file);
        }
        break;
    case SDL_MOUSEBUTTONDOWN:
        on_button_down(app, &event->button);
        break;
    case SDL_MOUSEBUTTONUP:
        on_button_up(app, &event->button);
        break;
    case SDL_MOUSEMOTION:
        on_motion(app, &event->motion);
        break;
    case SDL_MOUSEWHEEL:
        on_wheel(app, &event->wheel);
        break;
    case SDL_WINDOWEVENT:
        /* A new size reaches the camera through main.c (video_sync_size). */
        if (event->window.event == SDL_WINDOWEVENT_LEAVE) {
            app->mouse_inside = false;
        } else if (event->window.event == SDL_WINDOWEVENT_ENTER) {
            app->mouse_inside = true;
        } else if (event->window.event == SDL_WINDOWEVENT_FOCUS_LOST) {
            app->mods = 0;
            app->keys.left = app->keys.right = app->keys.fire = false;
        }
        break;
    default:
        break;
    }
}
