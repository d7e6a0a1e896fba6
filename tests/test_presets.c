/* The samples (assets/scenes/): each loads, runs headless for a few hundred
 * steps with every body finite, saves and loads back the same (at the start
 * and mid-run), and keeps the promise its `note` makes (the note the
 * sandbox's samples browser shows is the one checked here, word for word).
 * Run from the repository root, as make check does. */
#include <dirent.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "jostle/jostle.h"
#include "jostle/joint.h"
#include "game.h"
#include "jostle/scene_file.h"
#include "scene_file_check.h"
#include "test.h"

static scene_file_t *load(const char *name) {
    char path[256];
    snprintf(path, sizeof path, "assets/scenes/%s.scene", name);
    scene_file_error_t error;
    scene_file_t *file = scene_file_load(path, &error);
    if (file == NULL) test_fail(__FILE__, __LINE__, "%s", error.message);
    return file;
}

static void run(scene_file_t *file, int steps) {
    for (int i = 0; i < steps; i++)
        scene_tick(scene_file_get_scene(file), scene_file_get_timestep(file));
}

static bool all_finite(scene_file_t *file) {
    scene_t *scene = scene_file_get_scene(file);
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        if (!vec_is_finite(body_get_centroid(body)) || !vec_is_finite(body_get_velocity(body)) ||
            !isfinite(body_get_rotation(body)) || !isfinite(body_get_angular_velocity(body)))
            return false;
    }
    return true;
}

/* Saves the file as it is now and loads the text: the same scene. */
static void check_round_trip(scene_file_t *file, const char *name) {
    size_t length = 0;
    scene_file_error_t error;
    char *text = scene_file_write(file, &length, &error);
    CHECK(text != NULL);
    scene_file_t *again = scene_file_parse(text, length, name, &error);
    if (again == NULL) test_fail(__FILE__, __LINE__, "%s: %s", name, error.message);
    char why[256] = "";
    if (again != NULL && !scene_file_same(file, again, why, sizeof why))
        test_fail(__FILE__, __LINE__, "%s: %s", name, why);
    scene_file_free(again);
    free(text);
}

static body_t *named(scene_file_t *file, const char *name) {
    body_t *body = scene_file_find_body(file, name);
    if (body == NULL) test_fail(__FILE__, __LINE__, "no body named %s", name);
    return body;
}

static bool tagged(body_t *body, const char *tag) {
    const char *info = body_get_info(body);
    return info != NULL && strcmp(info, tag) == 0;
}

/* ---- What each preset promises -------------------------------------------- */

static double energy(scene_t *scene, double g, double G) {
    double e = 0.0;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *a = scene_get_body(scene, i);
        if (isinf(body_get_mass(a))) continue;
        e += body_get_kinetic_energy(a) + body_get_mass(a) * g * body_get_centroid(a).y;
        for (size_t j = i + 1; G > 0 && j < scene_bodies(scene); j++) {
            body_t *b = scene_get_body(scene, j);
            double r = vec_get_length(vec_subtract(body_get_centroid(a), body_get_centroid(b)));
            e -= G * body_get_mass(a) * body_get_mass(b) / r;
        }
    }
    return e;
}

/* How far (m) a point is inside a wall's inner face: the wall is a box
 * turned by its rotation, 1 m thick, and the board is on the side of its
 * middle line where `inside` lies. */
static double inside_wall(body_t *wall, vector_t inside, vector_t point) {
    double angle = body_get_rotation(wall);
    vector_t normal = {-sin(angle), cos(angle)}, centre = body_get_centroid(wall);
    if (vec_dot(vec_subtract(inside, centre), normal) < 0.0) normal = vec_negate(normal);
    return vec_dot(vec_subtract(point, centre), normal) - 0.5;
}

static void pegs_keep_every_ball_on_the_board(scene_file_t *file) {
    /* Ten minutes of play with the rules (a ball a second): every 0.1 s
     * every ball, falling or frozen, lies wholly inside both walls and above
     * the floor (its edge within 1 cm of them at most), and no ball stays in
     * the air (under 20 falling at once); the balls land and freeze, the
     * board fills and is cleared. */
    char error[256];
    game_t *game = game_start(file, error, sizeof error);
    CHECK(game != NULL);
    if (game == NULL) return;
    scene_t *scene = scene_file_get_scene(file);
    body_t *left = named(file, "left"), *right = named(file, "right");
    vector_t middle = {0, 40};
    const double radius = 1.0, slack = 0.01; /* the balls are circles of 1 m */
    double dt = scene_file_get_timestep(file), worst = INFINITY;
    int most_falling = 0, clears = 0, on_board = 0, failures = test_failures;
    long steps = lround(600.0 / dt), every = lround(0.1 / dt);
    for (long step = 1; step <= steps && test_failures == failures; step++) {
        scene_tick(scene, dt);
        game_update(game, (game_input_t){0}, dt);
        clears += game_status(game).remaining < on_board - 20;
        on_board = game_status(game).remaining;
        if (step % every != 0) continue;
        int falling = 0;
        for (size_t i = 0; i < scene_bodies(scene); i++) {
            body_t *body = scene_get_body(scene, i);
            bool ball = tagged(body, "ball");
            if (body_is_removed(body) || !(ball || tagged(body, "frozen"))) continue;
            falling += ball;
            vector_t at = body_get_centroid(body);
            double margin = fmin(inside_wall(left, middle, at), inside_wall(right, middle, at));
            margin = fmin(margin, at.y); /* the floor's top is at y = 0 */
            worst = fmin(worst, margin);
            CHECK(margin > radius - slack);
        }
        most_falling = most_falling > falling ? most_falling : falling;
    }
    game_status_t status = game_status(game);
    CHECK(most_falling < 20);
    CHECK(status.score >= 580); /* of 600 dropped */
    CHECK(clears >= 1);
    CHECK(status.outcome == GAME_PLAYING);
    if (test_failures != failures) printf("    worst margin %g m\n", worst - radius);
    game_free(game);
}

static double speed(body_t *body) {
    return vec_get_length(body_get_velocity(body));
}

/* Runs until the striker's blow reaches the ball at the other end (its
 * speed passes half the striker's), then 0.05 s more: that ball leaves with
 * at least 99% of the speed the striker had in the step before, the others
 * keep under 1% of it. At most max_steps steps; returns the steps run. */
