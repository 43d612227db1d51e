// The one parser for numbers typed by a user: decimal only, nothing clamped or wrapped, ranges in words.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <limits>
#include <string>

#include "dpdrng/common/error.hpp"
#include "dpdrng/common/numbers.hpp"

namespace dpdrng_test::common_test_numbers {

using namespace dpdrng;

namespace {

std::string error_of(auto&& parse) {
  try {
    parse();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(Numbers, DecimalOnlyNoOctalNoHex) {
  EXPECT_EQ(parse_number<std::uint64_t>("010", "--start"), 10u);  // strtoull(base 0) would read 8
  EXPECT_EQ(parse_number<int>("-007", "--x"), -7);
  EXPECT_EQ(parse_number<int>("+5", "--x"), 5);
  EXPECT_NE(error_of([] { parse_number<std::uint64_t>("0x10", "--start"); }).find("not a decimal integer"),
            std::string::npos);
  for (const char* bad : {"", "-", "1e3", "1.0", " 1", "1 ", "12a", "0b1", "--1"})
    EXPECT_NE(error_of([&] { parse_number<int>(bad, "--x"); }), "") << bad;
}

TEST(Numbers, TheWholeRangeOfATypeAndNotOneMore) {
  EXPECT_EQ(parse_number<std::uint64_t>("18446744073709551615", "--start"), std::numeric_limits<std::uint64_t>::max());
  EXPECT_EQ(parse_number<std::int64_t>("-9223372036854775808", "--x"), std::numeric_limits<std::int64_t>::min());
  const std::string e = error_of([] { parse_number<std::uint64_t>("18446744073709551616", "--start"); });
  EXPECT_EQ(e, "--start: '18446744073709551616' is out of range: expected an integer from 0 to 2^64 - 1");
  EXPECT_NE(error_of([] { parse_number<std::uint64_t>("-1", "--count"); }).find("'-1' is out of range"),
            std::string::npos);
  EXPECT_NE(error_of([] { parse_number<int>("2147483648", "--x"); }).find("-2^31 to 2^31 - 1"), std::string::npos);
  // Hundreds of digits are refused without echoing them whole.
  const std::string huge(300, '9');
  const std::string msg = error_of([&] { parse_number<std::uint64_t>(huge, "--per"); });
  EXPECT_NE(msg.find("out of range"), std::string::npos);
  EXPECT_LT(msg.size(), 120u) << msg;
}

TEST(Numbers, NarrowedRangesAreStatedInWords) {
  EXPECT_EQ(error_of([] { parse_number<std::size_t>("0", "--per", {1, std::numeric_limits<std::size_t>::max()}); }),
            "--per: '0' is out of range: expected an integer from 1 to 2^64 - 1");
  EXPECT_EQ(error_of([] { parse_number<int>("1025", "--threads", {0, 1024}); }),
            "--threads: '1025' is out of range: expected an integer from 0 to 1024");
  EXPECT_EQ(parse_list<std::uint32_t>("3,4,5,6", "--key"), (std::vector<std::uint32_t>{3, 4, 5, 6}));
  EXPECT_NE(error_of([] { parse_list<std::uint32_t>("3,,5", "--key"); }), "");
  EXPECT_NE(error_of([] { parse_list<std::uint32_t>("4294967296", "--key"); }).find("2^32 - 1"), std::string::npos);
}

TEST(Numbers, RealsAreFiniteAndInRange) {
  EXPECT_EQ(parse_real("0.04", "--dt"), 0.04);
  EXPECT_EQ(parse_real("+1e-3", "--dt"), 1e-3);
  for (const char* bad : {"nan", "inf", "-inf", "1e400", "0x1p3", "", "1,5", "1.5.2"})
    EXPECT_NE(error_of([&] { parse_real(bad, "--dt"); }), "") << bad;
  const RealRange open01{0, 1, true, true};
  EXPECT_EQ(error_of([&] { parse_real("-1", "--alpha", open01); }),
            "--alpha: '-1' is out of range: expected a number within (0, 1)");
  EXPECT_NE(error_of([&] { parse_real("1", "--alpha", open01); }), "");
  EXPECT_NE(error_of([&] { parse_real("0", "--alpha", open01); }), "");
  EXPECT_EQ(describe(RealRange{0, std::numeric_limits<double>::infinity(), true, false}), "a number > 0");
  EXPECT_EQ(describe(RealRange{}), "a finite number");
}

TEST(Numbers, ExactDecimalKeepsPrintfWhereExactAndRoundTripsEverywhere) {
  // %g where it reads back as the same double: the names stores already carry.
  EXPECT_EQ(exact_decimal(0.04), "0.04");
  EXPECT_EQ(exact_decimal(0.01), "0.01");
  EXPECT_EQ(exact_decimal(1e-5), "1e-05");
  EXPECT_EQ(exact_decimal(-1e-300), "-1e-300");
  EXPECT_EQ(exact_decimal(1e308), "1e+308");
  // Where %g's 6 digits lose bits: the shortest decimal that reads back (Steele & White / Ryu's definition).
  EXPECT_EQ(exact_decimal(0.0400000001), "0.0400000001");
  EXPECT_EQ(exact_decimal(0.1 + 0.2), "0.30000000000000004");
  std::mt19937_64 g(3);
  for (int i = 0; i < 10000; ++i) {
    const double x = std::bit_cast<double>(g());
    if (!std::isfinite(x)) continue;
    EXPECT_EQ(std::strtod(exact_decimal(x).c_str(), nullptr), x) << exact_decimal(x);
  }
}

TEST(Numbers, QuotedInputIsOneLineOfText) {
  EXPECT_EQ(quote_input("runs"), "'runs'");
  EXPECT_EQ(quote_input(std::string("a\0b\x01\xff", 5)), "'a\\x00b\\x01\\xff'");
  EXPECT_EQ(quote_input("it's"), "'it\\x27s'");
  EXPECT_EQ(quote_input("\xce\xbb=0.5"), "'\xce\xbb=0.5'");  // UTF-8 (lambda) is kept
  EXPECT_EQ(quote_input(std::string(30, 'x')), "'" + std::string(24, 'x') + "...'");
}

}  // namespace dpdrng_test::common_test_numbers
