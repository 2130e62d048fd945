#pragma once
// The subcommands of the `penumbra` CLI. Each registers its options on the parser and runs after
// parsing; behaviour lives in the library, these only parse and print. Errors are thrown
// (penumbra::Error and friends) and reported by main().
#include <functional>
#include <string>

#include <CLI/CLI.hpp>

namespace penumbra::cli {

struct Subcommand {
  CLI::App* parser = nullptr;
  std::function<int()> run;  // called when `parser` was parsed; returns the exit code
};

Subcommand addRenderCommand(CLI::App& app);
Subcommand addCompareCommand(CLI::App& app);
Subcommand addScenesCommand(CLI::App& app);
Subcommand addBenchCommand(CLI::App& app);
Subcommand addTechniquesCommand(CLI::App& app);
Subcommand addConvertCommand(CLI::App& app);
Subcommand addFidelityCommand(CLI::App& app);
Subcommand addViewCommand(CLI::App& app);  // runs penumbra-view (apps/viewer/)
// One technique's summary and options with their defaults (`penumbra techniques NAME`); throws
// penumbra::Error for an unknown name.
void printTechnique(const std::string& name);

}  // namespace penumbra::cli