static int check_transmission(scene_file_t *file, body_t *const ball[5], bool leftward,
                              int max_steps) {
    body_t *striker = ball[leftward ? 4 : 0], *last = ball[leftward ? 0 : 4];
    double before = 0.0, fastest = 0.0;
    int steps = 0;
    while (!(fastest > 0.0 && speed(last) > 0.5 * fastest) && steps < max_steps) {
        before = speed(striker);
        fastest = fmax(fastest, before);
        run(file, 1);
        steps++;
    }
    CHECK(steps < max_steps);
    double leaving = 0.0;
    for (int i = 0; i < 24; i++) { /* 0.05 s at 1/480 s */
        run(file, 1);
        leaving = fmax(leaving, speed(last));
    }
    CHECK(leaving >= 0.99 * before);
    for (int i = 0; i < 5; i++) {
        if (ball[i] != last) CHECK(speed(ball[i]) < 0.01 * before);
    }
    return steps + 24;
}

static void newtons_cradle_passes_the_blow_along_and_repeats(scene_file_t *file) {
    body_t *ball[5];
    char name[16];
    for (int i = 0; i < 5; i++) {
        snprintf(name, sizeof name, "ball%d", i + 1);
        ball[i] = named(file, name);
    }
    const double period = 2.0 * M_PI * sqrt(2.0 / 9.8), dt = scene_file_get_timestep(file);
    vector_t rest[5];
    for (int i = 0; i < 5; i++) rest[i] = body_get_centroid(ball[i]);
    rest[0].y = rest[1].y; /* the striker's rest is at the row's height */
    double release = body_get_centroid(ball[0]).y - rest[0].y;
    /* Ball 1 strikes the row, then ball 5 comes back and strikes it. */
    int half = (int)(0.6 * period / dt);
    int done = check_transmission(file, ball, false, half);
    done += check_transmission(file, ball, true, 2 * half);
    /* Two periods from the start: every swing of an end ball (from its
     * leaving the row to its coming back below 10% of the release height)
     * rises to 90% of the release height; the middle balls stay within a
     * tenth of it from where they hang. */
    double apex[2] = {0.0, 0.0}, middle = 0.0;
    int swings[2] = {0, 0};
    int steps = (int)lround(2.0 * period / dt);
    for (int step = done; step < steps; step++) {
        run(file, 1);
        for (int end = 0; end < 2; end++) {
            double height = body_get_centroid(ball[4 * end]).y - rest[4 * end].y;
            if (height > 0.5 * release) apex[end] = fmax(apex[end], height);
            if (height < 0.1 * release && apex[end] > 0.0) {
                CHECK(apex[end] >= 0.9 * release);
                swings[end]++;
                apex[end] = 0.0;
            }
        }
        for (int i = 1; i < 4; i++) {
            vector_t moved = vec_subtract(body_get_centroid(ball[i]), rest[i]);
            middle = fmax(middle, vec_get_length(moved));
        }
    }
    CHECK(swings[0] + swings[1] >= 1);
    CHECK(middle < 0.1 * release);
}

static void pyramid_stands(scene_file_t *file) {
    vector_t top = body_get_centroid(named(file, "top"));
    run(file, 600);
    CHECK_NEAR(body_get_centroid(named(file, "top")).y, top.y, 0.01);
    CHECK_NEAR(body_get_centroid(named(file, "top")).x, top.x, 0.01);
    scene_t *scene = scene_file_get_scene(file);
    for (size_t i = 0; i < scene_bodies(scene); i++)
        CHECK(vec_get_length(body_get_velocity(scene_get_body(scene, i))) < 0.01);
}

static void card_house_stands(scene_file_t *file) {
    scene_t *scene = scene_file_get_scene(file);
    size_t n = scene_bodies(scene);
    vector_t *at = malloc(n * sizeof *at);
    double *angle = malloc(n * sizeof *angle);
    for (size_t i = 0; i < n; i++) {
        at[i] = body_get_centroid(scene_get_body(scene, i));
        angle[i] = body_get_rotation(scene_get_body(scene, i));
    }
    run(file, 600);
    for (size_t i = 0; i < n; i++) {
        body_t *card = scene_get_body(scene, i);
        CHECK(vec_get_length(vec_subtract(body_get_centroid(card), at[i])) < 0.05);
        CHECK_NEAR(body_get_rotation(card), angle[i], 0.05);
    }
    free(at);
    free(angle);
}

static void orbits_stay_round(scene_file_t *file) {
    /* Four planets for 20 s, about two periods of the outermost: each stays
     * within 10% of its radius, the total energy within 0.1%. */
    scene_t *scene = scene_file_get_scene(file);
    body_t *sun = named(file, "sun");
    const char *const planets[] = {"mercury", "venus", "earth", "mars"};
    double radius[4];
    for (int i = 0; i < 4; i++) {
        radius[i] = vec_get_length(
            vec_subtract(body_get_centroid(named(file, planets[i])), body_get_centroid(sun)));
    }
    double start = energy(scene, 0, 1);
    for (int step = 0; step < 2400; step += 100) {
        run(file, 100);
        for (int i = 0; i < 4; i++) {
            double r = vec_get_length(
                vec_subtract(body_get_centroid(named(file, planets[i])), body_get_centroid(sun)));
            CHECK_RELATIVE(r, radius[i], 0.1);
        }
    }
    CHECK_RELATIVE(energy(scene, 0, 1), start, 1e-3);
    CHECK(scene_file_force_count(file) == 10); /* newton all: 5 bodies, 10 pairs */
}

static void spring_chain_hangs_at_its_length(scene_file_t *file) {
    /* 30 s: at rest straight below the anchor, each spring its rest length
     * (1 m) plus the weight it holds over k, n 1 kg links below it pulling
     * with n 9.8 N on k = 1000 N/m. */
    const double rest_length = 1.0, k = 1000.0, weight = 1.0 * 9.8;
    run(file, 3600);
    vector_t above = body_get_centroid(named(file, "anchor"));
    char name[16];
    for (int i = 1; i <= 8; i++) {
        snprintf(name, sizeof name, "link%d", i);
        body_t *link = named(file, name);
        vector_t at = body_get_centroid(link);
        int below = 9 - i; /* this link and those under it */
        CHECK_NEAR(at.x, above.x, 1e-4);
        CHECK_NEAR(above.y - at.y, rest_length + below * weight / k, 1e-4);
        CHECK(vec_get_length(body_get_velocity(link)) < 1e-4);
        above = at;
    }
}

