// Textured rectangle lights (issue 9 item 3): the texture itself (light.h), its exact
// per-channel coverage (textured_coverage.h) against an independent cell-by-cell computation
// and dense sampling, the scene file's "texture", and the techniques that see it (reference,
// heckbert-herf, coverage) on a scene whose two halves of the light differ in colour.
// Release run time about 1.5 s.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "core/image_io.h"
#include "raster/eye_pass.h"
#include "render/shading.h"
#include "render/shading_reuse.h"
#include "scene/generators.h"
#include "scene/light.h"
#include "scene/scene_file.h"
#include "shadows/coverage/shape_coverage.h"
#include "shadows/coverage/textured_coverage.h"
#include "shadows/technique.h"
#include "test_scene_util.h"

namespace penumbra {
namespace test_light_texture {

using test::contains;
using test::errorMessage;

double cross2(const dvec2& a, const dvec2& b) { return a.x * b.y - a.y * b.x; }

std::shared_ptr<const LightTexture> randomTexture(int w, int h, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<vec3> texels;
  for (int k = 0; k < w * h; ++k) texels.push_back(vec3(u(rng), u(rng), u(rng)));
  return makeLightTexture(w, h, texels, "random");
}

// The polygon's area (shoelace), counter-clockwise positive.
double polygonArea(const std::vector<dvec2>& p) {
  double a = 0.0;
  for (size_t k = 0; k < p.size(); ++k) a += cross2(p[k], p[(k + 1) % p.size()]);
  return 0.5 * a;
}

// Independent of Green's theorem: the polygon cut to every texel's square, the pieces' areas
// times the texels, over the sum of all texels.
dvec3 cellByCellFraction(const LightTexture& t, const std::vector<dvec2>& polygon) {
  dvec3 sum(0.0), total(0.0);
  for (int j = 0; j < t.height; ++j) {
    for (int i = 0; i < t.width; ++i) {
      const dvec3 texel(t.texels[size_t(j * t.width + i)]);
      total += texel;
      const double x0 = -1.0 + 2.0 * i / t.width, x1 = -1.0 + 2.0 * (i + 1) / t.width;
      const double y0 = -1.0 + 2.0 * j / t.height, y1 = -1.0 + 2.0 * (j + 1) / t.height;
      std::vector<dvec2> piece = clipPolygonToHalfPlane(polygon, dvec2(1, 0), -x0);
      piece = clipPolygonToHalfPlane(piece, dvec2(-1, 0), x1);
      piece = clipPolygonToHalfPlane(piece, dvec2(0, 1), -y0);
      piece = clipPolygonToHalfPlane(piece, dvec2(0, -1), y1);
      sum += texel * (polygonArea(piece) * t.width * t.height / 4.0);
    }
  }
  return sum / total;
}

// Green's theorem over the texels against the cell-by-cell sum, on random convex polygons
// (random half-planes cutting the square): a wrong prefix sum, texel border or orientation
// would differ by a texel's share, far above 1e-12.
TEST(LightTexture, PolygonIntegralMatchesCellByCellClipping) {
  const auto texture = randomTexture(5, 3, 1);
  const TexturedSquare square(*texture);
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int nonempty = 0;
  for (int k = 0; k < 200; ++k) {
    std::vector<dvec2> polygon = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    for (int cut = 0; cut < 3; ++cut) {
      polygon = clipPolygonToHalfPlane(polygon, dvec2(u(rng), u(rng)), 0.5 * u(rng));
    }
    if (polygon.empty()) continue;
    ++nonempty;
    const dvec3 green = square.polygonFraction(polygon);
    const dvec3 cells = cellByCellFraction(*texture, polygon);
    for (int c = 0; c < 3; ++c) ASSERT_NEAR(green[c], cells[c], 1e-12) << k;
  }
  EXPECT_GT(nonempty, 100);
}

// A uniform texture weighs every point alike: the per-channel coverage must be the area
// coverage (shape_coverage.h), with and without the visible surface's half-plane, in both
// orientations of the frame. A sign or mirroring slip would show here.
TEST(LightTexture, UniformTextureGivesTheAreaCoverage) {
  const auto texture = makeLightTexture(1, 1, {vec3(2.0f)}, "uniform");
  const TexturedSquare square(*texture);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 300; ++k) {
    const dvec2 lo(u(rng), u(rng)), hi(u(rng), u(rng));
    const dvec2 slope(u(rng), u(rng));
    const double offset = 0.7 * u(rng);
    for (bool flip : {false, true}) {
      EXPECT_NEAR(square.beyondFraction(lo, hi, flip, false, slope, offset).y,
                  insideFraction(LightOutline::Square, lo, hi), 1e-12);
      // The half-plane read mirrored is the mirrored half-plane: compare with the area
      // coverage of the mirrored half-plane on the mirrored segment, signed as the original.
      const dvec2 s = flip ? dvec2(slope.x, -slope.y) : slope;
      const dvec2 l = flip ? dvec2(lo.x, -lo.y) : lo, h = flip ? dvec2(hi.x, -hi.y) : hi;
      const double mirrored = insideFractionInHalfPlane(LightOutline::Square, l, h, s, offset);
      EXPECT_NEAR(square.beyondFraction(lo, hi, flip, true, slope, offset).x,
                  flip ? -mirrored : mirrored, 1e-12);
      EXPECT_NEAR(square.halfPlaneFraction(slope, offset, flip).z,
                  halfPlaneFraction(LightOutline::Square, s, offset), 1e-12);
    }
  }
}

// The definition, sampled: a 1680 x 1680 grid of the square, each point in the region beyond
// a-b (the cone from the centre, past the chord) weighing its texel, signed by the turn. The
// issue's bound for analytic coverage: 1e-4 of the light.
TEST(LightTexture, CoverageMatchesDenseSamplingPerChannel) {
  const auto texture = randomTexture(7, 4, 4);
  const TexturedSquare square(*texture);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int grid = 1680;  // a multiple of 7 and 4: texel borders fall between samples
  for (int k = 0; k < 6; ++k) {
    dvec2 a(u(rng), u(rng)), b(u(rng), u(rng));
    const dvec3 analytic = square.beyondFraction(a, b, false, false, dvec2(0), 0.0);
    const double turn = cross2(a, b);
    if (turn < 0.0) std::swap(a, b);
    dvec3 seen(0.0), all(0.0);
    for (int j = 0; j < grid; ++j) {
      for (int i = 0; i < grid; ++i) {
        const dvec2 x(-1.0 + (i + 0.5) * 2.0 / grid, -1.0 + (j + 0.5) * 2.0 / grid);
        const dvec3 w(texture->at(vec2(float((x.x + 1) / 2), float((x.y + 1) / 2))));
        all += w;
        if (cross2(a, x) >= 0.0 && cross2(x, b) >= 0.0 && cross2(b - a, x - a) < 0.0) seen += w;
      }
    }
    const dvec3 sampled = (turn > 0.0 ? 1.0 : -1.0) * seen / all;
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(analytic[c], sampled[c], 1e-4) << k << " " << c;
  }
}

// Large images are box-filtered to at most kMaxLightTextureCells a side, keeping their mean;
// bad texels and a black texture are refused by name.
TEST(LightTexture, BoxFilterKeepsTheMeanAndBadTexelsAreRefused) {
  std::vector<vec3> texels;
  for (int k = 0; k < 64 * 40; ++k) texels.push_back(vec3(float(k % 64) / 63.0f, 0.5f, 0.0f));
  const auto t = makeLightTexture(64, 40, texels, "big");
  EXPECT_EQ(t->width, kMaxLightTextureCells);
  EXPECT_EQ(t->height, kMaxLightTextureCells);
  EXPECT_NEAR(t->mean.x, 0.5f, 1e-5f);
  EXPECT_NEAR(t->texels[0].x, (0.0f + 1.0f / 63.0f) / 2.0f, 1e-6f);  // two columns averaged
  EXPECT_TRUE(contains(errorMessage([] { makeLightTexture(1, 1, {vec3(NAN)}, "nan.png"); }),
                       "nan.png: texel 0 (column 0, row 0)"));
  EXPECT_TRUE(contains(errorMessage([] { makeLightTexture(1, 1, {vec3(-1.0f)}, "neg"); }),
                       "must be finite and >= 0"));
  EXPECT_TRUE(contains(errorMessage([] { makeLightTexture(2, 1, {vec3(0), vec3(0)}, "black"); }),
                       "black: the light texture is black everywhere"));
}

// A scene with a light whose u-half toward -x is red and the other half blue, 0.4 above a
// floor, a square occluder's edge under the light's middle: points just past the edge see the
// blue half and not the red, so the shadow's red and blue channels differ.
Scene twoColourScene() {
  const std::string text = R"({
    "camera": {"position": [0, 6, 0.01], "target": [0, 0, 0], "fov": 40},
    "settings": {"width": 96, "height": 64},
    "meshes": [
      {"generator": "box", "min": [-4, -0.1, -4], "max": [4, 0, 4]},
      {"generator": "box", "min": [-3, 1.0, -0.5], "max": [0, 1.1, 0.5]}
    ],
    "lights": [{"center": [0, 3, 0], "shape": "rectangle", "u": [1.2, 0, 0], "v": [0, 0, 1.2],
                "texture": {"width": 2, "height": 1, "texels": [[1, 0, 0], [0, 0, 1]]}}]
  })";
  return parseSceneJson(text, "two-colour.json", "");
}

