// Whether two scenes are the same scene, field by field and to the bit: what a test
// asks of a builder scene (support/scene_builder.h) against the loader's reading of
// the JSON it stands for. Kinds (emitter shapes, sampler types, constraint types)
// are compared through their interfaces: name, description, and what they give in
// the frame they were read in.
#pragma once

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <luxplan/constraints/constraint_type.h>
#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/scene/scene.h>

namespace luxplan::test {

inline void expectSameBounds(const Bounds3& a, const Bounds3& b, const std::string& what) {
    EXPECT_EQ(a.lo, b.lo) << what;
    EXPECT_EQ(a.hi, b.hi) << what;
}

inline void expectSameMesh(const TriangleMesh& a, const TriangleMesh& b, const std::string& what) {
    EXPECT_EQ(a.positions, b.positions) << what;
    EXPECT_EQ(a.triangles, b.triangles) << what;
    EXPECT_EQ(a.materials, b.materials) << what;
    EXPECT_EQ(a.normals, b.normals) << what;
}

inline void expectSameVoxels(const VoxelGrid& a, const VoxelGrid& b, const std::string& what) {
    expectSameBounds(a.bounds, b.bounds, what + " voxels");
    EXPECT_EQ(a.nx, b.nx) << what;
    EXPECT_EQ(a.ny, b.ny) << what;
    EXPECT_EQ(a.nz, b.nz) << what;
    EXPECT_EQ(a.occupied, b.occupied) << what;
    EXPECT_EQ(a.count, b.count) << what;
}

inline void expectSameRegion(const Region& a, const Region& b, const std::string& what) {
    EXPECT_EQ(a.lo, b.lo) << what;
    EXPECT_EQ(a.hi, b.hi) << what;
    EXPECT_EQ(a.rotationsDeg, b.rotationsDeg) << what;
    EXPECT_EQ(a.continuousRotation, b.continuousRotation) << what;
    EXPECT_EQ(a.rotationMinDeg, b.rotationMinDeg) << what;
    EXPECT_EQ(a.rotationMaxDeg, b.rotationMaxDeg) << what;
}

inline void expectSameDaylight(const std::optional<DaylightParams>& a, const std::optional<DaylightParams>& b) {
    ASSERT_EQ(a.has_value(), b.has_value()) << "daylight";
    if (!a) return;
    EXPECT_EQ(a->model, b->model);
    EXPECT_EQ(a->turbidity, b->turbidity);
    EXPECT_EQ(a->horizontalIlluminanceLx, b->horizontalIlluminanceLx);
    EXPECT_EQ(a->luminanceNits, b->luminanceNits);
    EXPECT_EQ(a->cieSkyType, b->cieSkyType);
    EXPECT_EQ(a->sun, b->sun);
    ASSERT_EQ(a->sunOverride.has_value(), b->sunOverride.has_value());
    if (a->sunOverride) {
        EXPECT_EQ(a->sunOverride->altitudeDeg, b->sunOverride->altitudeDeg);
        EXPECT_EQ(a->sunOverride->azimuthDeg, b->sunOverride->azimuthDeg);
        EXPECT_EQ(a->sunOverride->normalIlluminanceLx, b->sunOverride->normalIlluminanceLx);
    }
    EXPECT_EQ(a->groundReflectance, b->groundReflectance);
    for (auto [ta, tb] : {std::pair{&a->from, &b->from}, std::pair{&a->to, &b->to}}) {
        ASSERT_EQ(ta->has_value(), tb->has_value());
        if (*ta) {
            EXPECT_EQ((*ta)->julianDayUT(), (*tb)->julianDayUT());
        }
    }
    EXPECT_EQ(a->stepMinutes, b->stepMinutes);
    EXPECT_EQ(a->pressureMbar, b->pressureMbar);
    EXPECT_EQ(a->temperatureC, b->temperatureC);
}

inline void expectSameSampler(const LightSamplerSpec& a, const LightSamplerSpec& b) {
    const std::string what = "sampler " + a.name;
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.jsonPath, b.jsonPath) << what;
    EXPECT_STREQ(a.type->name(), b.type->name()) << what;
    EXPECT_EQ(a.type->describe(), b.type->describe()) << what;
    auto pa = a.type->place(Transform()), pb = b.type->place(Transform());
    EXPECT_EQ(pa->items(), pb->items()) << what;
    SamplerDrawing da = pa->drawing(), db = pb->drawing();
    EXPECT_EQ(da.outline, db.outline) << what;
    EXPECT_EQ(da.dots, db.dots) << what;
    EXPECT_EQ(da.labelAt, db.labelAt) << what;
    EXPECT_EQ(a.targetMin, b.targetMin) << what;
    EXPECT_EQ(a.targetMax, b.targetMax) << what;
    EXPECT_EQ(a.tolerance, b.tolerance) << what;
    EXPECT_EQ(a.weight, b.weight) << what;
    EXPECT_EQ(a.entity, b.entity) << what;
    ASSERT_EQ(a.statistics.size(), b.statistics.size()) << what;
    for (size_t i = 0; i < a.statistics.size(); ++i) {
        const StatisticGoal &x = a.statistics[i], &y = b.statistics[i];
        EXPECT_EQ(x.statistic, y.statistic) << what;
        EXPECT_EQ(x.targetMin, y.targetMin) << what;
        EXPECT_EQ(x.targetMax, y.targetMax) << what;
        EXPECT_EQ(x.tolerance, y.tolerance) << what;
        EXPECT_EQ(x.jsonPath, y.jsonPath) << what;
    }
}

