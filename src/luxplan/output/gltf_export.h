// The scene under one layout as a binary glTF 2.0 file (.glb) for Blender and other
// viewers: room, static geometry, furniture, emitters as emissive meshes and as
// KHR_lights_punctual lights, one PBR material per scene material.
#pragma once

#include <filesystem>

#include <luxplan/daylight/environment.h>
#include <luxplan/output/black_body.h>
#include <luxplan/scene/layout.h>

namespace luxplan {

// The sun of a daylight period as one directional light: the illuminance-weighted
// mean direction of its disks (towards the sun), their time-weighted normal
// illuminance summed, and their weighted colour (luminance 1). Zero without a sun.
struct SunSummary {
    Vec3 direction{0, 0, 1};
    double normalIlluminanceLx = 0;
    Vec3 color{1, 1, 1};
};
SunSummary summarizeSun(const DaylightEnvironment& daylight);

// The sky (and ground below the horizon is left out) as one colour: its mean radiance
// over the upper hemisphere weighted by cos(theta), as luminance and a colour of
// luminance 1, with its horizontal illuminance.
struct SkySummary {
    Vec3 color{1, 1, 1};
    double luminance = 0;
    double horizontalIlluminanceLx = 0;
};
SkySummary summarizeSky(const DaylightEnvironment& daylight);

// A KHR_lights_punctual light's colour lies within [0, 1]: `rgb` (negative components
// taken as 0) scaled to a largest component of 1, with `intensity` times that largest
// component, so that colour x intensity stays rgb x intensity. Black (or not finite):
// white at intensity 0.
struct LightColor {
    Vec3 color{1, 1, 1};
    double intensity = 0;
};
LightColor lightColorAndIntensity(const Vec3& rgb, double intensity);

// Every glTF camera's near plane (m).
inline constexpr double kGltfCameraNear = 0.05;

// A glTF camera's far plane (m) at `eye` for a scene within `scene` (luxplan's frame):
// twice the distance to the bounds' farthest corner, rounded up to a whole metre, at
// least 10 m; so always beyond znear and beyond everything the file holds.
double cameraFar(const Bounds3& scene, const Vec3& eye);

// The name of the camera a file gets when its scene has none.
inline constexpr const char* kDefaultViewName = "default view";

// Writes `file` (glTF is y-up: luxplan's (x, y, z) becomes (x, z, -y)). Nodes, named
// after what they show: one per visible static item (world frame), one per entity with
// parts (placed by worldTransforms; a single part its mesh, several parts each a child
// node "PATH part K: KIND" with its own mesh) and one per emitter (an emissive rect,
// disk or sphere carrying a point light for a sphere, a spot light along the normal
// for a rect or disk, intensity in candela). Invisible blockers are left out. Each
// scene camera is a perspective camera node of its name; a scene without cameras gets
// one, kDefaultViewName, render.png's default view (defaultCamera: inside the room).
// Every camera has znear kGltfCameraNear and zfar cameraFar. With a room, the scene's
// extras give its inside in glTF's frame: {"room": {"min": [x, y, z], "max": [...]}}.
// With `daylight`: a directional light "sun" (summarizeSun, intensity in lux, colour
// and intensity by lightColorAndIntensity) and the sky in the scene's extras:
// {"sky": {"color": [r, g, b], "luminance_cd_m2", "horizontal_illuminance_lx"}}.
// Throws IoError when the file cannot be written.
void writeGlb(const std::filesystem::path& file, const Scene& scene, const Layout& layout,
              const DaylightEnvironment* daylight = nullptr);

}  // namespace luxplan
