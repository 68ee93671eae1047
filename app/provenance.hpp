#pragma once
#include <string>
#include <utility>
#include <vector>

#include "core/io/context_info.hpp"
#include "core/io/frame_timing.hpp"

namespace pbr {

// Where, when and how a measurement was taken, as ordered key/value pairs: the leading comment lines of a CSV,
// an object in JSON, metadata in a trace. Keys are lower_snake_case; values are never empty ("unknown").
struct Provenance {
  std::vector<std::pair<std::string, std::string>> entries;
  void set(const std::string& key, const std::string& value);  // replaces a key's value or appends the key
  std::string get(const std::string& key) const;                // "" when absent
};

// The GL strings, EGL platform and timing mode (with what its times mean on this renderer), CPU model and
// core count, build type, compiler, git commit, its date and whether the tree had uncommitted changes, the run
// date (UTC), the load average, the process's scheduling priority and its command line.
Provenance collectProvenance(const ContextInfo& gl, TimingMode timing);

// "pbr 0.2.0 (commit 1234abcd..., 2026-01-01T00:00:00Z, uncommitted changes: no; Release, GNU 12.2.0)".
std::string versionLine();

// The process's command line as typed (from /proc/self/cmdline), arguments quoted for a POSIX shell where needed.
std::string processCommandLine();
// The current time in UTC as ISO 8601, e.g. "2024-05-01T12:00:00Z".
std::string utcTimestamp();
// CPUs this process may run on: fewer than the machine has in a container or under taskset, and what a CPU
// rasterizer's threads actually get.
unsigned availableCpus();
// The 1-, 5- and 15-minute load averages: a benchmark sharing its CPUs with other work says so here.
std::string loadAverage();

}  // namespace pbr
