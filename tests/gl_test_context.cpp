#include "tests/gl_test_context.hpp"

#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

namespace pbr::test {

namespace {
std::string g_failure;
}

Context* glContext() {
  static std::unique_ptr<Context> context = [] {
    try {
      return createHeadlessContext(EglPlatform::Auto);
    } catch (const ContextError& e) {
      g_failure = e.what();
      return std::unique_ptr<Context>();
    }
  }();
  return context.get();
}

bool requireGl() {
  if (glContext()) return true;
  const char* allow = std::getenv("PBR_ALLOW_NO_GL");
  if (allow && std::strcmp(allow, "1") == 0) {
    MESSAGE("no OpenGL context (" << g_failure << "); allowed by PBR_ALLOW_NO_GL=1");
    return false;
  }
  FAIL("no OpenGL 4.5 context: " << g_failure << " (set PBR_ALLOW_NO_GL=1 to allow this)");
  return false;
}

}  // namespace pbr::test
