// Alignment (the paper's Eq. 4): the axes of a front of `a` and of `b` (or of the
// room) within a tolerance angle, the best pair of fronts counting.
#include <luxplan/constraints/relational.h>

namespace luxplan {
namespace {

class Alignment final : public AngleConstraint {
public:
    using AngleConstraint::AngleConstraint;
    const char* name() const override { return "alignment"; }
    bool acceptsRoom() const override { return true; }
    void evaluate(const ConstraintEnd& a, const ConstraintEnd& b, PenaltyTerm& t) const override {
        hold(axialAngle(a.fronts, b.fronts), t);
    }
};

}  // namespace

std::shared_ptr<const ConstraintKind> alignmentConstraint(double toleranceDeg) {
    return std::make_shared<Alignment>(toleranceDeg);
}

std::shared_ptr<const ConstraintKind> readAlignmentConstraint(const json::Fields& f) {
    return alignmentConstraint(readToleranceDeg(f));
}

}  // namespace luxplan
