// OpenGL 3.3 core entry points. Linux's libGL (glvnd) exports every core function, so the prototypes are enough:
// no loader library is needed.
#pragma once
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
