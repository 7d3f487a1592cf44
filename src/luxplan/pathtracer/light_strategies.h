// The path tracer's light strategies (light_strategy.h), each in its own file, in the
// order they draw their numbers at a vertex. They are stateless: what they read is
// the tracer's (its lights, set up per scene and layout) and the path's.
#pragma once

#include <vector>

#include <luxplan/materials/bsdf.h>
#include <luxplan/pathtracer/light_strategy.h>
#include <luxplan/scene/scene.h>

namespace luxplan {

// The area emitters (emitters.h): one chosen by EmitterSet's selection (flux /
// distance^2, or a photometric luminaire's intensity towards the vertex), a point on it
// by solid angle; its pdf includes the choice.
class EmitterStrategy final : public LightStrategy {
public:
    void sample(Path& path) const override;
    double pdf(const Path& path, const Vec3& wi, const Hit* hit) const override;
};

// The sun: a disk among those the room's shell may let through from the vertex
// (open_sun_disks.h), a direction uniform in it; pdf: the period's density over the
// open disks' share. Where the sky strategy goes on outside, it also draws from the
// same numbers the period's own sun sample that lights the surface there.
class SunStrategy final : public LightStrategy {
public:
    void sample(Path& path) const override;
    double pdf(const Path& path, const Vec3& wi, const Hit* hit) const override;
};

// The sky and the ground: through the room's openings from inside (sky_light.h's
// portals), the sky map's own importance sampling elsewhere. With the exterior
// strategy (PathTracer::samplesExteriorSun), a portal sample that meets a surface z
// outside the room takes z's light from the sun and the sky instead: a two-bounce
// strategy whose area density at z the integrator keeps (Path::outsideDensity).
class SkyStrategy final : public LightStrategy {
public:
    void sample(Path& path) const override;
    double pdf(const Path& path, const Vec3& wi, const Hit* hit) const override;
    // Whether the sun may light a visible static surface outside the room's box that an
    // opening sees (without one the exterior strategy finds nothing).
    static bool sunlitOutside(const Scene& scene, const DaylightEnvironment& daylight, const std::vector<Bsdf>& bsdfs);

private:
    void sampleOutside(Path& path, const EnvironmentSample& s) const;
};

// The sunlit patches (sun_patches.h): one patch point y per path, drawn at the first
// surface vertex (a sun direction, a point of an opening, the sunbeam through it to y)
// and connected to every later surface vertex that faces the beam. A two-bounce
// strategy: its pdf is the area density at the current vertex.
class SunPatchStrategy final : public LightStrategy {
public:
    void sample(Path& path) const override;
    double pdf(const Path& path, const Vec3& wi, const Hit* hit) const override;
    // Whether the path samples the patches at its current vertex.
    static bool samplesAt(const Path& path);
};

}  // namespace luxplan
