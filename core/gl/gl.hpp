#pragma once
// The one place that pulls in the generated OpenGL 4.5 core loader.
#include <glad/gl.h>
