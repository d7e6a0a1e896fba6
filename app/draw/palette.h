#ifndef SANDBOX_PALETTE_H
#define SANDBOX_PALETTE_H

/*
 * Every colour the sandbox draws, as 8-bit RGB. Shared with the smoke tests
 * (tests/app_smoke.c), which look for these colours in screenshots, so the
 * body colours and the overlay colours are kept far apart: no body colour is
 * near yellow (axes) or magenta (impulses).
 */

typedef struct {
    unsigned char r, g, b;
} palette_rgb_t;

#define PALETTE_BODY_COUNT 6
static const palette_rgb_t PALETTE_BODIES[PALETTE_BODY_COUNT] = {
    {66, 135, 245},  /* blue */
    {242, 140, 40},  /* orange */
    {38, 190, 160},  /* teal */
    {150, 110, 230}, /* violet */
    {225, 75, 75},   /* red */
    {120, 200, 70},  /* green */
};

static const palette_rgb_t PALETTE_BACKGROUND = {22, 24, 30};
static const palette_rgb_t PALETTE_GRID = {32, 35, 43};
static const palette_rgb_t PALETTE_STATIC = {92, 98, 112};

/* Overlays. */
static const palette_rgb_t PALETTE_AXIS = {255, 235, 0};      /* yellow */
static const palette_rgb_t PALETTE_IMPULSE = {255, 0, 220};   /* magenta */
static const palette_rgb_t PALETTE_POINT = {0, 240, 255};     /* cyan */
static const palette_rgb_t PALETTE_VELOCITY = {160, 255, 160};/* pale green */
static const palette_rgb_t PALETTE_CENTROID = {255, 255, 255};/* white */
static const palette_rgb_t PALETTE_BOUNDS = {130, 130, 150};  /* grey-blue */
/* The sleeping tint's colour in the OVERLAYS legend (the tint itself darkens
 * each body's own colour: palette_sleeping). */
static const palette_rgb_t PALETTE_SLEEPING = {160, 170, 240}; /* lavender */

/* A sleeping body's fill: its colour 55% of the way to the background, so
 * that the bodies that take part in the step stand out. */
static inline palette_rgb_t palette_sleeping(palette_rgb_t c) {
    palette_rgb_t b = PALETTE_BACKGROUND;
    return (palette_rgb_t){(unsigned char)(c.r + (b.r - c.r) * 55 / 100),
                           (unsigned char)(c.g + (b.g - c.g) * 55 / 100),
                           (unsigned char)(c.b + (b.b - c.b) * 55 / 100)};
}

/* The user interface. */
static const palette_rgb_t PALETTE_TEXT = {230, 232, 238};
static const palette_rgb_t PALETTE_TEXT_DIM = {140, 146, 160};
static const palette_rgb_t PALETTE_PANEL = {10, 11, 14};
static const palette_rgb_t PALETTE_ACCENT = {255, 200, 60};
static const palette_rgb_t PALETTE_WARNING = {255, 120, 100}; /* a refused drop */
static const palette_rgb_t PALETTE_WON = {130, 230, 130};     /* a game won */
/* A scene file's springs, drawn between the centroids they join. */
static const palette_rgb_t PALETTE_SPRING = {200, 200, 210};
static const palette_rgb_t PALETTE_OFF = {96, 101, 114};      /* an overlay that is off */
static const palette_rgb_t PALETTE_RULE = {44, 48, 58};       /* lines between panels */
static const palette_rgb_t PALETTE_GRAB = {255, 255, 255};
/* Joints (draw/joint_draw.c): the link and anchors, a limit's bounds, a
 * motor's arrow; the joint under the cursor in PALETTE_ACCENT. */
static const palette_rgb_t PALETTE_JOINT = {120, 225, 205};
static const palette_rgb_t PALETTE_JOINT_LIMIT = {235, 120, 90};
static const palette_rgb_t PALETTE_JOINT_MOTOR = {255, 220, 90};
/* The step's stages in the STEP panel's chart, in scene_stage_t's order:
 * forces, broadphase, narrowphase, prepare, solver, shock, position,
 * integrate, sleep, removal. */
#define PALETTE_STAGE_COUNT 10
static const palette_rgb_t PALETTE_STAGES[PALETTE_STAGE_COUNT] = {
    {120, 200, 70}, {66, 135, 245},  {38, 190, 160}, {250, 190, 130}, {242, 140, 40},
    {225, 75, 75},  {150, 110, 230}, {235, 210, 90}, {160, 170, 240}, {175, 175, 180},
};
/* The explosion tool's reach and a blast's ring. */
static const palette_rgb_t PALETTE_BLAST = {255, 150, 40};
/* The ring round the cursor inside which every axis and impulse is drawn. */
static const palette_rgb_t PALETTE_FOCUS = {120, 126, 140};
/* The INTEGRATOR panel's strip chart: the drift, its zero line, the marks
 * where the energy reference was taken again. */
static const palette_rgb_t PALETTE_DRIFT = {110, 215, 255};
static const palette_rgb_t PALETTE_CHART_ZERO = {90, 96, 110};
static const palette_rgb_t PALETTE_CHART_MARK = {150, 110, 60};

#endif
