#include <luxplan/pathtracer/light_strategies.h>

namespace luxplan {

void EmitterStrategy::sample(Path& path) const {
    const EmitterSet& emitters = path.tracer.emitters_;
    if (emitters.empty()) return;
    // The choice reads every luminaire, and so does a sensor's test of them: a moved one
    // changes the path either way.
    if (path.params.footprint) path.params.footprint->usedEmitterChoice = true;
    const Vertex& v = path.v;
    if (!v.isSurface() && !path.sensorSeesEmitters) return;
    const double uChoice = path.samples.get1D(PathSamples::EmitterChoice);
    const Vec2 uPoint = path.samples.get2D(PathSamples::EmitterPoint);
    // Every path of a sampler point starts at it: its thread's view of the luminaires
    // from there (the same numbers, set up once).
    const EmitterSample s = v.isSurface() ? emitters.sample(v.p, uChoice, uPoint)
                                          : emitters.sample(emitters.viewFrom(v.p), uChoice, uPoint);
    if (!(s.pdf > 0 && s.Lv > 0)) return;
    LightSample light;
    light.wi = s.wi, light.Le = Vec3(s.Lv, s.Lv, s.Lv), light.pdf = s.pdf;
    light.maxT = s.distance, light.target = s.emitter, light.source = s.emitter;
    path.tracer.connect(path, light);
}

double EmitterStrategy::pdf(const Path& path, const Vec3& /*wi*/, const Hit* hit) const {
    if (!hit || hit->kind != HitKind::Emitter) return 0;
    const EmitterSet& emitters = path.tracer.emitters_;
    const size_t e = size_t(hit->index);
    return path.lastAtSensor ? emitters.pdf(e, emitters.viewFrom(path.lastPoint), hit->point)
                             : emitters.pdf(e, path.lastPoint, hit->point);
}

}  // namespace luxplan