static void stiff_spring_stays_bounded(scene_file_t *file) {
    vector_t pin = body_get_centroid(named(file, "pin"));
    double worst = 0.0;
    for (int i = 0; i < 1200; i++) {
        run(file, 1);
        worst = fmax(worst,
                     vec_get_length(vec_subtract(body_get_centroid(named(file, "weight")), pin)));
    }
    CHECK(worst < 0.55); /* released 0.5 m away: no energy gained */
    CHECK(worst > 0.45);
}

static void mass_ratio_stack_holds(scene_file_t *file) {
    run(file, 600);
    CHECK_NEAR(body_get_centroid(named(file, "light")).y, 0.5, 0.01);
    CHECK_NEAR(body_get_centroid(named(file, "heavy")).y, 1.5, 0.01);
    CHECK_NEAR(body_get_centroid(named(file, "top")).y, 2.5, 0.01);
    CHECK_NEAR(body_get_centroid(named(file, "heavy")).x, 0, 0.01);
}

/* Whether the body lies wholly inside the file's view. */
static bool in_view(scene_file_t *file, body_t *body) {
    scene_file_view_t view = scene_file_get_view(file);
    aabb_t box = body_get_bounds(body);
    return view.has_view && box.min.x >= view.center.x - 0.5 * view.width &&
           box.max.x <= view.center.x + 0.5 * view.width &&
           box.min.y >= view.center.y - 0.5 * view.height &&
           box.max.y <= view.center.y + 0.5 * view.height;
}

static void tunnelling_stops_every_box_and_keeps_them_in_view(scene_file_t *file) {
    /* 5 s at 1/60 s: at every step every box is between the walls' faces
     * (x = -13.95 and 9.95), none passing through; then every box is in
     * the view, the two at elasticity 0 at rest against the wall, the one
     * at 1 crossing at 1000 m/s, the one at 0.5 slower than it started. */
    const char *const boxes[] = {"slow", "fast", "faster", "fastest"};
    const double half = 0.4;
    for (int step = 0; step < 300; step++) {
        run(file, 1);
        for (int i = 0; i < 4; i++) {
            double x = body_get_centroid(named(file, boxes[i])).x;
            CHECK(x - half >= -13.95 - 1e-3 && x + half <= 9.95 + 1e-3);
        }
    }
    for (int i = 0; i < 4; i++) CHECK(in_view(file, named(file, boxes[i])));
    CHECK_NEAR(body_get_centroid(named(file, "fast")).x, 9.95 - half, 1e-3);
    CHECK_NEAR(body_get_centroid(named(file, "fastest")).x, 9.95 - half, 1e-3);
    CHECK_VEC(body_get_velocity(named(file, "fast")), 0, 0, 1e-9);
    CHECK_VEC(body_get_velocity(named(file, "fastest")), 0, 0, 1e-9);
    CHECK_RELATIVE(fabs(body_get_velocity(named(file, "faster")).x), 1000, 1e-9);
    double slow = fabs(body_get_velocity(named(file, "slow")).x);
    CHECK(slow > 0.0 && slow < 50.0);
}

/* Breakout and Space Invaders are played in tests/test_games.c; here the
 * board the note promises starts (bricks or invaders, three lives) and the
 * scene runs without the rules too. */
static void game_starts_as_promised(scene_file_t *file, int remaining) {
    char error[256];
    game_t *game = game_start(file, error, sizeof error);
    CHECK(game != NULL);
    if (game == NULL) return;
    game_status_t status = game_status(game);
    CHECK(status.remaining == remaining && status.lives == 3 && status.score == 0 &&
          status.outcome == GAME_PLAYING);
    game_free(game);
    run(file, 300);
}

static void breakout_has_50_bricks(scene_file_t *file) {
    game_starts_as_promised(file, 50);
}

static void space_invaders_has_32_invaders(scene_file_t *file) {
    game_starts_as_promised(file, 32);
}

/* Five boxes fall 4 m (their bottoms from y = 4 to the floor's top at 0):
 * after the first impact (0.894 s) each rises to e^2 4 m, within 1 mm, by
 * 2.6 s (before the elastic box lands again at 2.68 s). */
static void bounce_apexes_are_e_squared_of_the_drop(scene_file_t *file) {
    const char *const names[] = {"e0", "e25", "e50", "e75", "e100"};
    double apex[5] = {0, 0, 0, 0, 0}, dt = scene_file_get_timestep(file);
    for (long step = 1; step * dt <= 2.6; step++) {
        run(file, 1);
        if (step * dt < 0.95) continue;
        for (int i = 0; i < 5; i++) {
            apex[i] = fmax(apex[i], body_get_bounds(named(file, names[i])).min.y);
        }
    }
    for (int i = 0; i < 5; i++) {
        double e = 0.25 * i;
        CHECK_NEAR(apex[i], e * e * 4.0, 1e-3);
        CHECK_NEAR(body_get_elasticity(named(file, names[i])), e, 0);
    }
}

/* On a 30 degree ramp, the boxes whose friction with it is 0.3 and 0.5
 * slide g (sin 30 - mu cos 30) t^2 / 2 in the first second (1.1769 m and
 * 0.3282 m, within 1 mm), along the ramp without turning; the box of 0.7
 * (above tan 30) does not move (1e-6 m). */
static void friction_holds_above_tan_30_and_slides_below(scene_file_t *file) {
    const char *const names[] = {"mu30", "mu50", "mu70"};
    const double mu[] = {0.3, 0.5, 0.7}, g = 9.8, angle = M_PI / 6;
    vector_t start[3];
    for (int i = 0; i < 3; i++) start[i] = body_get_centroid(named(file, names[i]));
    run(file, (int)lround(1.0 / scene_file_get_timestep(file)));
    for (int i = 0; i < 3; i++) {
        body_t *box = named(file, names[i]);
        vector_t moved = vec_subtract(body_get_centroid(box), start[i]);
        double slide = fmax(0.0, 0.5 * g * (sin(angle) - mu[i] * cos(angle)));
        CHECK_NEAR(vec_get_length(moved), slide, i == 2 ? 1e-6 : 1e-3);
        CHECK_NEAR(body_get_rotation(box), angle, 1e-6);
        if (i < 2) CHECK_NEAR(atan2(-moved.y, -moved.x), angle, 1e-3);
    }
}

