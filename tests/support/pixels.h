// Counting a picture's pixels, for the tests of what the output pictures show.
#pragma once

#include <algorithm>

#include <luxplan/output/image.h>

namespace luxplan::test {

// How many of `image`'s pixels pass `test`.
inline int countPixels(const Image& image, bool (*test)(Rgb)) {
    return int(std::count_if(image.pixels().begin(), image.pixels().end(), test));
}

}  // namespace luxplan::test
