/* The seed's bare header name, kept so that code written against the seed
 * API ("engine.h" with -Iengine/include) compiles unchanged; new code includes
 * <jostle/jostle.h>. docs/api.md, "Headers and versions". */
#include "jostle/jostle.h"
