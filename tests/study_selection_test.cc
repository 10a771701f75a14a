// The study's selection: the greedy set against brute force over every set of
// the same size, the objective's lexicographic order (items covered first,
// then lead) and its submodularity, which is what makes greedy sound.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "study/study_answers.h"
#include "study/study_selection.h"

namespace proxsim {
namespace {

// A random instance: each of n candidates detects each item with probability p, with a lead in [0, 2] m.
Coverage RandomCoverage(std::mt19937& rng, std::size_t n, std::size_t items, double p) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  Coverage coverage;
  coverage.items = items;
  coverage.covers.resize(n);
  coverage.lead_m.resize(n);
  for (std::size_t c = 0; c < n; ++c) {
    for (std::size_t i = 0; i < items; ++i) {
      if (unit(rng) >= p) continue;
      coverage.covers[c].push_back(i);
      coverage.lead_m[c].push_back(2.0 * unit(rng));
    }
  }
  coverage.lead_scale_m = (items + 1.0) * 2.0;
  return coverage;
}

// The best value over every set of k of the n candidates.
double BruteForceBest(const Coverage& coverage, std::size_t k) {
  const std::size_t n = coverage.covers.size();
  std::vector<bool> pick(n, false);
  std::fill(pick.begin(), pick.begin() + static_cast<long>(k), true);
  double best = 0;
  do {
    std::vector<std::size_t> set;
    for (std::size_t c = 0; c < n; ++c)
      if (pick[c]) set.push_back(c);
    best = std::max(best, SelectionValue(coverage, set));
  } while (std::prev_permutation(pick.begin(), pick.end()));
  return best;
}

std::size_t ItemsCovered(const Coverage& coverage, const std::vector<std::size_t>& set) {
  std::vector<bool> covered(coverage.items, false);
  for (std::size_t c : set)
    for (std::size_t i : coverage.covers[c]) covered[i] = true;
  return static_cast<std::size_t>(std::count(covered.begin(), covered.end(), true));
}

TEST(StudySelectionTest, GreedyIsWithinOneMinusOneOverEOfBruteForceAndExactForOneSensor) {
  std::mt19937 rng(20261123);
  double worst_ratio = 1.0;
  for (int instance = 0; instance < 200; ++instance) {
    const Coverage coverage = RandomCoverage(rng, 9, 14, 0.25);
    std::vector<std::size_t> rank(9);
    for (std::size_t c = 0; c < rank.size(); ++c) rank[c] = c;
    for (std::size_t k = 1; k <= 4; ++k) {
      const auto greedy = GreedySelection(coverage, k, rank, std::vector<bool>(9, true));
      const double best = BruteForceBest(coverage, k);
      const double value = SelectionValue(coverage, greedy);
      if (k == 1) EXPECT_DOUBLE_EQ(value, best) << "instance " << instance;
      ASSERT_LE(value, best + 1e-12);
      if (best > 0) worst_ratio = std::min(worst_ratio, value / best);
    }
  }
  EXPECT_GE(worst_ratio, 1.0 - 1.0 / std::exp(1.0));
}

TEST(StudySelectionTest, OnDisjointCoverageGreedyFindsTheBestSet) {
  // the classic case where greedy is optimal: candidates cover disjoint blocks
  Coverage coverage;
  coverage.items = 10;
  coverage.covers = {{0, 1, 2, 3}, {4, 5, 6}, {7, 8}, {9}, {0, 4}};
  for (const auto& items : coverage.covers) coverage.lead_m.push_back(std::vector<double>(items.size(), 1.0));
  coverage.lead_scale_m = 22.0;
  const std::vector<std::size_t> rank = {0, 1, 2, 3, 4};
  const auto greedy = GreedySelection(coverage, 3, rank, std::vector<bool>(5, true));
  EXPECT_EQ(greedy, (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_DOUBLE_EQ(SelectionValue(coverage, greedy), BruteForceBest(coverage, 3));
}

TEST(StudySelectionTest, MoreItemsCoveredAlwaysBeatsLongerLeads) {
  std::mt19937 rng(7);
  for (int instance = 0; instance < 100; ++instance) {
    const Coverage coverage = RandomCoverage(rng, 6, 10, 0.3);
    for (std::size_t a = 0; a < 6; ++a) {
      for (std::size_t b = 0; b < 6; ++b) {
        const std::size_t items_a = ItemsCovered(coverage, {a}), items_b = ItemsCovered(coverage, {b});
        if (items_a > items_b) EXPECT_GT(SelectionValue(coverage, {a}), SelectionValue(coverage, {b}));
      }
    }
  }
}

TEST(StudySelectionTest, TheObjectiveIsMonotoneAndSubmodular) {
  // f(A ∪ {x}) − f(A) ≥ f(B ∪ {x}) − f(B) for A ⊆ B, and f(A) ≤ f(B)
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> coin(0, 1);
  for (int instance = 0; instance < 300; ++instance) {
    const Coverage coverage = RandomCoverage(rng, 7, 12, 0.3);
    std::vector<std::size_t> a, b;
    for (std::size_t c = 0; c < 6; ++c) {
      const bool in_b = coin(rng), in_a = in_b && coin(rng);
      if (in_a) a.push_back(c);
      if (in_b) b.push_back(c);
    }
    auto with_x = [](std::vector<std::size_t> set) {
      set.push_back(6);
      return set;
    };
    EXPECT_LE(SelectionValue(coverage, a), SelectionValue(coverage, b) + 1e-12);
    EXPECT_GE(SelectionValue(coverage, with_x(a)) - SelectionValue(coverage, a),
              SelectionValue(coverage, with_x(b)) - SelectionValue(coverage, b) - 1e-12);
  }
}

TEST(StudySelectionTest, IneligibleCandidatesAreNeverPickedAndUselessOnesStopTheSelection) {
  Coverage coverage;
  coverage.items = 3;
  coverage.covers = {{0, 1, 2}, {0}, {1}, {}};
  coverage.lead_m = {{1, 1, 1}, {0.5}, {0.5}, {}};
  coverage.lead_scale_m = 8.0;
  const std::vector<std::size_t> rank = {0, 1, 2, 3};
  const auto picked = GreedySelection(coverage, 4, rank, {false, true, true, true});
  EXPECT_EQ(picked, (std::vector<std::size_t>{1, 2}));  // 0 is not eligible; 3 adds nothing
}

TEST(StudySelectionTest, ConfidenceIntervalFollowsStudentsT) {
  // three values 1, 2, 3: mean 2, s = 1, t(0.975, 2) = 4.303, half-width 4.303/√3
  const MeanCi ci = MeanWithCi95({1.0, 2.0, 3.0});
  EXPECT_DOUBLE_EQ(ci.mean, 2.0);
  EXPECT_NEAR(ci.ci95, 4.302652729911275 / std::sqrt(3.0), 1e-9);  // Boost.Math, against the published 4.3027
  EXPECT_EQ(MeanWithCi95({0.3, 0.3, 0.3}).ci95, 0.0);  // equal values: no spread, not rounding noise
  EXPECT_TRUE(std::isnan(MeanWithCi95({}).mean));
}

}  // namespace
}  // namespace proxsim
