// The Perez all-weather sky (Perez, Seals & Michalsky 1993, "All-weather model for sky
// luminance distribution - preliminary configuration and validation", Solar Energy 50(3)
// 235-245) driven by an hour's direct normal and diffuse horizontal irradiance, with the
// luminous efficacy model of Perez, Ineichen, Seals, Michalsky & Stewart (1990), "Modeling
// daylight availability and irradiance components from direct and global irradiance",
// Solar Energy 44(5) 271-289, the way Radiance's gendaylit (-W) uses them, special cases
// included. docs/daylight.md, "The Perez all-weather sky".
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include <luxplan/core/math.h>

namespace luxplan {

// One hour's measured input.
struct PerezSkyInput {
    double directNormalWm2 = 0;       // direct normal irradiance
    double diffuseHorizontalWm2 = 0;  // diffuse horizontal irradiance
    double sunZenithDeg = 0;          // apparent zenith angle of the sun
    int dayOfYear = 1;                // 1..366, for the sun's distance
    double dewPointC = std::numeric_limits<double>::quiet_NaN();  // NaN: W = 2 cm
};

// What the model makes of the hour.
struct PerezSkyCondition {
    bool lit = false;           // false: sun below the horizon or no irradiance (a dark sky)
    double epsilon = 1;         // sky clearness, limited to [1, 12.01)
    double delta = 0;           // sky brightness, limited to [0.01, 0.6]
    int bin = 1;                // clearness bin 1 (overcast) .. 8 (clear)
    double zenithDeg = 0;       // the zenith angle the formulas used (at most 87 deg)
    double precipitableWaterCm = 2;
    double diffuseEfficacy = 0, directEfficacy = 0;  // lm/W
    double diffuseHorizontalLx = 0, directNormalLx = 0;
    std::array<double, 5> coefficients{};  // a, b, c, d, e of the luminance distribution
};

// Relative optical air mass, Kasten (1966), the zenith angle limited to 90 deg.
double perezAirMass(double zenithDeg);
// Sun-earth distance correction (R0/R)^2 of Spencer (1971) by day of the year.
double perezEccentricity(int dayOfYear);
// Precipitable water (cm) from the surface dew point, Perez et al. 1990 (after Wright et
// al. 1989): W = exp(0.07 Td - 0.075); a missing or implausible dew point gives 2 cm.
double perezPrecipitableWater(double dewPointC);
// Clearness epsilon = ((Edh + Edn)/Edh + 1.041 Z^3) / (1 + 1.041 Z^3), Z in radians.
double perezClearness(double directNormalWm2, double diffuseHorizontalWm2, double zenithDeg);
// Brightness Delta = Edh m / (1367 W/m2 * eccentricity).
double perezBrightness(double diffuseHorizontalWm2, double zenithDeg, int dayOfYear);
// The bin of a clearness: 1 for [1, 1.065), ..., 8 for [6.2, inf).
int perezClearnessBin(double epsilon);
// The coefficients a..e of bin `bin` for a zenith angle (radians) and a brightness, from the
// 1993 table: x = x1 + x2 Z + Delta (x3 + x4 Z); bin 1's c and d in their own forms; Delta
// at least 0.2 in bins 2..5 (gendaylit's correction).
std::array<double, 5> perezCoefficients(int bin, double zenithRad, double delta);
// Perez 1990 luminous efficacies (lm/W) of the diffuse horizontal, direct normal and global
// horizontal irradiance: a + b W + c cos Z + d ln Delta (diffuse, global) and
// a + b W + c exp(5.73 Z - 5) + d Delta (direct, at least 0).
double perezDiffuseEfficacy(int bin, double precipitableWaterCm, double zenithDeg, double delta);
double perezDirectEfficacy(int bin, double precipitableWaterCm, double zenithDeg, double delta);
double perezGlobalEfficacy(int bin, double precipitableWaterCm, double zenithDeg, double delta);
// Relative luminance (1 + a e^(b / cos theta)) (1 + c e^(d gamma) + e cos^2 gamma), theta the
// zenith angle of the direction (cos theta at least 1e-6) and gamma its angle to the sun.
double perezRelativeLuminance(const std::array<double, 5>& k, double cosTheta, double gamma);

// The hour: epsilon, Delta, bin, efficacies, illuminances and coefficients; `lit` false
// when the sun is below the horizon, both irradiances are zero or the direct irradiance
// exceeds the solar constant (gendaylit's "error sky").
PerezSkyCondition perezSkyCondition(const PerezSkyInput& in);

// The hour's sky in scene coordinates (z up): luminance in cd/m2, scaled so that the sky
// gives condition.diffuseHorizontalLx on an open horizontal plane; 0 below the horizon
// and for an unlit condition.
class PerezAllWeatherSky {
public:
    // `normalise` false: the relative distribution only (scale() 0, luminance() 0), for a
    // caller that normalises it on its own quadrature (daylight coefficients' patches).
    PerezAllWeatherSky(const PerezSkyCondition& condition, const Vec3& sunDirection, bool normalise = true);
    double luminance(const Vec3& w) const;
    double relativeLuminance(const Vec3& w) const;
    double scale() const { return scale_; }  // cd/m2 per unit of relative luminance

    // Directions that share one cos(theta) (a row of a map), the gradation term computed
    // once; luminance(w) equals luminance() bit for bit.
    class Row {
    public:
        double luminance(const Vec3& w) const { return sky_->scale_ * std::max(0.0, gradation_ * sky_->indicatrix(w)); }

    private:
        friend class PerezAllWeatherSky;
        const PerezAllWeatherSky* sky_ = nullptr;
        double gradation_ = 0;
    };
    Row row(double cosTheta) const;

private:
    double gradation(double cosTheta) const;  // 1 + a exp(b / cos theta)
    double indicatrix(const Vec3& w) const;   // 1 + c exp(d gamma) + e cos^2 gamma

    std::array<double, 5> k_{};
    Vec3 sun_;
    double scale_ = 0;
};

}  // namespace luxplan
