// The 2004 evaluation sweep (evaluation/sweep.h, evaluation/sweep_report.h) on a tiny image:
// one row per configuration, exact integer counters that do not depend on the repetition, and
// culling that changes no pixel.
#include <gtest/gtest.h>

#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "evaluation/sweep.h"
#include "evaluation/sweep_report.h"

namespace penumbra {
namespace test_sweep {

SweepOptions tinySweep() {
  SweepOptions o;
  o.scenes = {"columns"};
  o.width = 96;
  o.height = 64;
  o.repeat = 2;
  o.tile_levels = {2, 5};
  o.oracle_rays = 0;
  return o;
}

const SweepResult& tinyResult() {
  static const SweepResult result = runSweep(tinySweep());
  return result;
}

std::vector<std::string> split(const std::string& line, char separator) {
  std::vector<std::string> fields;
  std::stringstream in(line);
  std::string field;
  while (std::getline(in, field, separator)) fields.push_back(field);
  return fields;
}

TEST(Sweep, OneRowPerConfiguration) {
  const SweepResult& r = tinyResult();
  // 2 implementations x 3 culling modes x 2 tile levels, plus the 2002 algorithm.
  ASSERT_EQ(r.rows.size(), 2u * 3u * 2u + 1u);
  for (const std::string kind : {kSweepThreePass, kSweepSinglePass})
    for (CullMode cull : {CullMode::None, CullMode::ZMax, CullMode::Full})
      for (int level : {2, 5}) {
        int found = 0;
        for (const SweepRow& row : r.rows)
          found += row.kind == kind && row.cull == cull && row.tile_level == level;
        EXPECT_EQ(found, 1) << kind << " " << cullModeName(cull) << " " << level;
      }
  int original = 0;
  for (const SweepRow& row : r.rows) {
    original += row.kind == kSweep2002;
    EXPECT_EQ(row.scene, "columns");
    EXPECT_EQ(row.width, 96);
    EXPECT_EQ(row.height, 64);
    EXPECT_EQ(row.runs, 2);
    EXPECT_GE(row.technique_ms_max, row.technique_ms);
    EXPECT_LE(row.technique_ms_min, row.technique_ms);
    EXPECT_GT(row.counters.wedges, 0u);
  }
  EXPECT_EQ(original, 1);
}

TEST(Sweep, CountersDoNotDependOnRepetition) {
  for (const SweepRow& row : tinyResult().rows)
    EXPECT_TRUE(row.counters_repeatable)
        << row.techniqueLabel() << " " << cullModeName(row.cull) << " " << row.tile_level;
  // And not on the sweep either: a second sweep with one run gives the same counters.
  SweepOptions once = tinySweep();
  once.repeat = 1;
  once.original_2002 = false;
  const SweepResult again = runSweep(once);
  for (const SweepRow& row : again.rows) {
    bool matched = false;
    for (const SweepRow& first : tinyResult().rows) {
      if (first.kind != row.kind || first.cull != row.cull || first.tile_level != row.tile_level)
        continue;
      matched = true;
      EXPECT_TRUE(first.counters.sameCounters(row.counters))
          << row.techniqueLabel() << " " << cullModeName(row.cull) << " " << row.tile_level;
    }
    EXPECT_TRUE(matched);
  }
}

TEST(Sweep, CullingChangesNoPixelAndNoWrite) {
  const SweepResult& r = tinyResult();
  EXPECT_EQ(r.cullMismatches(), 0u);
  for (const SweepRow& row : r.rows) {
    if (row.kind == kSweep2002) {
      EXPECT_EQ(row.cull_mismatch_pixels, -1);
      continue;
    }
    EXPECT_EQ(row.cull_mismatch_pixels, 0)
        << row.techniqueLabel() << " " << cullModeName(row.cull) << " " << row.tile_level;
  }
  // Culling only skips pixels that receive nothing (2004 paper, section 7: "the number of
  // stencil buffer write accesses is unaffected by occlusion culling"), so writes and the
  // pixels truly inside a wedge are the same in every mode, and culling never adds a read.
  for (const SweepRow& a : r.rows) {
    for (const SweepRow& b : r.rows) {
      if (a.kind != b.kind || a.tile_level != b.tile_level || a.kind == kSweep2002)
        continue;
      EXPECT_EQ(a.counters.stencil_writes, b.counters.stencil_writes);
      EXPECT_EQ(a.counters.penumbra_inside, b.counters.penumbra_inside);
      if (a.cull == CullMode::None && b.cull != CullMode::None) {
        EXPECT_LE(b.counters.z_reads, a.counters.z_reads);
        EXPECT_LE(b.counters.penumbra_tests, a.counters.penumbra_tests);
      }
      if (a.cull == CullMode::ZMax && b.cull == CullMode::Full) {
        EXPECT_LE(b.counters.penumbra_tests, a.counters.penumbra_tests);
      }
    }
  }
}

TEST(Sweep, CsvHasOneIntegerLinePerRow) {
  const SweepResult& r = tinyResult();
  std::stringstream csv;
  writeSweepCsv(csv, r);
  std::string line;
  ASSERT_TRUE(std::getline(csv, line));
  const std::vector<std::string> header = split(line, ',');
  auto column = [&](const std::string& name) {
    for (size_t i = 0; i < header.size(); ++i)
      if (header[i] == name) return int(i);
    ADD_FAILURE() << "no column " << name;
    return 0;
  };
  const std::vector<int> integer_columns = {
      column("z_reads"),         column("stencil_writes"), column("memory_accesses"),
      column("tiles_tested"),    column("tiles_culled"),   column("penumbra_tests"),
      column("penumbra_inside"), column("tile_level"),     column("tile_size")};
  const int z_reads = column("z_reads"), writes = column("stencil_writes");
  const int accesses = column("memory_accesses");
  size_t lines = 0;
  while (std::getline(csv, line)) {
    const std::vector<std::string> fields = split(line, ',');
    ASSERT_EQ(fields.size(), header.size()) << line;
    for (int c : integer_columns) {
      ASSERT_FALSE(fields[c].empty());
      EXPECT_EQ(fields[c].find_first_not_of("0123456789"), std::string::npos)
          << header[c] << " = " << fields[c];
    }
    EXPECT_EQ(std::stoull(fields[accesses]),
              std::stoull(fields[z_reads]) + std::stoull(fields[writes]));
    ++lines;
  }
  EXPECT_EQ(lines, r.rows.size());
  EXPECT_NE(sweepSummaryMarkdown(r).find("| columns | wedge-3pass |"), std::string::npos);
}

TEST(Sweep, SummaryRatiosComeFromTheRows) {
  const SweepResult& r = tinyResult();
  const std::vector<SweepSceneSummary> s = summarizeSweep(r);
  ASSERT_EQ(s.size(), 1u);
  ASSERT_EQ(s[0].implementations.size(), 2u);
  for (const auto& impl : s[0].implementations) {
    EXPECT_TRUE(impl.best_level_memory == 2 || impl.best_level_memory == 5);
    EXPECT_GT(impl.restructured_speedup, 0.0);
    EXPECT_GT(impl.culling_speedup, 0.0);
    // Culling can only lower the tests per inside pixel: each mode tests a subset.
    EXPECT_GE(impl.none_tests_per_inside, impl.full_tests_per_inside);
    EXPECT_GE(impl.full_tests_per_inside, 1.0);
  }
}

TEST(Sweep, RejectsBadOptions) {
  SweepOptions o = tinySweep();
  o.tile_levels = {9};
  EXPECT_THROW(runSweep(o), Error);
  o = tinySweep();
  o.repeat = 0;
  EXPECT_THROW(runSweep(o), Error);
  o = tinySweep();
  o.scenes = {"no-such-scene"};
  EXPECT_THROW(runSweep(o), Error);
  o = tinySweep();
  o.implementations = {"volume"};
  EXPECT_THROW(runSweep(o), Error);
}

}  // namespace test_sweep
}  // namespace penumbra
