#include <luxplan/lightsamplers/measure_plan.h>

#include <algorithm>
#include <stdexcept>


namespace luxplan {

std::vector<int> WorkPlan::workSamplers() const {
    std::vector<int> samplerOf;
    samplerOf.reserve(work.size());
    for (const WorkItem& w : work) samplerOf.push_back(w.sampler);
    return samplerOf;
}

WorkPlan planWork(const PathTracer& tracer, const MeasureOptions& options, const PathTracer* glareTracer) {
    const Scene& scene = tracer.rayTracer().scene();
    const size_t samplers = scene.samplers.size();
    WorkPlan plan;
    for (size_t k = 0; k < samplers; ++k) {
        plan.placed.push_back(placeSampler(scene.samplers[k], tracer));
        plan.firstWork.push_back(plan.work.size());
        for (int i = 0; i < plan.placed.back()->items(); ++i) plan.work.push_back({int(k), i});
    }
    plan.firstWork.push_back(plan.work.size());
    plan.tracerOf.assign(samplers, &tracer);
    if (glareTracer)
        for (size_t k = 0; k < samplers; ++k)
            if (scene.samplers[k].type->surveysSources()) plan.tracerOf[k] = glareTracer;
    if (!options.lightFloors.empty() && options.lightFloors.size() != samplers)
        throw std::logic_error("MeasureOptions::lightFloors: one per sampler of the scene");
    plan.lightFloorOf = options.lightFloors;
    plan.lightFloorOf.resize(samplers, 0.0);
    plan.sharesPaths.resize(samplers);
    for (size_t k = 0; k < samplers; ++k) plan.sharesPaths[k] = plan.placed[k]->sharesPaths();
    plan.paths = std::max(1, options.pathsPerPoint);
    return plan;
}

}  // namespace luxplan
