// Files under tests/data that more than one test reads.
#pragma once

#include <string>

namespace luxplan::test {

// IES LM-63 and EULUMDAT files (tests/data/photometry/).
inline const std::string kPhotometryFiles = std::string(LUXPLAN_TEST_DATA) + "/photometry/";
// Chicago O'Hare's TMY3 year in the EnergyPlus weather format (tests/data/weather/).
inline const std::string kChicagoEpw = std::string(LUXPLAN_TEST_DATA) + "/weather/chicago.epw";

}  // namespace luxplan::test
