// penumbra: render a scene with a shadow technique, compare results, list scenes, sweep the
// wedge implementations (bench).
// Every error ends as "penumbra: error: <message>" on stderr and exit code 1.
#include <cstdio>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "commands.h"
#include "core/memory.h"

namespace {


int reportError(const std::string& message) {
  std::fflush(stdout);
  std::cerr << "penumbra: error: " << message << std::endl;
  return 1;
}

int run(int argc, char** argv) {
  CLI::App app{"Penumbra: hard and soft shadows with shadow volumes and penumbra wedges, "
               "measured against a ray-traced oracle"};
  app.require_subcommand(1);
  const std::vector<penumbra::cli::Subcommand> commands = {
      penumbra::cli::addRenderCommand(app),
      penumbra::cli::addCompareCommand(app),
      penumbra::cli::addScenesCommand(app),
      penumbra::cli::addTechniquesCommand(app),
      penumbra::cli::addBenchCommand(app),
      penumbra::cli::addConvertCommand(app),
      penumbra::cli::addFidelityCommand(app),
      penumbra::cli::addViewCommand(app),
  };
  // CLI11 would call an unknown command word a missing subcommand; name it instead.
  if (argc > 1 && argv[1][0] != '-') {
    std::string known;
    bool found = false;
    for (const auto& command : commands) {
      found = found || command.parser->get_name() == argv[1];
      known += (known.empty() ? "" : ", ") + command.parser->get_name();
    }
    if (!found) {
      return reportError("unknown command '" + std::string(argv[1]) + "' (known: " + known + ")");
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) {  // --help
      const int code = app.exit(e);
      // `render --technique NAME --help`: that technique's own options too.
      if (argc > 1 && std::string(argv[1]) == "render") {
        for (int i = 2; i + 1 < argc; ++i)
          if (std::string(argv[i]) == "--technique") {
            std::cout << "\n";
            penumbra::cli::printTechnique(argv[i + 1]);
          }
      }
      return code;
    }
    return reportError(std::string(e.what()) + " (run 'penumbra --help')");
  }
  for (const auto& command : commands) {
    if (command.parser->parsed()) return command.run();
  }
  return reportError("no command given (run 'penumbra --help')");
}

}  // namespace

int main(int argc, char** argv) {
  penumbra::keepFrameBuffersMapped();
  try {
    return run(argc, argv);
  } catch (const std::exception& e) {
    return reportError(e.what());
  } catch (...) {
    return reportError("unknown failure");
  }
}
