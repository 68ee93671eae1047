#pragma once
#include <string>

namespace pbr {

// A message is one line of bounded length whatever produced it: a driver's multi-line log, a path of thousands of
// characters, a key or a name taken from a hostile file.
std::string oneLine(const std::string& text);

// `v` with `decimals` digits after the point, as messages and report cells print numbers.
std::string fixedDecimals(double v, int decimals);

// One line (oneLine) on stderr about an input that is used although not all of it is understood. Each line is
// printed once per process: loading the same file again (bench's light counts, the viewer's new light count, a
// model placed twice) says nothing new. After 4,096 distinct lines, one
// more says that the rest are not shown.
void warnOnce(const std::string& message);

}  // namespace pbr
