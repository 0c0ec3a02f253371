#include "dynamap/planning/TargetSelection.hpp"

#include <gtest/gtest.h>

namespace dynamap::planning {
namespace {

TargetCandidate Candidate(TargetKind kind, GridIndex viewpoint, double score) {
  TargetCandidate c;
  c.kind = kind;
  c.viewpoint = viewpoint;
  c.region_center = viewpoint;
  c.score = score;
  return c;
}

const GridMap kMap(100, 100, 0.05);
const GridIndex kRobot{50, 50};

TEST(SelectTarget, WithoutACurrentTargetTakesTheBestScore) {
  const auto s = SelectTarget({Candidate(TargetKind::kFrontier, {80, 50}, 1.0),
                               Candidate(TargetKind::kInspection, {20, 50}, 2.0)},
                              std::nullopt, kMap, kRobot, {});
  ASSERT_TRUE(s.chosen);
  EXPECT_EQ(s.chosen->kind, TargetKind::kInspection);
  EXPECT_FALSE(s.kept_current);
}

TEST(SelectTarget, KeepsTheCurrentTargetAgainstASlightlyBetterOne) {
  const TargetCandidate current = Candidate(TargetKind::kFrontier, {80, 50}, 1.0);
  // Re-scored this plan: its viewpoint moved by two cells, and the other side now wins a bit.
  const auto s = SelectTarget({Candidate(TargetKind::kFrontier, {82, 51}, 1.1),
                               Candidate(TargetKind::kInspection, {20, 50}, 1.4)},
                              current, kMap, kRobot, {});
  ASSERT_TRUE(s.chosen);
  EXPECT_TRUE(s.kept_current);
  EXPECT_EQ(s.chosen->kind, TargetKind::kFrontier);
  EXPECT_EQ(s.chosen->viewpoint, (GridIndex{80, 50}));  // The goal cell does not creep.
  EXPECT_DOUBLE_EQ(s.chosen->score, 1.1);
}

TEST(SelectTarget, SwitchesWhenAnotherScoresClearlyBetter) {
  const TargetCandidate current = Candidate(TargetKind::kFrontier, {80, 50}, 1.0);
  const auto s = SelectTarget({Candidate(TargetKind::kFrontier, {80, 50}, 1.0),
                               Candidate(TargetKind::kInspection, {20, 50}, 1.6)},
                              current, kMap, kRobot, {});
  ASSERT_TRUE(s.chosen);
  EXPECT_FALSE(s.kept_current);
  EXPECT_EQ(s.chosen->kind, TargetKind::kInspection);
}

TEST(SelectTarget, KeepsARegionWhoseViewpointMovedAgainstOneAcrossTheMap) {
  TargetCandidate current = Candidate(TargetKind::kInspection, {80, 50}, 1.0);
  current.region_center = {90, 60};
  // Partly seen on the way, the region's best viewpoint is now 1.5 m from the old one.
  TargetCandidate moved = Candidate(TargetKind::kInspection, {80, 80}, 0.8);
  moved.region_center = {92, 62};
  const auto s = SelectTarget({moved, Candidate(TargetKind::kInspection, {10, 10}, 1.1)},
                              current, kMap, kRobot, {});
  ASSERT_TRUE(s.chosen);
  EXPECT_TRUE(s.kept_current);
  EXPECT_EQ(s.chosen->viewpoint, (GridIndex{80, 80}));  // The new viewpoint of the same region.
}

TEST(SelectTarget, SwitchesWhenTheCurrentTargetIsGone) {
  const TargetCandidate current = Candidate(TargetKind::kFrontier, {80, 50}, 5.0);
  const auto s = SelectTarget({Candidate(TargetKind::kFrontier, {80, 80}, 0.5),
                               Candidate(TargetKind::kInspection, {81, 50}, 0.4)},
                              current, kMap, kRobot, {});
  ASSERT_TRUE(s.chosen);
  EXPECT_FALSE(s.kept_current);  // Another kind at the same place is another target.
  EXPECT_EQ(s.chosen->viewpoint, (GridIndex{80, 80}));
}

TEST(SelectTarget, NeverChoosesAViewpointAtTheRobotsFeet) {
  const auto s = SelectTarget({Candidate(TargetKind::kFrontier, {51, 50}, 9.0),
                               Candidate(TargetKind::kFrontier, {70, 50}, 1.0)},
                              std::nullopt, kMap, kRobot, {});
  ASSERT_TRUE(s.chosen);
  EXPECT_EQ(s.chosen->viewpoint, (GridIndex{70, 50}));
  ASSERT_EQ(s.too_near.size(), 1u);
  EXPECT_EQ(s.too_near[0].viewpoint, (GridIndex{51, 50}));

  const auto none = SelectTarget({Candidate(TargetKind::kFrontier, {51, 50}, 9.0)},
                                 std::nullopt, kMap, kRobot, {});
  EXPECT_FALSE(none.chosen);
  EXPECT_EQ(none.too_near.size(), 1u);
  EXPECT_EQ(none.looked_from_here.size(), 1u);  // Nothing else: the robot looks from here.
}

TEST(SelectTarget, AViewpointPassedOnTheWayToAnotherTargetIsNotCountedAsLookedFrom) {
  // Seed 2 of the office: driving along the corridor to another target, the robot passed the
  // cell from which a side room is seen through its doorway.
  const TargetCandidate current = Candidate(TargetKind::kFrontier, {90, 50}, 1.0);
  TargetCandidate room = Candidate(TargetKind::kFrontier, {51, 50}, 2.0);
  room.region_center = {51, 80};
  const auto s = SelectTarget({Candidate(TargetKind::kFrontier, {90, 50}, 1.0), room},
                              current, kMap, kRobot, {});
  ASSERT_TRUE(s.chosen);
  EXPECT_EQ(s.chosen->viewpoint, (GridIndex{90, 50}));
  ASSERT_EQ(s.too_near.size(), 1u);
  EXPECT_TRUE(s.looked_from_here.empty());
}

TEST(SelectTarget, TheReachedCurrentTargetCountsAsLookedFrom) {
  // Reached: the region is still there and its viewpoint moved a little, within reach.
  const TargetCandidate current = Candidate(TargetKind::kInspection, {52, 50}, 1.0);
  TargetCandidate again = Candidate(TargetKind::kInspection, {50, 51}, 1.0);
  again.region_center = {52, 50};
  const auto s = SelectTarget({again, Candidate(TargetKind::kFrontier, {20, 50}, 0.5),
                               Candidate(TargetKind::kFrontier, {51, 51}, 0.7)},
                              current, kMap, kRobot, {});
  ASSERT_TRUE(s.chosen);
  EXPECT_EQ(s.chosen->viewpoint, (GridIndex{20, 50}));
  EXPECT_EQ(s.too_near.size(), 2u);
  ASSERT_EQ(s.looked_from_here.size(), 1u);  // Not the frontier of another kind beside it.
  EXPECT_EQ(s.looked_from_here[0].kind, TargetKind::kInspection);
}

TEST(SelectTarget, AReachedCurrentTargetIsNotKept) {
  // The robot stands on the current viewpoint; the region moved its viewpoint a little
  // further off. Keeping the old goal cell would hold the robot where it is for good.
  const TargetCandidate current = Candidate(TargetKind::kFrontier, {53, 50}, 1.0);
  const auto s = SelectTarget({Candidate(TargetKind::kFrontier, {58, 50}, 1.0),
                               Candidate(TargetKind::kInspection, {20, 50}, 1.2)},
                              current, kMap, kRobot, {});
  ASSERT_TRUE(s.chosen);
  EXPECT_FALSE(s.kept_current);
  EXPECT_EQ(s.chosen->kind, TargetKind::kInspection);
}

TEST(DroppedTargetKeeper, KeepsATargetThatDropsOutForTheGraceTimeThenLetsItGo) {
  DroppedTargetKeeper keeper;  // 10 s grace.
  const TargetCandidate wall = Candidate(TargetKind::kInspection, {90, 50}, 1.0);
  // Dropped out: no candidate near it, the planner would send the robot home.
  auto kept = keeper.Keep(wall, std::nullopt, {}, kMap, kRobot, 100.0);
  ASSERT_TRUE(kept);
  EXPECT_EQ(kept->region_center, wall.region_center);
  EXPECT_TRUE(keeper.Keep(wall, std::nullopt, {}, kMap, kRobot, 109.0));
  EXPECT_FALSE(keeper.Keep(wall, std::nullopt, {}, kMap, kRobot, 110.5));  // Given up.
}

TEST(DroppedTargetKeeper, LetsGoWhenReachedStillThereOrBeaten) {
  const TargetCandidate wall = Candidate(TargetKind::kInspection, {90, 50}, 1.0);
  const TargetCandidate other = Candidate(TargetKind::kFrontier, {10, 50}, 1.5);
  DroppedTargetKeeper keeper;
  // Reached: the robot stands at its viewpoint.
  EXPECT_FALSE(keeper.Keep(wall, std::nullopt, {}, kMap, {90, 51}, 0.0));
  // Still a candidate: selection takes care of it.
  EXPECT_FALSE(keeper.Keep(wall, other, {wall, other}, kMap, kRobot, 0.0));
  // Dropped out, another one not twice as good: kept; twice as good: that one.
  EXPECT_TRUE(keeper.Keep(wall, other, {other}, kMap, kRobot, 0.0));
  const TargetCandidate much_better = Candidate(TargetKind::kFrontier, {10, 50}, 2.0);
  EXPECT_FALSE(keeper.Keep(wall, much_better, {much_better}, kMap, kRobot, 1.0));
  // Nothing was being driven to.
  EXPECT_FALSE(keeper.Keep(std::nullopt, other, {other}, kMap, kRobot, 2.0));
}

TEST(DroppedTargetKeeper, TheGraceTimeStartsAgainOnceTheTargetIsBack) {
  DroppedTargetKeeper keeper;
  const TargetCandidate wall = Candidate(TargetKind::kInspection, {90, 50}, 1.0);
  EXPECT_TRUE(keeper.Keep(wall, std::nullopt, {}, kMap, kRobot, 0.0));
  EXPECT_FALSE(keeper.Keep(wall, wall, {wall}, kMap, kRobot, 8.0));  // Back among them.
  EXPECT_TRUE(keeper.Keep(wall, std::nullopt, {}, kMap, kRobot, 15.0));  // Out again.
  EXPECT_TRUE(keeper.Keep(wall, std::nullopt, {}, kMap, kRobot, 24.0));
  EXPECT_FALSE(keeper.Keep(wall, std::nullopt, {}, kMap, kRobot, 25.5));
}

}  // namespace
}  // namespace dynamap::planning
