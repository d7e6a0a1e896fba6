/* The seed's bare header name, kept so that code written against the seed
 * API ("color.h" with -Iengine/include) compiles unchanged; new code includes
 * <jostle/color.h>. docs/api.md, "Headers and versions". */
#include "jostle/color.h"
