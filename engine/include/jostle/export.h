#ifndef JOSTLE_EXPORT_H
#define JOSTLE_EXPORT_H

/* What the shared library exports: the declarations between JOSTLE_API_BEGIN
 * and JOSTLE_API_END in the public headers. The library is built with hidden
 * visibility, so its internal functions do not clash with a program's own. */
#if defined(__GNUC__)
#define JOSTLE_API_BEGIN _Pragma("GCC visibility push(default)")
#define JOSTLE_API_END _Pragma("GCC visibility pop")
#else
#define JOSTLE_API_BEGIN
#define JOSTLE_API_END
#endif

#endif // #ifndef JOSTLE_EXPORT_H
