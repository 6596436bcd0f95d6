#pragma once
// OpenGL with prototypes: libOSMesa exports every GL 3.3 entry point itself,
// so no loader is needed.
#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
