#pragma once
#include "core/gl/gl.hpp"
#include "core/scene/shading_model.hpp"

namespace pbr {

// The internal format of an HDR radiance target of `format` (GL_RGBA16F, ...).
GLenum glInternalFormat(HdrFormat format);

}  // namespace pbr
