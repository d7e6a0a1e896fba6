/* The seed's bare header name, kept so that code written against the seed
 * API ("list.h" with -Iengine/include) compiles unchanged; new code includes
 * <jostle/list.h>. docs/api.md, "Headers and versions". */
#include "jostle/list.h"
