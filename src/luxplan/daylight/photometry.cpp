// CIE 1931 colour matching function table (10 nm) and colour-space conversions.
#include <luxplan/daylight/photometry.h>

namespace luxplan {
namespace {

// CIE 1931 2-degree standard observer, 380..780 nm every 10 nm: x-bar, y-bar, z-bar.
constexpr double kCmf[kSpectrumSamples][3] = {
    {0.001368, 0.000039, 0.006450}, {0.004243, 0.000120, 0.020050}, {0.014310, 0.000396, 0.067850},
    {0.043510, 0.001210, 0.207400}, {0.134380, 0.004000, 0.645600}, {0.283900, 0.011600, 1.385600},
    {0.348280, 0.023000, 1.747060}, {0.336200, 0.038000, 1.772110}, {0.290800, 0.060000, 1.669200},
    {0.195360, 0.090980, 1.287640}, {0.095640, 0.139020, 0.812950}, {0.032010, 0.208020, 0.465180},
    {0.004900, 0.323000, 0.272000}, {0.009300, 0.503000, 0.158200}, {0.063270, 0.710000, 0.078250},
    {0.165500, 0.862000, 0.042160}, {0.290400, 0.954000, 0.020300}, {0.433450, 0.994950, 0.008750},
    {0.594500, 0.995000, 0.003900}, {0.762100, 0.952000, 0.002100}, {0.916300, 0.870000, 0.001650},
    {1.026300, 0.757000, 0.001100}, {1.062200, 0.631000, 0.000800}, {1.002600, 0.503000, 0.000340},
    {0.854450, 0.381000, 0.000190}, {0.642400, 0.265000, 0.000050}, {0.447900, 0.175000, 0.000020},
    {0.283500, 0.107000, 0.000000}, {0.164900, 0.061000, 0.000000}, {0.087400, 0.032000, 0.000000},
    {0.046770, 0.017000, 0.000000}, {0.022700, 0.008210, 0.000000}, {0.011359, 0.004102, 0.000000},
    {0.005790, 0.002091, 0.000000}, {0.002899, 0.001047, 0.000000}, {0.001440, 0.000520, 0.000000},
    {0.000690, 0.000249, 0.000000}, {0.000332, 0.000120, 0.000000}, {0.000166, 0.000060, 0.000000},
    {0.000083, 0.000030, 0.000000}, {0.000042, 0.000015, 0.000000},
};

// sRGB primaries / D65 (IEC 61966-2-1), linear RGB -> XYZ. The inverse is computed from it so
// that XYZ -> RGB -> luminance() returns Y to rounding.
const Transform& rgbToXyzMatrix() {
    static const Transform m = [] {
        Transform t;
        t.m = {0.4124, 0.3576, 0.1805, 0.2126, 0.7152, 0.0722, 0.0193, 0.1192, 0.9505};
        return t;
    }();
    return m;
}

const Transform& xyzToRgbMatrix() {
    static const Transform inv = rgbToXyzMatrix().inverse();
    return inv;
}

}  // namespace

double cieXBar(int i) { return kCmf[i][0]; }
double cieYBar(int i) { return kCmf[i][1]; }
double cieZBar(int i) { return kCmf[i][2]; }

Vec3 spectrumToXYZ(std::span<const double> values) {
    Vec3 xyz;
    for (size_t i = 0; i < values.size() && i < size_t(kSpectrumSamples); ++i)
        xyz += Vec3(kCmf[i][0], kCmf[i][1], kCmf[i][2]) * (values[i] * kSpectrumStepNm);
    return xyz;
}

Vec3 xyzToRGB(const Vec3& xyz) { return xyzToRgbMatrix().applyVector(xyz); }
Vec3 rgbToXYZ(const Vec3& rgb) { return rgbToXyzMatrix().applyVector(rgb); }

Vec3 xyYToRGB(double x, double y, double Y) {
    if (y <= 0 || Y == 0) return {0, 0, 0};
    return xyzToRGB({x * Y / y, Y, (1 - x - y) * Y / y});
}

Vec3 clampToGamut(const Vec3& rgb) {
    if (rgb.x >= 0 && rgb.y >= 0 && rgb.z >= 0) return rgb;
    const Vec3 c = max(rgb, Vec3(0, 0, 0));
    const double target = luminance(rgb), now = luminance(c);
    return now > 0 && target > 0 ? c * (target / now) : Vec3(0, 0, 0);
}

}  // namespace luxplan
