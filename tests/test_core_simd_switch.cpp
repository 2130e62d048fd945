// PENUMBRA_SIMD=off must send every kernel down its scalar twin at run time: CI relies on it to
// test the scalar twins without a scalar-only build. If the switch did nothing, that CI run
// would test the SIMD kernels twice and a broken scalar twin would go unseen.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "cli_test_util.h"
#include "core/simd_dispatch.h"

namespace penumbra {
namespace test_core_simd_switch {

class SimdSwitch : public testing::CliTest {};

TEST_F(SimdSwitch, EnvironmentSendsTheKernelsScalarAndTheImageStaysTheSame) {
  if (!simdKernelsAvailable()) GTEST_SKIP() << "this run has no SIMD kernels to switch off";
  const std::string args = "render spheres --width 96 --height 64 --technique exact -q";
  const testing::CliRun simd = run(args + " -o simd.png --stats simd.json");
  ASSERT_EQ(simd.exit_code, 0) << simd.err;
  const testing::CliRun scalar =
      run(args + " -o scalar.png --stats scalar.json", "PENUMBRA_SIMD=off");
  ASSERT_EQ(scalar.exit_code, 0) << scalar.err;
  const auto simd_doc = nlohmann::json::parse(testing::slurp(path("simd.json")));
  const auto scalar_doc = nlohmann::json::parse(testing::slurp(path("scalar.json")));
  EXPECT_EQ(simd_doc["simd"], true);
  EXPECT_NE(simd_doc["simd_target"], "scalar");
  EXPECT_EQ(scalar_doc["simd"], false);
  EXPECT_EQ(scalar_doc["simd_target"], "scalar");
  // The twins round identically: the same picture, bit for bit.
  EXPECT_EQ(testing::slurp(path("simd.png")), testing::slurp(path("scalar.png")));
}

}  // namespace test_core_simd_switch
}  // namespace penumbra
