#pragma once
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace pbr {

// A CSV's circumstances (the provenance of its run, its settings) go in a file beside it, F.provenance.txt for
// F.csv, one "key: value" line each: the CSV itself starts with its header row, as csv readers and spreadsheets
// expect.
using KeyValues = std::vector<std::pair<std::string, std::string>>;
std::string provenancePath(const std::string& csvPath);  // "out/bench.csv" -> "out/bench.provenance.txt"
// Line breaks inside a value become spaces. Provenance values are single-line by construction, but a command line
// may hold anything; unlike core's oneLine, nothing is cut: the file keeps the whole command.
void writeKeyValues(std::ostream& out, const KeyValues& entries);

}  // namespace pbr
