#pragma once
#include "core/gl/gl.hpp"
#include "core/scene/shading_model.hpp"

namespace pbr {

// The internal format of an HDR radiance target of `format` (GL_RGBA16F, ...), and the format of a target of
// `internalFormat`: Rgba16f for a format no HdrFormat names.
GLenum glInternalFormat(HdrFormat format);
HdrFormat hdrFormatOf(GLenum internalFormat);

}  // namespace pbr