/* The ball rolls down the chain's straight slope (four segments, joins
 * flat) as a disc rolls without slipping: after 1 s it has covered
 * (1/3) g sin(theta) t^2 along the slope, with w = -v / r, both to 1%;
 * for 8 s it never sinks more than 5 mm into any segment, never lifts off
 * the ramp by more than 5 mm while on it (no bump at a join), and it ends
 * at rest on the floor against the wall. */
static void ramp_ball_rolls_at_two_thirds_g_sin(scene_file_t *file) {
    scene_t *scene = scene_file_get_scene(file);
    body_t *ball = named(file, "ball"), *ramp = named(file, "ramp");
    double dt = scene_file_get_timestep(file), r = body_get_round_radius(ball);
    double length = sqrt(73.0), sine = 3.0 / length;
    vector_t down = {8.0 / length, -3.0 / length}, start = body_get_centroid(ball);
    double deepest = 0.0, highest = 0.0;
    for (long step = 1; step <= lround(8.0 / dt); step++) {
        scene_tick(scene, dt);
        vector_t at = body_get_centroid(ball);
        double gap = INFINITY;
        for (size_t k = 0; k < body_get_segment_count(ramp); k++) {
            vector_t p1, p2;
            body_get_segment(ramp, k, &p1, &p2);
            vector_t d = vec_subtract(p2, p1);
            double t = fmax(0.0, fmin(1.0, vec_dot(vec_subtract(at, p1), d) / vec_dot(d, d)));
            gap = fmin(gap, vec_get_length(vec_subtract(at, vec_add(p1, vec_multiply(t, d)))) - r);
        }
        deepest = fmin(deepest, gap);
        highest = fmax(highest, gap);
        if (step == lround(1.0 / dt)) {
            double t = (double)step * dt;
            double travelled = vec_dot(vec_subtract(at, start), down);
            double v = vec_dot(body_get_velocity(ball), down);
            CHECK_RELATIVE(travelled, 9.8 * sine * t * t / 3.0, 0.01);
            CHECK_RELATIVE(body_get_angular_velocity(ball), -v / r, 0.01);
        }
    }
    CHECK(deepest > -0.005);
    CHECK(highest < 0.005);
    vector_t at = body_get_centroid(ball);
    CHECK_NEAR(at.y, r, 0.005);
    CHECK_NEAR(at.x, 10.0 - r, 0.01);
    CHECK(vec_get_length(body_get_velocity(ball)) < 0.05);
}

/* ---- The joint presets (their joints in the files; games: app/games/rigs.c) */

/* Starts the file's game, NULL when it names none; a failure when it names
 * one that does not start. */
static game_t *start_rig(scene_file_t *file) {
    char error[256];
    game_t *rig = game_start(file, error, sizeof error);
    if (rig == NULL && error[0] != '\0') {
        test_fail(__FILE__, __LINE__, "the game did not start: %s", error);
    }
    return rig;
}

/* One step of the file's timestep, then the rig with the input. */
static void rig_step(scene_file_t *file, game_t *rig, double move) {
    double dt = scene_file_get_timestep(file);
    scene_tick(scene_file_get_scene(file), dt);
    game_update(rig, (game_input_t){move, false}, dt);
}

/* The largest distance between a joint's two anchors (m), over every joint. */
static double widest_pin(scene_t *scene) {
    double widest = 0.0;
    for (size_t i = 0; i < scene_joints(scene); i++) {
        joint_t *joint = scene_get_joint(scene, i);
        double d = vec_get_length(vec_subtract(joint_get_anchor1(joint), joint_get_anchor2(joint)));
        widest = fmax(widest, d);
    }
    return widest;
}

/* The fastest point speed of a dynamic body: |v| + |w| times its extent. */
static double fastest(scene_t *scene) {
    double top = 0.0;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *body = scene_get_body(scene, i);
        if (isinf(body_get_mass(body))) continue;
        aabb_t box = body_get_bounds(body);
        double reach = vec_get_length(vec_subtract(box.max, box.min));
        top = fmax(top, vec_get_length(body_get_velocity(body)) +
                            fabs(body_get_angular_velocity(body)) * reach);
    }
    return top;
}

/* Five balls 1 mm apart on pins: the last rises to the striker's height. */
static void joint_cradle_swings_the_last_ball_to_the_striker_height(scene_file_t *file) {
    game_t *rig = start_rig(file);
    CHECK(scene_joints(scene_file_get_scene(file)) == 5);
    body_t *balls[5];
    for (int i = 0; i < 5; i++) {
        char name[16];
        snprintf(name, sizeof name, "ball%d", i + 1);
        balls[i] = named(file, name);
    }
    /* Apart at the start: 1 mm between the hanging balls. */
    for (int i = 1; i < 4; i++) {
        double d = vec_get_length(vec_subtract(body_get_centroid(balls[i + 1]),
                                               body_get_centroid(balls[i])));
        CHECK_NEAR(d - 1.0, 0.001, 1e-9);
    }
    double rest = body_get_centroid(balls[4]).y, release = body_get_centroid(balls[0]).y - rest;
    CHECK_NEAR(release, 2.0 - 2.0 * cos(M_PI / 6.0), 1e-9);
    /* The first strike: until the last ball, having risen, turns back. */
    double highest = rest;
    bool rose = false;
    for (int step = 0; step < 480 * 3; step++) {
        rig_step(file, rig, 0.0);
        double y = body_get_centroid(balls[4]).y;
        highest = fmax(highest, y);
        if (y > rest + 0.01) rose = true;
        if (rose && body_get_velocity(balls[4]).y < 0.0) break;
    }
    CHECK(rose);
    CHECK_NEAR((highest - rest) / release, 1.0, 0.01);
    printf("    joint_cradle: last ball rose to %.5f m of the striker's %.5f m\n", highest - rest,
           release);
    game_free(rig);
}

