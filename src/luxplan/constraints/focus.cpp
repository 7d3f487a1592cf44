// Focus (the paper's Eq. 7): G_A between a front of `a` and the direction from a's
// centre to b's.
#include <luxplan/constraints/relational.h>

namespace luxplan {
namespace {

class Focus final : public AngleConstraint {
public:
    using AngleConstraint::AngleConstraint;
    const char* name() const override { return "focus"; }
    void evaluate(const ConstraintEnd& a, const ConstraintEnd& b, PenaltyTerm& t) const override {
        hold(facingAngle(a, b), t);
    }
};

}  // namespace

std::shared_ptr<const ConstraintKind> focusConstraint(double toleranceDeg) { return std::make_shared<Focus>(toleranceDeg); }

std::shared_ptr<const ConstraintKind> readFocusConstraint(const json::Fields& f) {
    return focusConstraint(readToleranceDeg(f));
}

}  // namespace luxplan
