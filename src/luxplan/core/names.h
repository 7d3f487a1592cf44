// Names a user types: the closest known one for a "did you mean" hint, lists of
// choices for messages, and one table per enum that parses, prints and lists its
// names, so the three cannot disagree.
#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace luxplan {

// Edit distance counting insertions, deletions, substitutions and swaps of two
// neighbouring letters (optimal string alignment), the usual typos.
inline size_t editDistance(std::string_view a, std::string_view b) {
    const size_t w = b.size() + 1;
    std::vector<size_t> d((a.size() + 1) * w);
    for (size_t i = 0; i <= a.size(); ++i) d[i * w] = i;
    for (size_t j = 0; j <= b.size(); ++j) d[j] = j;
    for (size_t i = 1; i <= a.size(); ++i)
        for (size_t j = 1; j <= b.size(); ++j) {
            size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            size_t best = std::min({d[(i - 1) * w + j] + 1, d[i * w + j - 1] + 1, d[(i - 1) * w + j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) best = std::min(best, d[(i - 2) * w + j - 2] + 1);
            d[i * w + j] = best;
        }
    return d[a.size() * w + b.size()];
}

// The known name closest to `name`, if it is close enough to be a typo: at most a
// third of the name's letters (and at least one) edited.
inline std::optional<std::string> closestName(std::string_view name, const std::vector<std::string>& known) {
    std::optional<std::string> best;
    size_t bestDistance = std::max<size_t>(1, name.size() / 3) + 1;
    for (const std::string& k : known) {
        size_t d = editDistance(name, k);
        if (d < bestDistance) bestDistance = d, best = k;
    }
    return best;
}

// " (did you mean \"x\"?)" or "".
inline std::string didYouMean(std::string_view name, const std::vector<std::string>& known) {
    auto best = closestName(name, known);
    return best ? " (did you mean \"" + *best + "\"?)" : "";
}

// "a, b or c" (`last` joins the last two: "or", "and"); "a, b, c" with last = ",".
inline std::string listNames(const std::vector<std::string>& names, std::string_view last = "or") {
    std::string s;
    for (size_t i = 0; i < names.size(); ++i) {
        if (i && i + 1 == names.size() && last != ",") s.append(" ").append(last).append(" ");
        else if (i) s.append(", ");
        s.append(names[i]);
    }
    return s;
}

// A family's registration table (entries with a `name`): the entry of a name, or
// null, and the names in the table's order.
template <class Entry>
const Entry* findByName(const std::vector<Entry>& table, std::string_view name) {
    for (const Entry& e : table)
        if (name == e.name) return &e;
    return nullptr;
}
template <class Entry>
std::vector<std::string> namesOf(const std::vector<Entry>& table) {
    std::vector<std::string> names;
    for (const Entry& e : table) names.push_back(e.name);
    return names;
}

// The scene format's names of one enum, in the order the docs list them.
template <class E>
struct EnumNames {
    std::vector<std::pair<E, const char*>> entries;

    std::optional<E> parse(std::string_view name) const {
        for (const auto& [value, n] : entries)
            if (name == n) return value;
        return std::nullopt;
    }
    const char* name(E value) const {
        for (const auto& [v, n] : entries)
            if (v == value) return n;
        return "?";
    }
    std::vector<std::string> names() const {
        std::vector<std::string> out;
        for (const auto& e : entries) out.push_back(e.second);
        return out;
    }
    // "unknown wall \"x\" (north, south, east, west or ceiling)", with a hint when close.
    std::string unknown(std::string_view what, std::string_view name) const {
        return "unknown " + std::string(what) + " \"" + std::string(name) + "\"" + didYouMean(name, names()) + " (" +
               listNames(names()) + ")";
    }
};

}  // namespace luxplan
