#pragma once

// OpenGL 3.3 core entry points, declared by the system's headers and resolved by libGL (Mesa,
// or a vendor's through GLVND), so the viewer needs no loader of its own.
#ifndef GL_GLEXT_PROTOTYPES
#define GL_GLEXT_PROTOTYPES 1
#endif
#include <GL/gl.h>
#include <GL/glext.h>
