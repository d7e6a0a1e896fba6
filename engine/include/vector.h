/* The seed's bare header name, kept so that code written against the seed
 * API ("vector.h" with -Iengine/include) compiles unchanged; new code includes
 * <jostle/vector.h>. docs/api.md, "Headers and versions". */
#include "jostle/vector.h"