inline void expectSameEmitter(const Emitter& a, const Emitter& b) {
    const std::string what = "emitter " + a.name;
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.jsonPath, b.jsonPath) << what;
    EXPECT_STREQ(a.shape->name(), b.shape->name()) << what;
    EXPECT_EQ(a.shape->describe(), b.shape->describe()) << what;
    EXPECT_EQ(a.shape->area(), b.shape->area()) << what;
    EXPECT_EQ(a.shape->center(), b.shape->center()) << what;
    EXPECT_EQ(a.shape->normal(), b.shape->normal()) << what;
    EXPECT_EQ(a.shape->outline(), b.shape->outline()) << what;
    expectSameMesh(a.shape->mesh().mesh, b.shape->mesh().mesh, what);
    EXPECT_EQ(a.fluxLm, b.fluxLm) << what;
    EXPECT_EQ(a.cctK, b.cctK) << what;
    EXPECT_EQ(a.entity, b.entity) << what;
}

inline void expectSameConstraint(const ConstraintSpec& a, const ConstraintSpec& b) {
    const std::string what = "constraint " + a.jsonPath;
    EXPECT_EQ(a.jsonPath, b.jsonPath);
    EXPECT_STREQ(a.kind->name(), b.kind->name()) << what;
    EXPECT_EQ(a.kind->describe(), b.kind->describe()) << what;
    EXPECT_EQ(a.kind->acceptsRoom(), b.kind->acceptsRoom()) << what;
    EXPECT_EQ(a.kind->measuresAngle(), b.kind->measuresAngle()) << what;
    EXPECT_EQ(a.kind->toleranceDeg(), b.kind->toleranceDeg()) << what;
    auto ra = a.kind->distanceRange(), rb = b.kind->distanceRange();
    ASSERT_EQ(ra.has_value(), rb.has_value()) << what;
    if (ra) {
        EXPECT_EQ(ra->min, rb->min) << what;
        EXPECT_EQ(ra->max, rb->max) << what;
        EXPECT_EQ(ra->tolerance, rb->tolerance) << what;
    }
    EXPECT_EQ(a.a, b.a) << what;
    EXPECT_EQ(a.b, b.b) << what;
    EXPECT_EQ(a.weight, b.weight) << what;
}

inline void expectSameEntity(const Entity& a, const Entity& b) {
    const std::string what = "entity " + a.path;
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.path, b.path);
    EXPECT_EQ(a.jsonPath, b.jsonPath) << what;
    EXPECT_EQ(a.parent, b.parent) << what;
    EXPECT_EQ(a.children, b.children) << what;
    EXPECT_EQ(a.position, b.position) << what;
    EXPECT_EQ(a.rotationDeg, b.rotationDeg) << what;
    ASSERT_EQ(a.regions.size(), b.regions.size()) << what;
    for (size_t i = 0; i < a.regions.size(); ++i) expectSameRegion(a.regions[i], b.regions[i], what);
    expectSameMesh(a.mesh, b.mesh, what);
    ASSERT_EQ(a.parts.size(), b.parts.size()) << what;
    for (size_t i = 0; i < a.parts.size(); ++i) {
        EXPECT_EQ(a.parts[i].kind, b.parts[i].kind) << what;
        expectSameBounds(a.parts[i].bounds, b.parts[i].bounds, what);
        EXPECT_EQ(a.parts[i].material, b.parts[i].material) << what;
    }
    EXPECT_EQ(a.fronts, b.fronts) << what;
    EXPECT_EQ(a.samplers, b.samplers) << what;
    EXPECT_EQ(a.emitters, b.emitters) << what;
    expectSameVoxels(a.voxels, b.voxels, what);
}

