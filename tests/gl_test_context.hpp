#pragma once
#include <doctest/doctest.h>

#include "core/gl/context.hpp"

namespace pbr::test {

// The process-wide headless context for GPU tests, made on first use. Null when none can be made.
Context* glContext();

// True when a context is current. Without one a GPU test fails, unless PBR_ALLOW_NO_GL=1 lets it pass empty.
bool requireGl();

}  // namespace pbr::test

// Opens a GPU test case: returns early (failed, or allowed by PBR_ALLOW_NO_GL=1) when no context exists.
#define PBR_REQUIRE_GL()              \
  do {                                \
    if (!::pbr::test::requireGl()) return; \
  } while (0)
