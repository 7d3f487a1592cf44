// Perspective pictures from the photometric path tracer: a pinhole camera, jittered
// pixel samples, colour from what each pixel sees, automatic exposure and a Reinhard
// tone curve to sRGB; and the same luminance in false colour.
#include <luxplan/output/render.h>

#include <luxplan/core/estimator.h>
#include <luxplan/core/parallel.h>
#include <luxplan/core/rng.h>
#include <luxplan/output/black_body.h>
#include <luxplan/scene/layout.h>
#include <luxplan/scene/room.h>

namespace luxplan {
namespace {

constexpr uint64_t kRenderTag = 0x72656e646572ULL;  // "render"
constexpr double kKey = 0.18;
constexpr double kWhitePoint = 1.5;

double srgbEncode(double c) {
    c = std::clamp(c, 0.0, 1.0);
    return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055;
}

// Glazed area of the openings in one wall.
double glazedArea(const RoomShell& room, Wall wall) {
    double area = 0;
    for (const Opening& o : room.openings)
        if (o.wall == wall && o.material) area += o.width * o.height;
    return area;
}

}  // namespace

Camera lookingAt(Vec3 eye, Vec3 target, double fovDeg) {
    Camera c;
    c.position = eye;
    c.lookAt = target;
    c.fovDeg = fovDeg;
    const Vec3 d = normalize(target - eye);
    c.up = std::abs(d.z) > 0.999 ? Vec3(0, 1, 0) : Vec3(0, 0, 1);
    return c;
}

Camera defaultCamera(const Scene& scene) {
    Camera camera;
    camera.fovDeg = 65;
    if (const RoomShell* room = scene.room()) {
        // In the corner between the two walls with the most glass, so that the view
        // looks away from the windows into the daylit room.
        const Bounds3& b = room->box;
        bool south = glazedArea(*room, Wall::South) >= glazedArea(*room, Wall::North);
        bool west = glazedArea(*room, Wall::West) >= glazedArea(*room, Wall::East);
        const double inset = 0.25;
        Vec3 size = b.size();
        double height = std::max(std::min(2.0, size.z - 0.2), 0.5 * size.z);
        camera.position = {west ? b.lo.x + inset : b.hi.x - inset, south ? b.lo.y + inset : b.hi.y - inset,
                           b.lo.z + height};
        camera.lookAt = {west ? b.hi.x : b.lo.x, south ? b.hi.y : b.lo.y, b.lo.z + 0.3 * size.z};
        return camera;
    }
    // No room: from above one corner of everything, looking at its centre.
    Bounds3 b;
    for (const StaticItem& item : scene.geometry)
        if (!item.mesh.empty()) b.extend(item.mesh.bounds());
    std::vector<Transform> world = worldTransforms(scene, initialLayout(scene));
    for (size_t i = 0; i < scene.entities.size(); ++i)
        for (const PartInfo& part : scene.entities[i].parts) b.extend(world[i].apply(part.bounds));
    if (b.empty()) b = Bounds3({-1, -1, 0}, {1, 1, 1});
    Vec3 size = b.size();
    double reach = std::max({size.x, size.y, size.z, 1.0});
    camera.position = {b.lo.x - 0.6 * reach, b.lo.y - 0.6 * reach, b.hi.z + 0.6 * reach};
    camera.lookAt = b.center();
    return camera;
}

namespace {

// Primary rays of a pinhole camera: (px, py) in pixels from the top-left corner.
struct CameraRays {
    CameraRays(const Camera& camera, int width, int height) : origin(camera.position), width(width), height(height) {
        forward = normalize(camera.lookAt - camera.position);
        right = cross(forward, camera.up);
        if (length(right) < 1e-9) right = cross(forward, std::abs(forward.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0));
        right = normalize(right);
        up = cross(right, forward);
        tanHalf = std::tan(radians(std::clamp(camera.fovDeg, 1.0, 179.0)) / 2);
        aspect = double(width) / height;
    }
    Ray at(double px, double py) const {
        double sx = (2 * px / width - 1) * tanHalf * aspect;
        double sy = (1 - 2 * py / height) * tanHalf;
        return {origin, normalize(forward + right * sx + up * sy)};
    }
    Vec3 origin, forward, right, up;
    double tanHalf = 1, aspect = 1;
    int width, height;
};

}  // namespace

Vec3 seenColor(const PathTracer& tracer, Ray ray) {
    const EmbreeScene& rt = tracer.rayTracer();
    const Scene& scene = rt.scene();
    auto unitLuminance = [](Vec3 c) {
        double y = luminance(c);
        return y > 1e-12 ? c / y : Vec3(1, 1, 1);
    };
    for (int surfaces = 0; surfaces < 8; ++surfaces) {
        std::optional<Hit> hit = rt.intersect(ray);
        if (!hit) {
            const DaylightEnvironment* daylight = tracer.daylight();
            if (!daylight) return {1, 1, 1};
            Vec3 w = normalize(ray.direction);
            return unitLuminance(daylight->Le(w) + daylight->sunLe(w));
        }
        if (hit->kind == HitKind::Emitter)
            return unitLuminance(blackBodyRgb(scene.emitters.at(size_t(hit->index)).cctK));
        const Material& m = scene.materials.at(hit->material);
        const Vec3 d = normalize(ray.direction);
        const double offset = 1e-4 * std::max(1.0, hit->t * length(ray.direction));
        switch (m.type) {
            case MaterialType::Glass:
                ray = Ray{hit->point + d * offset, d};
                continue;
            case MaterialType::Mirror: {
                Vec3 n = hit->shadingNormal;
                Vec3 r = d - n * (2 * dot(d, n));
                ray = Ray{hit->point + r * offset, r};
                continue;
            }
            case MaterialType::Glossy: return unitLuminance(m.base + m.reflectance);
            default: return unitLuminance(m.reflectance);
        }
    }
    return {1, 1, 1};
}

LuminanceImage renderLuminance(const PathTracer& tracer, const Camera& camera, const RenderOptions& options) {
    LuminanceImage out;
    out.width = std::max(1, options.width);
    out.height = std::max(1, options.height);
    out.values.assign(size_t(out.width) * size_t(out.height), 0.0);
    out.variance.assign(out.values.size(), 0.0);
    out.emitters.assign(out.values.size(), 0.0);
    if (options.color) out.chroma.assign(out.values.size(), Vec3(1, 1, 1));
    const int spp = std::max(1, options.samplesPerPixel);
    const CameraRays rays(camera, out.width, out.height);

    parallelFor(size_t(out.height), [&](size_t row) {
        if (options.cancel && options.cancel->load(std::memory_order_relaxed)) return;
        const int y = int(row);
        RayStats stats;
        for (int x = 0; x < out.width; ++x) {
            const uint64_t pixel = uint64_t(y) * uint64_t(out.width) + uint64_t(x);
            // A luminaire sample counts as 0 in the surface estimate and the other way round,
            // so both are over the same samples (a dropped one is left out of both).
            MeanEstimator surfaces, emitters;
            Vec3 weighted, plain;  // sum of L x colour, and of colour
            for (int k = 0; k < spp; ++k) {
                Rng rng(hashValues({options.seed, kRenderTag, pixel, uint64_t(k)}));
                double u = rng.uniform(), v = rng.uniform();
                bool luminaire = false;
                const Ray ray = rays.at(x + u, y + v);
                double L = tracer.radianceSample(ray, rng, stats, luminaire);
                surfaces.add(luminaire ? 0.0 : L);
                emitters.add(luminaire ? L : 0.0);
                if (options.color) {
                    Vec3 c = seenColor(tracer, ray);
                    plain = plain + c;
                    if (std::isfinite(L) && L > 0) weighted = weighted + c * L;
                }
            }
            if (options.color) {
                const double seen = luminance(weighted);
                out.chroma[pixel] = seen > 0 ? weighted / seen : plain / std::max(luminance(plain), 1e-12);
            }
            const double mean = surfaces.mean();
            out.values[pixel] = mean + emitters.mean();
            out.emitters[pixel] = emitters.mean();
            // One sample tells nothing of the spread: assume an error as large as the mean.
            out.variance[pixel] = surfaces.count() > 1 ? surfaces.varianceOfMean() : mean * mean;
        }
        if (options.rowsDone) options.rowsDone->fetch_add(1, std::memory_order_relaxed);
    });
    return out;
}

GuideBuffer cameraGuide(const EmbreeScene& rt, const Camera& camera, int width, int height) {
    GuideBuffer g;
    g.width = width, g.height = height;
    const size_t n = size_t(width) * size_t(height);
    g.position.assign(n, Vec3()), g.normal.assign(n, Vec3(0, 0, 1)), g.surface.assign(n, -1);
    const CameraRays rays(camera, width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const size_t p = size_t(y) * width + x;
            Ray ray = rays.at(x + 0.5, y + 0.5);
            auto hit = rt.intersect(ray);
            if (!hit || hit->kind == HitKind::Emitter) continue;
            g.position[p] = hit->point;
            g.normal[p] = dot(hit->shadingNormal, ray.direction) <= 0 ? hit->shadingNormal : -hit->shadingNormal;
            g.surface[p] = int32_t(hit->material);
        }
    return g;
}

double autoExposure(const LuminanceImage& image) {
    if (image.values.empty()) return 1;
    const double delta = 1e-4;  // keeps black pixels from dominating the log average
    double sumLog = 0, peak = 0;
    for (double L : image.values) {
        sumLog += std::log(delta + std::max(0.0, L));
        peak = std::max(peak, L);
    }
    if (!(peak > 0)) return 1;
    double logAverage = std::exp(sumLog / double(image.values.size()));
    return kKey / std::max(logAverage, delta);
}

Image toneMap(const LuminanceImage& image, double exposure) {
    Image out(image.width, image.height, kBlack);
    const double w2 = kWhitePoint * kWhitePoint;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            double L = exposure * std::max(0.0, image.values[size_t(y) * size_t(image.width) + size_t(x)]);
            double d = L * (1 + L / w2) / (1 + L);
            const size_t p = size_t(y) * size_t(image.width) + size_t(x);
            if (image.chroma.empty()) {
                auto c = uint8_t(std::lround(255 * srgbEncode(d)));
                out.at(x, y) = {c, c, c};
                continue;
            }
            const Vec3 rgb = image.chroma[p] * d;
            out.at(x, y) = {uint8_t(std::lround(255 * srgbEncode(rgb.x))), uint8_t(std::lround(255 * srgbEncode(rgb.y))),
                            uint8_t(std::lround(255 * srgbEncode(rgb.z)))};
        }
    return out;
}

