#pragma once
// The one technique contract: given the eye pass's buffers, a light, the scene and
// the view, a technique writes the light visibility of every pixel's visible point, in [0, 1],
// and its work counters. Techniques read the eye buffers and never write them.
//
// A technique is one folder under src/shadows/ and one entry in the technique table
// (technique_table.cpp): a TechniqueInfo with its name, what it claims (hard or soft, exact or
// approximate, its error bound against the oracle), its own options struct with defaults and
// the option specs that read and print it (technique_options.h), and a factory that prepares
// per-scene state once (the oracle's BVH) and returns an object that renders one light at a
// time. The kind of technique is decided once, when it is prepared.
#include <any>
#include <array>
#include <deque>
#include <functional>
#include <memory>
#include <string>
#include <typeinfo>
#include <utility>
#include <vector>

#include <penumbra/core/error.h>
#include <penumbra/core/image.h>
#include <penumbra/core/stats.h>
#include <penumbra/core/view.h>
#include <penumbra/raster/depth_buffer.h>
#include <penumbra/scene/scene.h>
#include <penumbra/shadows/technique_options.h>

namespace penumbra {

// Whether the shadow stages leave out casters whose shadow reaches no visible point
// (docs/caster-culling.md). The image is the same in every mode; only the work differs.
enum class CasterCullingMode {
  Off,
  On,
  // On where the scene has at least as many edges as the frame has pixels: the receiver mask
  // costs a pass over the pixels, and what culling saves grows with the casters' edges.
  Auto,
};
// "off", "on", "auto": the names `penumbra render --caster-culling` and the stats JSON use.
const char* casterCullingName(CasterCullingMode mode);
// The mode of a name above; throws penumbra::Error naming the text and the choices.
CasterCullingMode parseCasterCulling(const std::string& name);

// Frame-level knobs every technique obeys; they are not technique options.
struct RenderContext {
  int threads = 0;             // worker threads, 0: all cores (applied by the frame)
  bool simd = true;            // false: every hot loop runs its scalar twin
  bool show_progress = false;  // progress bar on a terminal for long work
  // Ask the technique for its debug layers (TechniqueResult::debug_layers); off, a technique
  // spends nothing on them.
  bool debug_layers = false;
  // Leave out of the shadow volumes, wedges and potential edges every caster whose shadow
  // reaches no visible point (docs/caster-culling.md); the image is the same either way.
  CasterCullingMode caster_culling = CasterCullingMode::Auto;
};

// A picture of one shared stage's work for one light, at the frame's size, as the papers'
// figures draw it. A technique publishes the layers of the stages it runs, when
// RenderContext::debug_layers asks; a technique without such a stage publishes none.
struct DebugLayer {
  std::string name;         // one of the kDebugLayer* names below, or a technique's own
  std::string description;  // what a pixel's value counts
  Image<float> values;      // per pixel, >= 0; 0 where the stage did nothing
};
// The silhouette edges seen from the light centre, drawn as lines (silhouettes stage).
inline constexpr const char* kSilhouetteEdgesLayer = "silhouette_edges";
// Per pixel, the wedge faces that reached it after tile culling: the pixels tested against a
// wedge (penumbra wedges, 2004 paper, section 4).
inline constexpr const char* kWedgeFootprintsLayer = "wedge_footprints";
// Per pixel, the (polygon, culling tile) pairs culled at its tile (z-min / z-max culling,
// 2004 paper, section 4).
inline constexpr const char* kCulledTilesLayer = "culled_tiles";

// The layer called `name` in `layers`, added with zero values at width x height if missing.
Image<float>& debugLayer(std::vector<DebugLayer>& layers, const std::string& name,
                         const std::string& description, int width, int height);
// The layer called `name`, or null.
const DebugLayer* findDebugLayer(const std::vector<DebugLayer>& layers, const std::string& name);

// A textured light's visibility per colour channel (R, G, B), each in [0, 1]: the
// texture-weighted fraction of the light the point sees (scene/light.h, LightTexture).
using ChannelVisibility = std::array<Image<float>, 3>;

struct TechniqueResult {
  Image<float> visibility;  // per pixel, in [0, 1]; 1 on background pixels
  Stats stats;
  // Set by the techniques that see a textured light's texture (reference, heckbert-herf,
  // coverage) when the light has one; `visibility` is then their mean weighted by the light's
  // radiance per channel (the fraction of its power that arrives). Empty otherwise: the light
  // counts as uniform (hard techniques see only its centre) and `visibility` holds for every
  // channel.
  ChannelVisibility channels{};
  bool perChannel() const { return !channels[0].empty(); }
  // Filled only when RenderContext::debug_layers is set.
  std::vector<DebugLayer> debug_layers;
};

// Fills result.channels and sets result.visibility to their radiance-weighted mean (above).
void setChannelVisibility(TechniqueResult& result, const Light& light, ChannelVisibility channels);

// A technique prepared for one scene. The scene must outlive it and stay unchanged.
class PreparedTechnique {
 public:
  virtual ~PreparedTechnique() = default;
  virtual TechniqueResult render(const Light& light, const View& view, const EyeBuffers& eye,
                                 const RenderContext& context) const = 0;
};

// What a technique claims, which the conformance suite (tests/test_technique_conformance.cpp)
// holds it to.
struct TechniqueTraits {
  bool soft = false;  // penumbrae from the light's radius; radius 0 must give the hard volume
  bool ray_traced = false;  // visibility from rays: radius 0 gives the hard oracle instead
  bool exact = false;  // the oracle's answer on every pixel that is not a tie
  // Error against the oracle (1024 rays, or one ray to the centre for hard techniques) on the
  // built-in scenes at the conformance suite's size, with default options: the mean absolute
  // visibility error over pixels showing geometry, and over penumbra pixels (0 < oracle < 1).
  double covered_mae_bound = 1.0;
  double penumbra_mae_bound = 1.0;
  // Soft techniques that are not ray-traced: 0 means radius 0 gives the hard volume's image
  // exactly. A soft technique whose radius-0 limit is itself approximate (PCSS becomes the plain
  // shadow map, whose boundaries move by up to a texel) declares instead the mean absolute
  // difference from the hard volume over covered pixels that it keeps within at radius 0.
  double zero_radius_mae_bound = 0.0;
};

struct TechniqueInfo {
  std::string name;                  // what --technique takes
  std::vector<std::string> aliases;  // other names it answers to
  std::string summary;               // one line for `penumbra techniques`
  TechniqueTraits traits;
  TechniqueOptionTable options;      // its options struct: defaults, specs, checks, description
  // The counters it declares in its folder and reports besides the shared ones (core/stats.h).
  std::vector<CounterSpec> counters;
  // Prepares the technique for `scene` with `options` (an object of options.type(), checked).
  std::function<std::unique_ptr<PreparedTechnique>(const std::any& options, const Scene& scene)>
      prepare;
};

// Registered techniques, the table's first (technique_table.cpp), then any registered later.
// References to them stay valid for the program's life.
const std::deque<TechniqueInfo>& techniques();
std::vector<std::string> techniqueNames();
// The technique called `name` (or one of its aliases); throws penumbra::Error naming the known.
const TechniqueInfo& findTechnique(const std::string& name);
// Adds a technique; for tests and programs that bring their own. Call it before any frame is
// rendered (static initialisation is fine); throws when the name is taken.
void registerTechnique(TechniqueInfo info);
// The default soft technique: exact soft shadow volumes, the oracle's answer for a fixed light
// sample set on every light shape (README, "Why exact is the default").
inline constexpr const char* kDefaultTechnique = "exact";

// A technique and its options: what a frame is told to render with.
class TechniqueConfig {
 public:
  TechniqueConfig() : TechniqueConfig(kDefaultTechnique) {}
  explicit TechniqueConfig(const std::string& name);  // default options; throws if unknown
  // The technique with options given as its own struct: throws if they are not its type.
  template <class Options>
  TechniqueConfig(const std::string& name, Options options) : TechniqueConfig(name) {
    PENUMBRA_CHECK(options_.type() == typeid(Options),
                   "technique '{}' takes another options struct than the one given", info_->name);
    options_ = std::move(options);
  }

