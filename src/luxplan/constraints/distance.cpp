// Distance (the paper's Eq. 5): the distance between the centres of `a` and `b`
// within [min, max], rejecting l_rej outside.
#include <nlohmann/json.hpp>

#include <luxplan/constraints/penalty.h>
#include <luxplan/constraints/relational.h>
#include <luxplan/json/fields.h>

namespace luxplan {
namespace {

class Distance final : public ConstraintKind {
public:
    explicit Distance(const DistanceRange& range) : range_(range) {}
    const char* name() const override { return "distance"; }
    void evaluate(const ConstraintEnd& a, const ConstraintEnd& b, PenaltyTerm& t) const override {
        t.value = length(a.center - b.center);
        t.reference = range_.max;
        t.penalty = distancePenalty(t.value, range_);
        t.rejects = rejects(t.penalty);
    }
    bool measuresAngle() const override { return false; }
    bool symmetric() const override { return true; }  // |a - b|
    std::optional<DistanceRange> distanceRange() const override { return range_; }
    std::string describe() const override {
        return describeRange(range_) +
               (range_.tolerance ? ", elastic limit " + describeNumber(*range_.tolerance) + " m" : std::string());
    }
    std::string describe(const PenaltyTerm& t) const override {
        return describeNumber(t.value) + " m, " + describeRange(range_);
    }
    void report(const PenaltyTerm& t, nlohmann::ordered_json& j) const override {
        j["value"] = json::numberOrNull(t.value);
        j["unit"] = "m";
        j["range"] = {json::numberOrNull(range_.min), json::numberOrNull(range_.max)};
    }

private:
    DistanceRange range_;
};

}  // namespace

std::shared_ptr<const ConstraintKind> distanceConstraint(const DistanceRange& range) {
    return std::make_shared<Distance>(range);
}

std::shared_ptr<const ConstraintKind> readDistanceConstraint(const json::Fields& f) {
    return distanceConstraint(readDistanceRange(f));
}

}  // namespace luxplan
