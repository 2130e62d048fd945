// A caster exactly edge-on to the centre of a soft light (edge_on_sheet.h): a quad standing on its
// edge whose plane holds the light centre. Its hard shadow is empty, but the light shines across it
// from both sides and the floor gets a thin penumbra on either side of the quad's plane; the wedge
// techniques must draw both, against the ray-traced oracle.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "raster/eye_pass.h"
#include "scene/generators.h"
#include "scene/normals.h"
#include "shadows/reference/reference_technique.h"
#include "shadows/technique.h"
#include "shadows/wedge/wedge_technique.h"

namespace penumbra {
namespace test_wedge_edge_on {

// The quad x in [-0.5, 0.5], y in [0.25, 1.25] in the plane z = 0 (coordinates exact in float), the
// light centre (0, 2.5, 0) in that plane, a floor at y = 0. `tilt`: the top edge moved to z = tilt,
// so the plane misses the centre by 2.25 tilt (a quad meant to stand in that plane but
// rotated there in float).
Scene edgeOnQuadScene(float tilt) {
  Scene s;
  s.name = "edge-on-quad";
  s.materials.push_back(Material{});
  s.meshes.push_back(makeGroundPlane(vec3(0.0f), 3.0f));
  Mesh quad;
  quad.name = "quad";
  quad.positions = {vec3(-0.5f, 0.25f, 0.0f), vec3(0.5f, 0.25f, 0.0f), vec3(0.5f, 1.25f, tilt),
                    vec3(-0.5f, 1.25f, tilt)};
  quad.indices = {0, 1, 2, 0, 2, 3};
  computeCornerNormals(quad);
  s.meshes.push_back(std::move(quad));
  s.lights.push_back(Light{vec3(0.0f, 2.5f, 0.0f), 0.3f, vec3(1.0f), 1.0f});
  s.camera.position = vec3(1.0f, 3.2f, 1.6f);
  s.camera.target = vec3(0.0f, 0.2f, 0.0f);
  s.camera.fov_y = 40.0f;
  s.finalize();
  return s;
}

// Error against the oracle over the floor's pixels where the oracle sees part of the light hidden
// (v < 0.98): the two penumbra lines, one on either side of the quad's plane. The quad itself is
// left out (below).
struct LineError {
  double mae = 0;             // over the oracle's line pixels
  size_t pixels = 0;          // how many
  double darkest_missed = 0;  // largest (technique - oracle) there: light where it is dark
};

LineError lineError(const Scene& scene, const EyeBuffers& eye, const Image<float>& oracle,
                    const Image<float>& v) {
  LineError e;
  double sum = 0;
  for (int y = 0; y < v.height(); ++y)
    for (int x = 0; x < v.width(); ++x) {
      const uint32_t id = eye.primitive.at(x, y);
      if (id == kNoPrimitive || scene.locateTriangle(id).first != 0) continue;
      if (!(oracle.at(x, y) < 0.98f)) continue;
      const double d = double(v.at(x, y)) - double(oracle.at(x, y));
      sum += std::fabs(d);
      e.darkest_missed = std::max(e.darkest_missed, d);
      ++e.pixels;
    }
  e.mae = e.pixels ? sum / double(e.pixels) : 0.0;
  return e;
}

// Measured at 96 x 72 on the exact scene against 256 oracle rays (line MAE / the worst pixel too
// light), all three variants alike: before edge-on triangles cast, no wedge was built and both
// lines were missing (0.170 / 0.434); casting the mesh's facing only gave one line (0.110 / 0.426);
// with the other facing in its own buffer, 0.035 / 0.065. Tilted by 2e-7 (the centre 1.5e-6 of the
// radius off the plane), the same; before the tolerance (kEdgeOnRelative) it had one line only
// (0.095 / 0.434). Bounds 0.06 / 0.2: failing them means a line is missing again. The quad's own
// face (the light centre in its plane, half the light behind it) is not measured here: the wedges
// get it right too now (edge_on_sheet.h), but it is the terminator case of the 2002 paper's section
// 8, not the receiver's line.
TEST(WedgeEdgeOn, QuadEdgeOnToLightCentreCastsBothPenumbraLines) {
  for (const float tilt : {0.0f, 2e-7f}) {
    const Scene scene = edgeOnQuadScene(tilt);
    const View view = scene.camera.makeView(96, 72);
    Stats stats;
    const EyeBuffers eye = renderEyePass(scene, view, stats);
    TechniqueConfig reference("reference");
    reference.options<ReferenceOptions>().rays = 256;
    reference.options<ReferenceOptions>().seed = 1;
    const TechniqueResult oracle = renderShadows(reference, scene, scene.lights[0], view, eye);
    for (const WedgeAlgorithm kind :
         {WedgeAlgorithm::Original2002, WedgeAlgorithm::ThreePass, WedgeAlgorithm::SinglePass}) {
      const std::string name = wedgeTechniqueName(kind);
      const TechniqueResult r =
          renderShadows(TechniqueConfig(name), scene, scene.lights[0], view, eye);
      const LineError e = lineError(scene, eye, oracle.visibility, r.visibility);
      std::printf("[ edge-on  ] tilt %g %-12s line MAE %.4f over %zu px, worst too light %.3f\n",
                  double(tilt), name.c_str(), e.mae, e.pixels, e.darkest_missed);
      EXPECT_GT(e.pixels, 100u) << "the oracle's lines are gone: the scene is not edge-on";
      EXPECT_LE(e.mae, 0.06) << name << " tilt " << tilt;
      EXPECT_LE(e.darkest_missed, 0.2) << name << " tilt " << tilt;
    }
  }
}

}  // namespace test_wedge_edge_on
}  // namespace penumbra
