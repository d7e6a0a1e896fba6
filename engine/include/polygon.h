/* The seed's bare header name, kept so that code written against the seed
 * API ("polygon.h" with -Iengine/include) compiles unchanged; new code includes
 * <jostle/polygon.h>. docs/api.md, "Headers and versions". */
#include "jostle/polygon.h"
