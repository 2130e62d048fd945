// penumbra compare A B: error between two visibility buffers (EXR, gray PNG) or renders (PNG).
#include <cctype>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "core/error.h"
#include "core/image_io.h"
#include "metrics/heatmap.h"
#include "metrics/image_compare.h"

namespace penumbra::cli {
namespace {

struct CompareArgs {
  std::string a;
  std::string b;
  double tolerance = 0.01;
  std::string diff;
  std::optional<float> diff_scale;
  std::string mask;  // a depth EXR (render --depth): only pixels showing geometry
  bool json = false;
};

Image<vec3> asColor(const ImageFile& file) {
  if (file.is_color) return file.color;
  Image<vec3> out(file.gray.width(), file.gray.height());
  for (size_t i = 0; i < out.size(); ++i) out[i] = vec3(file.gray[i]);
  return out;
}

// A NaN or infinite pixel is a bug in whatever wrote the image: the comparison fails (exit
// code 1) whatever the tolerance, instead of averaging the NaN away into "MAE 0".
void failOnNonFinite(const CompareArgs& args, const ImageDifference& d) {
  PENUMBRA_CHECK(d.count_nonfinite == 0,
                 "'{}' vs '{}': {} of {} pixels are NaN or infinite in one of the images",
                 args.a, args.b, d.count_nonfinite, d.pixels);
}

int runCompare(const CompareArgs& args) {
  PENUMBRA_CHECK(args.tolerance >= 0.0, "--tolerance {} must be a number >= 0", args.tolerance);
  PENUMBRA_CHECK(!args.diff_scale || (*args.diff_scale > 0.0f && std::isfinite(*args.diff_scale)),
                 "--diff-scale {} must be a finite number > 0", args.diff_scale.value_or(0.0f));
  if (!args.diff.empty()) {
    std::string ext = std::filesystem::path(args.diff).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    PENUMBRA_CHECK(ext == ".png",
                   "--diff '{}' must be a .png file", args.diff);
  }
  const ImageFile a = readImageFile(args.a);
  const ImageFile b = readImageFile(args.b);
  PENUMBRA_CHECK(a.width() == b.width() && a.height() == b.height(),
                 "cannot compare '{}' ({}x{}) with '{}' ({}x{}): the sizes differ", args.a,
                 a.width(), a.height(), args.b, b.width(), b.height());

  std::optional<Image<uint8_t>> mask;
  if (!args.mask.empty()) {
    const Image<float> depth = readExr(args.mask);
    PENUMBRA_CHECK(depth.width() == a.width() && depth.height() == a.height(),
                   "--mask '{}' is {}x{} but the images are {}x{}", args.mask, depth.width(),
                   depth.height(), a.width(), a.height());
    mask.emplace(depth.width(), depth.height(), uint8_t(0));
    for (size_t i = 0; i < depth.size(); ++i) (*mask)[i] = depth[i] > 0.0f ? 1 : 0;
  }
  const Image<uint8_t>* covered = mask ? &*mask : nullptr;
  // Gray against gray stays gray (visibility); anything with colour compares as linear RGB.
  const bool gray = !a.is_color && !b.is_color;
  const ImageDifference d = gray ? compareImages(a.gray, b.gray, args.tolerance, covered)
                                 : compareImages(asColor(a), asColor(b), args.tolerance, covered);

  float scale = 1.0f;
  if (!args.diff.empty()) {
    // Default scale: the largest error, so the brightest colour marks the worst pixel.
    scale = args.diff_scale.value_or(
        d.max_error > 0 && std::isfinite(d.max_error) ? float(d.max_error) : 1.0f);
    const Image<glm::u8vec3> heat = gray ? diffHeatmap(a.gray, b.gray, scale)
                                         : diffHeatmap(asColor(a), asColor(b), scale);
    writePngRgb8(args.diff, heat);
  }

  if (args.json) {
    nlohmann::json doc = {
        {"a", args.a},
        {"b", args.b},
        {"width", a.width()},
        {"height", a.height()},
        {"mode", gray ? "gray" : "rgb"},
        {"pixels", d.pixels},
        {"mae", d.mae},
        {"rmse", d.rmse},
        {"max_error", d.max_error},  // infinite (a NaN pixel) prints as null
        {"tolerance", args.tolerance},
        {"count_over_tolerance", d.count_over_tolerance},
        {"fraction_over_tolerance", d.fraction_over_tolerance},
        {"count_nonfinite", d.count_nonfinite},
    };
    if (!args.diff.empty()) doc["diff"] = {{"path", args.diff}, {"scale", scale}};
    std::cout << doc.dump(2) << "\n";
    failOnNonFinite(args, d);
    return 0;
  }
  std::cout << fmt::format("{} vs {}: {}x{} {}\n", args.a, args.b, a.width(), a.height(),
                           gray ? "gray" : "RGB (per-pixel error: largest channel difference)");
  if (d.count_nonfinite > 0) {
    std::cout << fmt::format("MAE nan  RMSE nan  max nan ({} of {} pixels are NaN or infinite; "
                             "over the others: MAE {:.6g}  RMSE {:.6g})\n",
                             d.count_nonfinite, d.pixels, d.mae, d.rmse);
  } else {
    std::cout << fmt::format("MAE {:.6g}  RMSE {:.6g}  max {:.6g}\n", d.mae, d.rmse, d.max_error);
  }
  std::cout << fmt::format("off by more than {:g}: {:.4f}% ({} of {} pixels)\n", args.tolerance,
                           100.0 * d.fraction_over_tolerance, d.count_over_tolerance, d.pixels);
  if (!args.diff.empty()) {
    std::cout << fmt::format("wrote {} (heat map, brightest = error {:g})\n", args.diff, scale);
  }
  failOnNonFinite(args, d);
  return 0;
}

}  // namespace

Subcommand addCompareCommand(CLI::App& app) {
  auto args = std::make_shared<CompareArgs>();
  CLI::App* cmd = app.add_subcommand(
      "compare", "Compare two images: EXR or gray PNG visibility, or colour PNG renders");
  cmd->add_option("a", args->a, "First image (.exr or .png)")->required();
  cmd->add_option("b", args->b, "Second image (.exr or .png)")->required();
  cmd->add_option("--tolerance", args->tolerance,
                  "Count pixels whose error is larger than this")
      ->capture_default_str();
  cmd->add_option("--diff", args->diff, "Write a heat map of the error (PNG)");
  cmd->add_option("--diff-scale", args->diff_scale,
                  "Error shown brightest in the heat map (default: the largest error)");
  cmd->add_option("--mask", args->mask,
                  "Compare only the pixels that show geometry in this depth EXR (render --depth)");
  cmd->add_flag("--json", args->json, "Print the result as JSON");
  return {cmd, [args] { return runCompare(*args); }};
}

}  // namespace penumbra::cli
