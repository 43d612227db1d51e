// Input decoding for the χ², t and correlation commands: formats, and every malformed input an InputError.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "dpdrng/common/error.hpp"
#include "dpdrng/rng/distribution.hpp"
#include "dpdrng/stats/input.hpp"

namespace dpdrng_test::stats_test_input {

using namespace dpdrng;
using namespace dpdrng::stats;

namespace {
template <class T>
std::vector<char> bytes_of(const std::vector<T>& v) {
  std::vector<char> b(v.size() * sizeof(T));
  std::memcpy(b.data(), v.data(), b.size());
  return b;
}
std::vector<double> text(const std::string& s) { return decode_values(std::span(s.data(), s.size()), InputFormat::text, "t"); }
}  // namespace

TEST(StatsInput, U64WordsGoThroughThe53BitMapping) {
  const std::vector<std::uint64_t> w{0, ~0ull, 1ull << 63, 0x0123456789abcdefull};
  const auto u = decode_values(bytes_of(w), InputFormat::u64, "w");
  ASSERT_EQ(u.size(), 4u);
  EXPECT_EQ(u[0], 0.0);
  EXPECT_EQ(u[1], 1.0 - 0x1p-53);
  EXPECT_EQ(u[2], 0.5);
  EXPECT_EQ(u[3], rng::to_unit(0x0123456789abcdefull));
}

TEST(StatsInput, TruncatedBinaryIsRejected) {
  auto b = bytes_of(std::vector<std::uint64_t>{1, 2});
  b.pop_back();
  EXPECT_THROW(decode_values(b, InputFormat::u64, "w"), InputError);
  EXPECT_THROW(decode_values(b, InputFormat::f64, "w"), InputError);
  EXPECT_THROW(decode_values(std::span<const char>{}, InputFormat::u64, "w"), InputError);  // no values
}

TEST(StatsInput, F64IsTakenAsIsButMustBeFinite) {
  EXPECT_EQ(decode_values(bytes_of(std::vector<double>{0.25, -3.5}), InputFormat::f64, "d"),
            (std::vector<double>{0.25, -3.5}));
  EXPECT_THROW(decode_values(bytes_of(std::vector<double>{0.25, std::nan("")}), InputFormat::f64, "d"), InputError);
  EXPECT_THROW(decode_values(bytes_of(std::vector<double>{std::numeric_limits<double>::infinity()}),
                             InputFormat::f64, "d"),
               InputError);
}

TEST(StatsInput, TextOneNumberALine) {
  EXPECT_EQ(text("0.5\n\n# a comment\n  0.25 \r\n+1e-3\n-2"), (std::vector<double>{0.5, 0.25, 1e-3, -2.0}));
  for (const char* bad : {"0.5\nabc\n", "0.5 0.6\n", "nan\n", "inf\n", "0.5x\n", "\n\n", ""})
    EXPECT_THROW(text(bad), InputError) << bad;
}

TEST(StatsInput, FormatNamesAndMissingFiles) {
  EXPECT_EQ(parse_input_format("u64"), InputFormat::u64);
  EXPECT_EQ(parse_input_format("text"), InputFormat::text);
  EXPECT_THROW(parse_input_format("hex"), InputError);
  EXPECT_THROW(read_values("/nonexistent/dpdrng-input", InputFormat::u64), InputError);
}

}  // namespace dpdrng_test::stats_test_input
