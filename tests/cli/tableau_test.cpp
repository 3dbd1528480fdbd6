// `springlab tableau` as a user runs it: the shipped table, one tableau's report, a student's own
// file, and bad input's one message with exit status 2.
#include <gtest/gtest.h>

#include <sstream>
#include <vector>

#include "cli/cli_support.hpp"

namespace springlab::test {
namespace {

TEST(TableauCommand, ListsTheShippedTableauxWithOrderAndLimits) {
  const Result r = springlab("tableau");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("rk4                Classic RK4"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("2.78529     2.82843"), std::string::npos) << r.out;
  // Every row's cells start where their heading does (the longest name sets a column's width:
  // "Qin and Zhang's symplectic DIRK" once ran into its kind).
  std::istringstream lines(r.out);
  std::string header;
  std::getline(lines, header);
  std::vector<std::size_t> starts;
  for (const char* heading :
       {"tableau", "kind", "order", "embedded", "real axis", "imaginary axis"})
    starts.push_back(header.find(heading));
  int rows = 0;
  for (std::string line; std::getline(lines, line) && line.rfind("(order", 0) != 0; ++rows)
    for (const std::size_t at : starts) {
      ASSERT_LT(at, line.size()) << line;
      EXPECT_TRUE(line[at - 1] == ' ' && line[at - 2] == ' ' && line[at] != ' ')
          << "column at " << at << ": " << line;
    }
  EXPECT_GE(rows, 15);
  const std::size_t sdirk2 = r.out.find("\nsdirk2 ");
  ASSERT_NE(sdirk2, std::string::npos);
  const std::string row = r.out.substr(sdirk2 + 1, r.out.find('\n', sdirk2 + 1) - sdirk2 - 1);
  EXPECT_EQ(row.substr(starts[0], 18), "Alexander's SDIRK2") << row;
  EXPECT_EQ(row.substr(starts[2], 5), "1 (2)") << row;
}

TEST(TableauCommand, ReportsAStudentsTableau) {
  TempDir dir;
  const auto file = dir.path / "heun-wrong.json";
  std::ofstream(file)
      << R"({"name": "Heun, one entry wrong", "A": [[0], ["1/2"]], "b": ["1/2", "1/2"], "order": 2})";
  const Result r = springlab("tableau '" + file.string() + "'");
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_NE(r.out.find("order       1, exactly"), std::string::npos) << r.out;
  EXPECT_NE(
      r.out.find("fails       order 2, tree [t]: sum b_i c_i = 1/2, but the tableau gives 1/4"),
      std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("R(z)        1 + z + 1/4 z^2"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("warning     the file states order 2, the conditions give 1"),
            std::string::npos)
      << r.out;
}

TEST(TableauCommand, BadInputExitsTwoWithOneMessage) {
  TempDir dir;
  const auto file = dir.path / "full.json";
  std::ofstream(file) << R"({"A": [["1/4", "1/4"], [0, "1/2"]], "b": ["1/2", "1/2"]})";
  const Result r = springlab("tableau '" + file.string() + "'");
  EXPECT_EQ(r.status, 2);
  EXPECT_TRUE(r.out.empty()) << r.out;
  EXPECT_NE(r.err.find("/A/0/1: A row 1, column 2 is 1/4, above the diagonal"), std::string::npos)
      << r.err;
  const Result missing = springlab("tableau rk5");
  EXPECT_EQ(missing.status, 2);
  EXPECT_NE(
      missing.err.find(
          "tableau 'rk5': no such file, and no shipped tableau of that name; did you mean 'rk4'?"),
      std::string::npos)
      << missing.err;
}

}  // namespace
}  // namespace springlab::test