inline void expectSameStatic(const StaticItem& a, const StaticItem& b) {
    const std::string what = "geometry " + a.name;
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.jsonPath, b.jsonPath) << what;
    EXPECT_EQ(a.kind, b.kind) << what;
    EXPECT_EQ(a.invisible, b.invisible) << what;
    expectSameMesh(a.mesh, b.mesh, what);
    ASSERT_EQ(a.room.has_value(), b.room.has_value()) << what;
    if (a.room) {
        expectSameBounds(a.room->box, b.room->box, what);
        EXPECT_EQ(a.room->floorMaterial, b.room->floorMaterial) << what;
        EXPECT_EQ(a.room->wallMaterial, b.room->wallMaterial) << what;
        EXPECT_EQ(a.room->ceilingMaterial, b.room->ceilingMaterial) << what;
        ASSERT_EQ(a.room->openings.size(), b.room->openings.size()) << what;
        for (size_t i = 0; i < a.room->openings.size(); ++i) {
            const Opening &oa = a.room->openings[i], &ob = b.room->openings[i];
            EXPECT_EQ(oa.wall, ob.wall) << what;
            EXPECT_EQ(oa.offset, ob.offset) << what;
            EXPECT_EQ(oa.width, ob.width) << what;
            EXPECT_EQ(oa.sill, ob.sill) << what;
            EXPECT_EQ(oa.height, ob.height) << what;
            EXPECT_EQ(oa.center, ob.center) << what;
            EXPECT_EQ(oa.size, ob.size) << what;
            EXPECT_EQ(oa.material, ob.material) << what;
        }
    }
    expectSameVoxels(a.voxels, b.voxels, what);
}

// Everything but the file the scene was read from.
inline void expectSameScene(const Scene& a, const Scene& b) {
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.site.latitudeDeg, b.site.latitudeDeg);
    EXPECT_EQ(a.site.longitudeDeg, b.site.longitudeDeg);
    EXPECT_EQ(a.site.northDeg, b.site.northDeg);
    expectSameDaylight(a.daylight, b.daylight);
    ASSERT_EQ(a.materials.size(), b.materials.size());
    for (size_t i = 0; i < a.materials.size(); ++i) {
        const Material &ma = a.materials[i], &mb = b.materials[i];
        EXPECT_EQ(ma.name, mb.name);
        EXPECT_EQ(ma.type, mb.type) << ma.name;
        EXPECT_EQ(ma.reflectance, mb.reflectance) << ma.name;
        EXPECT_EQ(ma.base, mb.base) << ma.name;
        EXPECT_EQ(ma.roughness, mb.roughness) << ma.name;
        EXPECT_EQ(ma.transmittance, mb.transmittance) << ma.name;
    }
    EXPECT_EQ(a.materialIndex, b.materialIndex);
    ASSERT_EQ(a.geometry.size(), b.geometry.size());
    for (size_t i = 0; i < a.geometry.size(); ++i) expectSameStatic(a.geometry[i], b.geometry[i]);
    ASSERT_EQ(a.emitters.size(), b.emitters.size());
    for (size_t i = 0; i < a.emitters.size(); ++i) expectSameEmitter(a.emitters[i], b.emitters[i]);
    ASSERT_EQ(a.entities.size(), b.entities.size());
    for (size_t i = 0; i < a.entities.size(); ++i) expectSameEntity(a.entities[i], b.entities[i]);
    ASSERT_EQ(a.samplers.size(), b.samplers.size());
    for (size_t i = 0; i < a.samplers.size(); ++i) expectSameSampler(a.samplers[i], b.samplers[i]);
    ASSERT_EQ(a.constraints.size(), b.constraints.size());
    for (size_t i = 0; i < a.constraints.size(); ++i) expectSameConstraint(a.constraints[i], b.constraints[i]);
    EXPECT_EQ(a.overlap.tolerance, b.overlap.tolerance);
    EXPECT_EQ(a.overlap.weight, b.overlap.weight);
    EXPECT_EQ(a.overlap.jsonPath, b.overlap.jsonPath);
    EXPECT_EQ(a.overlap.exempt, b.overlap.exempt);
    EXPECT_EQ(a.objective.lightingWeight, b.objective.lightingWeight);
    EXPECT_EQ(a.maintenanceFactor, b.maintenanceFactor);
    const OptimizerSettings &oa = a.optimizer, &ob = b.optimizer;
    EXPECT_EQ(oa.iterations, ob.iterations);
    EXPECT_EQ(oa.seed, ob.seed);
    EXPECT_EQ(oa.pathsPerPoint, ob.pathsPerPoint);
    EXPECT_EQ(oa.searchPathsPerPoint, ob.searchPathsPerPoint);
    EXPECT_EQ(oa.reportPathsPerPoint, ob.reportPathsPerPoint);
    EXPECT_EQ(oa.selectionPathsPerPoint, ob.selectionPathsPerPoint);
    EXPECT_EQ(oa.flat, ob.flat);
    EXPECT_EQ(oa.innerIterations, ob.innerIterations);
    EXPECT_EQ(oa.constantTemperature, ob.constantTemperature);
    EXPECT_EQ(oa.temperatureStart, ob.temperatureStart);
    EXPECT_EQ(oa.temperatureEnd, ob.temperatureEnd);
    EXPECT_EQ(oa.startFromScene, ob.startFromScene);
}

}  // namespace luxplan::test