struct ChannelRun {
  TechniqueResult result;
  EyeBuffers eye;
};

ChannelRun run(const Scene& scene, TechniqueConfig config) {
  ChannelRun r;
  const View view = scene.camera.makeView(scene.settings.width, scene.settings.height);
  Stats stats;
  r.eye = renderEyePass(scene, view, stats);
  r.result = renderShadows(config, scene, scene.lights[0], view, r.eye);
  return r;
}

double channelMae(const ChannelRun& a, const ChannelRun& b, int c, long* penumbra = nullptr) {
  double sum = 0.0;
  long n = 0;
  const Image<float>& x = a.result.channels[size_t(c)];
  const Image<float>& y = b.result.channels[size_t(c)];
  for (size_t i = 0; i < x.size(); ++i) {
    if (!(a.eye.depth.depth[i] > 0.0f)) continue;
    sum += std::abs(x[i] - y[i]);
    ++n;
  }
  if (penumbra) *penumbra = n;
  return n ? sum / double(n) : 0.0;
}

// Every technique that sees the texture gives per-channel visibility near the oracle's, and the
// red and blue channels really differ (the texture matters: a technique ignoring it would give
// equal channels). The grey visibility is the radiance-weighted mean. Coverage is exact for one
// straight edge over a flat floor; Heckbert-Herf with 64 points is within its banding.
TEST(LightTexture, TechniquesSeeEachChannelOfTheLight) {
  const Scene scene = twoColourScene();
  TechniqueConfig oracle("reference");
  oracle.set("rays", "1024");
  const ChannelRun truth = run(scene, oracle);
  ASSERT_TRUE(truth.result.perChannel());
  long differing = 0;
  for (size_t i = 0; i < truth.result.channels[0].size(); ++i) {
    const float r = truth.result.channels[0][i], b = truth.result.channels[2][i];
    if (std::abs(r - b) > 0.3f) ++differing;
    EXPECT_NEAR(truth.result.visibility[i], 0.5f * (r + b), 1e-6f);
  }
  EXPECT_GT(differing, 20) << "the two halves of the light do not shadow differently";
  TechniqueConfig coverage("coverage");
  const ChannelRun cov = run(scene, coverage);
  ASSERT_TRUE(cov.result.perChannel());
  TechniqueConfig hh("heckbert-herf");
  hh.set("samples", "64");
  const ChannelRun avg = run(scene, hh);
  ASSERT_TRUE(avg.result.perChannel());
  for (int c : {0, 2}) {
    EXPECT_LT(channelMae(cov, truth, c), 0.006) << "coverage channel " << c;
    EXPECT_LT(channelMae(avg, truth, c), 0.012) << "heckbert-herf channel " << c;
  }
  // Hard techniques see only the centre: one visibility for every channel.
  EXPECT_FALSE(run(scene, TechniqueConfig("volume")).result.perChannel());
}

