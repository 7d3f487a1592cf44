// Thin-pane optics: Fresnel at both faces, absorption inside, all inter-reflections.
#include <luxplan/materials/thin_glass.h>

#include <algorithm>
#include <cmath>

#include <luxplan/materials/microfacet.h>

namespace luxplan {

ThinGlass::ThinGlass(double normalTransmittance, double ior) {
    double t0 = std::clamp(normalTransmittance, 0.0, 1.0);
    double n = std::max(1.0, ior);
    double r0 = (n - 1) / (n + 1);
    r0 *= r0;
    if (t0 >= (1 - r0) / (1 + r0)) {
        // Too clear for this index: a lossless pane with T(0) = (1 - R) / (1 + R) = t0.
        double sqrtR = std::sqrt((1 - t0) / (1 + t0));
        ior_ = (1 + sqrtR) / (1 - sqrtR);
        tau0_ = 1;
        return;
    }
    // T(0) = (1 - R)^2 tau / (1 - R^2 tau^2) = t0, solved for tau in the cancellation-free form.
    ior_ = n;
    double a = (1 - r0) * (1 - r0);
    tau0_ = std::min(1.0, 2 * t0 / (a + std::sqrt(a * a + 4 * t0 * t0 * r0 * r0)));
}

PaneResponse ThinGlass::response(double cosTheta) const {
    double c = std::min(1.0, std::abs(cosTheta));
    if (c <= 0) return {1, 0};
    PolarizedReflectance r = dielectricFresnel(c, ior_);
    // Beer-Lambert: the path inside grows as 1 / cos(theta_t).
    double cosT = std::sqrt(std::max(0.0, 1 - (1 - c * c) / (ior_ * ior_)));
    double tau = tau0_ >= 1 ? 1.0 : std::pow(tau0_, 1 / cosT);
    PaneResponse out;
    for (double ri : {r.s, r.p}) {
        if (ri >= 1) {
            out.reflectance += 0.5;
            continue;
        }
        // Geometric series over the bounces between the two faces.
        double denom = 1 - ri * ri * tau * tau;
        double enter = (1 - ri) * (1 - ri);
        out.reflectance += 0.5 * (ri + enter * ri * tau * tau / denom);
        out.transmittance += 0.5 * enter * tau / denom;
    }
    return out;
}

double thinGlassTransmittance(double cosTheta, double normalTransmittance, double ior) {
    return ThinGlass(normalTransmittance, ior).transmittance(cosTheta);
}

double thinGlassReflectance(double cosTheta, double normalTransmittance, double ior) {
    return ThinGlass(normalTransmittance, ior).reflectance(cosTheta);
}

}  // namespace luxplan
