// The report's verdict: each line names the measured winner, ties as ties,
// and lines without data are left out.
#include "report/verdict.hpp"

#include <gtest/gtest.h>

namespace {

using penumbra::StudyFindings;
using penumbra::VerdictLine;

const VerdictLine* line(const std::vector<VerdictLine>& lines, const std::string& when) {
  for (const VerdictLine& l : lines) {
    if (l.when.rfind(when, 0) == 0) return &l;
  }
  return nullptr;
}

TEST(Verdict, NamesTheWinnerWithItsNumberAndTies) {
  StudyFindings f;
  f.light_size = 0.5f;
  f.rmse = {{"hard", 0.0475}, {"pcss", 0.02131}, {"msm", 0.02129}, {"esm", 0.0403}};
  f.map_bytes = {4, 4, 16, 4};
  f.contact_mae = {{"hard", 0.0256}, {"pcss", 0.0090}};
  const auto lines = penumbra::verdict_lines(f);
  const VerdictLine* overall = line(lines, "Closest");
  ASSERT_NE(overall, nullptr);
  EXPECT_EQ(overall->choice, "pcss and msm (tied)") << "0.02131 and 0.02129 both print 0.0213";
  EXPECT_EQ(overall->number, "0.0213");
  EXPECT_EQ(overall->section, "errors");
  // The memory line looks only at the techniques with the fewest bytes.
  const VerdictLine* memory = line(lines, "Tight memory");
  ASSERT_NE(memory, nullptr);
  EXPECT_EQ(memory->choice, "pcss");
  EXPECT_NE(memory->after.find("4 bytes"), std::string::npos);
  const VerdictLine* contact = line(lines, "Hard contact");
  ASSERT_NE(contact, nullptr);
  EXPECT_EQ(contact->choice, "pcss");
  EXPECT_EQ(contact->number, "0.0090");
  EXPECT_EQ(contact->section, "closeups");
  // No data, no line.
  EXPECT_EQ(line(lines, "Wide soft"), nullptr);
  EXPECT_EQ(line(lines, "Large scenes"), nullptr);
  EXPECT_EQ(line(lines, "Most quality"), nullptr);
}

TEST(Verdict, QualityPerMillisecondIsTheCheapestGoodPointOfTheFront) {
  StudyFindings f;
  // The front: 1 ms at 0.09 (too far from the best), 2 ms at 0.03, 5 ms at 0.02.
  f.pareto = {{"hard", {1.0, 0.09}}, {"pcf", {2.0, 0.03}}, {"pcss", {5.0, 0.02}}};
  const auto lines = penumbra::verdict_lines(f);
  const VerdictLine* cost = line(lines, "Most quality");
  ASSERT_NE(cost, nullptr);
  EXPECT_EQ(cost->choice, "pcf");
  EXPECT_EQ(cost->number, "2.00");
  EXPECT_EQ(cost->section, "timings");
  EXPECT_EQ(cost->after.find("emulated"), std::string::npos);
  EXPECT_EQ(cost->when, "Most quality per millisecond");
  // Times of an emulated GPU are not a GPU ranking, and the line says so
  // where it is read.
  f.software_times = true;
  const auto emulated = penumbra::verdict_lines(f);
  EXPECT_EQ(line(emulated, "Most quality")->when,
            "Most quality per millisecond (CPU emulation, not a GPU ranking)");
  EXPECT_NE(line(emulated, "Most quality")->after.find("emulated on the CPU"), std::string::npos);
}

TEST(Verdict, AFoliageLineIsKeptWhenGiven) {
  StudyFindings f;
  EXPECT_TRUE(penumbra::verdict_lines(f).empty());
  f.foliage = VerdictLine{"Foliage", "msm", "RMSE ", "0.0100", ".", "foliage", "section 9"};
  const auto lines = penumbra::verdict_lines(f);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines.front().section, "foliage");
}

}  // namespace
