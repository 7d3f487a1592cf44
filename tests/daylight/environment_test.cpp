// DaylightEnvironment: illuminance of analytic skies (by quadrature and by importance
// sampling), ground light, chi-square tests of sky and sun sampling, pdf normalization.
#include <gtest/gtest.h>

#include <luxplan/core/rng.h>
#include <luxplan/core/warp.h>
#include <luxplan/daylight/daylight.h>
#include <luxplan/daylight/preetham.h>
#include "support/chi2.h"

namespace luxplan {
namespace {

// A sun disk at (altitude, azimuth) with its share `weight` of a period and its normal
// illuminance, as the daylight builder makes them.
SunDisk sunDisk(double altitudeDeg, double azimuthDeg, double weight, double normalIlluminanceLx) {
    SunDisk s;
    s.altitudeDeg = altitudeDeg;
    s.azimuthDeg = azimuthDeg;
    s.direction = horizonToScene(altitudeDeg, azimuthDeg, 0);
    s.weight = weight;
    s.normalIlluminanceLx = normalIlluminanceLx;
    s.luminance = weight * normalIlluminanceLx / kSunDiskProjectedSolidAngle;
    return s;
}

DaylightEnvironment uniformSky(double nits, double rho, int w = 128, int h = 64) {
    DaylightParams p;
    p.model = SkyModelType::Uniform;
    p.luminanceNits = nits;
    p.groundReflectance = rho;
    return buildDaylight(p, Site{}, {w, h, 1, {}});
}

DaylightEnvironment overcastSky(double lux, double rho) {
    DaylightParams p;
    p.model = SkyModelType::CieOvercast;
    p.horizontalIlluminanceLx = lux;
    p.groundReflectance = rho;
    return buildDaylight(p, Site{}, {256, 128, 2, {}});
}

DaylightEnvironment preethamSky(int w = 64, int h = 32) {
    DaylightParams p;
    p.turbidity = 3;
    p.sunOverride = SunOverride{35, 200, std::nullopt};
    p.groundReflectance = 0.2;
    return buildDaylight(p, Site{}, {w, h, 2, {}});
}

// Monte Carlo estimate of the illuminance on the open horizontal plane by sampling the sky
// distribution, with its standard error.
struct Estimate {
    double mean, stdError;
};
Estimate horizontalByImportanceSampling(const DaylightEnvironment& env, int n, uint64_t seed) {
    Rng rng(seed);
    double sum = 0, sum2 = 0;
    for (int k = 0; k < n; ++k) {
        EnvironmentSample s = env.sampleSky({rng.uniform(), rng.uniform()});
        double f = s.pdf > 0 ? luminance(s.Le) * std::max(0.0, s.wi.z) / s.pdf : 0;
        sum += f;
        sum2 += f * f;
    }
    double mean = sum / n, var = std::max(0.0, sum2 / n - mean * mean);
    return {mean, std::sqrt(var / n)};
}

TEST(UniformSky, GivesPiLOnTheOpenHorizontalPlane) {
    const double L = 1000;
    DaylightEnvironment env = uniformSky(L, 0.0);
    EXPECT_NEAR(env.skyHorizontalIlluminance(), kPi * L, 1e-9 * L);
    EXPECT_NEAR(env.totalHorizontalIlluminance(), kPi * L, 1e-9 * L);
    EXPECT_NEAR(env.illuminance({0, 0, 1}), kPi * L, 1e-4 * L);  // 4x4 sub-sample quadrature
    EXPECT_DOUBLE_EQ(env.Lv({0.3, 0.1, 0.9}), L);
    EXPECT_DOUBLE_EQ(env.Lv({0.3, 0.1, -0.9}), 0.0);
    // Importance sampling: unbiased within 4 standard errors.
    Estimate e = horizontalByImportanceSampling(env, 100000, 1);
    EXPECT_NEAR(e.mean, kPi * L, 4 * e.stdError);
    EXPECT_LT(e.stdError, 0.01 * kPi * L);
}

TEST(UniformSky, GroundReflectsTheSky) {
    const double L = 1000, rho = 0.3;
    DaylightEnvironment env = uniformSky(L, rho);
    EXPECT_NEAR(env.groundLuminance(), rho * kPi * L / kPi, 1e-9 * L);
    EXPECT_NEAR(env.Lv({0, 0, -1}), rho * L, 1e-9 * L);
    // A plane facing down sees only the ground: E = pi L_ground.
    EXPECT_NEAR(env.illuminance({0, 0, -1}), kPi * rho * L, 1e-4 * L);
    // Sampling the whole sphere and integrating cos+ over the upper hemisphere is still pi L.
    Estimate e = horizontalByImportanceSampling(env, 100000, 2);
    EXPECT_NEAR(e.mean, kPi * L, 4 * e.stdError);
}

TEST(CieOvercastSky, GivesItsHorizontalIlluminanceAndVerticalRatio) {
    const double eh = 10000;
    DaylightEnvironment env = overcastSky(eh, 0.0);
    EXPECT_NEAR(env.totalHorizontalIlluminance(), eh, 1e-4 * eh);
    EXPECT_NEAR(env.illuminance({0, 0, 1}), eh, 1e-4 * eh);
    // Open vertical plane, no ground: Lz (pi/6 + 4/9) = 0.396 E_h.
    const double ratio = (kPi / 6 + 4.0 / 9.0) / (7 * kPi / 9);
    EXPECT_NEAR(ratio, 0.396, 5e-4);
    for (Vec3 n : {Vec3(1, 0, 0), Vec3(0, -1, 0), normalize(Vec3(1, 1, 0))})
        EXPECT_NEAR(env.illuminance(n, /*withGround=*/false), ratio * eh, 2e-4 * eh);
    // Zenith three times as bright as the horizon; pixels hold averages, so compare the
    // top and the last sky row with the profile at their mean cos(theta) (it is linear in it).
    const SkyMap& map = env.skyMap();
    const int last = map.height() / 2 - 1;
    const double zTop = (1 + map.cosEdge(1)) / 2, zLast = map.cosEdge(last) / 2;
    EXPECT_NEAR(env.Lv({0, 0, 1}) / env.Lv({1, 0, 1e-4}), (1 + 2 * zTop) / (1 + 2 * zLast), 1e-9);
    EXPECT_NEAR(env.Lv({0, 0, 1}) / env.Lv({1, 0, 1e-4}), 3.0, 0.1);
    Estimate e = horizontalByImportanceSampling(env, 100000, 3);
    EXPECT_NEAR(e.mean, eh, 4 * e.stdError);
}

TEST(CieOvercastSky, GroundAddsHalfItsLuminanceTimesPiOnAVerticalPlane) {
    // Ground of reflectance rho: L_g = rho E_h / pi; a vertical plane sees half the lower
    // hemisphere, so it gains L_g pi / 2 = rho E_h / 2.
    const double eh = 10000, rho = 0.2;
    DaylightEnvironment env = overcastSky(eh, rho);
    EXPECT_NEAR(env.groundLuminance(), rho * eh / kPi, 1e-4 * eh);
    const double ratio = (kPi / 6 + 4.0 / 9.0) / (7 * kPi / 9);
    EXPECT_NEAR(env.illuminance({1, 0, 0}), (ratio + rho / 2) * eh, 2e-4 * eh);
    EXPECT_NEAR(env.illuminance({1, 0, 0}, false), ratio * eh, 2e-4 * eh);
}

TEST(SkySampling, PdfIsNormalizedAndMatchesEvaluation) {
    DaylightEnvironment env = preethamSky();
    const SkyMap& map = env.skyMap();
    // Exact: sum of pixel pdf x pixel solid angle.
    double total = 0;
    for (int iy = 0; iy < map.height(); ++iy)
        for (int ix = 0; ix < map.width(); ++ix)
            total += env.skyPdf(map.direction(ix, iy, 0.5, 0.5)) * map.pixelSolidAngle(iy);
    EXPECT_NEAR(total, 1.0, 1e-12);
    // Quadrature on a grid unrelated to the pixels: midpoint rule in (cos theta, phi).
    double q = 0;
    const int nz = 1000, np = 1000;
    for (int i = 0; i < nz; ++i)
        for (int j = 0; j < np; ++j) {
            double z = -1 + 2 * (i + 0.5) / nz, phi = 2 * kPi * (j + 0.37) / np, r = std::sqrt(1 - z * z);
            q += env.skyPdf({r * std::cos(phi), r * std::sin(phi), z});
        }
    EXPECT_NEAR(q * (2.0 / nz) * (2 * kPi / np), 1.0, 2e-3);
    // pdf is proportional to luminance: pdf = Lv / integral of Lv over the sphere.
    Rng rng(4);
    for (int k = 0; k < 1000; ++k) {
        EnvironmentSample s = env.sampleSky({rng.uniform(), rng.uniform()});
        ASSERT_GT(s.pdf, 0);
        EXPECT_NEAR(length(s.wi), 1.0, 1e-12);
        EXPECT_DOUBLE_EQ(s.pdf, env.skyPdf(s.wi));
        EXPECT_EQ(s.Le, env.Le(s.wi));
        EXPECT_NEAR(s.pdf, luminance(s.Le) / env.skyIntegral(), 1e-9 * s.pdf);
    }
}

TEST(SkySampling, ChiSquareAgainstPdf) {
    DaylightEnvironment env = preethamSky(64, 32);
    const SkyMap& map = env.skyMap();
    // Cells: 2 x 2 pixel blocks, whose probability is exact (the map is piecewise constant).
    const int cw = map.width() / 2, ch = map.height() / 2, n = 300000;
    std::vector<double> observed(cw * ch, 0), expected(cw * ch, 0);
    Rng rng(12);
    for (int k = 0; k < n; ++k) {
        EnvironmentSample s = env.sampleSky({rng.uniform(), rng.uniform()});
        int ix, iy;
        map.pixelOf(s.wi, ix, iy);
        observed[(iy / 2) * cw + ix / 2] += 1;
    }
    for (int iy = 0; iy < map.height(); ++iy)
        for (int ix = 0; ix < map.width(); ++ix)
            expected[(iy / 2) * cw + ix / 2] += env.skyPdf(map.direction(ix, iy, 0.5, 0.5)) * map.pixelSolidAngle(iy) * n;
    auto r = test::chi2Test(observed, expected);
    EXPECT_GT(r.pValue, 0.01) << r.table;
}

// Two overlapping disks and one apart, with different luminance.
DaylightEnvironment threeSuns() {
    DaylightParams p;
    p.model = SkyModelType::Uniform;
    p.luminanceNits = 0;
    p.groundReflectance = 0;
    p.sun = false;
    DaylightEnvironment sky = buildDaylight(p, Site{}, {16, 8, 1, {}});
    std::vector<SunDisk> disks;
    auto disk = [&](double alt, double az, double en) {
        disks.push_back(sunDisk(alt, az, 1.0 / 3, en));
    };
    disk(40.0, 180.0, 90000);
    disk(40.2, 180.1, 60000);  // overlaps the first
    disk(41.0, 181.0, 30000);
    return DaylightEnvironment(sky.skyMap(), disks, 0.0);
}

TEST(SunSampling, ChiSquareAgainstPdfOnTheTangentPlane) {
    DaylightEnvironment env = threeSuns();
    // Project onto the plane tangent at the cluster's middle; bins of a 24 x 24 grid over
    // [-r, r]^2, expected counts by integrating sunPdf with 24 x 24 sub-cells (dw = dA / (1 + x^2 + y^2)^1.5).
    const Frame f = Frame::fromNormal(horizonToScene(40.5, 180.5, 0));
    const double r = std::tan(radians(1.2));
    const int bins = 24, sub = 24, n = 200000;
    std::vector<double> observed(bins * bins, 0), expected(bins * bins, 0);
    Rng rng(21);
    int outside = 0;
    for (int k = 0; k < n; ++k) {
        EnvironmentSample s = env.sampleSun(rng.uniform(), {rng.uniform(), rng.uniform()});
        ASSERT_GT(s.pdf, 0);
        EXPECT_DOUBLE_EQ(s.pdf, env.sunPdf(s.wi));
        EXPECT_EQ(s.Le, env.sunLe(s.wi));
        Vec3 l = f.toLocal(s.wi);
        double x = l.x / l.z, y = l.y / l.z;
        int i = int((x + r) / (2 * r) * bins), j = int((y + r) / (2 * r) * bins);
        if (i < 0 || j < 0 || i >= bins || j >= bins) { ++outside; continue; }
        observed[j * bins + i] += 1;
    }
    EXPECT_EQ(outside, 0);
    const double h = 2 * r / (bins * sub);
    for (int j = 0; j < bins; ++j)
        for (int i = 0; i < bins; ++i) {
            double sum = 0;
            for (int b = 0; b < sub; ++b)
                for (int a = 0; a < sub; ++a) {
                    double x = -r + (i * sub + a + 0.5) * h, y = -r + (j * sub + b + 0.5) * h;
                    double jac = 1 / std::pow(1 + x * x + y * y, 1.5);
                    sum += env.sunPdf(normalize(f.toWorld({x, y, 1}))) * jac * h * h;
                }
            expected[j * bins + i] = sum * n;
        }
    double total = 0;
    for (double e : expected) total += e / n;
    EXPECT_NEAR(total, 1.0, 2e-3);  // the pdf integrates to 1 (quadrature of the disk rims)
    auto res = test::chi2Test(observed, expected);
    EXPECT_GT(res.pValue, 0.01) << res.table;
}

TEST(SunSampling, DisksArePickedByLuminanceAndStaySharp) {
    DaylightEnvironment env = threeSuns();
    const auto& disks = env.sunDisks();
    double sumL = 0;
    for (const SunDisk& s : disks) sumL += s.luminance;
    EXPECT_NEAR(env.sunIntegral(), sumL * kSunSolidAngle, 1e-9 * env.sunIntegral());
    // Inside the lone disk, pdf = pmf / solid angle; outside every disk both vanish.
    EXPECT_NEAR(env.sunPdf(disks[2].direction), disks[2].luminance / sumL / kSunSolidAngle, 1e-6);
    EXPECT_EQ(env.sunPdf(horizonToScene(45, 180, 0)), 0.0);
    // 0.345 deg from the first disk's centre and 0.334 from the second's: outside (radius 0.2665).
    EXPECT_EQ(env.sunLv(horizonToScene(40, 180.45, 0)), 0.0);
    // 0.2 deg from the first disk's centre, 0.4 from the second's: inside the first only.
    EXPECT_NEAR(env.sunLv(horizonToScene(39.8, 180, 0)), disks[0].luminance, 1e-9 * disks[0].luminance);
    // Horizontal illuminance of the disks: sum of weight x E_n x sin(altitude).
    double eh = 0;
    for (const SunDisk& s : disks) eh += s.weight * s.normalIlluminanceLx * std::sin(radians(s.altitudeDeg));
    EXPECT_NEAR(env.sunHorizontalIlluminance(), eh, 1e-9 * eh);
    // Illuminance at normal incidence on the lone disk.
    EXPECT_NEAR(env.illuminance(disks[2].direction, false, true) - env.illuminance(disks[2].direction, false, false),
                disks[2].weight * disks[2].normalIlluminanceLx + disks[1].weight * disks[1].normalIlluminanceLx *
                    dot(disks[1].direction, disks[2].direction) + disks[0].weight * disks[0].normalIlluminanceLx *
                    dot(disks[0].direction, disks[2].direction), 1e-6);
}

TEST(DaylightEnvironment, NightIsBlack) {
    DaylightEnvironment night;
    EXPECT_EQ(night.Le({0, 0, 1}), Vec3());
    EXPECT_EQ(night.skyPdf({0, 0, 1}), 0.0);
    EXPECT_EQ(night.sampleSky({0.5, 0.5}).pdf, 0.0);
    EXPECT_EQ(night.sampleSun(0.5, {0.5, 0.5}).pdf, 0.0);
    EXPECT_FALSE(night.hasSky());
    EXPECT_FALSE(night.hasSun());
    EXPECT_EQ(night.totalHorizontalIlluminance(), 0.0);
}

TEST(DaylightEnvironment, RadianceIsPositiveEverywhereOnlyWhereEveryPixelAndTheGroundAre) {
    // The path tracer traces a sky sample's shadow ray before it looks up its radiance
    // only where no direction can read 0 (it would have skipped the ray).
    EXPECT_TRUE(uniformSky(1000, 0.2).radiancePositive());
    EXPECT_TRUE(preethamSky().radiancePositive());
    EXPECT_FALSE(uniformSky(1000, 0).radiancePositive());  // a black ground
    SkyMap map(32, 16);
    for (int iy = 0; iy < 16; ++iy)
        for (int ix = 0; ix < 32; ++ix) map.at(ix, iy) = Vec3(100, 100, 100);
    EXPECT_TRUE(DaylightEnvironment(map, {}, 0.2).radiancePositive());
    map.at(5, 3) = Vec3();  // one black pixel of the sky
    EXPECT_FALSE(DaylightEnvironment(map, {}, 0.2).radiancePositive());
    EXPECT_FALSE(DaylightEnvironment().radiancePositive());  // night
}

TEST(SkyMap, PixelLookupAgreesWithPixelDirections) {
    SkyMap map(32, 16);
    for (int iy = 0; iy < 16; ++iy)
        for (int ix = 0; ix < 32; ++ix)
            for (double f : {0.01, 0.5, 0.99}) {
                int jx, jy;
                map.pixelOf(map.direction(ix, iy, f, f), jx, jy);
                EXPECT_EQ(jx, ix);
                EXPECT_EQ(jy, iy);
            }
    int ix, iy;
    map.pixelOf({1, 0, 0}, ix, iy);
    EXPECT_EQ(iy, 8);  // horizontal directions belong to the ground
    map.pixelOf({0, 0, 1}, ix, iy);
    EXPECT_EQ(iy, 0);
    map.pixelOf({0, 0, -1}, ix, iy);
    EXPECT_EQ(iy, 15);
    // Random directions, and directions on and next to every row edge: the row is the
    // one whose edges enclose cos(theta), (cosEdge(iy + 1), cosEdge(iy)].
    Rng rng(5);
    std::vector<double> zs;
    for (int k = 0; k < 20000; ++k) zs.push_back(2 * rng.uniform() - 1);
    for (int e = 0; e <= 16; ++e)
        for (double z : {map.cosEdge(e), std::nextafter(map.cosEdge(e), 2.0), std::nextafter(map.cosEdge(e), -2.0)})
            zs.push_back(std::clamp(z, -1.0, 1.0));
    for (double z : zs) {
        int row = 0;
        while (row < 15 && z <= map.cosEdge(row + 1)) ++row;
        const double r = std::sqrt(std::max(0.0, 1 - z * z));
        map.pixelOf({r, 0, z}, ix, iy);
        ASSERT_EQ(iy, row) << z;
    }
    double total = 0;
    for (int r = 0; r < 16; ++r) total += map.pixelSolidAngle(r) * 32;
    EXPECT_NEAR(total, 4 * kPi, 1e-12);
}

}  // namespace
}  // namespace luxplan

