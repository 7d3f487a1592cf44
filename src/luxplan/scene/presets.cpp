#include <luxplan/scene/presets.h>

#include <algorithm>
#include <functional>

namespace luxplan {
namespace {

// The stand lamp's shade walls (m).
constexpr double kShadeWall = 0.012;

// Adds boxes given in the preset's own frame: x in [-w/2, w/2], y in [-d/2, d/2], z in [0, h].
struct Builder {
    TriangleMesh mesh;
    Vec3 size;
    const std::map<std::string, uint32_t>& materials;
    std::string body;

    uint32_t material(const std::string& slot) const {
        auto it = materials.find(slot);
        if (it != materials.end()) return it->second;
        auto b = materials.find(body);
        return b != materials.end() ? b->second : 0;
    }
    void box(double x0, double y0, double z0, double x1, double y1, double z1, const std::string& slot = "") {
        addBox(mesh, Bounds3({x0, y0, z0}, {x1, y1, z1}), material(slot.empty() ? body : slot));
    }
    double w() const { return size.x; }
    double d() const { return size.y; }
    double h() const { return size.z; }
    // Four legs of square section `t` under a top at height `top`, inset by `inset`.
    void legs(double t, double top, double inset) {
        double x = w() / 2 - inset, y = d() / 2 - inset;
        for (double sx : {-1.0, 1.0})
            for (double sy : {-1.0, 1.0}) {
                double cx = sx * (x - t / 2), cy = sy * (y - t / 2);
                box(cx - t / 2, cy - t / 2, 0, cx + t / 2, cy + t / 2, top);
            }
    }
};

void table(Builder& b) {
    double top = std::min(0.04, b.h() * 0.1);
    b.box(-b.w() / 2, -b.d() / 2, b.h() - top, b.w() / 2, b.d() / 2, b.h());
    b.legs(std::min(0.05, b.w() * 0.1), b.h() - top, 0.03);
}

void desk(Builder& b) {
    double top = std::min(0.03, b.h() * 0.1), side = std::min(0.03, b.w() * 0.05);
    b.box(-b.w() / 2, -b.d() / 2, b.h() - top, b.w() / 2, b.d() / 2, b.h());
    b.box(-b.w() / 2, -b.d() / 2, 0, -b.w() / 2 + side, b.d() / 2, b.h() - top);
    b.box(b.w() / 2 - side, -b.d() / 2, 0, b.w() / 2, b.d() / 2, b.h() - top);
    // Modesty panel at the back (+y), away from the user.
    b.box(-b.w() / 2 + side, b.d() / 2 - 0.02, b.h() * 0.35, b.w() / 2 - side, b.d() / 2, b.h() - top);
}

void chair(Builder& b) {
    double seatZ = b.h() * 0.5, seat = 0.04, back = std::min(0.05, b.d() * 0.12);
    b.box(-b.w() / 2, -b.d() / 2, seatZ - seat, b.w() / 2, b.d() / 2, seatZ);
    b.legs(std::min(0.04, b.w() * 0.1), seatZ - seat, 0.0);
    b.box(-b.w() / 2, b.d() / 2 - back, seatZ, b.w() / 2, b.d() / 2, b.h());
}

void officeChair(Builder& b) {
    double seatZ = b.h() * 0.47, back = std::min(0.06, b.d() * 0.12);
    b.box(-b.w() / 2, -b.d() / 2, 0, b.w() / 2, b.d() / 2, 0.06);  // five-star base, as its footprint
    b.box(-0.03, -0.03, 0.06, 0.03, 0.03, seatZ - 0.08);         // gas column
    b.box(-b.w() * 0.42, -b.d() * 0.42, seatZ - 0.08, b.w() * 0.42, b.d() * 0.42, seatZ);
    b.box(-b.w() * 0.38, b.d() * 0.42 - back, seatZ, b.w() * 0.38, b.d() * 0.42, b.h());
}

void screenDevice(Builder& b, double panelFrom) {
    // Foot and neck at the back, the panel on top; the screen is a thin face on -y.
    double footD = b.d(), neck = 0.04;
    b.box(-b.w() * 0.2, -footD / 2, 0, b.w() * 0.2, footD / 2, 0.02);
    b.box(-neck / 2, 0, 0.02, neck / 2, neck, b.h() * panelFrom + 0.02);
    double panelD = std::min(0.04, b.d() * 0.3);
    b.box(-b.w() / 2, -panelD / 2, b.h() * panelFrom, b.w() / 2, panelD / 2, b.h());
    b.box(-b.w() / 2 + 0.01, -panelD / 2 - 0.004, b.h() * panelFrom + 0.01, b.w() / 2 - 0.01, -panelD / 2, b.h() - 0.01,
          "screen");
}

void bookshelf(Builder& b) {
    double t = 0.02;
    b.box(-b.w() / 2, b.d() / 2 - t, 0, b.w() / 2, b.d() / 2, b.h());  // back panel
    b.box(-b.w() / 2, -b.d() / 2, 0, -b.w() / 2 + t, b.d() / 2 - t, b.h());
    b.box(b.w() / 2 - t, -b.d() / 2, 0, b.w() / 2, b.d() / 2 - t, b.h());
    int shelves = std::max(2, int(b.h() / 0.35));
    for (int i = 0; i <= shelves; ++i) {
        double z = (b.h() - t) * i / shelves;
        b.box(-b.w() / 2 + t, -b.d() / 2, z, b.w() / 2 - t, b.d() / 2 - t, z + t);
    }
}

void seat(Builder& b, double armFraction) {
    double baseZ = b.h() * 0.45, back = std::min(0.2, b.d() * 0.25), arm = std::min(0.2, b.w() * armFraction);
    b.box(-b.w() / 2 + arm, -b.d() / 2, 0, b.w() / 2 - arm, b.d() / 2 - back, baseZ, "cushion");
    b.box(-b.w() / 2, b.d() / 2 - back, 0, b.w() / 2, b.d() / 2, b.h());
    b.box(-b.w() / 2, -b.d() / 2, 0, -b.w() / 2 + arm, b.d() / 2 - back, b.h() * 0.7);
    b.box(b.w() / 2 - arm, -b.d() / 2, 0, b.w() / 2, b.d() / 2 - back, b.h() * 0.7);
}

void bed(Builder& b) {
    double frame = std::min(0.3, b.h() * 0.35), mattress = std::min(0.2, b.h() * 0.25), head = 0.06;
    b.box(-b.w() / 2, -b.d() / 2, 0, b.w() / 2, b.d() / 2 - head, frame);
    b.box(-b.w() / 2 + 0.02, -b.d() / 2 + 0.02, frame, b.w() / 2 - 0.02, b.d() / 2 - head, frame + mattress, "mattress");
    b.box(-b.w() / 2, b.d() / 2 - head, 0, b.w() / 2, b.d() / 2, b.h());  // headboard at +y
}

void standLamp(Builder& b) {
    double shade = std::min(0.35, b.h() * 0.2), pole = 0.03;
    b.box(-b.w() * 0.4, -b.d() * 0.4, 0, b.w() * 0.4, b.d() * 0.4, 0.03);
    b.box(-pole / 2, -pole / 2, 0.03, pole / 2, pole / 2, b.h() - shade);
    // The shade: four walls around an open top and bottom, so that an emitter inside
    // lights the ceiling and the floor directly and the room through the walls when
    // their material is translucent. The walls are thicker than half a voxel cell
    // (voxels.h: cells of at most 2 cm, sampled at their centres), so they collide.
    double z0 = b.h() - shade, t = std::min(kShadeWall, std::min(b.w(), b.d()) / 4);
    double x = b.w() / 2, y = b.d() / 2;
    b.box(-x, -y, z0, x, -y + t, b.h(), "shade");
    b.box(-x, y - t, z0, x, y, b.h(), "shade");
    b.box(-x, -y + t, z0, -x + t, y - t, b.h(), "shade");
    b.box(x - t, -y + t, z0, x, y - t, b.h(), "shade");
}

void conferenceTable(Builder& b) {
    double top = std::min(0.05, b.h() * 0.1);
    b.box(-b.w() / 2, -b.d() / 2, b.h() - top, b.w() / 2, b.d() / 2, b.h());
    double px = b.w() * 0.3, pw = std::min(0.3, b.w() * 0.15), pd = b.d() * 0.4;
    for (double s : {-1.0, 1.0}) b.box(s * px - pw / 2, -pd / 2, 0, s * px + pw / 2, pd / 2, b.h() - top);
}

void projectionScreen(Builder& b) {
    double leg = 0.04, housing = std::min(0.1, b.h() * 0.08);
    b.box(-b.w() / 2, -b.d() / 2, 0, -b.w() / 2 + leg, b.d() / 2, b.h());
    b.box(b.w() / 2 - leg, -b.d() / 2, 0, b.w() / 2, b.d() / 2, b.h());
    b.box(-b.w() / 2 + leg, -0.04, b.h() - housing, b.w() / 2 - leg, 0.04, b.h());
    b.box(-b.w() / 2 + leg, -0.005, b.h() * 0.3, b.w() / 2 - leg, 0.005, b.h() - housing, "screen");
}

struct PresetEntry {
    PresetInfo info;
    std::function<void(Builder&)> build;
};

const std::vector<PresetEntry>& entries() {
    static const std::vector<PresetEntry> list = {
        {{"table", {1.2, 0.8, 0.75}, {"body"}, "dining or work table: top on four legs"}, table},
        {{"chair", {0.45, 0.5, 0.9}, {"body"}, "chair: seat, four legs, backrest at +y"}, chair},
        {{"desk", {1.4, 0.7, 0.75}, {"body"}, "desk: top, side panels, modesty panel at +y"}, desk},
        {{"office_chair", {0.6, 0.6, 1.0}, {"body"}, "swivel chair: base, column, seat, backrest at +y"}, officeChair},
        {{"monitor", {0.55, 0.2, 0.45}, {"body", "screen"}, "computer monitor on a foot; screen faces -y"},
         [](Builder& b) { screenDevice(b, 0.3); }},
        {{"bookshelf", {0.8, 0.3, 1.8}, {"body"}, "open bookshelf: back panel at +y, shelves"}, bookshelf},
        {{"sofa", {2.0, 0.9, 0.85}, {"body", "cushion"}, "three-seat sofa: seat, backrest at +y, armrests"},
         [](Builder& b) { seat(b, 0.1); }},
        {{"armchair", {0.85, 0.85, 0.85}, {"body", "cushion"}, "armchair: seat, backrest at +y, armrests"},
         [](Builder& b) { seat(b, 0.2); }},
        {{"coffee_table", {1.0, 0.6, 0.4}, {"body"}, "low table: top on four legs"}, table},
        {{"tv", {1.2, 0.25, 0.8}, {"body", "screen"}, "television on a stand; screen faces -y"},
         [](Builder& b) { screenDevice(b, 0.15); }},
        {{"bed", {1.6, 2.1, 0.9}, {"body", "mattress"}, "double bed: frame, mattress, headboard at +y"}, bed},
        {{"stand_lamp", {0.35, 0.35, 1.6}, {"body", "shade"},
          "floor lamp: base, pole, a shade open at top and bottom (add an emitter in it)"},
         standLamp},
        {{"conference_table", {2.4, 1.2, 0.75}, {"body"}, "meeting table: top on two pedestals"}, conferenceTable},
        {{"projection_screen", {2.0, 0.1, 2.0}, {"body", "screen"}, "screen on two legs; the screen faces -y"},
         projectionScreen},
    };
    return list;
}

}  // namespace

const std::vector<PresetInfo>& presetCatalog() {
    static const std::vector<PresetInfo> catalog = [] {
        std::vector<PresetInfo> c;
        for (const auto& e : entries()) c.push_back(e.info);
        return c;
    }();
    return catalog;
}

const PresetInfo* findPreset(std::string_view name) {
    for (const auto& p : presetCatalog())
        if (p.name == name) return &p;
    return nullptr;
}

TriangleMesh buildPreset(const PresetInfo& preset, const Vec3& size, const std::map<std::string, uint32_t>& slotMaterials) {
    Builder b{{}, size, slotMaterials, preset.slots.front()};
    for (const auto& e : entries())
        if (e.info.name == preset.name) e.build(b);
    return std::move(b.mesh);
}

}  // namespace luxplan
