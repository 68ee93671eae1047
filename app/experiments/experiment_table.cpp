#include <stdexcept>

#include "app/experiments/experiments.hpp"
#include "core/io/output_file.hpp"

namespace pbr {

double ExperimentTable::at(size_t row, const std::string& column) const {
  for (size_t j = 0; j < columns.size(); ++j) {
    if (columns[j] == column) return rows.at(row).at(j);
  }
  throw std::out_of_range("experiment table has no column '" + column + "'");
}

void writeExperimentCsv(const std::string& path, const ExperimentTable& table) {
  writeOutputFile(path, [&](std::ostream& out) {
    out << table.xLabel;
    for (const std::string& c : table.columns) out << "," << c;
    out << "\n";
    out.precision(9);
    for (size_t i = 0; i < table.x.size(); ++i) {
      out << table.x[i];
      for (double v : table.rows[i]) out << "," << v;
      out << "\n";
    }
  });
}

}  // namespace pbr
