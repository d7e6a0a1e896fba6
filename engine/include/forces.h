/* The seed's bare header name, kept so that code written against the seed
 * API ("forces.h" with -Iengine/include) compiles unchanged; new code includes
 * <jostle/forces.h>. docs/api.md, "Headers and versions". */
#include "jostle/forces.h"
