#pragma once

namespace pbr {

// Where the buffers and images a glTF file references may live. By default only in the model's own folder and
// below it: a model downloaded from elsewhere must not make the renderer read (and show in a texture, or report
// the size of) /etc/passwd or ~/.ssh through "../../" or an absolute URI. `pbr ... --allow-outside-uris` lifts
// this for models that share assets with their neighbours. docs/robustness.md describes the policy.
//
// `strict` (`--strict`) refuses what widely used viewers read anyway (a bufferView's byteStride of 0, read as
// tightly packed), where by default it is read as they read it with one warning line; docs/robustness.md lists
// which deviations are tolerated.
struct UriPolicy {
  bool allowOutside = false;
  bool strict = false;
};

}  // namespace pbr
