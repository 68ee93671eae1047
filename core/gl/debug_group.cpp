#include "core/gl/debug_group.hpp"

#include "core/gl/gl.hpp"

namespace pbr {

namespace {

// Longer messages are an error (GL_MAX_DEBUG_MESSAGE_LENGTH); cut them instead.
std::string fitted(const std::string& message) {
  GLint maxLength = 0;
  glGetIntegerv(GL_MAX_DEBUG_MESSAGE_LENGTH, &maxLength);
  return message.substr(0, maxLength > 0 ? static_cast<size_t>(maxLength) - 1 : 0);
}

}  // namespace

DebugGroup::DebugGroup(const std::string& name) {
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, fitted(name).c_str());
}

DebugGroup::~DebugGroup() { glPopDebugGroup(); }

void insertDebugMarker(const std::string& message) {
  glDebugMessageInsert(GL_DEBUG_SOURCE_APPLICATION, GL_DEBUG_TYPE_MARKER, 0, GL_DEBUG_SEVERITY_NOTIFICATION, -1,
                       fitted(message).c_str());
}

}  // namespace pbr
