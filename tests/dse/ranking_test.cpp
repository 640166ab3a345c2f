// Pareto ranking and the statistics of replicates.
#include <cstdlib>
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "impl/dse/objectives.hpp"
#include "impl/dse/pareto.hpp"

using namespace swarmcheck::dse;

namespace {

// One seed for every run (an RC_PARAMS in the environment wins): CI and a developer see the
// same cases.
const bool kSeededDseRankingTest = [] { return ::setenv("RC_PARAMS", "seed=17", 0) == 0; }();
bool dominates(const RankInput& a, const RankInput& b) {
  bool better = false;
  for (std::size_t d = 0; d < a.values.size(); ++d) {
    if (a.values[d] < b.values[d]) return false;
    better = better || a.values[d] > b.values[d];
  }
  return better;
}
}  // namespace

TEST(Pareto, StaircaseOfFrontsAndUnrankedPoints) {
  const std::vector<RankInput> in{{true, {1, 5}}, {true, {2, 4}}, {true, {3, 3}}, {true, {2, 2}},
                                  {true, {1, 1}}, {false, {9, 9}}, {true, {3, 3}}};
  EXPECT_EQ(pareto_ranks(in), (std::vector<int32_t>{1, 1, 1, 2, 3, 0, 1}));   // equal points share a rank
}

RC_GTEST_PROP(Pareto, RankOneIsUndominatedAndEveryLaterRankIsDominatedByThePreviousOne, ()) {
  const auto dims = *rc::gen::inRange<std::size_t>(1, 4);
  const auto n = *rc::gen::inRange<std::size_t>(0, 40);
  std::vector<RankInput> in(n);
  for (auto& p : in) {
    p.ranked = *rc::gen::weightedElement<bool>({{9, true}, {1, false}});
    for (std::size_t d = 0; d < dims; ++d) p.values.push_back(*rc::gen::inRange(0, 5));   // small range: many ties
  }
  const std::vector<int32_t> rank = pareto_ranks(in);
  for (std::size_t i = 0; i < n; ++i) {
    RC_ASSERT((rank[i] == 0) == !in[i].ranked);
    if (!in[i].ranked) continue;
    for (std::size_t j = 0; j < n; ++j)
      if (in[j].ranked && dominates(in[j], in[i])) RC_ASSERT(rank[j] < rank[i]);
    if (rank[i] > 1) {
      bool by_previous = false;
      for (std::size_t j = 0; j < n; ++j) by_previous = by_previous || (rank[j] == rank[i] - 1 && dominates(in[j], in[i]));
      RC_ASSERT(by_previous);
    }
  }
}

TEST(Replicates, MeanAndStudentInterval) {
  EXPECT_DOUBLE_EQ(student_t_975(1), 12.706204736);
  EXPECT_DOUBLE_EQ(student_t_975(4), 2.776445105);
  EXPECT_NEAR(student_t_975(60), 2.000297822, 2e-5);
  EXPECT_NEAR(student_t_975(1000), 1.962339, 2e-5);
  DseConfig c;
  c.objectives.push_back(Objective{"e", "eP", Column{Series::eP, -1, "eP"}, Function::max});
  c.objectives.push_back(Objective{"done", "completion_step", Column{Series::completion_step, -1, "completion_step"}, Function::max});
  PointRuns p;
  for (const double v : {1.0, 2.0, 3.0}) {
    RunOutputs r;
    r.columns.push_back({"eP", Aggregate{0, v, 0}});
    r.completion_step = v == 2.0 ? std::nullopt : std::optional<int64_t>(10);
    p.runs.push_back(r);
  }
  const auto v = objective_values(c, p);
  EXPECT_EQ(v[0].mean, 2.0);
  EXPECT_EQ(v[0].runs, (std::vector<double>{1, 2, 3}));
  EXPECT_DOUBLE_EQ(*v[0].ci95, 4.302652730 / std::sqrt(3.0));
  EXPECT_FALSE(v[1].present);   // one replicate did not complete
}
