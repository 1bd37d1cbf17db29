// Numbers from text: the one reader of the command line's options, a batch
// manifest's cells, a record's samples and headers, a pulse train and the
// rows the studies write, with one set of messages (docs/cli.md, "Numbers").
//
// The rules: blanks (space, tab, CR, LF, VT, FF) around a number are ignored,
// at either end alike; inside it nothing else is read: an optional sign (+ or
// -), digits with an optional decimal point (".5" and "5." are numbers) and an
// optional exponent (e or E, then an optional sign and digits).  Not read:
// hexadecimal ("0x10"), decimal commas ("1,5"), "nan" and "inf" (not finite),
// nor a magnitude beyond the largest double (1e400 is too large).  The text
// becomes the nearest double.  A magnitude below the smallest normal double
// (2.2e-308) is a parameter's problem (an option or a cell: its digits are
// lost, and no quantity of the model lives there), but a sample's value: a
// record that numpy or `record synth` wrote reads back as written, where a
// subnormal is the nearest double and a smaller magnitude rounds to 0.
#pragma once

#include <string>
#include <string_view>

namespace rocking::numerics {

enum class NumberProblem {
    none,
    not_a_number,  // anything the rules above do not read, "" included
    not_finite,    // nan, inf, infinity
    too_large,     // beyond the largest double in magnitude
    subnormal,     // non-zero, below the smallest normal double in magnitude (value then holds the nearest double)
};

struct NumberRead {
    double value = 0;
    NumberProblem problem = NumberProblem::none;
};

// The text as the rules above read it; value is set unless the problem is
// not_a_number, not_finite or too_large.
NumberRead read_number(std::string_view text);

// The problem in words, quoting the text: "'1e400' is too large for a double
// (magnitude beyond 1.7976931348623157e+308)".  The callers prefix the option, the
// column or the file and line.
std::string number_problem(std::string_view text, NumberProblem problem);

// The limits as the messages print them, to every digit.
std::string largest_double_text();    // 1.7976931348623157e+308
std::string smallest_normal_text();   // 2.2250738585072014e-308

// A parameter (an option's value, a manifest's cell, a header's value):
// finite, and normal or 0.  Throws std::invalid_argument with number_problem().
double parameter_number(std::string_view text);

// A sample: finite, a subnormal kept (a smaller magnitude reads as 0).
// Returns false when the text is not one; number_problem(text,
// read_number(text).problem) then says why.
bool sample_number(std::string_view text, double& value);

// A whole number in [lo, hi], read as a parameter: "2", "2.0" and "1e3" are
// whole.  Throws std::invalid_argument "must be a whole number from lo to hi
// (got TEXT)" for anything else, so that the range is said whatever was wrong.
long long whole_number(std::string_view text, long long lo, long long hi);

}  // namespace rocking::numerics
