// The interface every relational constraint type implements (the paper's Section
// 5.2): how it is read from the scene file, what it measures between its two ends,
// and how it describes itself. Each type is one file of this folder (alignment.cpp,
// distance.cpp, focus.cpp, conversation.cpp) and one line of constraint_registry.cpp;
// docs/architecture.md walks through adding one. The overlap rule (Eq. 6) is a rule
// of the scene (Scene::overlap), not a type.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include <luxplan/core/math.h>
#include <luxplan/json/fields.h>

namespace luxplan {

struct PenaltyTerm;    // constraints/terms.h
struct ConstraintEnd;  // constraints/relational.h
struct Scene;          // scene/scene.h
class EntityInfo;      // constraints/entity_info.h

// The scene file's "type" of the `constraints` entry that sets the overlap rule.
inline constexpr const char* kOverlapRuleName = "overlap";

// The accepted distance of Eq. 5 (distance, conversation): [min, max] in metres
// (max may be infinite) and the elastic limit l_rej (default: distanceElasticLimit()).
struct DistanceRange {
    double min = 0, max = kInf;
    std::optional<double> tolerance;
};

// A constraint type's own parameters. Immutable: a scene shares it between copies.
class ConstraintKind {
public:
    virtual ~ConstraintKind() = default;
    virtual const char* name() const = 0;  // the scene file's "type"
    // Whether "b" may be "room" (the room's axes stand in for its fronts).
    virtual bool acceptsRoom() const { return false; }
    // The kind's Eq. between ends `a` and `b`: fills the term's value, reference,
    // penalty, rejects and, for a term made of parts, parts.
    virtual void evaluate(const ConstraintEnd& a, const ConstraintEnd& b, PenaltyTerm& t) const = 0;
    // Where the ends of a constraint of this kind between entities `a` and `b` are under
    // `world`. By default each entity's own end (relational.h: entityEnd()); the
    // constraints flattenScene() moved off a group keep measuring the group
    // (optimizer/flatten.h: FlatConstraint).
    virtual std::array<ConstraintEnd, 2> ends(const Scene& scene, const EntityInfo& info,
                                              const std::vector<Transform>& world, int a, int b) const;
    // Whether G's normalizer (Eq. 2's sum of weights) counts its weight: all but
    // flattenScene()'s cohesion rules, so that a layout the hierarchy allows costs the
    // same in the flat scene.
    virtual bool countsInNormalizer() const { return true; }
    // Whether it measures the same with `a` and `b` exchanged (a distance between
    // centres; not a focus of a on b). The search uses it to find entities a swap
    // cannot tell apart (optimizer/interchangeable.h).
    virtual bool symmetric() const { return false; }

    // Whether reports show its value as an angle (degrees) or a distance (metres).
    virtual bool measuresAngle() const = 0;
    // The bounds reports show: the angular tolerance (deg), the distance range.
    virtual std::optional<double> toleranceDeg() const { return std::nullopt; }
    virtual std::optional<DistanceRange> distanceRange() const { return std::nullopt; }
    // Its parameters for people: "tolerance 10 deg", "range [0.5, 3] m".
    virtual std::string describe() const = 0;
    // A measurement for people: "14.2 deg, tolerance 10 deg".
    virtual std::string describe(const PenaltyTerm& t) const = 0;
    // report.json's fields of a term of this kind: "value", "unit" and its bounds.
    virtual void report(const PenaltyTerm& t, nlohmann::ordered_json& j) const = 0;
};

// Constructed in C++ (flattenScene's cohesion constraints, tests).
std::shared_ptr<const ConstraintKind> alignmentConstraint(double toleranceDeg);
std::shared_ptr<const ConstraintKind> distanceConstraint(const DistanceRange& range);
std::shared_ptr<const ConstraintKind> focusConstraint(double toleranceDeg);
std::shared_ptr<const ConstraintKind> conversationConstraint(const DistanceRange& range, double toleranceDeg);

// A registered type: its name in the scene file and how its own keys are read (all
// but "type", "weight", "a" and "b", which every type has). A reader reports problems
// through `f` and reads nothing but `f`, so the loader can probe it for the keys it knows.
struct ConstraintKindEntry {
    const char* name;
    std::shared_ptr<const ConstraintKind> (*read)(const json::Fields& f);
};

// Every constraint type, in the order the docs list them (constraint_registry.cpp).
const std::vector<ConstraintKindEntry>& constraintKinds();
const ConstraintKindEntry* findConstraintKind(std::string_view name);
// Every "type" a `constraints` entry may have: the registered types, then the overlap rule.
std::vector<std::string> constraintTypeNames();

}  // namespace luxplan
