#include "app/bench/text_table.hpp"

#include <algorithm>

namespace pbr {

TextTable::TextTable(std::vector<std::vector<std::string>> rows, std::vector<size_t> leftAligned)
    : rows_(std::move(rows)), leftAligned_(std::move(leftAligned)) {
  for (const auto& row : rows_) {
    if (width_.size() < row.size()) width_.resize(row.size(), 0);
    for (size_t c = 0; c < row.size(); ++c) width_[c] = std::max(width_[c], row[c].size());
  }
}

std::string TextTable::line(size_t row) const {
  std::string text;
  const std::vector<std::string>& cells = rows_[row];
  for (size_t c = 0; c < cells.size(); ++c) {
    const std::string pad(width_[c] - cells[c].size(), ' ');
    const bool left = std::find(leftAligned_.begin(), leftAligned_.end(), c) != leftAligned_.end();
    text += (c ? "  " : "") + (left ? cells[c] + pad : pad + cells[c]);
  }
  return text;
}

}  // namespace pbr
