#include "studies/eq27_of_block.hpp"

#include "pulse/pulse_train.hpp"
#include "qfactor/closed_forms.hpp"
#include "qfactor/imperfect_q.hpp"

namespace rocking::studies {

Eq27OfBlock eq27_of_block(double alpha, double p, const records::CollapseOptions& model, double to) {
    static const PulseTrain train = repeated_case(2, 6);
    Eq27OfBlock out;
    out.q_as_printed = q2_n6(p * to);
    if (!model.imperfection.any()) {
        // The paper's own: bit for bit the closed form every scene checks.
        out.q = out.q_as_printed;
        out.excursion = collapse_excursion(train, p * to);
        return out;
    }
    // A setback alone keeps the block symmetric, but with its own alpha and p on both corners.
    const dynamics::Model m = records::model_of(alpha, p, model);
    const CornerOfBlock plus{m.block.alpha, m.block.p};
    const CornerOfBlock minus = m.symmetric() ? plus : CornerOfBlock{m.minus.alpha, m.minus.p};
    const ImperfectCollapse c = imperfect_collapse(train, to, plus, minus);
    out.q = c.pga_g() / alpha;
    out.side = c.weaker_side();
    out.excursion = out.side > 0 ? c.toward_plus.excursion : c.toward_minus.excursion;
    return out;
}

}  // namespace rocking::studies