  const TechniqueInfo& info() const { return *info_; }
  const std::string& name() const { return info_->name; }
  // Typed access to the options; throws penumbra::Error when Options is not the technique's.
  template <class Options>
  Options& options() {
    return *checkedCast<Options>(options_);
  }
  template <class Options>
  const Options& options() const {
    return *checkedCast<const Options>(options_);
  }
  const std::any& rawOptions() const { return options_; }
  // One option by its flag name (without dashes), value as on the command line; throws
  // penumbra::Error naming the technique, the option and what is wrong.
  void set(const std::string& option, const std::string& value);
  std::string get(const std::string& option) const;
  // Throws penumbra::Error when the options are inconsistent or out of range.
  void validate() const { info_->options.validate(options_); }
  // "wedge-3pass (auto, cull full, 16x16 tiles)": for summaries and stats files.
  std::string describe() const;

 private:
  template <class Options, class Any>
  Options* checkedCast(Any& any) const {
    auto* p = std::any_cast<Options>(&any);
    PENUMBRA_CHECK(p != nullptr, "technique '{}' has another options struct than the one asked for",
                   info_->name);
    return p;
  }

  const TechniqueInfo* info_;
  std::any options_;
};

// Prepares `config` for `scene` (per-scene state) after validating its options.
std::unique_ptr<PreparedTechnique> prepareTechnique(const TechniqueConfig& config,
                                                    const Scene& scene);

// One light's visibility with a technique prepared on the spot: for tests and one-off use
// (frames prepare once and render every light: render/frame.h).
TechniqueResult renderShadows(const TechniqueConfig& config, const Scene& scene,
                              const Light& light, const View& view, const EyeBuffers& eye,
                              const RenderContext& context = {});

}  // namespace penumbra
