// The one number reader (numerics/number_text.hpp): every rule and message.
#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "numerics/number_text.hpp"

using namespace rocking::numerics;

namespace {

NumberProblem problem_of(const std::string& text) { return read_number(text).problem; }

std::string message_of(const std::string& text) { return number_problem(text, problem_of(text)); }

std::string whole_error(const std::string& text, long long lo, long long hi) {
    try {
        whole_number(text, lo, hi);
    } catch (const std::invalid_argument& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(NumberText, NumbersAsDecimalTextWritesThem) {
    EXPECT_EQ(read_number("0.1").value, 0.1);
    EXPECT_EQ(read_number("+1").value, 1.0);
    EXPECT_EQ(read_number("-2.5e3").value, -2500.0);
    EXPECT_EQ(read_number(".5").value, 0.5);
    EXPECT_EQ(read_number("5.").value, 5.0);
    EXPECT_EQ(read_number("1E-2").value, 0.01);
    EXPECT_EQ(read_number("1e+2").value, 100.0);
    EXPECT_TRUE(std::signbit(read_number("-0").value));
    EXPECT_EQ(read_number("1.7976931348623157e308").value, DBL_MAX);
    EXPECT_EQ(read_number("2.2250738585072014e-308").value, DBL_MIN);
    for (const char* t : {"0.1", "+1", ".5", "5.", "-0", "0", "1e308", "-1e-307"})
        EXPECT_EQ(problem_of(t), NumberProblem::none) << t;
}

TEST(NumberText, BlanksAtEitherEndAlikeNotInside) {
    for (const char* t : {" 0.1", "0.1 ", " 0.1 ", "\t0.1", "0.1\t", "0.1\r\n", "\t 0.1 \t"}) {
        EXPECT_EQ(problem_of(t), NumberProblem::none) << "'" << t << "'";
        EXPECT_EQ(read_number(t).value, 0.1) << "'" << t << "'";
    }
    for (const char* t : {"0. 1", "1 2", "- 1", "1e 3"}) EXPECT_EQ(problem_of(t), NumberProblem::not_a_number) << t;
}

TEST(NumberText, WhatIsNotReadIsNotANumber) {
    for (const char* t : {"", " ", "\t", "1e", "1e+", "e5", ".", "-", "+", "+-1", "--1", "++1", "1,5", "0x10", "0x1p3",
                          "-0x10", "abc", "0.1x", "1d3", "nan(1)", "infinite", "1.2.3"})
        EXPECT_EQ(problem_of(t), NumberProblem::not_a_number) << "'" << t << "'";
    EXPECT_EQ(message_of("abc"), "'abc' is not a number");
    EXPECT_EQ(message_of("1e"), "'1e' is not a number");
    EXPECT_EQ(message_of(""), "'' is empty, not a number");
    // A byte that is not printable ASCII shows as \xNN (a tab, a NUL, a CR).
    EXPECT_EQ(message_of(" \t"), "' \\x09' is empty, not a number");
    EXPECT_EQ(message_of(std::string("1\0" "2", 3)), "'1\\x002' is not a number");
    EXPECT_EQ(message_of(std::string(50, 'a')), "'" + std::string(40, 'a') + "... (50 bytes)' is not a number");
    EXPECT_EQ(message_of("1,5"), "'1,5' is not a number (decimal commas are not read)");
    EXPECT_EQ(message_of("0x10"), "'0x10' is not a number (hexadecimal is not read)");
    EXPECT_EQ(message_of("-0X1p3"), "'-0X1p3' is not a number (hexadecimal is not read)");
}

TEST(NumberText, NanAndInfinityAreNotFinite) {
    for (const char* t : {"nan", "NaN", "-nan", "+nan", "inf", "-inf", "+INF", "Infinity", "-infinity", " inf "})
        EXPECT_EQ(problem_of(t), NumberProblem::not_finite) << t;
    EXPECT_EQ(message_of("inf"), "'inf' is not a finite number");
    EXPECT_EQ(message_of("nan"), "'nan' is not a finite number");
}

TEST(NumberText, BeyondTheLargestDoubleIsTooLarge) {
    for (const char* t : {"1e400", "-1e400", "1.8e308", "-1.8e308", "1000e306", "0.001e312", "1e99999999999999999999"})
        EXPECT_EQ(problem_of(t), NumberProblem::too_large) << t;
    EXPECT_EQ(message_of("1e400"), "'1e400' is too large for a double (magnitude beyond 1.7976931348623157e+308)");
    EXPECT_EQ(message_of("-1e400"), "'-1e400' is too large for a double (magnitude beyond 1.7976931348623157e+308)");
    EXPECT_THROW(parameter_number("1e400"), std::invalid_argument);
    double v;
    EXPECT_FALSE(sample_number("-1e400", v));
}

TEST(NumberText, BelowTheSmallestNormalIsAParametersProblemButASamplesValue) {
    for (const char* t : {"1e-320", "-1e-320", "1.9e-308", "4.9e-324", "1e-400", "-1e-400", "0.0001e-305",
                          "1e-99999999999999999999"})
        EXPECT_EQ(problem_of(t), NumberProblem::subnormal) << t;
    EXPECT_EQ(message_of("1e-320"), "'1e-320' is below the smallest normal double, 2.2250738585072014e-308");
    try {
        parameter_number("1.9e-308");
        ADD_FAILURE() << "a subnormal parameter was read";
    } catch (const std::invalid_argument& e) {
        EXPECT_STREQ(e.what(), "'1.9e-308' is below the smallest normal double, 2.2250738585072014e-308");
    }
    double v = 1;
    EXPECT_TRUE(sample_number("1.9e-308", v));
    EXPECT_EQ(v, 1.9e-308);
    EXPECT_TRUE(sample_number("-1e-320", v));
    EXPECT_EQ(v, -1e-320);
    EXPECT_TRUE(sample_number("4.9406564584124654e-324", v));  // the smallest subnormal, %.17g as the tool writes it
    EXPECT_EQ(v, 4.9406564584124654e-324);
    EXPECT_TRUE(sample_number("1e-400", v));  // nearer 0 than the smallest subnormal: the nearest double
    EXPECT_EQ(v, 0.0);
    EXPECT_TRUE(sample_number("-1e-400", v));
    EXPECT_TRUE(v == 0.0 && std::signbit(v));
    EXPECT_EQ(parameter_number("0"), 0.0);  // 0 itself is normal enough
    EXPECT_EQ(parameter_number(" -0.1 "), -0.1);
}

TEST(NumberText, WholeNumbersSayTheirRangeWhateverIsWrong) {
    EXPECT_EQ(whole_number("2", 2, 100000), 2);
    EXPECT_EQ(whole_number("100000", 2, 100000), 100000);
    EXPECT_EQ(whole_number("1e3", 2, 100000), 1000);
    EXPECT_EQ(whole_number("20.0", 2, 100000), 20);
    EXPECT_EQ(whole_number(" 7 ", 2, 100000), 7);
    EXPECT_EQ(whole_number("-3", -5, 5), -3);
    const std::string range = "must be a whole number from 2 to 100000 (got ";
    EXPECT_EQ(whole_error("10000000", 2, 100000), range + "10000000)");
    EXPECT_EQ(whole_error("1", 2, 100000), range + "1)");
    EXPECT_EQ(whole_error("2.5", 2, 100000), range + "2.5)");
    EXPECT_EQ(whole_error("abc", 2, 100000), range + "'abc')");
    EXPECT_EQ(whole_error("1e400", 2, 100000), range + "'1e400')");
    EXPECT_EQ(whole_error("nan", 2, 100000), range + "'nan')");
    EXPECT_EQ(whole_error("", 2, 100000), range + "'')");
    EXPECT_EQ(whole_error("1e-320", 0, 10), "must be a whole number from 0 to 10 (got '1e-320')");
}

TEST(NumberText, EveryDoubleWrittenToSeventeenDigitsReadsBack) {
    for (double v : {0.1, -1.0 / 3, 1e-300, 6.02214076e23, DBL_MAX, -DBL_MIN, 1e-310, 4.9406564584124654e-324}) {
        char text[40];
        std::snprintf(text, sizeof text, "%.17g", v);
        double back;
        ASSERT_TRUE(sample_number(text, back)) << text;
        EXPECT_EQ(back, v) << text;
    }
}