FalseColor luminanceFalseColor(const LuminanceImage& image) {
    std::vector<double> finite;
    for (double v : image.values)
        if (std::isfinite(v) && v > 0) finite.push_back(v);
    FalseColor f;
    f.scale = ColorScale::Log;
    f.decades = 4;
    f.maxValue = 1;
    if (finite.empty()) return f;
    std::sort(finite.begin(), finite.end());
    f.maxValue = niceCeil(finite[std::min(finite.size() - 1, size_t(0.995 * double(finite.size())))]);
    return f;
}

Image falseColorView(const LuminanceImage& image, const FalseColor& scale) {
    const int legend = 90;
    Image out(image.width + legend, std::max(image.height, 140), kWhite);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) out.at(x, y) = scale.color(image.values[size_t(y) * size_t(image.width) + size_t(x)]);
    drawLegend(out, scale, image.width + 14, 24, 16, std::max(60, out.height() - 40), "cd/m2");
    return out;
}

LuminanceImage renderView(const PathTracer& tracer, const Camera& camera, const RenderOptions& options) {
    LuminanceImage luminance = renderLuminance(tracer, camera, options);
    if (options.denoise) {
        std::vector<double> surfaces(luminance.values.size());
        for (size_t i = 0; i < surfaces.size(); ++i) surfaces[i] = luminance.values[i] - luminance.emitters[i];
        denoiseLuminance(surfaces, luminance.variance,
                         cameraGuide(tracer.rayTracer(), camera, luminance.width, luminance.height), camera.position);
        for (size_t i = 0; i < surfaces.size(); ++i) luminance.values[i] = surfaces[i] + luminance.emitters[i];
    }
    return luminance;
}

Image renderPerspective(const PathTracer& tracer, const Camera& camera, const RenderOptions& options) {
    LuminanceImage luminance = renderView(tracer, camera, options);
    double exposure = options.exposure > 0 ? options.exposure : autoExposure(luminance);
    return toneMap(luminance, exposure);
}

Image sideBySide(const Image& a, const Image& b, const std::string& labelA, const std::string& labelB) {
    const int pad = 10, scale = 2;
    const int labelHeight = std::max(textHeight(labelA, scale), textHeight(labelB, scale)) + pad;
    Image out(a.width() + b.width() + 3 * pad, std::max(a.height(), b.height()) + labelHeight + 2 * pad, kWhite);
    out.drawText(pad + a.width() / 2.0, pad, labelA, kBlack, scale, TextAlign::Center);
    out.drawText(2 * pad + a.width() + b.width() / 2.0, pad, labelB, kBlack, scale, TextAlign::Center);
    out.blit(a, pad, pad + labelHeight);
    out.blit(b, 2 * pad + a.width(), pad + labelHeight);
    return out;
}

}  // namespace luxplan