/* The bridge holds three boxes, every pin together. */
static void joint_bridge_holds_its_boxes(scene_file_t *file) {
    game_t *rig = start_rig(file);
    scene_t *scene = scene_file_get_scene(file);
    CHECK(scene_joints(scene) == 11);
    double widest = 0.0;
    for (int step = 0; step < 8 * 120; step++) {
        rig_step(file, rig, 0.0);
        if (step >= 2 * 120) widest = fmax(widest, widest_pin(scene)); /* the boxes landed */
    }
    CHECK(widest < 1e-3);
    for (int i = 1; i <= 3; i++) {
        char name[16];
        snprintf(name, sizeof name, "box%d", i);
        vector_t at = body_get_centroid(named(file, name));
        CHECK(at.y > -1.0 && fabs(at.x) < 4.5);
    }
    printf("    joint_bridge: widest pin %.2e m from 2 s to 8 s\n", widest);
    game_free(rig);
}

/* Kinetic energy and m g y of the scene's dynamic bodies. */
static double joint_energy(scene_t *scene, double g) {
    double e = 0.0;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        body_t *b = scene_get_body(scene, i);
        if (isinf(body_get_mass(b))) continue;
        e += body_get_kinetic_energy(b) + body_get_mass(b) * g * body_get_centroid(b).y;
    }
    return e;
}

static void joint_double_pendulum_keeps_its_energy(scene_file_t *file) {
    game_t *rig = start_rig(file);
    scene_t *scene = scene_file_get_scene(file);
    CHECK(scene_joints(scene) == 2);
    double start = joint_energy(scene, 9.8), worst = 0.0, mgl = 1.0 * 9.8 * 1.0;
    int steps = (int)lround(10.0 / scene_file_get_timestep(file));
    for (int step = 0; step < steps; step++) {
        rig_step(file, rig, 0.0);
        worst = fmax(worst, fabs(joint_energy(scene, 9.8) - start));
    }
    CHECK(worst < 0.01 * mgl);
    printf("    joint_double_pendulum: energy within %.2e J (%.3f%% of m g L) over 10 s\n", worst,
           100.0 * worst / mgl);
    game_free(rig);
}

static void joint_crank_follows_the_crank_slider_law(scene_file_t *file) {
    game_t *rig = start_rig(file);
    CHECK(scene_joints(scene_file_get_scene(file)) == 4);
    body_t *crank = named(file, "crank"), *slider = named(file, "slider");
    double r = 0.5, length = 2.0, worst = 0.0, speed_error = 0.0;
    for (int step = 0; step < 6 * 120; step++) {
        rig_step(file, rig, 0.0);
        double theta = body_get_rotation(crank), s = sin(theta);
        double law = r * cos(theta) + sqrt(length * length - r * r * s * s);
        worst = fmax(worst, fabs(body_get_centroid(slider).x - law));
        if (step >= 60) {
            speed_error = fmax(speed_error, fabs(body_get_angular_velocity(crank) - 2.0) / 2.0);
        }
    }
    CHECK(body_get_rotation(crank) > 11.0); /* nearly two turns in 6 s */
    CHECK(worst < 1e-3);
    CHECK(speed_error < 0.01);
    printf("    joint_crank: slider within %.2e m of the law, crank speed within %.2e\n", worst,
           speed_error);
    game_free(rig);
}

static void joint_ragdoll_rests_within_its_limits(scene_file_t *file) {
    game_t *rig = start_rig(file);
    scene_t *scene = scene_file_get_scene(file);
    CHECK(scene_joints(scene) == 9);
    double beyond = 0.0;
    for (int step = 0; step < 8 * 120; step++) {
        rig_step(file, rig, 0.0);
        if (step < 4 * 120) continue;
        for (size_t i = 0; i < scene_joints(scene); i++) {
            joint_t *joint = scene_get_joint(scene, i);
            joint_def_t def = joint_get_def(joint);
            double angle = joint_get_angle(joint);
            beyond = fmax(beyond, fmax(def.lower_angle - angle, angle - def.upper_angle));
        }
    }
    CHECK(fastest(scene) < 0.05);
    CHECK(widest_pin(scene) < 1e-3);
    CHECK(beyond < 0.5 * M_PI / 180.0);
    printf("    joint_ragdoll: %.3f degrees past a limit at most, widest pin %.2e m\n",
           beyond * 180.0 / M_PI, widest_pin(scene));
    game_free(rig);
}

static void joint_car_rolls_without_slipping(scene_file_t *file) {
    game_t *rig = start_rig(file);
    CHECK(rig != NULL && scene_joints(scene_file_get_scene(file)) == 2);
    body_t *chassis = named(file, "chassis"), *wheel = named(file, "rear_wheel");
    for (int step = 0; step < 3 * 120; step++) rig_step(file, rig, 1.0);
    double v = body_get_velocity(chassis).x, w = body_get_angular_velocity(wheel);
    CHECK_NEAR(w / -8.0, 1.0, 0.02);
    CHECK_NEAR(v / (-w * 0.4), 1.0, 0.02);
    CHECK(body_get_centroid(chassis).x < 5.0); /* still on the flat, before the bumps */
    /* On over both bumps (the second ends at x = 11), upright. */
    double tilt = 0.0;
    int steps = 0;
    while (body_get_centroid(chassis).x < 12.0 && steps < 6 * 120) {
        rig_step(file, rig, 1.0);
        tilt = fmax(tilt, fabs(body_get_rotation(chassis)));
        steps++;
    }
    CHECK(body_get_centroid(chassis).x >= 12.0);
    CHECK(tilt < 0.5);
    printf("    joint_car: %.3f m/s at %.3f rad/s (%.3f m/s rolling); over the bumps in %.2f s, "
           "tilted %.3f rad at most\n",
           v, w, -w * 0.4, steps / 120.0, tilt);
    game_free(rig);
}

/* ---- Every preset --------------------------------------------------------- */

typedef struct {
    const char *name;
    void (*promise)(scene_file_t *file);
    /* The file's `category` and `note`: the promise in words, which the
     * sandbox's samples browser shows and the function above checks. */
    const char *category, *note;
} preset_t;

