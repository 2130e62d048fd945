// penumbra techniques [NAME]: the registered shadow techniques, or one technique's options.
#include <algorithm>
#include <iostream>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "commands.h"
#include "shadows/technique.h"

namespace penumbra::cli {
namespace {

std::string claims(const TechniqueTraits& t) {
  std::string text = t.soft ? "soft" : "hard";
  if (t.exact) text += ", exact";
  if (t.ray_traced) text += ", ray-traced";
  return text;
}

int runTechniques(const std::string& name) {
  if (name.empty()) {
    std::cout << "techniques ('penumbra techniques NAME' lists one's options):\n";
    size_t width = 0;  // names in one column, however long the longest
    for (const TechniqueInfo& info : techniques()) width = std::max(width, info.name.size());
    for (const TechniqueInfo& info : techniques())
      std::cout << fmt::format("  {:<{}} [{}] {}\n", info.name, width, claims(info.traits),
                               info.summary);
    return 0;
  }
  printTechnique(name);
  return 0;
}

}  // namespace

void printTechnique(const std::string& name) {
  const TechniqueInfo& info = findTechnique(name);
  const TechniqueConfig defaults(info.name);
  std::cout << fmt::format("{} [{}]: {}\n", info.name, claims(info.traits), info.summary);
  if (!info.aliases.empty()) std::cout << fmt::format("also called: {}\n", fmt::join(info.aliases, ", "));
  for (const CounterSpec& counter : info.counters)
    std::cout << fmt::format("counts {}: {}\n", counter.name, counter.description);
  if (info.options.specs().empty()) {
    std::cout << "no options\n";
    return;
  }
  std::cout << "options (give them to 'penumbra render --technique " << info.name << "'):\n";
  for (const OptionSpec& spec : info.options.specs()) {
    std::cout << fmt::format("  {:<32} {} (default: {})\n", spec.usage(), spec.help,
                             defaults.get(spec.name));
  }
}

Subcommand addTechniquesCommand(CLI::App& app) {
  auto name = std::make_shared<std::string>();
  CLI::App* cmd = app.add_subcommand("techniques", "List the shadow techniques and their options");
  cmd->add_option("name", *name, "A technique: list its options with their defaults");
  return {cmd, [name] { return runTechniques(*name); }};
}

}  // namespace penumbra::cli
