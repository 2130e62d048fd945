#pragma once
// Scripted input for tests and screenshots (`penumbra-view --script FILE`): one command a line,
// '#' starts a comment. Mouse and key commands become window events (so they take the same path
// as the user's hands); the others are the panel's controls, set as its sliders set them.
//
//   wait N                           let N window frames pass
//   drag BUTTON X0 Y0 X1 Y1 [STEPS] [ctrl] [shift]
//                                    press BUTTON (left, middle, right) at window pixel
//                                    (X0, Y0), move to (X1, Y1) in STEPS motion events, release;
//                                    ctrl / shift are held throughout (ctrl+left drags the light,
//                                    ctrl+shift+left moves it along the vertical line)
//   wheel STEPS X Y                  the mouse wheel at window pixel (X, Y)
//   key NAME                         press and release a key (SDL's key name: "s", "Tab")
//   technique NAME                   the panel's technique list
//   option NAME VALUE                a technique option, as `penumbra render --NAME VALUE`
//   light INDEX | light-radius R | light-intensity I
//   overlay shaded|visibility|penumbra|depth|tiles
//   compare off|split|heatmap
//   overlay silhouette-edges|wedge-footprints|culled-tiles   (the technique's debug layers)
//   preview-scale S | preview-samples on|off | threads N | simd on|off
//   save-scene FILE | screenshot FILE | window-screenshot FILE
//                                    once the events pushed so far are handled and the
//                                    full-size frame of the view is rendered
//   wait-oracle PASSES               wait until the oracle has accumulated PASSES passes
#include <string>
#include <vector>

namespace penumbra::viewer {

struct ScriptCommand {
  int line = 0;  // in the file, for messages
  std::string name;
  std::vector<std::string> args;
};

// Reads and checks every line (command names and argument counts); throws penumbra::Error
// "FILE:LINE: what is wrong".
std::vector<ScriptCommand> readScript(const std::string& path);
std::vector<ScriptCommand> parseScript(const std::string& text, const std::string& origin);

}  // namespace penumbra::viewer
