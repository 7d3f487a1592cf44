// Instants written as ISO 8601 text in the daylight tests.
#pragma once

#include <string>

#include <gtest/gtest.h>

#include <luxplan/daylight/solar_position.h>

namespace luxplan::test {

// The instant `iso` names ("2020-06-21T12:00:00+03:00"); a test that gives a malformed
// one fails, saying why.
inline DateTime at(const char* iso) {
    std::string err;
    auto t = parseIso8601(iso, &err);
    EXPECT_TRUE(t) << err;
    return t.value_or(DateTime{});
}

}  // namespace luxplan::test