static const preset_t PRESETS[] = {
    {"bounce", bounce_apexes_are_e_squared_of_the_drop, "Basics",
     "watch the apexes: a box of elasticity e rises back to e^2 of its 4 m drop"},
    {"friction", friction_holds_above_tan_30_and_slides_below, "Basics",
     "three boxes on a 30 degree ramp: friction 0.7 holds, 0.5 and 0.3 slide at g (sin - mu "
     "cos)"},
    {"pegs", pegs_keep_every_ball_on_the_board, "Games",
     "a ball a second falls through 11 rows of pegs and freezes where it lands, and none leaves "
     "the board"},
    {"breakout", breakout_has_50_bricks, "Games",
     "Left/Right or A/D move the paddle: clear 50 bricks before the ball gets past three times"},
    {"space_invaders", space_invaders_has_32_invaders, "Games",
     "Left/Right move, Space fires: shoot 32 invaders before their bombs take three lives"},
    {"newtons_cradle", newtons_cradle_passes_the_blow_along_and_repeats, "Collisions",
     "the blow runs along the row: the last ball leaves with 99% of the striker's speed, for two "
     "periods"},
    {"pyramid", pyramid_stands, "Stacking",
     "watch the top box: 55 boxes settle, the top moves less than 1 cm in 5 s"},
    {"card_house", card_house_stands, "Stacking",
     "14 cards held up by friction alone: each moves under 5 cm and turns under 0.05 rad in 5 s"},
    {"orbits", orbits_stay_round, "Integrators and accuracy",
     "four planets under symplectic Euler: radii within 10% and the energy within 0.1% for 20 s"},
    {"spring_chain", spring_chain_hangs_at_its_length, "Springs",
     "the chain swings down and hangs at rest within 30 s, each spring 1 + n 9.8/1000 m long"},
    {"stiff_spring", stiff_spring_stays_bounded, "Springs",
     "k = 10000 N/m at w dt = 0.83: bounded under symplectic Euler, while Shift+N (explicit "
     "Euler) flings it out"},
    {"mass_ratio_stack", mass_ratio_stack_holds, "Stability",
     "1000 kg on 1 kg on the floor: the stack stands, every box within 1 cm"},
    {"ramp", ramp_ball_rolls_at_two_thirds_g_sin, "Shapes",
     "a ball rolls down a ramp of chain segments at (2/3) g sin theta without slipping, over the "
     "joins"},
    {"tunnelling", tunnelling_stops_every_box_and_keeps_them_in_view, "Collisions",
     "boxes at 50 to 5000 m/s meet a 0.1 m wall: not one passes through"},
    {"joint_cradle", joint_cradle_swings_the_last_ball_to_the_striker_height, "Joints",
     "the last ball swings out to the striker's height (within 1%) on the first strike"},
    {"joint_bridge", joint_bridge_holds_its_boxes, "Joints",
     "the planks sag between the posts and hold three boxes, every pin within 1 mm once they "
     "land"},
    {"joint_double_pendulum", joint_double_pendulum_keeps_its_energy, "Joints",
     "chaotic, yet its energy in the plot stays within 1% of m g L of the start over 10 s"},
    {"joint_crank", joint_crank_follows_the_crank_slider_law, "Joints",
     "a motor turns the crank at 2 rad/s, the slider follows the exact crank-slider law within "
     "1 mm"},
    {"joint_ragdoll", joint_ragdoll_rests_within_its_limits, "Joints",
     "tumbles off the step and comes to rest with every joint within its limits (0.5 degrees)"},
    {"joint_car", joint_car_rolls_without_slipping, "Joints",
     "Left / Right drive it: on the flat it runs at 8 rad/s x 0.4 m = 3.2 m/s within 2%, no slip"},
};
#define PRESET_COUNT (sizeof PRESETS / sizeof PRESETS[0])

static void every_preset_file_is_listed_here(void) {
    DIR *directory = opendir("assets/scenes");
    CHECK(directory != NULL);
    if (directory == NULL) return;
    size_t files = 0;
    struct dirent *entry;
    while ((entry = readdir(directory)) != NULL) {
        size_t n = strlen(entry->d_name);
        if (n < 7 || strcmp(entry->d_name + n - 6, ".scene") != 0) continue;
        files++;
        bool listed = false;
        for (size_t i = 0; i < PRESET_COUNT; i++) {
            listed = listed || (strlen(PRESETS[i].name) == n - 6 &&
                                strncmp(PRESETS[i].name, entry->d_name, n - 6) == 0);
        }
        if (!listed) test_fail(__FILE__, __LINE__, "%s has no test", entry->d_name);
    }
    closedir(directory);
    CHECK(files == PRESET_COUNT);
}

static void every_preset_loads_runs_and_round_trips(void) {
    for (size_t i = 0; i < PRESET_COUNT; i++) {
        scene_file_t *file = load(PRESETS[i].name);
        if (file == NULL) continue;
        check_round_trip(file, PRESETS[i].name);
        run(file, 300);
        if (!all_finite(file)) test_fail(__FILE__, __LINE__, "%s: not finite", PRESETS[i].name);
        check_round_trip(file, PRESETS[i].name); /* mid-run: the state as it is */
        scene_file_free(file);
    }
    CHECK(test_no_leaks());
}

static void every_preset_does_what_it_says(void) {
    for (size_t i = 0; i < PRESET_COUNT; i++) {
        scene_file_t *file = load(PRESETS[i].name);
        if (file == NULL) continue;
        int failures = test_failures;
        if (strcmp(scene_file_get_category(file), PRESETS[i].category) != 0 ||
            strcmp(scene_file_get_note(file), PRESETS[i].note) != 0) {
            test_fail(__FILE__, __LINE__, "%s: category \"%s\", note \"%s\": not what is checked",
                      PRESETS[i].name, scene_file_get_category(file), scene_file_get_note(file));
        }
        PRESETS[i].promise(file);
        if (!all_finite(file)) test_fail(__FILE__, __LINE__, "not finite");
        if (test_failures != failures) printf("    (in %s)\n", PRESETS[i].name);
        scene_file_free(file);
    }
}

