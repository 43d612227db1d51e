// docs/bad-input.md is kept true by the tests: every row names the test that checks it, every named test exists,
// and every BadInput test has its row.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <string>

namespace dpdrng_test::cli_test_bad_input_doc {

namespace {

std::set<std::string> registered_tests() {
  std::set<std::string> out;
  const auto* unit = ::testing::UnitTest::GetInstance();
  for (int i = 0; i < unit->total_test_suite_count(); ++i) {
    const auto* suite = unit->GetTestSuite(i);
    for (int j = 0; j < suite->total_test_count(); ++j)
      out.insert(std::string(suite->name()) + "." + suite->GetTestInfo(j)->name());
  }
  return out;
}

}  // namespace

TEST(BadInputDoc, EveryRowNamesAnExistingTestAndEveryBadInputTestHasARow) {
  std::ifstream in(std::string(DPDRNG_SOURCE_DIR) + "/docs/bad-input.md");
  ASSERT_TRUE(in) << "docs/bad-input.md is missing";
  const std::set<std::string> tests = registered_tests();
  const std::regex named("`([A-Za-z0-9_]+\\.[A-Za-z0-9_]+)`");
  std::set<std::string> in_doc;
  std::size_t rows = 0;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("| ", 0) != 0 || line.rfind("| class", 0) == 0) continue;
    ++rows;
    std::size_t here = 0;
    for (std::sregex_iterator m(line.begin(), line.end(), named), end; m != end; ++m) {
      const std::string t = (*m)[1];
      if (!tests.count(t)) continue;  // a code span that is not a test name (a flag like `--dt`)
      in_doc.insert(t);
      ++here;
    }
    EXPECT_GT(here, 0u) << "a row without a test: " << line;
  }
  EXPECT_GT(rows, 20u);
  for (const auto& t : tests)
    if (t.rfind("BadInput.", 0) == 0) {
      EXPECT_TRUE(in_doc.count(t)) << t << " has no row in docs/bad-input.md";
    }
}

}  // namespace dpdrng_test::cli_test_bad_input_doc
