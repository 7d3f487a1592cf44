// Conversation (the paper's Eq. 8): `a` and `b` face each other (a focus each way)
// within a distance range; G_C is the mean of the three parts, each of which rejects.
#include <nlohmann/json.hpp>

#include <luxplan/constraints/penalty.h>
#include <luxplan/constraints/relational.h>
#include <luxplan/json/fields.h>

namespace luxplan {
namespace {

class Conversation final : public ConstraintKind {
public:
    Conversation(const DistanceRange& range, double toleranceDeg) : range_(range), toleranceDeg_(toleranceDeg) {}
    const char* name() const override { return "conversation"; }
    void evaluate(const ConstraintEnd& a, const ConstraintEnd& b, PenaltyTerm& t) const override {
        t.value = length(a.center - b.center);
        t.reference = range_.max;
        t.parts = {anglePenalty(facingAngle(a, b), toleranceDeg_), anglePenalty(facingAngle(b, a), toleranceDeg_),
                   distancePenalty(t.value, range_)};
        t.penalty = (t.parts[0] + t.parts[1] + t.parts[2]) / 3.0;
        t.rejects = rejects(t.parts[0]) || rejects(t.parts[1]) || rejects(t.parts[2]);
    }
    bool measuresAngle() const override { return false; }
    std::optional<double> toleranceDeg() const override { return toleranceDeg_; }
    std::optional<DistanceRange> distanceRange() const override { return range_; }
    std::string describe() const override { return describeRange(range_) + ", " + describeTolerance(toleranceDeg_); }
    std::string describe(const PenaltyTerm& t) const override {
        return describeNumber(t.value) + " m, " + describeRange(range_) + ", focus penalties " + describeNumber(t.parts[0]) +
               " and " + describeNumber(t.parts[1]) + ", distance penalty " + describeNumber(t.parts[2]);
    }
    void report(const PenaltyTerm& t, nlohmann::ordered_json& j) const override {
        j["value"] = json::numberOrNull(t.value);
        j["unit"] = "m";
        j["range"] = {json::numberOrNull(range_.min), json::numberOrNull(range_.max)};
        j["tolerance_deg"] = toleranceDeg_;
        j["focus_ab"] = t.parts[0];
        j["focus_ba"] = t.parts[1];
        j["distance_penalty"] = t.parts[2];
    }

private:
    DistanceRange range_;
    double toleranceDeg_;
};

}  // namespace

std::shared_ptr<const ConstraintKind> conversationConstraint(const DistanceRange& range, double toleranceDeg) {
    return std::make_shared<Conversation>(range, toleranceDeg);
}

std::shared_ptr<const ConstraintKind> readConversationConstraint(const json::Fields& f) {
    double toleranceDeg = readToleranceDeg(f);  // read first: the order the keys are listed in messages
    return conversationConstraint(readDistanceRange(f), toleranceDeg);
}

}  // namespace luxplan
