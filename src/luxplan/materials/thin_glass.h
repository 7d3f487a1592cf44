// A thin clear glass pane: two parallel smooth interfaces with absorption in
// between, summed over all inter-reflections; used by the glass BSDF and by
// shadow rays that pass straight through panes.
#pragma once

namespace luxplan {

// Refractive index of ordinary soda-lime window glass.
inline constexpr double kGlassIor = 1.52;
// Normal-incidence transmittance of the scene format's default pane.
inline constexpr double kDefaultGlassTransmittance = 0.88;

// Reflectance and transmittance of the whole pane (fractions of the incident flux).
struct PaneResponse {
    double reflectance = 0, transmittance = 0;
    double absorptance() const { return 1 - reflectance - transmittance; }
};

// The pane is set by its transmittance at normal incidence (what glazing data
// sheets quote). The internal absorption is solved so that this is matched
// exactly. A clear pane of index n transmits at most (1 - R0) / (1 + R0) at
// normal incidence (R0 = ((n - 1) / (n + 1))^2, 0.918 for n = 1.52); above that,
// the index is lowered until a non-absorbing pane reaches the requested value
// (as anti-reflection coatings do), so T(0) = normalTransmittance in all cases.
class ThinGlass {
public:
    ThinGlass() : ThinGlass(kDefaultGlassTransmittance) {}
    explicit ThinGlass(double normalTransmittance, double ior = kGlassIor);

    // Response to light arriving at angle acos(|cosTheta|) from the normal, either side.
    // Each polarization (s, p) is summed over the inter-reflections separately, then averaged.
    PaneResponse response(double cosTheta) const;
    double reflectance(double cosTheta) const { return response(cosTheta).reflectance; }
    double transmittance(double cosTheta) const { return response(cosTheta).transmittance; }

    // The index actually used (kGlassIor unless lowered, see above).
    double ior() const { return ior_; }
    // Fraction of the flux that survives one pass through the glass at normal incidence.
    double internalTransmittance() const { return tau0_; }

private:
    double ior_ = kGlassIor;
    double tau0_ = 1;
};

// Scalar conveniences for shadow rays and tests (they solve the absorption on every call;
// hold a ThinGlass where that matters).
double thinGlassTransmittance(double cosTheta, double normalTransmittance = kDefaultGlassTransmittance,
                              double ior = kGlassIor);
double thinGlassReflectance(double cosTheta, double normalTransmittance = kDefaultGlassTransmittance,
                            double ior = kGlassIor);

}  // namespace luxplan
