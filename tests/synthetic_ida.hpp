// A synthetic IDA (studies/ida.hpp) whose overturning set in q is given, for
// the tests of the fits a block's IDAs feed (test_stripe_fit.cpp,
// test_record_order.cpp).
#pragma once

#include <utility>
#include <vector>

#include "studies/ida.hpp"

namespace rocking::testing {

// The IDA whose overturning set is `intervals` (each bracketed at its ends,
// 1e-7 wide; the last open where it reaches q = 20), its first robust
// collapse given, on the block alpha 0.1, p 2 by the refine method.
inline studies::Ida synthetic_ida(const std::vector<std::pair<double, double>>& intervals, studies::IdaPoint robust) {
    studies::Ida ida;
    ida.alpha = 0.1;
    ida.p = 2;
    ida.refined = true;
    for (const auto& [from, to] : intervals) {
        studies::IdaInterval in;
        in.from = from;
        in.to = to;
        in.has_lower = true;
        in.lower = {from * (1 - 1e-7), from};
        in.has_upper = to < 20;
        if (in.has_upper) in.upper = {to * (1 + 1e-7), to};
        ida.intervals.push_back(in);
    }
    ida.point = ida.intervals.empty() ? studies::IdaPoint{20, false} : studies::IdaPoint{intervals.front().first, true};
    ida.first_overturning = ida.point;
    ida.first_robust_collapse = robust;
    return ida;
}

}  // namespace rocking::testing
