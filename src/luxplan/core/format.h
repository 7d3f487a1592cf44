// The number formats of every text luxplan writes for people: messages, tables,
// reports, picture labels. One place, so that a figure reads the same everywhere.
#pragma once

#include <string>

namespace luxplan {

// `digits` decimals, as printf's "%.*f": fixedDigits(2.345, 2) == "2.35" (also "inf", "nan").
std::string fixedDigits(double v, int digits);

// At most `digits` significant digits, as printf's "%.*g": significantDigits(0.000123456, 3)
// == "0.000123", significantDigits(1e7, 6) == "1e+07" ("inf", "-inf", "nan" as printf).
std::string significantDigits(double v, int digits);

// A number as read from a file, for messages: 10 significant digits
// (significantDigits(v, 10)): "0.1", "300", "inf".
inline std::string formatNumber(double v) { return significantDigits(v, 10); }

// A compact label for pictures: "0", "12.5", "250", "2270", "25k" (no decimals from
// 100 up, whole numbers without any, thousands as k from 10000 up).
std::string compactNumber(double v);

}  // namespace luxplan
