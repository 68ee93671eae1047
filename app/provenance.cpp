#include "app/provenance.hpp"

#include <sched.h>
#include <sys/resource.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iterator>
#include <sstream>
#include <thread>

#include "pbr_build_info.hpp"

namespace pbr {

namespace {

std::string orUnknown(const std::string& s) { return s.empty() ? "unknown" : s; }

std::string cpuModel() {
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("model name", 0) != 0) continue;
    const size_t colon = line.find(':');
    if (colon == std::string::npos) continue;
    const size_t start = line.find_first_not_of(" \t", colon + 1);
    return start == std::string::npos ? "unknown" : line.substr(start);
  }
  return "unknown";
}

std::string shellQuoted(const std::string& arg) {
  const bool plain = !arg.empty() && std::all_of(arg.begin(), arg.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || std::string("_./=:,@%+-").find(c) != std::string::npos;
  });
  if (plain) return arg;
  std::string out = "'";
  for (char c : arg) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// A benchmark raised above other work on a shared machine (nice, chrt) says so.
std::string scheduling() {
  const int policy = sched_getscheduler(0);
  sched_param param{};
  sched_getparam(0, &param);
  errno = 0;
  const int niceness = getpriority(PRIO_PROCESS, 0);
  std::string out = policy == SCHED_FIFO ? "SCHED_FIFO" : policy == SCHED_RR ? "SCHED_RR" : "SCHED_OTHER";
  if (policy == SCHED_FIFO || policy == SCHED_RR) out += " priority " + std::to_string(param.sched_priority);
  if (errno == 0) out += ", nice " + std::to_string(niceness);
  std::ifstream autogroup("/proc/self/autogroup");  // e.g. "/autogroup-7 nice 0"
  std::string group, word, value;
  if (autogroup >> group >> word >> value) out += ", autogroup nice " + value;
  return out;
}

std::string timingNote(const ContextInfo& gl, TimingMode timing) {
  if (isSoftwareRenderer(gl.renderer)) {
    return "llvmpipe is a CPU rasterizer: these are CPU-rasterizer times on this machine's cores, not GPU times";
  }
  return timing == TimingMode::GpuQueries ? "GPU timestamps around each pass"
                                          : "glFinish around each pass: includes submission and idle gaps";
}

}  // namespace

void Provenance::set(const std::string& key, const std::string& value) {
  for (auto& [k, v] : entries) {
    if (k == key) {
      v = orUnknown(value);
      return;
    }
  }
  entries.emplace_back(key, orUnknown(value));
}

std::string Provenance::get(const std::string& key) const {
  for (const auto& [k, v] : entries) {
    if (k == key) return v;
  }
  return "";
}

std::string processCommandLine() {
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  const std::string raw{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  std::string out;
  std::istringstream args(raw);
  for (std::string arg; std::getline(args, arg, '\0');) out += (out.empty() ? "" : " ") + shellQuoted(arg);
  return orUnknown(out);
}

unsigned availableCpus() {
  cpu_set_t set;
  CPU_ZERO(&set);
  if (sched_getaffinity(0, sizeof(set), &set) == 0) return static_cast<unsigned>(CPU_COUNT(&set));
  return std::thread::hardware_concurrency();
}

std::string utcTimestamp() {
  const std::time_t now = std::time(nullptr);
  std::tm utc{};
  gmtime_r(&now, &utc);
  char text[32];
  std::strftime(text, sizeof(text), "%Y-%m-%dT%H:%M:%SZ", &utc);
  return text;
}

std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  std::string one, five, fifteen;
  if (!(in >> one >> five >> fifteen)) return "unknown";
  return one + " " + five + " " + fifteen;
}

Provenance collectProvenance(const ContextInfo& gl, TimingMode timing) {
  Provenance p;
  p.set("command", processCommandLine());
  p.set("run_date_utc", utcTimestamp());
  p.set("gl_renderer", gl.renderer);
  p.set("gl_version", gl.version);
  p.set("gl_vendor", gl.vendor);
  p.set("egl_platform", gl.platform);
  p.set("timing_mode", describe(timing));
  p.set("timing_note", timingNote(gl, timing));
  p.set("cpu_model", cpuModel());
  p.set("cpu_cores", std::to_string(availableCpus()));
  const char* lpThreads = std::getenv("LP_NUM_THREADS");
  p.set("lp_num_threads", lpThreads && *lpThreads ? lpThreads : "unset");
  p.set("load_average", loadAverage());
  p.set("scheduling", scheduling());
  p.set("version", PBR_VERSION);
  p.set("build_type", PBR_BUILD_TYPE);
  p.set("compiler", PBR_COMPILER);
  p.set("git_commit", PBR_GIT_COMMIT);
  p.set("git_commit_date", PBR_GIT_COMMIT_DATE);
  p.set("git_dirty", PBR_GIT_DIRTY);
  return p;
}

}  // namespace pbr

namespace pbr {

std::string versionLine() {
  return std::string("pbr ") + PBR_VERSION + " (commit " + PBR_GIT_COMMIT + ", " + PBR_GIT_COMMIT_DATE +
         ", uncommitted changes: " + PBR_GIT_DIRTY + "; " + PBR_BUILD_TYPE + ", " + PBR_COMPILER + ")";
}

}  // namespace pbr
