// The one table of relational constraint types: a new type is its file and one line here.
#include <luxplan/core/names.h>
#include <luxplan/constraints/constraint_type.h>

namespace luxplan {

std::shared_ptr<const ConstraintKind> readAlignmentConstraint(const json::Fields& f);     // alignment.cpp
std::shared_ptr<const ConstraintKind> readDistanceConstraint(const json::Fields& f);      // distance.cpp
std::shared_ptr<const ConstraintKind> readFocusConstraint(const json::Fields& f);         // focus.cpp
std::shared_ptr<const ConstraintKind> readConversationConstraint(const json::Fields& f);  // conversation.cpp

const std::vector<ConstraintKindEntry>& constraintKinds() {
    static const std::vector<ConstraintKindEntry> kinds = {
        {"alignment", readAlignmentConstraint},
        {"distance", readDistanceConstraint},
        {"focus", readFocusConstraint},
        {"conversation", readConversationConstraint},
    };
    return kinds;
}

const ConstraintKindEntry* findConstraintKind(std::string_view name) { return findByName(constraintKinds(), name); }

std::vector<std::string> constraintTypeNames() {
    std::vector<std::string> names = namesOf(constraintKinds());
    names.push_back(kOverlapRuleName);
    return names;
}

}  // namespace luxplan
