#pragma once
// The viewer's state as plain data, testable without a window: the registered techniques with
// their options (drawn from each technique's option table, so a technique added later shows
// up with its options and no viewer code), the camera, the lights, the frame settings and what
// the window overlays. The window (viewer_window.cpp) draws and edits this; the frame worker
// renders what it describes.
#include <cstdint>
#include <string>
#include <vector>

#include <penumbra/penumbra.h>

namespace penumbra::viewer {

// One option of a technique as a control: its spec (from the technique's option table; the
// table lives as long as the program) and its current value as the command line writes it.
struct OptionControl {
  const OptionSpec* spec = nullptr;
  std::string value;
};

struct TechniqueEntry {
  const TechniqueInfo* info = nullptr;
  std::vector<OptionControl> options;  // the table's order
};

// What the frame area shows. The last three are the technique's debug layers (DebugLayer,
// shadows/technique.h), rendered only while one of them is shown.
enum class Overlay {
  Shaded,
  Visibility,
  Penumbra,
  Depth,
  TileDepthRange,
  SilhouetteEdges,
  WedgeFootprints,
  CulledTiles,
};
enum class CompareMode { Off, Split, Heatmap };
// "shaded", "visibility", "penumbra", "depth", "tiles", "silhouette-edges", "wedge-footprints",
// "culled-tiles"
std::string overlayName(Overlay overlay);
// The debug layer an overlay shows (kSilhouetteEdgesLayer...), or empty for the others.
std::string overlayLayer(Overlay overlay);
std::string compareModeName(CompareMode mode);  // "off", "split", "heatmap"
const std::vector<Overlay>& allOverlays();
const std::vector<CompareMode>& allCompareModes();
// Throws penumbra::Error naming the known names.
Overlay parseOverlay(const std::string& name);
CompareMode parseCompareMode(const std::string& name);

struct ViewerModel {
  std::vector<TechniqueEntry> techniques;  // every registered technique, registration order
  size_t technique = 0;                    // index into `techniques`
  Camera camera;
  std::vector<Light> lights;
  size_t selected_light = 0;
  int width = 0, height = 0;  // the full-resolution frame
  // While the user drags, frames render at this fraction of the size, refined when the view
  // rests (1: always full size).
  float preview_scale = 0.5f;
  // While the user drags, the options with a preview value (fewer samples or rays:
  // OptionSpec::preview) take it too.
  bool preview_samples = true;
  int threads = 0;  // 0: all cores
  bool simd = true;
  Overlay overlay = Overlay::Shaded;
  CompareMode compare = CompareMode::Off;
  float compare_tolerance = 0.05f;  // a pixel is "off" when |technique - oracle| exceeds it
  float heatmap_scale = 0.25f;      // the error shown brightest
  // Bumped by every change to what a frame shows (camera, lights, technique, options, size,
  // threads, SIMD): the frame worker renders again and the oracle restarts.
  uint64_t generation = 0;
};

// The model of `scene` at its settings' size (or width x height when > 0), the technique
// `technique` with its default options (throws penumbra::Error for an unknown name).
ViewerModel makeViewerModel(const Scene& scene, const std::string& technique, int width = 0,
                            int height = 0);

const TechniqueEntry& currentTechnique(const ViewerModel& model);
// Selects a technique by name or alias, keeping every technique's option values; throws
// penumbra::Error naming the known techniques.
void selectTechnique(ViewerModel& model, const std::string& name);
// Sets an option of the current technique, as `penumbra render --NAME VALUE` would ("true" or
// "false" for a flag). The value is checked with the technique's own rules (range, choices,
// consistency with the other options); on error the model is unchanged and penumbra::Error
// says what is wrong.
void setOption(ViewerModel& model, const std::string& name, const std::string& value);
// The current technique with its option values.
TechniqueConfig techniqueConfig(const ViewerModel& model);
// The same with every option that has a cheaper preview value (OptionSpec::preview) set to it;
// `changed` receives "NAME VALUE" for each, empty when the preview renders like the full frame.
TechniqueConfig previewConfig(const ViewerModel& model, std::vector<std::string>& changed);
// Shows `overlay`; a switch to or from a debug layer bumps the generation (the frame must be
// rendered with or without the layers).
void setOverlay(ViewerModel& model, Overlay overlay);
// The `penumbra render` flags that select the current technique and its option values, for
// reproducing a frame from a saved scene file.
std::vector<std::string> renderFlags(const ViewerModel& model);

// Light edits as the sliders make them; each bumps the generation. Values are clamped to what
// the light takes (radius, sizes and intensity >= 0).
void selectLight(ViewerModel& model, size_t index);  // throws when out of range
void setLightRadius(ViewerModel& model, float radius);       // sphere and disk
void setLightIntensity(ViewerModel& model, float intensity);
// A rectangle light's edge lengths and its turn (degrees) about the plane's normal, a disk's
// normal tilted from straight down by `tilt` degrees towards azimuth `azimuth` degrees.
void setRectangleLight(ViewerModel& model, float width, float height, float turn_degrees);
void setDiskNormal(ViewerModel& model, float tilt_degrees, float azimuth_degrees);

}  // namespace penumbra::viewer
