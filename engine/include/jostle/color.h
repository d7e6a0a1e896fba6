#ifndef COLOR_H
#define COLOR_H
#include "export.h"

JOSTLE_API_BEGIN

/* A colour with red, green and blue components, each in [0, 1]. The engine
 * stores it for its callers (the sandbox draws it) and never reads it. */
typedef struct {
    double r;
    double g;
    double b;
} rgb_color_t;

JOSTLE_API_END

#endif // #ifndef COLOR_H
