#pragma once
#include <ostream>
#include <vector>

#include "app/accuracy/accuracy_variants.hpp"
#include "app/accuracy/pair_cost_settings.hpp"
#include "app/bench/csv_provenance.hpp"
#include "app/provenance.hpp"

namespace pbr {

// A per-pair cost run and its circumstances, as `pbr bench --pair-cost` writes it.
struct PairCostReport {
  Provenance provenance;
  PairCostSettings settings;
  std::vector<AccuracyVariant> variants;  // a row's variant: each of --pair-cost's, once per fixture material
  std::vector<PairCost> costs;            // one per row, same order, with the row's fixture material
};

// CSV: a header row, then one row per variant; its provenance file (csv_provenance.hpp) holds the provenance and
// settings.
void writePairCostCsv(std::ostream& out, const PairCostReport& report);
KeyValues pairCostCsvProvenance(const PairCostReport& report);
// JSON (schema "pbr-pair-cost/1"): provenance, settings and one object per variant.
void writePairCostJson(std::ostream& out, const PairCostReport& report);
void printPairCostTable(std::ostream& out, const PairCostReport& report);

}  // namespace pbr
