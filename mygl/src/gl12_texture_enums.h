#pragma once
// The GL 1.2 texture and pixel enums course programs use; the loader is generated for GL 1.1 only.
#include <glad/gl.h>

#ifndef GL_CLAMP_TO_EDGE
#define GL_CLAMP_TO_EDGE 0x812F
#endif
#ifndef GL_BGR
#define GL_BGR 0x80E0
#define GL_BGRA 0x80E1
#endif