// A uniform texture changes nothing but the colour: coverage's channels equal its area
// visibility (same edges, same frame) to float rounding.
TEST(LightTexture, UniformTextureChannelsEqualTheUntexturedVisibility) {
  Scene textured = twoColourScene();
  textured.lights[0].texture = makeLightTexture(1, 1, {vec3(1.0f)}, "white");
  Scene plain = twoColourScene();
  plain.lights[0].texture = nullptr;
  const ChannelRun a = run(textured, TechniqueConfig("coverage"));
  const ChannelRun b = run(plain, TechniqueConfig("coverage"));
  ASSERT_TRUE(a.result.perChannel());
  for (int c = 0; c < 3; ++c) {
    for (size_t i = 0; i < b.result.visibility.size(); ++i) {
      ASSERT_NEAR(a.result.channels[size_t(c)][i], b.result.visibility[i], 2e-5f) << i;
    }
  }
}

// Shading takes the channels as three lights: a red-only visibility of 0 darkens only red.
TEST(LightTexture, ShadingUsesEachChannel) {
  const Scene scene = twoColourScene();
  const View view = scene.camera.makeView(scene.settings.width, scene.settings.height);
  Stats stats;
  const EyeBuffers eye = renderEyePass(scene, view, stats);
  ChannelVisibility channels;
  for (Image<float>& c : channels) c.resize(view.width, view.height, 1.0f);
  const Image<float> ones(view.width, view.height, 1.0f);
  const Image<vec3> lit = shadeFrame(scene, view, eye, {&ones});
  for (size_t i = 0; i < channels[0].size(); ++i) channels[0][i] = 0.0f;
  Image<vec3> dark;
  shadeFrameInto(scene, view, eye, {&ones}, dark, true, {&channels});
  const int x = view.width / 2 + 20, y = view.height / 2;
  EXPECT_GT(lit.at(x, y).x, dark.at(x, y).x + 0.05f);
  EXPECT_NEAR(lit.at(x, y).z, dark.at(x, y).z, 1e-6f);
}

