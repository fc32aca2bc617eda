/* Calling-convention macros of the HD API. The SDK's Linux header declares them stdcall (which
 * x86-64 ignores) or empty depending on its version; code written against either compiles when
 * they are empty, so this header leaves any existing definition alone and otherwise defines
 * them as nothing. */
#ifndef COSMEMS_FAKE_HD_EXPORT_H
#define COSMEMS_FAKE_HD_EXPORT_H

#ifndef HDAPI
#define HDAPI
#endif
#ifndef HDAPIENTRY
#define HDAPIENTRY
#endif
#ifndef HDCALLBACK
#define HDCALLBACK
#endif

#endif
