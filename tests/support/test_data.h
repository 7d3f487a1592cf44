// Files under tests/data that more than one test reads.
#pragma once

#include <string>

namespace luxplan::test {

// IES LM-63 and EULUMDAT files (tests/data/photometry/).
inline const std::string kPhotometryFiles = std::string(LUXPLAN_TEST_DATA) + "/photometry/";

}  // namespace luxplan::test
