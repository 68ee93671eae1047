#pragma once
#include <string>
#include <utility>
#include <vector>

#include "app/args.hpp"

namespace pbr {

// `pbr render`'s settings record: every option of its table that decides the frame (not the outputs, the timing
// or how many frames are timed), with the value it was given or, for an option with one, its default. `--json`
// writes it whole as "render_settings"; `--settings F.json` reads it back, so that a report reproduces its frame.
using RenderSettings = std::vector<std::pair<std::string, std::string>>;  // option -> value; flags have ""

// Whether `option` of pbr render's table decides the frame (and so belongs to the record).
bool decidesFrame(const std::string& option);
// The record of a parsed command line. Scene and environment files are named by absolute path, so that the record
// reads back from any folder.
RenderSettings renderSettings(const std::vector<OptionSpec>& specs, const Args& args);
// `argv` with the options of the record in `--settings F.json` that argv does not give itself appended: options
// given on the command line replace the report's. `--settings F.json#K` takes configuration K (from 1) of a pbr
// bench report instead: its scene, size, lights, culling, model, shadows and tone curve, with the bench's display
// (no anti-aliasing). Unchanged without --settings. Throws std::runtime_error naming the file when it holds neither
// a render_settings object nor that configuration, or an entry that is not a frame option of the table.
std::vector<std::string> withSettingsFile(const std::vector<OptionSpec>& specs, const std::vector<std::string>& argv);

}  // namespace pbr
