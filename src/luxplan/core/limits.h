// Every limit on what an input file may ask for, in one place: beyond these a file is
// refused with a clear error (FILE: /json/path: N things exceeds the limit of M), so
// that no input can crash, hang or exhaust the machine. docs/scene-format.md
// ("Limits") lists them; change both together.
#pragma once

#include <cstdint>

namespace luxplan::limits {

// ---- files ----
// A scene or layout JSON file: far above any real scene (the bundled ones are < 100 kB).
inline constexpr std::uintmax_t kMaxJsonFileBytes = 64ull << 20;
// A mesh file (OBJ, glTF, GLB) and each external glTF buffer: a 2-million-triangle
// OBJ is about 150 MB.
inline constexpr std::uintmax_t kMaxMeshFileBytes = 512ull << 20;
// An IES or EULUMDAT file (real ones are a few kB; a dense one a few hundred).
inline constexpr std::uintmax_t kMaxPhotometryFileBytes = 16ull << 20;
// An EPW weather file (a year of hourly rows is about 1.7 MB).
inline constexpr std::uintmax_t kMaxWeatherFileBytes = 64ull << 20;

// ---- JSON structure ----
// Arrays and objects nested inside each other in a scene or layout file; checked
// while parsing, before any of it is built.
inline constexpr int kMaxJsonDepth = 128;
// Entities nested through "children" (a group of groups ...), checked before
// recursing into the next level.
inline constexpr int kMaxEntityDepth = 32;

// ---- geometry ----
// Every coordinate (positions, centres, corners, translations, region bounds, mesh
// vertices after their transform) lies in [-kMaxCoordinate, kMaxCoordinate] m: 100 km,
// where single-precision ray tracing still resolves millimetres well enough.
inline constexpr double kMaxCoordinate = 1e5;
// Every size (lengths, widths, radii, side vectors) is positive and at most this, m.
inline constexpr double kMaxLength = 1e5;
// Every rotation (an entity's, a layout's, a region's rotations and rotation_range, a
// mesh transform's rotate_deg) lies in [-kMaxRotationDeg, kMaxRotationDeg] degrees: ten
// turns either way, beyond which single precision no longer resolves a degree.
inline constexpr double kMaxRotationDeg = 3600;
// A mesh transform's scale factor lies in (0, kMaxScale].
inline constexpr double kMaxScale = 1e4;
// Triangles in one mesh file (after glTF instancing) and in the whole scene.
inline constexpr std::uint64_t kMaxMeshTriangles = 4'000'000;
inline constexpr std::uint64_t kMaxSceneTriangles = 8'000'000;
// glTF node instances (a node reached through several parents counts once per path):
// bounds a scene graph whose nodes share children, which can grow exponentially.
inline constexpr std::uint64_t kMaxGltfNodeInstances = 100'000;
// glTF node hierarchy depth (deeper is taken for a cycle).
inline constexpr int kMaxGltfNodeDepth = 64;

// ---- light ----
// A luminaire's side or radius, m: the light sampling's set-up (spherical rectangles,
// cones) loses its precision far below it (a rect of 1e-7 m read 36% high, of 1e-8 m
// nothing). A lamp's smallest opening, an LED die, is about a millimetre.
inline constexpr double kMinLuminaireSize = 1e-4;
// A luminaire's flux, lm (a stadium floodlight gives about 2e5 lm).
inline constexpr double kMaxFluxLm = 1e9;
// Sky and sun illuminance, lx (direct sunlight is about 1.3e5 lx), and a uniform
// sky's luminance, cd/m2 (the sun's disk is about 1.6e9).
inline constexpr double kMaxIlluminanceLx = 1e7;
inline constexpr double kMaxLuminanceNits = 1e10;

// A luminous intensity in a photometric file, cd, after its multipliers (a narrow
// stadium floodlight peaks at a few 10^6 cd).
inline constexpr double kMaxCandela = 1e9;

// Candela values in one IES file (horizontal x vertical angles; EULUMDAT's own
// bounds, 3600 x 1801 planes, are below it).
inline constexpr std::int64_t kMaxPhotometryValues = 10'000'000;

// ---- samplers ----
// Measurement points (or strata) of one sampler: a planar grid's nx * ny, a volume's
// points, a directional sampler's strata^2.
inline constexpr std::int64_t kMaxSamplerPoints = 65536;
// A directional sampler's strata per side: each stratum's paths reach every other
// stratum, so its estimates grow as strata^4 (16: 79 MB in all; 32: 600 MB).
inline constexpr int kMaxDirectionalStrata = 32;
// The glare sources a "ugr" eye surveys (every luminaire of the scene) or a "dgp" eye
// (every luminaire and every sun disk: one per daylight step with the sun up), each
// with six estimates of its own.
inline constexpr std::int64_t kMaxGlareSources = 1024;

// ---- daylight ----
// Instants from..to every step_minutes (counted in floating point before any
// allocation). The daylight module's kMaxDaylightSteps is this value.
inline constexpr std::int64_t kMaxTimeSteps = 10000;

// ---- the cost C (issue 58): every factor that multiplies or divides a penalty ----
// With these bounds no finite input gives a non-finite cost: a term's penalty is at
// most (kMaxTargetValue + a measured value) / kMinTolerance (lighting) or
// (kMaxLength / kMinTolerance)^2 (geometry), times kMaxWeight, far below 1e308 even
// summed over millions of terms.
// A weight (a sampler's, a constraint's, the overlap rule's) lies in [0, kMaxWeight];
// only the ratios of weights matter, and 10^6 leaves room for any emphasis.
inline constexpr double kMaxWeight = 1e6;
// A sampler's target and its statistics goals' targets, in the sampler's unit (lx,
// cd/m2, UGR, DGP, U0): at most 10^10 (the brightest sky luminance allowed,
// kMaxLuminanceNits; direct sunlight is about 1.3e5 lx).
inline constexpr double kMaxTargetValue = 1e10;
// A tolerance (the distance at which a penalty reaches 1): a sampler's or a goal's, in
// its unit, at least kMinTolerance and at most kMaxTargetValue; a distance
// constraint's, m, at least kMinTolerance and at most kMaxLength.
inline constexpr double kMinTolerance = 1e-6;
// An angle constraint's tolerance_deg: at least a thousandth of a degree.
inline constexpr double kMinToleranceDeg = 1e-3;
// The overlap rule's tolerance (a fraction of the smaller volume): at least 10^-6.
inline constexpr double kMinOverlapTolerance = 1e-6;
// A photometric file's own flux, lm (what "flux_lm" is divided by to scale it): at
// least a milli-lumen, so that the scale stays finite.
inline constexpr double kMinPhotometryFluxLm = 1e-3;

// ---- integers ----
// Counts read from JSON (iterations, paths) must fit an int; seeds are 64-bit.
inline constexpr std::int64_t kMaxCount = 2147483647;

}  // namespace luxplan::limits
