// The one table of emitter shapes: a new shape is its file and one line here.
#include <luxplan/core/names.h>
#include <luxplan/emitters/emitter_shape.h>

namespace luxplan {

std::shared_ptr<const EmitterShape> readRectEmitter(const json::Fields& f);    // rect.cpp
std::shared_ptr<const EmitterShape> readDiskEmitter(const json::Fields& f);    // disk.cpp
std::shared_ptr<const EmitterShape> readSphereEmitter(const json::Fields& f);  // sphere.cpp

const std::vector<EmitterShapeEntry>& emitterShapes() {
    static const std::vector<EmitterShapeEntry> shapes = {
        {"rect", readRectEmitter},
        {"disk", readDiskEmitter},
        {"sphere", readSphereEmitter},
    };
    return shapes;
}

const EmitterShapeEntry* findEmitterShape(std::string_view name) { return findByName(emitterShapes(), name); }
std::vector<std::string> emitterShapeNames() { return namesOf(emitterShapes()); }

double emitterLuminance(const Emitter& e) { return e.fluxLm / (kPi * e.shape->area()); }

std::unique_ptr<const EmitterShape::FromPoint> EmitterShape::from(const Vec3& p) const {
    class Calls final : public FromPoint {
    public:
        Calls(const EmitterShape& shape, const Vec3& p) : shape_(shape), p_(p) {}
        std::optional<EmitterPoint> sample(Vec2 u) const override { return shape_.sample(p_, u); }
        double pdf(const Vec3& q) const override { return shape_.pdf(p_, q); }

    private:
        const EmitterShape& shape_;
        Vec3 p_;
    };
    return std::make_unique<Calls>(*this, p);
}

}  // namespace luxplan
