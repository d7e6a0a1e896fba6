/* The seed's bare header name, kept so that code written against the seed
 * API ("scene.h" with -Iengine/include) compiles unchanged; new code includes
 * <jostle/scene.h>. docs/api.md, "Headers and versions". */
#include "jostle/scene.h"
