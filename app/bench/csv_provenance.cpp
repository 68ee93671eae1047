#include "app/bench/csv_provenance.hpp"

#include <algorithm>

namespace pbr {

std::string provenancePath(const std::string& csvPath) {
  const std::string suffix = ".csv";
  const bool csv = csvPath.size() >= suffix.size() &&
                   csvPath.compare(csvPath.size() - suffix.size(), suffix.size(), suffix) == 0;
  return (csv ? csvPath.substr(0, csvPath.size() - suffix.size()) : csvPath) + ".provenance.txt";
}

void writeKeyValues(std::ostream& out, const KeyValues& entries) {
  for (const auto& [key, value] : entries) {
    std::string line = value;
    std::replace(line.begin(), line.end(), '\n', ' ');
    std::replace(line.begin(), line.end(), '\r', ' ');
    out << key << ": " << line << "\n";
  }
}

}  // namespace pbr
