// Human-readable names and descriptions of penalty terms (reports, rejection reasons).
#include <luxplan/constraints/terms.h>

#include <luxplan/constraints/constraint_type.h>
#include <luxplan/constraints/overlap.h>
#include <luxplan/constraints/relational.h>

namespace luxplan {

const char* termName(const PenaltyTerm& t) { return t.kind ? t.kind->name() : kOverlapRuleName; }

static std::string quoted(const std::string& name) {
    std::string s;
    s.reserve(name.size() + 2);
    s.append(1, '"').append(name).append(1, '"');
    return s;
}

std::string describe(const Scene& scene, const PenaltyTerm& t) {
    std::string s = termName(t);
    s.append(1, ' ').append(quoted(scene.entities[t.a].path)).append(" / ");
    if (t.overlap()) {
        if (t.target == OverlapTarget::Entity) s += quoted(scene.entities[t.b].path);
        else if (t.target == OverlapTarget::Static) s.append("geometry ").append(quoted(scene.geometry[t.b].name));
        else s += describeSides(t.walls);
        if (!scene.overlap.jsonPath.empty()) s.append(" (").append(scene.overlap.jsonPath).append(1, ')');
        s += ": " + describeNumber(t.value) + " m3 shared, " + (t.hardOverlap() ? "hard limit " : "tolerance ") +
             describeNumber(t.reference) + " m3";
    } else {
        s += t.b == kRoomEntity ? std::string("room") : quoted(scene.entities[t.b].path);
        s.append(" (").append(scene.constraints[t.constraint].jsonPath).append("): ");
        s += t.kind->describe(t);
    }
    return s + ", P = " + describeNumber(t.penalty);
}

}  // namespace luxplan
