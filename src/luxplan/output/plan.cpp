// The plan view (top-down picture of a layout) and the work-plane illuminance grid
// that colours its floor.
#include <luxplan/output/plan.h>

#include <cmath>
#include <cstdio>

#include <luxplan/core/format.h>
#include <luxplan/scene/room.h>
#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/output/contours.h>
#include <luxplan/output/label_font.h>
#include <luxplan/pathtracer/illuminance_at.h>
#include <luxplan/optimizer/sampler_report.h>

namespace luxplan {
namespace {

constexpr uint64_t kWorkPlaneTag = 0x776f726b706c616eULL;  // "workplan"

constexpr Rgb kWallColor{45, 45, 50};
constexpr Rgb kFloorColor{238, 238, 234};
constexpr Rgb kGlassColor{150, 205, 250};
constexpr Rgb kLuminaireColor{255, 200, 0};
constexpr Rgb kLuminaireEdge{200, 150, 0};
constexpr Rgb kFrontColor{25, 60, 150};
constexpr Rgb kPassColor{0, 165, 60};
constexpr Rgb kFailColor{220, 30, 30};
constexpr Rgb kUnknownColor{110, 110, 110};
constexpr Rgb kStaticColor{150, 150, 150};
constexpr Rgb kHatchColor{205, 205, 205};
constexpr Rgb kContourColor{40, 40, 40};

// World (x, y) to pixels: +y up.
struct PlanMapping {
    double x0 = 0, y1 = 0, scale = 1, left = 0, top = 0;
    Vec2 operator()(double x, double y) const { return {left + (x - x0) * scale, top + (y1 - y) * scale}; }
    Vec2 operator()(const Vec3& p) const { return (*this)(p.x, p.y); }
};

double crossZ(Vec2 o, Vec2 a, Vec2 b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// Andrew's monotone chain; degenerate inputs give two points (a segment) or one.
std::vector<Vec2> convexHull(std::vector<Vec2> p) {
    std::sort(p.begin(), p.end(), [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    p.erase(std::unique(p.begin(), p.end(), [](Vec2 a, Vec2 b) { return length(a - b) < 1e-9; }), p.end());
    if (p.size() < 3) return p;
    std::vector<Vec2> h(2 * p.size());
    size_t k = 0;
    for (size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && crossZ(h[k - 2], h[k - 1], p[i]) <= 1e-12) --k;
        h[k++] = p[i];
    }
    for (size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
        while (k >= t && crossZ(h[k - 2], h[k - 1], p[i - 1]) <= 1e-12) --k;
        h[k++] = p[i - 1];
    }
    h.resize(k - 1);
    return h;
}

std::vector<Vec2> footprint(const std::vector<Vec3>& points, const PlanMapping& map) {
    std::vector<Vec2> px;
    for (const Vec3& p : points) px.push_back(map(p));
    return convexHull(px);
}

std::vector<Vec3> boxCorners(const Bounds3& b, const Transform& t) {
    std::vector<Vec3> c;
    for (int i = 0; i < 8; ++i)
        c.push_back(t.applyPoint({(i & 1) ? b.hi.x : b.lo.x, (i & 2) ? b.hi.y : b.lo.y, (i & 4) ? b.hi.z : b.lo.z}));
    return c;
}

Vec2 centroid(const std::vector<Vec2>& points) {
    Vec2 c;
    for (Vec2 p : points) c = c + p;
    return points.empty() ? c : c * (1.0 / double(points.size()));
}

// Linear sRGB reflectance to a display colour (gamma 1/2.2, lifted so dark materials stay visible).
Rgb materialColor(const Material& m) {
    Vec3 r = m.type == MaterialType::Glossy ? m.base + m.reflectance : m.reflectance;
    auto channel = [](double v) {
        return uint8_t(std::lround(255 * (0.25 + 0.75 * std::pow(std::clamp(v, 0.0, 1.0), 1 / 2.2))));
    };
    return {channel(r.x), channel(r.y), channel(r.z)};
}

Rgb darker(Rgb c, double f = 0.55) { return mix(kBlack, c, f); }

void drawArrow(Image& image, Vec2 from, Vec2 to, Rgb color, double thickness) {
    Vec2 d = to - from;
    double len = length(d);
    if (len < 1e-6) return;
    Vec2 u = d * (1 / len), n{-u.y, u.x};
    double head = std::max(6.0, 3 * thickness);
    image.drawLine(from, to - u * (head * 0.5), color, thickness);
    image.fillPolygon({to, to - u * head + n * (head * 0.5), to - u * head - n * (head * 0.5)}, color);
}

// The extent of the plan: the room, else everything with geometry.
Bounds3 planBounds(const Scene& scene, const std::vector<Transform>& world) {
    if (const RoomShell* room = scene.room()) return room->box;
    Bounds3 b;
    for (const StaticItem& item : scene.geometry)
        if (!item.mesh.empty()) b.extend(item.mesh.bounds());
    for (size_t i = 0; i < scene.entities.size(); ++i)
        for (const PartInfo& part : scene.entities[i].parts) b.extend(world[i].apply(part.bounds));
    if (b.empty()) b = Bounds3({-1, -1, 0}, {1, 1, 1});
    return b;
}

// Greedy label placement in the labels' font: each label takes the free spot nearest
// its anchor among spots shifted by whole label heights down and up and half label
// widths left and right, one that overlaps no label placed before, no reserved area
// and stays inside the picture; without one it is left out.
class LabelPlacer {
public:
    LabelPlacer(Image& image, const LabelFont& font) : image_(image), font_(font) {}

    // `anchor` is the top centre of the text; `reach`: how many label heights (and
    // half widths) away the label may go. A label moved off its anchor by more than its
    // height gets a thin leader back to it, unless the leader would cross another label
    // (then none). Returns whether it was placed.
    bool place(Vec2 anchor, const std::string& text, Rgb color, double backgroundAlpha, int reach) {
        const double w = font_.width(text), h = font_.height(text), step = h + 2 * kPad + 1;
        const double half = (w + 2 * kPad + 2) / 2;
        struct Spot {
            double dx, dy, distance;
        };
        std::vector<Spot> spots;
        for (int row = -reach; row <= reach; ++row)
            for (int column = -2 * reach; column <= 2 * reach; ++column) {
                const double dx = column * half, dy = row * step;
                spots.push_back({dx, dy, std::hypot(dx, 1.5 * dy)});
            }
        std::stable_sort(spots.begin(), spots.end(), [](const Spot& a, const Spot& b) { return a.distance < b.distance; });
        for (const Spot& spot : spots) {
            const Vec2 at{std::round(anchor.x + spot.dx), std::round(anchor.y + spot.dy)};
            const PlanLabel box{text, at.x - w / 2 - kPad, at.y - kPad, at.x + w / 2 + kPad, at.y + h + kPad};
            if (box.x0 < 0 || box.y0 < 0 || box.x1 > image_.width() || box.y1 > image_.height() || overlaps(box)) continue;
            if (std::abs(spot.dx) > half || std::abs(spot.dy) > step) {
                const Vec2 near{std::clamp(anchor.x, box.x0, box.x1), std::clamp(anchor.y, box.y0, box.y1)};
                if (!crossesALabel(anchor, near)) image_.drawLine(anchor, near, color, 1, 0.8);
            }
            image_.fillRect(box.x0, box.y0, box.x1, box.y1, kWhite, backgroundAlpha);
            font_.draw(image_, at.x, at.y, text, color, TextAlign::Center);
            labels_.push_back(box);
            return true;
        }
        return false;
    }

    // Reserves an area (a legend, a table) that no label may cover.
    void reserve(double x0, double y0, double x1, double y1) { reserved_.push_back({"", x0, y0, x1, y1}); }

    const std::vector<PlanLabel>& labels() const { return labels_; }

private:
    static constexpr double kPad = 2;
    static bool intersects(const PlanLabel& a, const PlanLabel& b) {
        return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
    }
    bool overlaps(const PlanLabel& b) const {
        for (const PlanLabel& o : labels_)
            if (intersects(b, o)) return true;
        for (const PlanLabel& o : reserved_)
            if (intersects(b, o)) return true;
        return false;
    }
    // Whether the segment from a to b passes through a label placed before (sampled
    // every pixel).
    bool crossesALabel(Vec2 a, Vec2 b) const {
        const int n = std::max(1, int(std::ceil(length(b - a))));
        for (int k = 0; k <= n; ++k) {
            const Vec2 p = a + (b - a) * (double(k) / n);
            for (const PlanLabel& o : labels_)
                if (p.x > o.x0 && p.x < o.x1 && p.y > o.y0 && p.y < o.y1) return true;
        }
        return false;
    }

    Image& image_;
    const LabelFont& font_;
    std::vector<PlanLabel> labels_, reserved_;
};

void drawScaleBar(Image& image, const PlanMapping& map, Vec2 at, double roomWidth) {
    double metres = 1;
    for (double m : {0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0})
        if (m <= roomWidth / 3) metres = m;
    double px = metres * map.scale;
    for (int i = 0; i < 2; ++i) {
        double x0 = at.x + px * i / 2, x1 = at.x + px * (i + 1) / 2;
        image.fillRect(x0, at.y, x1, at.y + 6, i == 0 ? kBlack : kWhite);
    }
    image.drawRect(at.x, at.y, at.x + px, at.y + 6, kBlack, 1);
    image.drawText(at.x, at.y + 10, "0", kBlack, 1, TextAlign::Center);
    char label[32];
    std::snprintf(label, sizeof label, "%g m", metres);
    image.drawText(at.x + px, at.y + 10, label, kBlack, 1, TextAlign::Center);
}

void drawNorthArrow(Image& image, Vec2 center, double northDeg) {
    // True north in scene coordinates: azimuth 0 (see horizonToScene), then +y up on screen.
    double a = radians(northDeg);
    Vec2 dir{-std::sin(a), -std::cos(a)};  // pixel space
    const double r = 16;
    image.drawCircle(center, r, kBlack, 1);
    drawArrow(image, center - dir * (r - 3), center + dir * (r - 3), kBlack, 2);
    Vec2 label = center + dir * (r + 9);
    image.drawText(label.x, label.y - 3, "N", kBlack, 1, TextAlign::Center);
}

}  // namespace

IlluminanceGrid measureWorkPlane(const PathTracer& tracer, const Bounds3& room, double height, double cellSize,
                                 int paths, uint64_t seed) {
    IlluminanceGrid grid;
    grid.cellSize = cellSize > 0 ? cellSize : 0.25;
    grid.height = room.lo.z + height;
    Vec3 size = room.size();
    grid.nx = std::max(1, int(std::ceil(size.x / grid.cellSize - 1e-9)));
    grid.ny = std::max(1, int(std::ceil(size.y / grid.cellSize - 1e-9)));
    // Centred on the room: the edge cells overhang the walls by less than half a cell,
    // so every cell centre is inside.
    grid.origin = {room.lo.x - (grid.nx * grid.cellSize - size.x) / 2,
                   room.lo.y - (grid.ny * grid.cellSize - size.y) / 2};
    std::vector<Vec3> centres;
    centres.reserve(size_t(grid.nx) * size_t(grid.ny));
    for (int j = 0; j < grid.ny; ++j)
        for (int i = 0; i < grid.nx; ++i) centres.push_back(grid.cellCenter(i, j));
    PointIlluminance lux = illuminanceAt(tracer, centres, Vec3(0, 0, 1), paths, seed, kWorkPlaneTag);
    grid.values = std::move(lux.values);
    grid.errors = std::move(lux.errors);
    return grid;
}

std::vector<char> freeCells(const Scene& scene, const Layout& layout, const IlluminanceGrid& grid) {
    const std::vector<Transform> world = worldTransforms(scene, layout);
    std::vector<Transform> local(world.size());
    for (size_t e = 0; e < world.size(); ++e) local[e] = world[e].inverse();
    std::vector<char> free(size_t(grid.nx) * size_t(grid.ny), 1);
    for (int j = 0; j < grid.ny; ++j)
        for (int i = 0; i < grid.nx; ++i) {
            const Vec3 p = grid.cellCenter(i, j);
            bool inside = false;
            for (size_t e = 0; e < scene.entities.size() && !inside; ++e)
                for (const PartInfo& part : scene.entities[e].parts)
                    if (part.bounds.contains(local[e].applyPoint(p))) inside = true;
            for (const StaticItem& item : scene.geometry)
                if (!inside && item.kind != StaticKind::Room && !item.invisible && !item.mesh.empty() &&
                    item.mesh.bounds().contains(p))
                    inside = true;
            free[size_t(j) * size_t(grid.nx) + size_t(i)] = inside ? 0 : 1;
        }
    return free;
}

PointStatistics workPlaneStatistics(const IlluminanceGrid& grid, const std::vector<char>& free) {
    std::vector<double> values, errors;
    for (size_t c = 0; c < grid.values.size(); ++c)
        if (free.empty() || free[c]) {
            values.push_back(grid.values[c]);
            errors.push_back(c < grid.errors.size() ? grid.errors[c] : 0.0);
        }
    return pointStatistics(values, errors);
}

FalseColor planFalseColor(const Scene& scene, const std::vector<double>& values) {
    double lo = kInf, hi = -kInf;
    for (const LightSamplerSpec& spec : scene.samplers)
        if (spec.type->hasPointStatistics() && std::string_view(spec.type->unit()) == "lx")
            lo = std::min(lo, spec.targetMin), hi = std::max(hi, spec.targetMax);
    if (lo <= hi && (lo > 0 || std::isfinite(hi))) return targetFalseColor(lo, hi);
    return autoFalseColor(values, ColorScale::Log);
}

namespace {

// The work planes' table under the plan: one row per illuminance sampler with points
// that has results, green where it meets its goals.
struct PlanTable {
    struct Row {
        std::string text;
        bool met = false;
    };
    std::string header;
    std::vector<Row> rows;
};

PlanTable planTable(const Scene& scene, const PlanData& data) {
    PlanTable table;
    size_t nameWidth = 10;
    for (const LightSamplerSpec& spec : scene.samplers) nameWidth = std::max(nameWidth, spec.name.size());
    char header[200];
    std::snprintf(header, sizeof header, "%-*s %8s %8s %8s %6s  target (lx)", int(nameWidth), "work plane", "Em", "Emin",
                  "Emax", "U0");
    table.header = header;
    if (!data.samplers) return table;
    for (size_t k = 0; k < scene.samplers.size() && k < data.samplers->size(); ++k) {
        const LightSamplerSpec& spec = scene.samplers[k];
        if (!spec.type->hasPointStatistics() || std::string_view(spec.type->unit()) != "lx") continue;
        const SamplerRow sampler(spec, (*data.samplers)[k]);
        const PointStatistics& st = *sampler.statistics();
        std::string target = compactNumber(spec.targetMin);
        if (std::isfinite(spec.targetMax)) {
            target += '-';
            target += compactNumber(spec.targetMax);
        } else {
            target += '+';
        }
        char row[300];
        std::snprintf(row, sizeof row, "%-*s %8s %8s %8s %6.2f  %s", int(nameWidth), spec.name.c_str(),
                      compactNumber(st.mean.value).c_str(), compactNumber(st.min.value).c_str(),
                      compactNumber(st.max.value).c_str(), st.u0.value, target.c_str());
        table.rows.push_back({row, sampler.met()});
    }
    return table;
}

// The plan's frame: the picture's size and where the room lies in it.
struct PlanFrame {
    Bounds3 bounds;
    PlanMapping map;
    Vec2 roomLo, roomHi;  // the plan area's top-left and bottom-right corners, pixels
    double wall = 0;      // the walls' band, pixels
    int planTop = 0, planH = 0, margin = 0;
};

// A label to place once everything is drawn.
struct PendingLabel {
    Vec2 at;
    std::string text;
    Rgb color;
};

// Work-plane illuminance, clipped to the plan area; cells inside furniture hatched.
void drawWorkPlane(Image& image, const PlanFrame& f, const IlluminanceGrid& g, const FalseColor& falseColor,
                   const std::vector<char>& free) {
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
            double x0 = std::max(f.bounds.lo.x, g.origin.x + i * g.cellSize);
            double x1 = std::min(f.bounds.hi.x, g.origin.x + (i + 1) * g.cellSize);
            double y0 = std::max(f.bounds.lo.y, g.origin.y + j * g.cellSize);
            double y1 = std::min(f.bounds.hi.y, g.origin.y + (j + 1) * g.cellSize);
            if (x1 <= x0 || y1 <= y0) continue;
            Vec2 a = f.map(x0, y1), b = f.map(x1, y0);
            if (free[size_t(j) * size_t(g.nx) + size_t(i)]) {
                image.fillRect(a.x, a.y, b.x, b.y, falseColor.color(g.at(i, j)));
                continue;
            }
            image.fillRect(a.x, a.y, b.x, b.y, kHatchColor);
            for (int y = int(std::ceil(a.y - 0.5)); y < int(std::ceil(b.y - 0.5)); ++y)
                for (int x = int(std::ceil(a.x - 0.5)); x < int(std::ceil(b.x - 0.5)); ++x)
                    if ((x + y) % 6 == 0 && x >= 0 && y >= 0 && x < image.width() && y < image.height())
                        image.at(x, y) = kStaticColor;
        }
}

// The map smoothed by a 3 x 3 binomial filter over free cells, so that isolux lines
// follow the light and not the per-cell noise of a quick grid.
std::vector<double> smoothedWorkPlane(const IlluminanceGrid& g, const std::vector<char>& free) {
    std::vector<double> smooth(g.values.size(), 0.0);
    for (int j = 0; j < g.ny; ++j)
        for (int i = 0; i < g.nx; ++i) {
            double sum = 0, weight = 0;
            for (int dj = -1; dj <= 1; ++dj)
                for (int di = -1; di <= 1; ++di) {
                    int a = i + di, b = j + dj;
                    if (a < 0 || b < 0 || a >= g.nx || b >= g.ny || !free[size_t(b) * size_t(g.nx) + size_t(a)]) continue;
                    double w = (di ? 1 : 2) * (dj ? 1 : 2);
                    sum += w * g.at(a, b), weight += w;
                }
            smooth[size_t(j) * size_t(g.nx) + size_t(i)] = weight > 0 ? sum / weight : g.at(i, j);
        }
    return smooth;
}

// Isolux contours at the legend's ticks (the target band's ends bolder); returns a
// label for each, to be placed where one fits.
std::vector<PendingLabel> drawContours(Image& image, const PlanFrame& f, const IlluminanceGrid& g, const FalseColor& falseColor,
                                       const std::vector<char>& free, double labelHeight) {
    auto toPixels = [&](Vec2 p) { return f.map(g.origin.x + (p.x + 0.5) * g.cellSize, g.origin.y + (p.y + 0.5) * g.cellSize); };
    const std::vector<double> smooth = smoothedWorkPlane(g, free);
    std::vector<double> levels = legendTicks(falseColor);
    if (falseColor.band) levels.insert(levels.end(), falseColor.band->begin(), falseColor.band->end());
    std::sort(levels.begin(), levels.end());
    levels.erase(std::unique(levels.begin(), levels.end(), [](double a, double b) { return std::abs(a - b) <= 1e-9 * b; }),
                 levels.end());
    std::vector<PendingLabel> labels;
    for (double level : levels) {
        if (!(level > falseColor.minValue()) || !(level < falseColor.maxValue)) continue;
        std::vector<ContourSegment> segments = isolines(smooth, g.nx, g.ny, level, free);
        if (segments.empty()) continue;
        const bool bandEdge = falseColor.band && (std::abs(level - (*falseColor.band)[0]) <= 1e-9 * level ||
                                                 std::abs(level - (*falseColor.band)[1]) <= 1e-9 * level);
        for (const ContourSegment& seg : segments)
            image.drawLine(toPixels(seg.a), toPixels(seg.b), kContourColor, bandEdge ? 2 : 1, bandEdge ? 0.9 : 0.6);
        const ContourSegment& mid = segments[segments.size() / 2];
        labels.push_back({(toPixels(mid.a) + toPixels(mid.b)) * 0.5 - Vec2(0, labelHeight / 2), compactNumber(level),
                          kContourColor});
    }
    return labels;
}

// Openings: glazed ones light blue across the wall band, open ones a gap.
void drawOpenings(Image& image, const PlanFrame& f, const RoomShell& room) {
    for (const Opening& o : room.openings) {
        WallFrame w = wallFrame(room.box, o.wall);
        auto r = openingRect(room.box, o);
        if (o.wall == Wall::Ceiling) {
            std::vector<Vec3> corners{w.origin + w.u * r[0] + w.v * r[1], w.origin + w.u * r[2] + w.v * r[1],
                                      w.origin + w.u * r[2] + w.v * r[3], w.origin + w.u * r[0] + w.v * r[3]};
            auto poly = footprint(corners, f.map);
            image.fillPolygon(poly, kGlassColor, o.material ? 0.35 : 0.15);
            image.drawPolygon(poly, darker(kGlassColor, 0.7), 2);
            continue;
        }
        Vec2 a = f.map(w.origin + w.u * r[0]), b = f.map(w.origin + w.u * r[2]);
        Vec2 out{-w.inward.x, w.inward.y};  // pixel space (y flipped)
        std::vector<Vec2> band{a - out * 0.5, b - out * 0.5, b + out * (f.wall + 0.5), a + out * (f.wall + 0.5)};
        if (o.material) {
            image.fillPolygon(band, kGlassColor);
            image.drawLine(a + out * (f.wall / 2), b + out * (f.wall / 2), darker(kGlassColor, 0.6), 1.5);
        } else {
            image.fillPolygon(band, kWhite);
            image.drawLine(a, a + out * f.wall, kWallColor, 1);
            image.drawLine(b, b + out * f.wall, kWallColor, 1);
        }
    }
}

// Fixed objects (boxes, meshes, blockers); returns their name labels.
std::vector<PendingLabel> drawStaticItems(Image& image, const PlanFrame& f, const Scene& scene, const PlanOptions& options) {
    std::vector<PendingLabel> labels;
    for (const StaticItem& item : scene.geometry) {
        if (item.kind == StaticKind::Room || item.mesh.empty()) continue;
        Bounds3 b = item.mesh.bounds();
        auto poly = footprint(boxCorners(b, Transform()), f.map);
        if (item.invisible) {
            image.drawPolygon(poly, kStaticColor, 1);
        } else {
            image.fillPolygon(poly, kStaticColor, 0.45);
            image.drawPolygon(poly, darker(kStaticColor), 1.5);
        }
        if (options.entityLabels)
            labels.push_back({centroid(poly) - Vec2(0, options.labelHeight / 2), item.name, darker(kStaticColor, 0.4)});
    }
    return labels;
}

// Furniture footprints (the union of the parts' projected boxes, filled once) with
// their fronts as arrows; returns their name labels.
std::vector<PendingLabel> drawFurniture(Image& image, const PlanFrame& f, const Scene& scene,
                                        const std::vector<Transform>& world, const PlanOptions& options) {
    std::vector<PendingLabel> labels;
    for (size_t e = 0; e < scene.entities.size(); ++e) {
        const Entity& entity = scene.entities[e];
        if (entity.parts.empty()) continue;
        std::vector<std::vector<Vec2>> parts;
        std::vector<Vec2> all;
        for (const PartInfo& part : entity.parts) {
            parts.push_back(footprint(boxCorners(part.bounds, world[e]), f.map));
            all.insert(all.end(), parts.back().begin(), parts.back().end());
        }
        Rgb color = materialColor(scene.materials.at(entity.parts.front().material));
        Image mask(image.width(), image.height(), kBlack);
        for (const auto& poly : parts) mask.fillPolygon(poly, kWhite);
        for (int y = 0; y < image.height(); ++y)
            for (int x = 0; x < image.width(); ++x)
                if (mask.at(x, y).r) image.blendPixel(x, y, color, 0.6);
        for (const auto& poly : parts) image.drawPolygon(poly, darker(color, 0.45), 1.5);

        // Fronts: arrows from the footprint centre, half its size long.
        Vec2 c = centroid(convexHull(all));
        Bounds3 pixelBox;
        for (Vec2 p : all) pixelBox.extend(Vec3(p.x, p.y, 0));
        double reach = std::max(12.0, 0.5 * std::min(pixelBox.size().x, pixelBox.size().y));
        for (Vec2 front : entity.fronts) {
            Vec3 d = world[e].applyVector(Vec3(front.x, front.y, 0));
            double len = std::hypot(d.x, d.y);
            if (len < 1e-9) continue;
            Vec2 dir{d.x / len, -d.y / len};
            drawArrow(image, c, c + dir * reach, kFrontColor, 2);
        }
        if (options.entityLabels) labels.push_back({c - Vec2(0, options.labelHeight / 2), entity.name, kBlack});
    }
    return labels;
}

void drawLuminaires(Image& image, const PlanFrame& f, const Scene& scene, const std::vector<Transform>& world) {
    for (const Emitter& emitter : scene.emitters) {
        Transform t = emitter.entity >= 0 ? world[size_t(emitter.entity)] : Transform();
        std::vector<Vec3> outline = emitter.shape->outline();
        for (Vec3& p : outline) p = t.applyPoint(p);
        auto poly = footprint(outline, f.map);
        image.fillPolygon(poly, kLuminaireColor, 0.35);
        image.drawPolygon(poly, kLuminaireEdge, 2);
    }
}

// Light samplers, green when they meet their targets (statistics goals too); returns
// their labels (name, and value where measured).
std::vector<PendingLabel> drawSamplers(Image& image, const PlanFrame& f, const Scene& scene,
                                       const std::vector<Transform>& world, const PlanData& data, const PlanOptions& options) {
    std::vector<PendingLabel> labels;
    for (size_t k = 0; k < scene.samplers.size(); ++k) {
        const LightSamplerSpec& spec = scene.samplers[k];
        Transform t = spec.entity >= 0 ? world[size_t(spec.entity)] : Transform();
        SamplerDrawing drawing = spec.type->place(t)->drawing();
        Rgb color = kUnknownColor;
        std::string text = spec.name;
        if (data.samplers && k < data.samplers->size()) {
            const SamplerRow row(spec, (*data.samplers)[k]);
            color = row.met() ? kPassColor : kFailColor;
            text.append(" ").append(compactNumber(std::round(row.result().value * 10) / 10)).append(" ").append(spec.type->unit());
        }
        auto poly = footprint(drawing.outline, f.map);
        if (drawing.fillOpacity > 0) image.fillPolygon(poly, color, drawing.fillOpacity);
        image.drawPolygon(poly, color, drawing.lineWidth);
        for (const Vec3& p : drawing.dots) image.fillCircle(f.map(p), drawing.dotRadius, color);
        Vec2 c = drawing.labelAt ? f.map(*drawing.labelAt) : centroid(poly);
        if (options.samplerLabels) labels.push_back({c + Vec2(0, 8), text, darker(color, 0.7)});
    }
    return labels;
}

// The legend right of the plan and the work plane's statistics under it, an area no
// label may cover.
void drawWorkPlaneLegend(Image& image, const PlanFrame& f, const IlluminanceGrid& g, const FalseColor& falseColor,
                         const std::vector<char>& free, LabelPlacer& labels) {
    int lx = int(f.roomHi.x + f.wall + 62), ly = int(f.roomLo.y + 30);
    int lh = std::min(300, std::max(60, int(f.roomHi.y - f.roomLo.y) - 110));
    char text[160];
    std::snprintf(text, sizeof text, "lx at %.2g m", g.height - f.bounds.lo.z);
    drawLegend(image, falseColor, lx, ly, 16, lh, text);
    const PointStatistics st = workPlaneStatistics(g, free);
    std::snprintf(text, sizeof text, "work plane\nEm   %s lx\nEmin %s lx\nEmax %s lx\nU0   %.2f", compactNumber(st.mean.value).c_str(),
                  compactNumber(st.min.value).c_str(), compactNumber(st.max.value).c_str(), st.u0.value);
    const double sx = lx - 50, sy = ly + lh + 16;
    image.drawText(sx, sy, text, kBlack, 1, TextAlign::Left);
    labels.reserve(lx - 50, ly - 14, image.width(), sy + textHeight(text) + 2);
}

// PlanData::cells: each quad in its value's colour, or the hatch grey without one.
void drawPlanCells(Image& image, const PlanFrame& f, const PlanCells& cells) {
    for (size_t k = 0; k < cells.quads.size(); ++k) {
        std::vector<Vec2> poly;
        for (const Vec3& p : cells.quads[k]) poly.push_back(f.map(p));
        const double v = k < cells.values.size() ? cells.values[k] : std::nan("");
        image.fillPolygon(poly, std::isfinite(v) ? cells.colors.color(v) : kHatchColor);
    }
}

// The cells' legend where the work plane's goes.
void drawCellsLegend(Image& image, const PlanFrame& f, const PlanCells& cells, LabelPlacer& labels) {
    const int lx = int(f.roomHi.x + f.wall + 62), ly = int(f.roomLo.y + 30);
    const int lh = std::min(300, std::max(60, int(f.roomHi.y - f.roomLo.y) - 60));
    drawLegend(image, cells.colors, lx, ly, 16, lh, cells.unit);
    labels.reserve(lx - 50, ly - 14, image.width(), ly + lh + 10);
}

}  // namespace

Image renderPlan(const Scene& scene, const Layout& layout, const PlanOptions& options, const PlanData& data,
                 std::vector<PlanLabel>* placedLabels) {
    const std::vector<Transform> world = worldTransforms(scene, layout);
    PlanFrame f;
    f.bounds = planBounds(scene, world);
    const RoomShell* room = scene.room();
    const double s = options.pixelsPerMetre > 0 ? options.pixelsPerMetre : 80;
    f.margin = std::max(40, options.margin);
    const int titleHeight = options.title.empty() ? 0 : 24;
    const bool hasMap = data.workPlane && !data.workPlane->values.empty();
    const bool hasCells = data.cells && !data.cells->quads.empty();
    const int legendWidth = hasMap || hasCells ? 150 : 0;
    const Vec3 size = f.bounds.size();
    const int planW = int(std::ceil(size.x * s));
    f.planH = int(std::ceil(size.y * s));

    const PlanTable table = planTable(scene, data);
    const int tableHeight = table.rows.empty() ? 0 : int(table.rows.size() + 1) * (kLineAdvance + 3) + 8;
    const int tableWidth = table.rows.empty() ? 0 : textWidth(table.rows.front().text) + 2 * f.margin;

    Image image(std::max(planW + 2 * f.margin + legendWidth, tableWidth), f.planH + 2 * f.margin + titleHeight + 10 + tableHeight,
                kWhite);
    f.planTop = titleHeight;
    f.map = PlanMapping{f.bounds.lo.x, f.bounds.hi.y, s, double(f.margin), double(f.margin + titleHeight)};
    f.roomLo = f.map(f.bounds.lo.x, f.bounds.hi.y), f.roomHi = f.map(f.bounds.hi.x, f.bounds.lo.y);
    f.wall = std::max(4.0, 0.12 * s);

    const LabelFont labelFont(options.labelHeight);
    if (!options.title.empty()) LabelFont(20).draw(image, f.margin, 3, options.title, kBlack);

    // Walls as a dark band around the floor, then the floor.
    if (room) image.fillRect(f.roomLo.x - f.wall, f.roomLo.y - f.wall, f.roomHi.x + f.wall, f.roomHi.y + f.wall, kWallColor);
    image.fillRect(f.roomLo.x, f.roomLo.y, f.roomHi.x, f.roomHi.y, kFloorColor);

    FalseColor falseColor;
    std::vector<char> free;
    std::vector<PendingLabel> contourLabels;
    if (hasMap) {
        const IlluminanceGrid& g = *data.workPlane;
        falseColor = options.colors ? *options.colors : planFalseColor(scene, g.values);
        free = freeCells(scene, layout, g);
        drawWorkPlane(image, f, g, falseColor, free);
        if (options.contours) contourLabels = drawContours(image, f, g, falseColor, free, options.labelHeight);
    }
    if (hasCells) drawPlanCells(image, f, *data.cells);
    if (room) drawOpenings(image, f, *room);
    const std::vector<PendingLabel> staticLabels = drawStaticItems(image, f, scene, options);
    const std::vector<PendingLabel> entityLabels = drawFurniture(image, f, scene, world, options);
    drawLuminaires(image, f, scene, world);
    const std::vector<PendingLabel> samplerLabels = drawSamplers(image, f, scene, world, data, options);

    LabelPlacer labels(image, labelFont);
    if (hasCells)
        drawCellsLegend(image, f, *data.cells, labels);
    else if (hasMap)
        drawWorkPlaneLegend(image, f, *data.workPlane, falseColor, free, labels);

    // Labels last, so nothing covers them, and none over another: sampler results
    // first (they may go further from their samplers, with a leader), then names and
    // contour values near where they belong, or not at all.
    for (const PendingLabel& l : samplerLabels) labels.place(l.at, l.text, l.color, 0.85, 8);
    for (const PendingLabel& l : entityLabels) labels.place(l.at, l.text, l.color, 0.7, 2);
    for (const PendingLabel& l : staticLabels) labels.place(l.at, l.text, l.color, 0.5, 2);
    for (const PendingLabel& l : contourLabels) labels.place(l.at, l.text, l.color, 0.6, 1);
    if (placedLabels) *placedLabels = labels.labels();

    // Scale bar under the plan, north arrow in the top-right margin.
    drawScaleBar(image, f.map, {f.roomLo.x, f.roomHi.y + f.wall + 12}, size.x);
    drawNorthArrow(image, {f.roomHi.x + f.margin / 2.0, f.roomLo.y - f.margin / 2.0 + 6}, scene.site.northDeg);

    // The work planes' table under the plan.
    double rowY = f.planTop + f.planH + 2 * f.margin + 4;
    if (!table.rows.empty()) image.drawText(f.margin, rowY, table.header, kBlack, 1, TextAlign::Left);
    for (const PlanTable::Row& row : table.rows) {
        rowY += kLineAdvance + 3;
        image.drawText(f.margin, rowY, row.text, row.met ? darker(kPassColor, 0.8) : darker(kFailColor, 0.8), 1, TextAlign::Left);
    }
    return image;
}

}  // namespace luxplan