/* The ragdoll comes to rest on the floor under every integrator, not only
 * the symplectic Euler its file chooses: a pin's velocity sweep closes the
 * gap the step would end with, and under a scheme that moves bodies by
 * their start velocity too (weight 1/2: seed, Verlet, RK4, symplectic4)
 * that made the end velocity the start one mirrored; a head lying on the
 * floor kept swinging at 1.2 m/s, step after step, for good. */
static void joint_ragdoll_rests_under_every_integrator(void) {
    for (int integrator = 0; integrator < INTEGRATOR_COUNT; integrator++) {
        scene_file_t *file = load("joint_ragdoll");
        if (file == NULL) return;
        scene_t *scene = scene_file_get_scene(file);
        scene_set_integrator(scene, (integrator_t)integrator);
        scene_set_sleeping(scene, false);
        double dt = scene_file_get_timestep(file);
        for (int step = 0; step < (int)(20.0 / dt); step++) scene_tick(scene, dt);
        printf("    %s: fastest %.2e m/s after 20 s\n", integrator_get_name((integrator_t)integrator),
               fastest(scene));
        CHECK(fastest(scene) < 1e-3);
        scene_file_free(file);
    }
}

/* Nor only at the file's launch speed: walked off the platform at 2.3 to
 * 2.7 m/s it lands in other poses and comes to rest in each. Frictionless
 * joints left a lower arm hanging over the torso swinging for good (0.4 m/s
 * after 20 s at 2.55 and 2.6 m/s); the file's joints have friction. */
static void joint_ragdoll_rests_from_any_launch_speed(void) {
    const double speeds[] = {2.3, 2.4, 2.45, 2.55, 2.6, 2.7};
    for (size_t k = 0; k < sizeof speeds / sizeof speeds[0]; k++) {
        scene_file_t *file = load("joint_ragdoll");
        if (file == NULL) return;
        scene_t *scene = scene_file_get_scene(file);
        scene_set_sleeping(scene, false);
        for (size_t i = 0; i < scene_bodies(scene); i++) {
            body_t *body = scene_get_body(scene, i);
            if (isfinite(body_get_mass(body))) body_set_velocity(body, (vector_t){speeds[k], 0.0});
        }
        double dt = scene_file_get_timestep(file);
        for (int step = 0; step < (int)(20.0 / dt); step++) scene_tick(scene, dt);
        printf("    %.2f m/s: fastest %.2e m/s after 20 s\n", speeds[k], fastest(scene));
        CHECK(fastest(scene) < 1e-3);
        scene_file_free(file);
    }
}

/* ---- Saving mid-run and going on ------------------------------------------ */

static bool same_bits(double a, double b) {
    return memcmp(&a, &b, sizeof a) == 0;
}

/* The first body (counting those not marked removed) whose pose, velocity or
 * sleep differs in a bit between the two scenes, or -1; -2 when they hold
 * different numbers of bodies. */
static long first_differing_body(scene_t *x, scene_t *y) {
    size_t i = 0, j = 0;
    long compared = 0;
    for (;; i++, j++, compared++) {
        while (i < scene_bodies(x) && body_is_removed(scene_get_body(x, i))) i++;
        while (j < scene_bodies(y) && body_is_removed(scene_get_body(y, j))) j++;
        if (i == scene_bodies(x) || j == scene_bodies(y)) break;
        body_t *a = scene_get_body(x, i), *b = scene_get_body(y, j);
        vector_t p = body_get_centroid(a), q = body_get_centroid(b);
        vector_t u = body_get_velocity(a), v = body_get_velocity(b);
        if (!same_bits(p.x, q.x) || !same_bits(p.y, q.y) ||
            !same_bits(body_get_rotation(a), body_get_rotation(b)) || !same_bits(u.x, v.x) ||
            !same_bits(u.y, v.y) ||
            !same_bits(body_get_angular_velocity(a), body_get_angular_velocity(b)) ||
            body_is_sleeping(a) != body_is_sleeping(b))
            return compared;
    }
    return i == scene_bodies(x) && j == scene_bodies(y) ? -1 : -2;
}

/* The length of the next step: the file's timestep, or, given a seed, a
 * length drawn uniformly from half the timestep to the whole (the
 * benchmark scenes' generator, docs/bench.md), as a game that steps with its
 * frame time does. */
static double next_dt(scene_file_t *file, uint32_t *seed) {
    double timestep = scene_file_get_timestep(file);
    if (seed == NULL) return timestep;
    *seed = (uint32_t)((1103515245ull * *seed + 12345u) % 2147483648u);
    return timestep * (0.5 + 0.5 * (*seed / 2147483648.0));
}

/* Runs `steps` steps (of next_dt), saves, loads the text into a new file,
 * and runs both `more` steps of the same lengths: every body equal to the
 * bit after every step. Returns the number of bodies asleep at the save. */
static int check_continuation(scene_file_t *file, const char *name, int steps, int more,
                              uint32_t *seed) {
    scene_t *scene = scene_file_get_scene(file);
    for (int i = 0; i < steps; i++) scene_tick(scene, next_dt(file, seed));
    int asleep = 0;
    for (size_t i = 0; i < scene_bodies(scene); i++) {
        asleep += body_is_sleeping(scene_get_body(scene, i));
    }
    size_t length = 0;
    scene_file_error_t error;
    char *text = scene_file_write(file, &length, &error);
    scene_file_t *again = text != NULL ? scene_file_parse(text, length, name, &error) : NULL;
    free(text);
    if (again == NULL) {
        test_fail(__FILE__, __LINE__, "%s: %s", name, error.message);
        return asleep;
    }
    scene_t *copy = scene_file_get_scene(again);
    long differing = first_differing_body(scene, copy);
    if (differing != -1) {
        test_fail(__FILE__, __LINE__, "%s: body %ld differs at once", name, differing);
    }
    for (int step = 0; step < more && differing == -1; step++) {
        double dt = next_dt(file, seed);
        scene_tick(scene, dt);
        scene_tick(copy, dt);
        differing = first_differing_body(scene, copy);
        if (differing != -1) {
            test_fail(__FILE__, __LINE__,
                      "%s saved after %d steps: body %ld differs %d steps later", name, steps,
                      differing, step + 1);
        }
    }
    scene_file_free(again);
    return asleep;
}

/* Calls check(file, name) on a fresh load of every preset (every file in
 * assets/scenes/). */
