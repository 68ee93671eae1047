#pragma once
#include <string>
#include <vector>

namespace pbr {

// Fixed-width text columns, two spaces apart: numbers right-aligned, the columns named in `leftAligned` (words)
// left-aligned. Rows may be shorter than others (a skipped configuration's).
class TextTable {
 public:
  TextTable(std::vector<std::vector<std::string>> rows, std::vector<size_t> leftAligned);
  size_t rows() const { return rows_.size(); }
  std::string line(size_t row) const;

 private:
  std::vector<std::vector<std::string>> rows_;
  std::vector<size_t> leftAligned_;
  std::vector<size_t> width_;
};

}  // namespace pbr
