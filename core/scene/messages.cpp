#include "core/scene/messages.hpp"

#include <algorithm>
#include <cstdio>
#include <iostream>
#include <mutex>
#include <set>

namespace pbr {

std::string oneLine(const std::string& text) {
  std::string joined = text;
  for (char& c : joined) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  // A word over 240 characters (a path of thousands) keeps its ends, so that the reason after it still shows.
  constexpr size_t kMaxWord = 240, kKept = 100;
  std::string line;
  for (size_t start = 0; start < joined.size();) {
    const size_t end = std::min(joined.find(' ', start), joined.size());
    if (end - start > kMaxWord) {
      line += joined.substr(start, kKept) + "..." + joined.substr(end - kKept, kKept);
    } else {
      line += joined.substr(start, end - start);
    }
    if (end < joined.size()) line += ' ';
    start = end + 1;
  }
  constexpr size_t kMaxChars = 400;
  if (line.size() > kMaxChars) line = line.substr(0, kMaxChars - 3) + "...";
  return line;
}

std::string fixedDecimals(double v, int decimals) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", decimals, v);
  return text;
}

void warnOnce(const std::string& message) {
  static std::mutex mutex;
  static std::set<std::string> printed;
  static bool silenced = false;
  const std::string line = oneLine(message);
  // A process that loads many files (a fuzzer, a long sweep) stops remembering, and saying, after this many.
  constexpr size_t kMaxLines = 4096;
  const std::lock_guard<std::mutex> lock(mutex);
  if (silenced || printed.count(line) != 0) return;
  if (printed.size() == kMaxLines) {
    silenced = true;
    std::cerr << "further warnings are not shown (" << kMaxLines << " printed)\n";
    return;
  }
  printed.insert(line);
  std::cerr << line << "\n";
}

}  // namespace pbr
