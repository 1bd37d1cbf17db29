// The NRML export of a fragility study (studies/nrml.hpp): the lognormal's
// moments against their closed form at 30 digits (mpmath) and back, the XML
// escaping of names against what XML 1.0 allows, and the model's functions
// and comments for blocks with and without a fit.  Its well-formedness and
// the numbers read back by Python's own XML parser are ctest
// fragility_nrml_cli's.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "harness/table.hpp"
#include "studies/nrml.hpp"

using namespace rocking;
using namespace rocking::studies;

namespace {

int count(const std::string& text, const std::string& what) {
    int n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

BlockFragility fitted_block(double alpha, double p, double median, double beta) {
    BlockFragility f;
    f.block = {alpha, p};
    f.fitted = true;
    f.fit.median = median;
    f.fit.beta = beta;
    f.fit.collapsed = 9;
    f.fit.censored = 1;
    return f;
}

}  // namespace

TEST(Nrml, TheMomentsAreThoseOfTheIntensityNotOfItsLogarithm) {
    // mpmath at 30 digits: mean = theta exp(beta^2/2), stddev = mean sqrt(expm1(beta^2)).
    struct Case {
        double theta, beta, mean, stddev;
    };
    for (const Case& c : {Case{0.25, 0.4, 0.27082176691873963861, 0.1128098215316786063},
                          Case{1.5, 1e-8, 1.500000000000000075, 1.5000000000000001125e-8},
                          Case{0.7, 2.5, 15.931926565468709588, 362.25880818986444117}}) {
        const LognormalMoments m = lognormal_moments(c.theta, c.beta);
        EXPECT_NEAR(m.mean, c.mean, 2e-16 * c.mean) << c.beta;
        EXPECT_NEAR(m.stddev, c.stddev, 1e-15 * c.stddev) << c.beta;
    }
}

TEST(Nrml, TheMomentsReadBackToTheMedianAndBeta) {
    // Over beta from 1e-6 to 3 and theta over six decades: back to 1e-14
    // (beta at 1e-6 too: expm1 and log1p keep its digits).
    for (double theta : {1e-3, 0.02, 0.5, 1.0, 7.0, 300.0})
        for (double beta = 1e-6; beta < 3.1; beta *= 1.7) {
            const LognormalMoments m = lognormal_moments(theta, beta);
            const LognormalParameters back = lognormal_from_moments(m.mean, m.stddev);
            EXPECT_NEAR(back.median, theta, 1e-14 * theta) << theta << " " << beta;
            EXPECT_NEAR(back.beta, beta, 1e-14 * beta) << theta << " " << beta;
        }
    EXPECT_THROW(lognormal_from_moments(0, 1), std::invalid_argument);
    EXPECT_THROW(lognormal_from_moments(1, -1e-9), std::invalid_argument);
    EXPECT_THROW(lognormal_from_moments(NAN, 1), std::invalid_argument);
    EXPECT_EQ(lognormal_from_moments(2, 0).beta, 0.0);
}

TEST(Nrml, NamesAreEscapedToWhatXmlHolds) {
    EXPECT_EQ(xml_escaped("a&b<c>d\"e'f"), "a&amp;b&lt;c&gt;d&quot;e&apos;f");
    EXPECT_EQ(xml_escaped("tab\there"), "tab\there");
    EXPECT_EQ(xml_escaped("bell\x07"), "bell?");
    // UTF-8 of two, three and four bytes: numeric references, the file ASCII.
    EXPECT_EQ(xml_escaped("caf\xc3\xa9"), "caf&#xE9;");
    EXPECT_EQ(xml_escaped("\xe2\x82\xac"), "&#x20AC;");
    EXPECT_EQ(xml_escaped("\xf0\x9f\x98\x80"), "&#x1F600;");
    // Not characters: a stray continuation byte, an overlong '/', a
    // surrogate, a truncated sequence, a lead byte beyond UTF-8, U+FFFE.
    EXPECT_EQ(xml_escaped("\x80"), "?");
    EXPECT_EQ(xml_escaped("\xc0\xaf"), "??");
    EXPECT_EQ(xml_escaped("\xed\xa0\x80"), "???");
    EXPECT_EQ(xml_escaped("\xe2\x82"), "??");
    EXPECT_EQ(xml_escaped("\xf8\x88\x80\x80\x80"), "?????");
    EXPECT_EQ(xml_escaped("\xef\xbf\xbe"), "???");
}

TEST(Nrml, EachFittedBlockIsAFunctionAndEachOtherAComment) {
    FragilityStudyOptions o;  // the grid method, q from 1 to 20
    std::vector<BlockFragility> study = {fitted_block(0.1, 3, 2.5, 0.4), fitted_block(0.15, 1.5, 6.0, 0.8)};
    BlockFragility none;
    none.block = {0.2, 1.5};
    none.no_fit = "no record overturned (every point is censored): ln L has no maximum -- said twice --";
    study.insert(study.begin() + 1, none);
    const NrmlModel m = fragility_nrml(study, o, {"a&b.txt", "<c>.txt"});
    EXPECT_EQ(count(m.xml, "<fragilityFunction "), 2);
    EXPECT_EQ(count(m.xml, "</fragilityFunction>"), 2);
    EXPECT_EQ(count(m.xml, "<limitStates>overturning</limitStates>"), 1);
    EXPECT_NE(m.xml.find("<nrml xmlns=\"http://openquake.org/xmlns/nrml/0.5\">"), std::string::npos);
    // (N1), (N2) and the range, each number to the bit.
    const LognormalMoments first = lognormal_moments(2.5 * 0.1, 0.4);
    EXPECT_NE(m.xml.find("<fragilityFunction id=\"rocking_alpha_0_1_p_3\" format=\"continuous\" shape=\"logncdf\">"),
              std::string::npos);
    EXPECT_NE(m.xml.find("<params ls=\"overturning\" mean=\"" + harness::format_number(first.mean) + "\" stddev=\"" +
                         harness::format_number(first.stddev) + "\"/>"),
              std::string::npos);
    EXPECT_NE(m.xml.find("<imls imt=\"PGA\" noDamageLimit=\"" + harness::format_number(0.15) + "\" minIML=\"" +
                         harness::format_number(0.15) + "\" maxIML=\"" + harness::format_number(0.15 * 20) + "\"/>"),
              std::string::npos);
    EXPECT_NE(m.xml.find("id=\"rocking_alpha_0_15_p_1_5\""), std::string::npos);
    // The block without a fit: a comment, never "--" inside it, and a line of unfitted.
    ASSERT_EQ(m.unfitted.size(), 1u);
    EXPECT_EQ(m.unfitted[0], "alpha 0.2, p 1.5 rad/s: no fit: " + none.no_fit);
    const std::size_t at = m.xml.find("<!-- alpha 0.2, p 1.5 rad/s: no fit: no record overturned");
    ASSERT_NE(at, std::string::npos);
    const std::string comment = m.xml.substr(at + 4, m.xml.find("-->", at) - at - 4);
    EXPECT_EQ(comment.find("--"), std::string::npos) << comment;
    EXPECT_NE(comment.find("- - said twice - -"), std::string::npos) << comment;
    // The names, escaped, and which fit: the grid's first collapse.
    EXPECT_NE(m.xml.find("Records: a&amp;b.txt; &lt;c&gt;.txt."), std::string::npos);
    EXPECT_NE(m.xml.find("on the IDA&apos;s grid (its first collapse"), std::string::npos);
    // Under the refine method, the first overturning's.
    o.ida.method = IdaOptions::Method::refine;
    o.ida.width = 1e-3;
    EXPECT_NE(fragility_nrml(study, o, {"r"}).xml.find("the refine method&apos;s fit on the first overturning, the "
                                                       "conservative one of its three fits"),
              std::string::npos);
    // Every byte ASCII.
    for (unsigned char c : m.xml) EXPECT_LT(c, 0x80);
}
