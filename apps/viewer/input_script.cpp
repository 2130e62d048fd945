#include "input_script.h"

#include <fstream>
#include <map>
#include <sstream>

#include <fmt/format.h>

#include <penumbra/core/error.h>

namespace penumbra::viewer {

namespace {

struct Arity {
  size_t min, max;
};

const std::map<std::string, Arity>& commandArity() {
  static const std::map<std::string, Arity> arity = {{"wait", {1, 1}},
                                                     {"drag", {5, 8}},
                                                     {"wheel", {3, 3}},
                                                     {"key", {1, 1}},
                                                     {"technique", {1, 1}},
                                                     {"option", {2, 2}},
                                                     {"light", {1, 1}},
                                                     {"light-radius", {1, 1}},
                                                     {"light-intensity", {1, 1}},
                                                     {"overlay", {1, 1}},
                                                     {"compare", {1, 1}},
                                                     {"preview-scale", {1, 1}},
                                                     {"preview-samples", {1, 1}},
                                                     {"threads", {1, 1}},
                                                     {"simd", {1, 1}},
                                                     {"save-scene", {1, 1}},
                                                     {"screenshot", {1, 1}},
                                                     {"window-screenshot", {1, 1}},
                                                     {"wait-oracle", {1, 1}}};
  return arity;
}

}  // namespace

std::vector<ScriptCommand> parseScript(const std::string& text, const std::string& origin) {
  std::vector<ScriptCommand> commands;
  std::istringstream lines(text);
  std::string line;
  for (int number = 1; std::getline(lines, line); ++number) {
    if (const size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream words(line);
    ScriptCommand command;
    command.line = number;
    if (!(words >> command.name)) continue;
    for (std::string word; words >> word;) command.args.push_back(word);
    const auto known = commandArity().find(command.name);
    if (known == commandArity().end()) {
      throw Error(fmt::format("{}:{}: unknown command '{}'", origin, number, command.name));
    }
    const Arity arity = known->second;
    if (command.args.size() < arity.min || command.args.size() > arity.max) {
      throw Error(
          fmt::format("{}:{}: '{}' takes {} arguments (got {})", origin, number, command.name,
                      arity.min == arity.max ? fmt::format("{}", arity.min)
                                             : fmt::format("{} to {}", arity.min, arity.max),
                      command.args.size()));
    }
    commands.push_back(std::move(command));
  }
  return commands;
}

std::vector<ScriptCommand> readScript(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  PENUMBRA_CHECK(in.good(), "{}: cannot read the script", path);
  std::ostringstream text;
  text << in.rdbuf();
  return parseScript(text.str(), path);
}

}  // namespace penumbra::viewer