// The scene file's texture: inline texels, refused on a sphere and with a wrong count, and a PNG
// file that does not exist named with the key path.
TEST(LightTexture, SceneFileTextureIsCheckedByKeyPath) {
  const Scene scene = twoColourScene();
  ASSERT_TRUE(scene.lights[0].texture);
  EXPECT_EQ(scene.lights[0].texture->width, 2);
  const auto parse = [](const std::string& light) {
    return errorMessage([&] {
      parseSceneJson(R"({"camera": {"position": [0, 6, 1], "target": [0, 0, 0]},
        "meshes": [{"generator": "box", "min": [-1, -1, -1], "max": [1, 0, 1]}],
        "lights": [)" + light + "]}",
                     "t.json", "");
    });
  };
  EXPECT_TRUE(contains(parse(R"({"center": [0, 3, 0], "radius": 0.5,
                                 "texture": {"width": 1, "height": 1, "texels": [[1, 1, 1]]}})"),
                       "lights[0].texture: only a rectangle light takes a texture"));
  EXPECT_TRUE(contains(parse(R"({"center": [0, 3, 0], "shape": "rectangle", "u": [1, 0, 0],
                                 "v": [0, 0, 1],
                                 "texture": {"width": 2, "height": 2, "texels": [[1, 1, 1]]}})"),
                       "lights[0].texture.texels: holds 1 texels, width x height is 4"));
  EXPECT_TRUE(contains(parse(R"({"center": [0, 3, 0], "shape": "rectangle", "u": [1, 0, 0],
                                 "v": [0, 0, 1], "texture": "missing-light.png"})"),
                       "lights[0].texture"));
  // A PNG beside the scene file: sRGB decoded to linear texels, its row 0 the texture's.
  test::ScratchDir dir;
  Image<vec3> png(2, 1, vec3(0.0f));
  png.at(0, 0) = vec3(1.0f, 0.0f, 0.0f);
  png.at(1, 0) = vec3(0.0f, 0.0f, 0.2f);
  writePng(dir.path() + "/glass.png", png);
  const std::string file = dir.write("lit.json", R"({"camera": {"position": [0, 6, 1], "target": [0, 0, 0]},
      "meshes": [{"generator": "box", "min": [-1, -1, -1], "max": [1, 0, 1]}],
      "lights": [{"center": [0, 3, 0], "shape": "rectangle", "u": [1, 0, 0], "v": [0, 0, 1],
                  "texture": "glass.png"}]})");
  const Scene loaded = loadSceneFile(file);
  ASSERT_TRUE(loaded.lights[0].texture);
  EXPECT_NEAR(loaded.lights[0].texture->texels[1].z, 0.2f, 0.01f);
  EXPECT_EQ(loaded.lights[0].texture->texels[0], vec3(1.0f, 0.0f, 0.0f));
}

}  // namespace test_light_texture
}  // namespace penumbra
