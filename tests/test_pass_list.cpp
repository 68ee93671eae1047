// The check that refuses a declared pass list reading a target before any pass wrote it, and the list's description.
#include <doctest/doctest.h>

#include <stdexcept>
#include <string>

#include "renderer/pass_list.hpp"

using namespace pbr;
using R = FrameResource;

TEST_CASE("pass list: a pass reading a target no earlier pass wrote is refused by name") {
  const PassList ok = {{"a", {R::Geometry, R::Camera}, {R::GBuffer}, [] {}},
                       {"b", {R::GBuffer, R::Lights, R::Environment}, {R::Radiance}, [] {}}};
  CHECK_NOTHROW(checkPassList(ok));
  const PassList early = {{"post", {R::Radiance}, {R::Display}, [] {}},
                          {"lighting", {R::GBuffer}, {R::Radiance}, [] {}}};
  CHECK_THROWS_WITH_AS(checkPassList(early), "pass list: 'post' reads radiance, which no earlier pass writes",
                       std::logic_error);
  CHECK(describePassList(ok) ==
        "a (reads geometry, camera; writes gbuffer) -> b (reads gbuffer, lights, environment; writes radiance)");
}
