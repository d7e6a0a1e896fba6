/* The seed's bare header name, kept so that code written against the seed
 * API ("body.h" with -Iengine/include) compiles unchanged; new code includes
 * <jostle/body.h>. docs/api.md, "Headers and versions". */
#include "jostle/body.h"
