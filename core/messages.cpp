#include "core/messages.hpp"

#include <iostream>
#include <mutex>
#include <set>

namespace pbr {

std::string oneLine(const std::string& text) {
  std::string line = text;
  for (char& c : line) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  constexpr size_t kMaxChars = 400;
  if (line.size() > kMaxChars) line = line.substr(0, kMaxChars - 3) + "...";
  return line;
}

void warnOnce(const std::string& message) {
  static std::mutex mutex;
  static std::set<std::string> printed;
  const std::string line = oneLine(message);
  const std::lock_guard<std::mutex> lock(mutex);
  if (printed.insert(line).second) std::cerr << line << "\n";
}

}  // namespace pbr
