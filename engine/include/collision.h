/* The seed's bare header name, kept so that code written against the seed
 * API ("collision.h" with -Iengine/include) compiles unchanged; new code includes
 * <jostle/collision.h>. docs/api.md, "Headers and versions". */
#include "jostle/collision.h"
