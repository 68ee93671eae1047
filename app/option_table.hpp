#pragma once
#include <string>
#include <vector>

#include "app/args.hpp"

namespace pbr {

enum class Command { Render, Bench, BenchMerge, Experiment, View, Reference, Accuracy };
const char* toString(Command command);  // "render", "bench-merge", ...

// Every option of every command, each once: its name, its value's form and its meaning are the same wherever it
// is taken. A command's table (below) is the rows it takes, in its help's order; a command may give a row its
// own default (pbr bench measures the stress scene, pbr reference at 640x360), and pbr bench sweeps --lights,
// --culling and --model, taking a comma-separated list of the row's values, each measured in turn.
const std::vector<OptionSpec>& optionTable();

// The options of `command`, as its Args parse them and its --help prints them.
const std::vector<OptionSpec>& commandOptions(Command command);

}  // namespace pbr
