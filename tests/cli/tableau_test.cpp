// `springlab tableau` as a user runs it: the shipped table, one tableau's report, a student's own
// file, and bad input's one message with exit status 2.
#include <gtest/gtest.h>

#include "cli/cli_support.hpp"

namespace springlab::test {
namespace {

TEST(TableauCommand, ListsTheShippedTableauxWithOrderAndLimits) {
  const Result r = springlab("tableau");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("rk4                Classic RK4"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("2.78529     2.82843"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("sdirk2             Alexander's SDIRK2           diagonally implicit, 2 stages  1 (2)"),
            std::string::npos) << r.out;
}

TEST(TableauCommand, ReportsAStudentsTableau) {
  TempDir dir;
  const auto file = dir.path / "heun-wrong.json";
  std::ofstream(file) << R"({"name": "Heun, one entry wrong", "A": [[0], ["1/2"]], "b": ["1/2", "1/2"], "order": 2})";
  const Result r = springlab("tableau '" + file.string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("order       1, exactly"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("fails       order 2, tree [t]: sum b_i c_i = 1/2, but the tableau gives 1/4"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("R(z)        1 + z + 1/4 z^2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("warning     the file states order 2, the conditions give 1"), std::string::npos) << r.out;
}

TEST(TableauCommand, BadInputExitsTwoWithOneMessage) {
  TempDir dir;
  const auto file = dir.path / "full.json";
  std::ofstream(file) << R"({"A": [["1/4", "1/4"], [0, "1/2"]], "b": ["1/2", "1/2"]})";
  const Result r = springlab("tableau '" + file.string() + "'");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_NE(r.err.find("/A/0/1: A row 1, column 2 is 1/4, above the diagonal"), std::string::npos) << r.err;
  const Result missing = springlab("tableau rk5");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(missing.err.find("tableau 'rk5': no such file, and no shipped tableau of that name; did you mean 'rk4'?"),
            std::string::npos) << missing.err;
}

}  // namespace
}  // namespace springlab::test