namespace luxplan {
namespace {

// A black sky and no sun of its own, for tests that set the disks themselves.
DaylightEnvironment blackSkyWithoutSun() {
    DaylightParams p;
    p.model = SkyModelType::Uniform;
    p.luminanceNits = 0;
    p.sun = false;
    return buildDaylight(p, Site{}, {16, 8, 1, {}});
}

// sunLe and sunPdf look disks up by direction; they must find exactly the disks a scan
// of all of them finds: near every disk's centre and rim, near the zenith, and at
// random, for disks spread over the sky and crowded round the zenith.
TEST(SunDiskIndex, FindsWhatAScanOfEveryDiskFinds) {
    DaylightEnvironment sky = blackSkyWithoutSun();
    std::vector<SunDisk> disks;
    Rng rng(7);
    for (int k = 0; k < 600; ++k) {
        const double altitude = k < 500 ? 90 * rng.uniform() : 89 + rng.uniform();  // the last 100 at the zenith
        const double azimuth = 360 * rng.uniform();
        disks.push_back(sunDisk(altitude, azimuth, 1.0 / 600, 50000 + 100 * k));
    }
    DaylightEnvironment env(sky.skyMap(), disks, 0.0);
    const double cosHalf = std::cos(radians(kSunAngularDiameterDeg / 2));
    double total = 0;
    for (const SunDisk& s : disks) total += s.luminance;
    auto scan = [&](const Vec3& w, double& Lv, double& pdf) {
        Lv = 0, pdf = 0;
        for (const SunDisk& s : disks)
            if (dot(w, s.direction) >= cosHalf - 1e-12) Lv += s.luminance, pdf += s.luminance / total;
        pdf /= 2 * kPi * (1 - cosHalf);
    };
    std::vector<Vec3> probes;
    for (const SunDisk& s : disks) {
        Frame f = Frame::fromNormal(s.direction);
        probes.push_back(s.direction);
        for (double r : {0.5, 0.99, 1.0, 1.01})
            for (int a = 0; a < 8; ++a) {
                double phi = 2 * kPi * a / 8, t = r * radians(kSunAngularDiameterDeg / 2);
                probes.push_back(f.toWorld(Vec3(std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t))));
            }
    }
    for (int k = 0; k < 20000; ++k) probes.push_back(sampleUniformSphere({rng.uniform(), rng.uniform()}));
    probes.push_back({0, 0, 1});
    int hits = 0;
    for (const Vec3& w : probes) {
        double Lv, pdf;
        scan(w, Lv, pdf);
        hits += Lv > 0;
        ASSERT_NEAR(env.sunLv(w), Lv, 1e-9 * Lv) << w.x << " " << w.y << " " << w.z;
        ASSERT_NEAR(env.sunPdf(w), pdf, 1e-9 * pdf);
    }
    EXPECT_GT(hits, 600 * 20);
}

// A period's disks crowd into a few tens of degrees: a cone around them all answers
// most directions with one dot product. It must miss no disk: near every rim, and at
// random over the sphere.
TEST(SunDiskIndex, TheConeAroundAPeriodsDisksMissesNone) {
    DaylightEnvironment sky = blackSkyWithoutSun();
    std::vector<SunDisk> disks;
    for (int k = 0; k < 13; ++k) {  // a morning: 15 to 55 degrees high, east to south-east
        disks.push_back(sunDisk(15 + 40.0 * k / 12, 95 + 45.0 * k / 12, 1.0 / 13, 60000 + 1000 * k));
    }
    DaylightEnvironment env(sky.skyMap(), disks, 0.0);
    const double cosHalf = std::cos(radians(kSunAngularDiameterDeg / 2));
    Rng rng(11);
    std::vector<Vec3> probes;
    for (const SunDisk& s : disks) {
        Frame f = Frame::fromNormal(s.direction);
        for (double r : {0.0, 0.99, 1.0, 1.001})
            for (int a = 0; a < 16; ++a) {
                double phi = 2 * kPi * a / 16, t = r * radians(kSunAngularDiameterDeg / 2);
                probes.push_back(f.toWorld(Vec3(std::sin(t) * std::cos(phi), std::sin(t) * std::sin(phi), std::cos(t))));
            }
    }
    for (int k = 0; k < 20000; ++k) probes.push_back(sampleUniformSphere({rng.uniform(), rng.uniform()}));
    int hits = 0;
    for (const Vec3& w : probes) {
        double Lv = 0;
        for (const SunDisk& s : disks)
            if (dot(w, s.direction) >= cosHalf - 1e-12) Lv += s.luminance;
        hits += Lv > 0;
        ASSERT_NEAR(env.sunLv(w), Lv, 1e-9 * Lv) << w.x << " " << w.y << " " << w.z;
    }
    EXPECT_GT(hits, 13 * 16 * 2);
}

// A sun sample's radiance and density are sunLe and sunPdf at its direction, both when
// the disks lie apart (a morning's half-hour steps: no lookup) and when they overlap
// (minute steps).
TEST(SunDiskIndex, SamplesCarryTheRadianceAndDensityOfTheirDirection) {
    DaylightEnvironment sky = blackSkyWithoutSun();
    for (const double stepDeg : {3.0, 0.2}) {
        std::vector<SunDisk> disks;
        for (int k = 0; k < 13; ++k) {
            disks.push_back(sunDisk(15 + stepDeg * k, 95 + stepDeg * k / 2, 1.0 / 13, 60000 + 1000 * k));
        }
        DaylightEnvironment env(sky.skyMap(), disks, 0.0);
        Rng rng(5);
        int overlapping = 0;
        for (int i = 0; i < 20000; ++i) {
            const EnvironmentSample s = env.sampleSun(rng.uniform(), {rng.uniform(), rng.uniform()});
            ASSERT_GT(s.pdf, 0);
            EXPECT_EQ(s.pdf, env.sunPdf(s.wi));
            EXPECT_EQ(s.Le, env.sunLe(s.wi));
            overlapping += s.pdf * kSunSolidAngle > 0.1;  // more than any one disk's share
        }
        if (stepDeg > 1) EXPECT_EQ(overlapping, 0);
        else EXPECT_GT(overlapping, 1000);
    }
}

// The tracer draws no sun sample where a sensor cannot see the cone round the disks
// (Sensor::maySee): every sample must lie inside it, the disks' rims included.
TEST(SunDiskIndex, EverySunSampleLiesInTheConeAroundTheDisks) {
    DaylightEnvironment sky = blackSkyWithoutSun();
    std::vector<SunDisk> disks;
    for (int k = 0; k < 13; ++k) disks.push_back(sunDisk(15 + 40.0 * k / 12, 95 + 45.0 * k / 12, 1.0 / 13, 60000));
    DaylightEnvironment env(sky.skyMap(), disks, 0.0);
    ASSERT_GT(env.sunConeCos(), 0.5);  // a cone of a few tens of degrees, not everything
    Rng rng(3);
    double closest = 1;
    for (int i = 0; i < 200000; ++i) {
        const EnvironmentSample s = env.sampleSun(rng.uniform(), {rng.uniform(), rng.uniform()});
        ASSERT_GT(s.pdf, 0);
        closest = std::min(closest, dot(s.wi, env.sunConeAxis()));
    }
    EXPECT_GE(closest, env.sunConeCos());
    // Not a cone far wider than the disks: the farthest samples come within a disk of its rim.
    EXPECT_LT(std::acos(closest), std::acos(env.sunConeCos()));
    EXPECT_GT(std::acos(closest), std::acos(env.sunConeCos()) - radians(2 * kSunAngularDiameterDeg));
}

// sunBehind(n) lets a surface that only reflects skip its sun sample: it must hold
// only where every sample lies behind the surface, and hold up to the cone's edge.
TEST(SunDiskIndex, ASunBehindASurfaceLeavesEverySampleBehindIt) {
    DaylightEnvironment sky = blackSkyWithoutSun();
    std::vector<SunDisk> disks;
    for (int k = 0; k < 13; ++k) disks.push_back(sunDisk(15 + 40.0 * k / 12, 95 + 45.0 * k / 12, 1.0 / 13, 60000));
    DaylightEnvironment env(sky.skyMap(), disks, 0.0);
    Rng rng(5);
    std::vector<Vec3> suns;
    for (int i = 0; i < 20000; ++i) suns.push_back(env.sampleSun(rng.uniform(), {rng.uniform(), rng.uniform()}).wi);
    int behind = 0;
    for (int i = 0; i < 3000; ++i) {
        const Vec3 n = sampleUniformSphere({rng.uniform(), rng.uniform()});
        if (!env.sunBehind(n)) continue;
        ++behind;
        for (const Vec3& w : suns) ASSERT_LE(dot(w, n), 0) << "normal " << i;
    }
    EXPECT_GT(behind, 300);
    // Normals tilted from straight against the cone's axis towards it: behind until the
    // cone's edge reaches the surface's plane, then not.
    const double edge = kPi / 2 - std::acos(env.sunConeCos());
    const Frame f = Frame::fromNormal(-env.sunConeAxis());
    for (double tilt : {0.0, 0.5 * edge, edge - 1e-3, edge + 1e-3, kPi / 2}) {
        const Vec3 n = f.toWorld({std::sin(tilt), 0, std::cos(tilt)});
        EXPECT_EQ(env.sunBehind(n), tilt < edge) << "tilt " << tilt;
    }
    // No sun: never.
    EXPECT_FALSE(sky.sunBehind(Vec3(0, 0, -1)));
}

}  // namespace
}  // namespace luxplan
