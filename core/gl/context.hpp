#pragma once
#include <memory>
#include <stdexcept>
#include <string>

#include "core/io/context_info.hpp"

namespace pbr {

class ContextError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// An OpenGL 4.5 core context, current on the calling thread once made.
class Context {
 public:
  virtual ~Context() = default;
  Context(const Context&) = delete;
  Context& operator=(const Context&) = delete;

  virtual void makeCurrent() = 0;
  virtual void swapBuffers() = 0;
  const ContextInfo& info() const { return info_; }

 protected:
  Context() = default;
  // Loads GL entry points, checks the version and fills info(); called by subclasses once current.
  void initializeGl(const std::string& platform, void* (*getProc)(const char*), bool debug);

 private:
  ContextInfo info_;
};

// Whether the current context offers the GL extension `name`.
bool glHasExtension(const char* name);

// Debug output (KHR_debug to stderr) is on in debug builds, or when PBR_GL_DEBUG=1.
bool glDebugRequested();

// Throws ContextError with a one-line reason when no OpenGL 4.5 core context can be made.
std::unique_ptr<Context> createHeadlessContext(EglPlatform platform = EglPlatform::Auto);

}  // namespace pbr