static void for_every_preset(void (*check)(const char *name)) {
    DIR *directory = opendir("assets/scenes");
    CHECK(directory != NULL);
    if (directory == NULL) return;
    struct dirent *entry;
    while ((entry = readdir(directory)) != NULL) {
        size_t n = strlen(entry->d_name);
        if (n < 7 || strcmp(entry->d_name + n - 6, ".scene") != 0) continue;
        char name[256];
        snprintf(name, sizeof name, "%.*s", (int)(n - 6), entry->d_name);
        check(name);
    }
    closedir(directory);
}

/* Saved after 0.5 s (contacts warm, bodies settling) and after 4 s (the
 * pyramid and the card house asleep). */
static void check_fixed_steps(const char *name) {
    for (int steps = 60; steps <= 480; steps += 420) {
        scene_file_t *file = load(name);
        if (file == NULL) continue;
        int asleep = check_continuation(file, name, steps, 480, NULL);
        bool resting = strcmp(name, "pyramid") == 0 || strcmp(name, "card_house") == 0;
        if (resting && steps == 480) CHECK(asleep > 0);
        scene_file_free(file);
    }
}

/* Every preset, saved and loaded into a new scene, goes on for 4 s as the
 * scene that was not saved does, to the bit: sleep, timers, contact memory
 * and filters are in the file. */
static void every_preset_continues_bit_for_bit_after_a_save(void) {
    for_every_preset(check_fixed_steps);
}

/* Saved after 20 and 50 steps of lengths drawn from half the timestep to
 * the whole, while contacts are warm and before the stacks sleep. */
static void check_varying_steps(const char *name) {
    for (int steps = 20; steps <= 50; steps += 30) {
        scene_file_t *file = load(name);
        if (file == NULL) continue;
        uint32_t seed = 2024u + (uint32_t)steps;
        check_continuation(file, name, steps, 300, &seed);
        scene_file_free(file);
    }
}

/* And under a varying step, which rescales the warm start by the lengths of
 * the last two steps from the contacts of both: those are in the file too.
 * Before they were, every preset with contacts differed within a step of
 * the load. */
static void every_preset_continues_bit_for_bit_under_varying_steps(void) {
    for_every_preset(check_varying_steps);
}

/* The sandbox's default scene (app/sandbox_scene.c) with a pile of 36
 * polygons of the file's in its container, saved while part of it settles. */
static const char SANDBOX_PILE[] =
    "gravity 0 -10\n"
    "contacts on\n"
    "timestep 1/120\n"
    "body floor      { box 30 1; static; position 0 -0.5;   tag floor }\n"
    "body left_wall  { box 1 30; static; position -14.5 15; tag left_wall }\n"
    "body right_wall { box 1 30; static; position 14.5 15;  tag right_wall }\n"
    "body tri { regular 3 0.6; position -9 1; angle 0.3; repeat 6 1 3.1 0 }\n"
    "body hex { regular 6 0.5; position -8 3; elasticity 0.3; repeat 6 1 3.2 0 }\n"
    "body box { box 1 0.6; position -9.5 5; angle 0.2; friction 0.3; repeat 6 1 3.3 0 }\n"
    "body pent { regular 5 0.55; position -8.5 7; density 2; repeat 6 1 3.0 0 }\n"
    "body oct { regular 8 0.45; position -9 9; velocity 1 0; repeat 6 1 3.1 0 }\n"
    "body sq { box 0.7 0.7; position -8 11; spin 2; filter 1 0xffffffff 0; repeat 6 1 3.2 0 }\n";

/* And twelve polygons dropped as the sandbox drops them (sandbox_drop: made
 * around the origin, moved, added), which the file did not make. */
static void drop_as_the_sandbox_does(scene_file_t *file) {
    for (int i = 0; i < 12; i++) {
        list_t *shape = polygon_make_regular((size_t)(3 + i % 6), 0.4, VEC_ZERO, 0.1 * i);
        body_t *body = body_init(shape, 0.5 + 0.1 * i, (rgb_color_t){0.9, 0.4, 0.2});
        body_set_centroid(body, (vector_t){-9.0 + 1.6 * i, 13.0 + 0.3 * (i % 3)});
        body_set_velocity(body, (vector_t){0.5 - 0.1 * i, 0.0});
        body_set_elasticity(body, 0.1 * (i % 4));
        scene_add_body(scene_file_get_scene(file), body);
    }
}

static void a_sandbox_pile_continues_bit_for_bit_after_a_save(void) {
    scene_file_error_t error;
    for (int steps = 120; steps <= 600; steps += 240) {
        scene_file_t *file =
            scene_file_parse(SANDBOX_PILE, strlen(SANDBOX_PILE), "sandbox", &error);
        if (file == NULL) {
            test_fail(__FILE__, __LINE__, "%s", error.message);
            return;
        }
        drop_as_the_sandbox_does(file);
        check_continuation(file, "sandbox", steps, 480, NULL);
        scene_file_free(file);
    }
}

/* Saved after 90 steps of lengths drawn from half the timestep to the
 * whole. */
static void a_sandbox_pile_continues_bit_for_bit_under_varying_steps(void) {
    scene_file_error_t error;
    scene_file_t *file = scene_file_parse(SANDBOX_PILE, strlen(SANDBOX_PILE), "sandbox", &error);
    if (file == NULL) {
        test_fail(__FILE__, __LINE__, "%s", error.message);
        return;
    }
    drop_as_the_sandbox_does(file);
    uint32_t seed = 77u;
    check_continuation(file, "sandbox", 90, 480, &seed);
    scene_file_free(file);
}

TEST_SUITE(presets, TEST_CASE(every_preset_file_is_listed_here),
           TEST_CASE(every_preset_loads_runs_and_round_trips),
           TEST_CASE(every_preset_does_what_it_says),
           TEST_CASE(joint_ragdoll_rests_under_every_integrator),
           TEST_CASE(joint_ragdoll_rests_from_any_launch_speed),
           TEST_CASE(every_preset_continues_bit_for_bit_after_a_save),
           TEST_CASE(every_preset_continues_bit_for_bit_under_varying_steps),
           TEST_CASE(a_sandbox_pile_continues_bit_for_bit_after_a_save),
           TEST_CASE(a_sandbox_pile_continues_bit_for_bit_under_varying_steps));
