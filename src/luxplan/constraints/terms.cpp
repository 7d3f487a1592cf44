// Human-readable names and descriptions of penalty terms (reports, rejection reasons).
#include <luxplan/constraints/terms.h>

#include <cstdio>

namespace luxplan {

const char* termName(TermKind kind) {
    switch (kind) {
        case TermKind::Alignment: return "alignment";
        case TermKind::Distance: return "distance";
        case TermKind::Focus: return "focus";
        case TermKind::Conversation: return "conversation";
        case TermKind::Overlap: return "overlap";
    }
    return "?";
}

static std::string quoted(const std::string& name) {
    std::string s;
    s.reserve(name.size() + 2);
    s.append(1, '"').append(name).append(1, '"');
    return s;
}

static std::string number(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.4g", v);
    return buffer;
}

std::string describe(const Scene& scene, const PenaltyTerm& t) {
    std::string s = termName(t.kind);
    s.append(1, ' ').append(quoted(scene.entities[t.a].path)).append(" / ");
    if (t.kind == TermKind::Overlap) {
        if (t.target == OverlapTarget::Entity) s += quoted(scene.entities[t.b].path);
        else if (t.target == OverlapTarget::Static) s.append("geometry ").append(quoted(scene.geometry[t.b].name));
        else s += "walls";
    } else {
        s += t.b == kRoomEntity ? std::string("room") : quoted(scene.entities[t.b].path);
    }
    if (t.constraint >= 0) s.append(" (").append(scene.constraints[t.constraint].jsonPath).append(1, ')');
    s += ": ";
    switch (t.kind) {
        case TermKind::Alignment:
        case TermKind::Focus:
            s += number(degrees(t.value)) + " deg, tolerance " + number(degrees(t.reference)) + " deg";
            break;
        case TermKind::Distance:
        case TermKind::Conversation: {
            const ConstraintSpec& c = scene.constraints[t.constraint];
            s += number(t.value) + " m, range [" + number(c.minDistance) + ", " + number(c.maxDistance) + "] m";
            if (t.kind == TermKind::Distance) break;
            s += ", focus penalties " + number(t.parts[0]) + " and " + number(t.parts[1]) +
                 ", distance penalty " + number(t.parts[2]);
            break;
        }
        case TermKind::Overlap:
            s += number(t.value) + " m3 shared, tolerance " + number(t.reference) + " m3";
            break;
    }
    return s + ", P = " + number(t.penalty);
}

}  // namespace luxplan
