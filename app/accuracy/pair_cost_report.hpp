#pragma once
#include <ostream>
#include <vector>

#include "app/accuracy/accuracy_variants.hpp"
#include "app/accuracy/pair_cost.hpp"
#include "core/provenance.hpp"

namespace pbr {

// A per-pair cost run and its circumstances, as `pbr bench --pair-cost` writes it.
struct PairCostReport {
  Provenance provenance;
  PairCostSettings settings;
  std::vector<AccuracyVariant> variants;
  std::vector<PairCost> costs;  // one per variant, same order
};

// CSV: provenance and settings as leading "# key: value" lines, then one row per variant.
void writePairCostCsv(std::ostream& out, const PairCostReport& report);
// JSON (schema "pbr-pair-cost/1"): provenance, settings and one object per variant.
void writePairCostJson(std::ostream& out, const PairCostReport& report);
void printPairCostTable(std::ostream& out, const PairCostReport& report);

}  // namespace pbr
