#include "lighting/cluster_config.hpp"

#include <stdexcept>

namespace pbr {

const char* toString(AssignShape shape) {
  switch (shape) {
    case AssignShape::Automatic: return "auto";
    case AssignShape::Invocation: return "invocation";
    case AssignShape::Workgroup: return "workgroup";
    case AssignShape::Cluster: return "cluster";
  }
  return "?";
}

AssignShape parseAssignShape(const std::string& text) {
  for (const AssignShape s : kAssignShapes) {
    if (text == toString(s)) return s;
  }
  throw std::invalid_argument("unknown assignment shape '" + text +
                              "' (expected auto, invocation, workgroup or cluster)");
}

}  // namespace pbr
