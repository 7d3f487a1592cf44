// The colour of a black body (the Planckian locus) in linear sRGB, for luminaires'
// `cct_k` in renders and in the glTF scene.
#pragma once

#include <luxplan/core/math.h>

namespace luxplan {

// Linear RGB of a black body at `kelvin` (clamped to [1667, 25000] K), scaled so that
// its largest component is 1: the colour that `cct_k` gives lights in images.
Vec3 blackBodyRgb(double kelvin);

}  // namespace luxplan
